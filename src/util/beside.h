/* Where the running binary is, for what a build tree keeps beside it
 * (lessons, headers, sources). */
#ifndef SW_UTIL_BESIDE_H
#define SW_UTIL_BESIDE_H

#include <stddef.h>

/* The first of the binary's directory and up to three above it where
 * DIR/sub satisfies ok (a build tree); 1 with the path in out, else 0. */
int sw_beside_binary(const char *sub, int (*ok)(const char *path), char *out, size_t len);

#endif
