/* Non-blocking input. Invariant: open(2) is the only call that could wait,
 * and with O_NONBLOCK it does not: a FIFO without a writer opens at once and
 * is then refused by its type. */
#include "util/infile.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

int sw_infile_open(const char *path, struct stat *st, const char **what)
{
    *what = NULL;
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY);
    if (fd < 0)
        return -1;
    if (fstat(fd, st) != 0) {
        int e = errno;
        close(fd);
        errno = e;
        return -1;
    }
    if (!S_ISREG(st->st_mode)) {
        *what = S_ISDIR(st->st_mode) ? "a directory" : S_ISFIFO(st->st_mode) ? "a FIFO"
              : S_ISSOCK(st->st_mode) ? "a socket"
              : S_ISCHR(st->st_mode) || S_ISBLK(st->st_mode) ? "a device" : "not a regular file";
        close(fd);
        return -1;
    }
    int flags = fcntl(fd, F_GETFL);
    if (flags >= 0)
        fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    return fd;
}

int sw_infile_read(int fd, size_t max, char **out, size_t *len)
{
    /* One byte more than allowed, to notice a file that grew after fstat. */
    char *buf = malloc(max + 2);
    if (!buf) {
        errno = ENOMEM;
        return -1;
    }
    size_t got = 0;
    while (got < max + 1) {
        ssize_t n = read(fd, buf + got, max + 1 - got);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            int e = errno;
            free(buf);
            errno = e;
            return -1;
        }
        if (n == 0)
            break;
        got += (size_t)n;
    }
    if (got > max) {
        free(buf);
        return 1;
    }
    buf[got] = '\0';
    *out = buf;
    *len = got;
    return 0;
}
