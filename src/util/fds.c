/* Closing inherited descriptors (fds.h). */
#define _GNU_SOURCE /* close_range's number, Linux-only like the sandbox */
#include "util/fds.h"

#include <dirent.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

static int kept(int fd, const int *keep, int n)
{
    for (int i = 0; i < n; i++)
        if (keep[i] == fd)
            return 1;
    return 0;
}

/* close_range over [from, ∞) minus keep; 0, or -1 when the kernel lacks it. */
static int by_ranges(int from, const int *keep, int n)
{
#ifdef SYS_close_range
    int lo = from;
    for (;;) {
        int next = -1; /* the smallest kept descriptor at or above lo */
        for (int i = 0; i < n; i++)
            if (keep[i] >= lo && (next < 0 || keep[i] < next))
                next = keep[i];
        unsigned hi = next < 0 ? ~0u : (unsigned)next - 1;
        if ((next < 0 || next > lo) && syscall(SYS_close_range, (unsigned)lo, hi, 0) != 0)
            return -1;
        if (next < 0)
            return 0;
        lo = next + 1;
    }
#else
    (void)from, (void)keep, (void)n;
    return -1;
#endif
}

/* The open descriptors /proc/self/fd lists; 0, or -1 without /proc. */
static int by_listing(int from, const int *keep, int n)
{
    DIR *d = opendir("/proc/self/fd");
    if (!d)
        return -1;
    int self = dirfd(d);
    struct dirent *e;
    while ((e = readdir(d))) {
        char *end;
        long fd = strtol(e->d_name, &end, 10);
        if (*end || end == e->d_name || fd < from || fd == self || kept((int)fd, keep, n))
            continue;
        close((int)fd);
    }
    closedir(d);
    return 0;
}

/* Each descriptor below RLIMIT_NOFILE (at most 65536) in turn. */
static int by_trying(int from, const int *keep, int n)
{
    struct rlimit nofile;
    long maxfd = getrlimit(RLIMIT_NOFILE, &nofile) == 0 && nofile.rlim_cur != RLIM_INFINITY &&
                         nofile.rlim_cur < 65536 ? (long)nofile.rlim_cur : 65536;
    for (long fd = from; fd < maxfd; fd++)
        if (!kept((int)fd, keep, n))
            close((int)fd);
    return 0;
}

int sw_close_fds_by(int way, int from, const int *keep, int n)
{
    return way == 0 ? by_ranges(from, keep, n) : way == 1 ? by_listing(from, keep, n)
                                                          : by_trying(from, keep, n);
}

void sw_close_fds(int from, const int *keep, int n)
{
    if (by_ranges(from, keep, n) != 0 && by_listing(from, keep, n) != 0)
        by_trying(from, keep, n);
}
