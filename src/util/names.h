/* Lists of names for messages: joining them ("euler, rk4, verlet") and
 * suggesting the nearest one to a misspelt word ("did you mean 'rk4'?"). */
#ifndef SW_UTIL_NAMES_H
#define SW_UTIL_NAMES_H

#include <stddef.h>

/* Name i of a list (0 <= i < n); ctx is the caller's. */
typedef const char *sw_name_at_fn(const void *ctx, int i);

/* Join the n names with ", " into buf, always NUL-terminated and cut to
 * len; returns the bytes written. */
size_t sw_names_join(char *buf, size_t len, sw_name_at_fn *at, const void *ctx, int n);

/* Edit distance between a and b (insertions, deletions, substitutions);
 * 99 when either is longer than 40 bytes. */
int sw_names_distance(const char *a, const char *b);

/* The name closest to word when it is near enough to be a typo (fewer than
 * 3 edits, and fewer edits than word has bytes); NULL otherwise. */
const char *sw_names_nearest(const char *word, sw_name_at_fn *at, const void *ctx, int n);

#endif
