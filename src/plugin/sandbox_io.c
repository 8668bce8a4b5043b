/* The parent's side of a child's channel: reads and writes with a
 * deadline that the cancel flag (util/signals.h) cuts short, and the
 * monotonic clock they share with the watchdog (sandbox.c). Writing to a
 * dead child is an error, never a SIGPIPE (MSG_NOSIGNAL). */
#define _GNU_SOURCE /* MSG_NOSIGNAL, Linux-only like the sandbox */
#include "plugin/sandbox.h"
#include "plugin/jail.h"

#include <errno.h>
#include <math.h>
#include <poll.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/uio.h>
#include <time.h>
#include <unistd.h>

#include "stepwise/stepwise.h"
#include "util/signals.h"

/* How long a read waits awake before it sleeps in poll. */
#define SPIN_SECONDS 20e-6

/* Every signal util/signals.h catches (record, play, grade all use it). */
static int sandbox_cancelled(void) { return sw_signal_caught != 0; }

double sw_sandbox_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int sw_sandbox_read_file(int fd, size_t max, double seconds, char **buf, size_t *len)
{
    int64_t size;
    *buf = NULL;
    *len = 0;
    if (sw_sandbox_read(fd, &size, sizeof size, seconds) != 1)
        return -1;
    if (size == -1)
        return 0;
    if (size < 0 || (uint64_t)size > SW_JAIL_FILE_MAX)
        return -1;
    /* Larger than max: its first max bytes, the rest read and dropped, so
     * that the sender (blocked on a full socket) ends and what follows on
     * fd still comes (a compiler's log of 60 MiB of errors once held its
     * jail until the build's timeout). */
    size_t keep = (uint64_t)size > max ? max : (size_t)size;
    char *b = malloc(keep + 1);
    if (!b)
        return -1;
    if (keep > 0 && sw_sandbox_read(fd, b, keep, seconds) != 1) {
        free(b);
        return -1;
    }
    char drop[65536];
    for (size_t left = (size_t)size - keep; left > 0;) {
        size_t n = left < sizeof drop ? left : sizeof drop;
        if (sw_sandbox_read(fd, drop, n, seconds) != 1) {
            free(b);
            return -1;
        }
        left -= n;
    }
    b[keep] = '\0';
    *buf = b;
    *len = keep;
    return 1;
}

/* Wait until fd is readable, for at most `seconds` (< 0: no limit). 1
 * readable (or at end of file), 0 timed out, -1 cancelled (a signal
 * util/signals.h caught). */
static int sandbox_wait(int fd, double seconds)
{
    double deadline = seconds >= 0 ? sw_sandbox_now() + seconds : 0;
    for (;;) {
        if (sandbox_cancelled())
            return -1;
        int slice = 100;
        if (seconds >= 0) {
            double left = deadline - sw_sandbox_now();
            if (left <= 0)
                return 0;
            if (left * 1000 < slice)
                slice = (int)(left * 1000) + 1;
        }
        struct pollfd p = { .fd = fd, .events = POLLIN };
        int rc = poll(&p, 1, slice);
        if (rc > 0)
            return 1;
        if (rc < 0 && errno != EINTR)
            return 1; /* let the read report it */
    }
}

long sw_sandbox_read_some(int fd, void *buf, size_t max, double seconds)
{
    double deadline = seconds >= 0 ? sw_sandbox_now() + seconds : -1;
    double spin_until = -1;
    for (;;) {
        ssize_t n = recv(fd, buf, max, MSG_DONTWAIT);
        if (n > 0)
            return (long)n;
        if (n == 0)
            return 0;
        if (errno == ENOTSOCK) {
            int w = sandbox_wait(fd, seconds >= 0 ? fmax(deadline - sw_sandbox_now(), 0) : -1);
            if (w <= 0)
                return w < 0 ? -1 : -2;
            n = read(fd, buf, max);
            if (n >= 0)
                return (long)n;
        }
        if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)
            return errno == ECONNRESET ? 0 : -3;
        double now = sw_sandbox_now();
        if (spin_until < 0)
            spin_until = now + SPIN_SECONDS;
        if (now < spin_until)
            continue;
        double left = seconds >= 0 ? deadline - now : -1;
        if (seconds >= 0 && left < 0)
            left = 0;
        int w = sandbox_wait(fd, left);
        if (w < 0)
            return -1;
        if (w == 0)
            return -2;
    }
}

int sw_sandbox_read(int fd, void *buf, size_t len, double seconds)
{
    /* pieces as they come, within one deadline for the whole */
    double deadline = seconds >= 0 ? sw_sandbox_now() + seconds : -1;
    char *p = buf;
    for (size_t got = 0; got < len;) {
        double left = seconds >= 0 ? fmax(deadline - sw_sandbox_now(), 0) : -1;
        long n = sw_sandbox_read_some(fd, p + got, len - got, left);
        if (n <= 0)
            return (int)n;
        got += (size_t)n;
    }
    return 1;
}

int sw_sandbox_write(int fd, const void *buf, size_t len)
{
    struct iovec part = { (void *)buf, len };
    return sw_sandbox_writev(fd, &part, 1);
}

int sw_sandbox_writev(int fd, struct iovec *parts, int n)
{
    struct msghdr msg;
    memset(&msg, 0, sizeof msg);
    msg.msg_iov = parts;
    msg.msg_iovlen = (size_t)n;
    while (msg.msg_iovlen > 0) {
        ssize_t sent = sendmsg(fd, &msg, MSG_NOSIGNAL);
        if (sent < 0 && errno == EINTR)
            continue;
        if (sent <= 0)
            return -1;
        while (msg.msg_iovlen > 0 && (size_t)sent >= msg.msg_iov->iov_len) {
            sent -= (ssize_t)msg.msg_iov->iov_len;
            msg.msg_iov++;
            msg.msg_iovlen--;
        }
        if (msg.msg_iovlen > 0) {
            msg.msg_iov->iov_base = (char *)msg.msg_iov->iov_base + sent;
            msg.msg_iov->iov_len -= (size_t)sent;
        }
    }
    return 0;
}
