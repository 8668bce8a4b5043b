/* Output files the Unix way, for every writer (traces, bench CSV and SVG,
 * lesson progress): a regular file (or a new name) is written to a
 * temporary beside it and renamed over it only when complete, keeping the
 * old file's mode; a symbolic link is followed to its target; standard
 * output ("-", /dev/stdout, or the very file stdout goes to), character
 * devices and FIFOs are written in place, streaming. */
#ifndef SW_UTIL_OUTFILE_H
#define SW_UTIL_OUTFILE_H

#include <stddef.h>
#include <stdio.h>
#include <sys/stat.h>

#define SW_OUTFILE_PATH_MAX 4096

typedef struct sw_outfile {
    FILE *f;                          /* write here */
    int is_stdout;                    /* "-" (or NULL): standard output */
    int direct;                       /* written in place: stdout, a device, a FIFO */
    char path[SW_OUTFILE_PATH_MAX];   /* the target, symbolic links followed */
    char shown[SW_OUTFILE_PATH_MAX];  /* the name as given, for messages */
    char tmp[SW_OUTFILE_PATH_MAX];    /* the temporary beside it; "" when direct or gone */
} sw_outfile;

/* Where writing path would go, decided without creating anything. */
typedef struct sw_outfile_target {
    int is_stdout;                    /* "-", NULL, or the file standard output writes to */
    int direct;                       /* written in place: stdout, a character device, a FIFO */
    int exists;                       /* path names an existing file: st describes it */
    struct stat st;
    char path[SW_OUTFILE_PATH_MAX];   /* the file written: links followed (a regular file or a
                                         new name), the name as given (a device, a FIFO) */
} sw_outfile_target;

/* Resolve path as sw_outfile_open would and check it can be written: a
 * regular file or new name needs a writable directory; a directory, a block
 * device or a socket is refused. 0, SW_EINVAL (empty, too long, not a file
 * to write) or SW_EIO (no directory to create it in, or not writable), with
 * err filled. */
int sw_outfile_resolve(const char *path, sw_outfile_target *t, char *err, size_t errlen);
/* Whether path could be opened for writing, without creating anything:
 * sw_outfile_resolve's answer. */
int sw_outfile_check(const char *path, char *err, size_t errlen);
/* Open path for writing (NULL or "-": standard output). Temporary names
 * are "NAME.tmp.XXXXXX", NAME cut short when that would pass the file
 * system's name limit. 0, SW_EINVAL or SW_EIO with err filled; on failure
 * nothing is left behind. */
int sw_outfile_open(sw_outfile *o, const char *path, char *err, size_t errlen);
/* Flush everything; a regular file is synced, closed and renamed onto its
 * name. 0, or SW_EIO ("cannot write 'NAME': why") with the temporary
 * removed. The file is closed (standard output only flushed) either way. */
int sw_outfile_commit(sw_outfile *o, char *err, size_t errlen);
/* Give up: close and remove the temporary. Safe to call twice and after a
 * failed open or commit. */
void sw_outfile_abort(sw_outfile *o);
/* The name for messages: the path as given, or "standard output". */
const char *sw_outfile_name(const sw_outfile *o);

#endif
