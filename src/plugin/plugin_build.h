/* Building a student's integrator from C source (plugin_build.c): the
 * documented flags, the compiler jailed with limits of its own. */
#ifndef SW_PLUGIN_PLUGIN_BUILD_H
#define SW_PLUGIN_PLUGIN_BUILD_H

#include <stddef.h>

/* The compiler's warnings on a source that compiled: how many lines say
 * "warning", the first (escaped, named as the student named the file; ""
 * when none). */
typedef struct sw_build_warnings {
    int count;
    char first[400];
} sw_build_warnings;

/* Compile src, with the headers beside it (plugin_headers.h; shared: a
 * grader's folder, whose headers go with src only where it is the one .c
 * there), into dir/NAME.so (its messages in dir/NAME.log), the .so's path
 * into so: 0, or SW_EINVAL (it does not compile, or took 60 s of CPU) or
 * SW_EIO (a limit of the grader's: no room, 60 s of wall clock) with err saying which, the
 * compiler's first error quoted; its warnings into warn (may be NULL).
 * Messages name it as shown_as (NULL: src). */
int sw_plugin_compile(const char *src, const char *shown_as, int shared, const char *dir, const char *name,
                      char *so, size_t solen, sw_build_warnings *warn, char *err, size_t errlen);

#endif
