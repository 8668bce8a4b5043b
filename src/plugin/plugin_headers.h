/* The headers a student's C source is built with (docs/plugins.md, "More
 * than one file"): the *.h files in the source's own folder, copied beside
 * it into the compiler's jail, so that `#include "tableau.h"` works as it
 * did on the student's machine. Nothing else of the folder goes in. */
#ifndef SW_PLUGIN_PLUGIN_HEADERS_H
#define SW_PLUGIN_PLUGIN_HEADERS_H

#include <limits.h>
#include <stddef.h>

#define SW_HEADERS_MAX 12
/* A source and its headers together, in bytes: what is built is what
 * --similarity reads whole (red team 4: a 60 MiB sparse header each was
 * copied into the jail's disk, and a 1 MiB comment in a header hid a
 * copy from --similarity). */
#define SW_PLUGIN_SOURCE_MAX ((size_t)1 << 20)
#define SW_HEADER_NAME_MAX 200 /* with its NUL: the jail's paths hold it */

typedef struct sw_headers {
    char dir[PATH_MAX];                            /* the source's folder */
    int n;                                         /* headers to build with, sorted by name */
    char name[SW_HEADERS_MAX][SW_HEADER_NAME_MAX];
    int withheld;  /* headers beside it that are not used: the folder is shared (below) */
    int sources;   /* the .c files in the folder */
} sw_headers;

/* The headers beside src: regular files (never a link) whose names end in
 * .h, do not start with a dot and hold no control character. A name as
 * long as SW_HEADER_NAME_MAX or longer is refused (-1), never left out. shared (grade's submissions, where one folder may
 * hold several students' files): a folder's headers go with a source only
 * where it is the one .c in that folder; otherwise (the student's own
 * folder: try, check, record) always. 0, or -1 with err saying why (more
 * than SW_HEADERS_MAX headers). */
int sw_headers_find(const char *src, int shared, sw_headers *h, char *err, size_t errlen);

/* Header i opened for reading, never through a link, never blocking: the
 * descriptor of a regular file, or -1 (errno set). */
int sw_headers_open(const sw_headers *h, int i);

#endif
