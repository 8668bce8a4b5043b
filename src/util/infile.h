/* Input files opened without ever blocking: a FIFO, a device or a directory
 * named where a file is expected is refused at once, never waited on. */
#ifndef SW_UTIL_INFILE_H
#define SW_UTIL_INFILE_H

#include <stddef.h>
#include <sys/stat.h>

/* Open path for reading (O_NONBLOCK, then fstat): a regular file gives its
 * descriptor (blocking mode restored) and *st. -1 otherwise, with *what
 * naming the kind of file it is ("a directory", "a FIFO", "a device", "a
 * socket") or NULL when open or fstat failed (errno says why). */
int sw_infile_open(const char *path, struct stat *st, const char **what);

/* Read all of fd into a new buffer of at most max bytes (*len set, a NUL
 * added after them). 0; 1 when the file holds more than max bytes (nothing
 * returned); -1 on a read error or no memory (errno set). */
int sw_infile_read(int fd, size_t max, char **out, size_t *len);

#endif
