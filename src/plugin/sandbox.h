/* Child processes for untrusted work (student plugins, graded submissions):
 * fork with CPU-time, memory, output, descriptor and process limits, in the
 * jail (plugin/jail.h) where asked, talk over a socket with a watchdog on
 * every wait, and say in words how a child ended. Pure C, no printing;
 * Linux (the child also dies with its parent). */
#ifndef SW_PLUGIN_SANDBOX_H
#define SW_PLUGIN_SANDBOX_H

#include <signal.h>
#include <stddef.h>
#include <sys/types.h>

#include "plugin/jail.h"

/* Limits applied in the child before it runs anything; 0 means none. */
typedef struct sw_limits {
    double cpu_seconds;    /* RLIMIT_CPU: SIGXCPU past it */
    size_t memory_bytes;   /* RLIMIT_AS: allocations fail past it */
    size_t output_bytes;   /* RLIMIT_FSIZE: files it writes stop growing past it */
} sw_limits;

/* Always, whatever the limits: descriptors a child may hold and processes
 * its user may run at once (RLIMIT_NOFILE, RLIMIT_NPROC in the jail). */
#define SW_CHILD_FILES 64
#define SW_CHILD_PROCS 64

/* A running child and the parent's ends of its channel. */
typedef struct sw_child {
    pid_t pid;             /* 0: none (jailed: the first of the jail's processes) */
    int to_child;          /* the child reads its commands from the other end */
    int from_child;        /* the child writes its replies to the other end */
    int status_fd;         /* jailed: the jail's init reports how the payload ended; else -1 */
    int uid_jail;          /* a UID jail: its directory goes with it (jail.h) */
} sw_child;

/* How a child ended. */
typedef struct sw_child_end {
    int exited;            /* 1: exit status in code */
    int code;
    int signal;            /* the signal that killed it, or 0 */
    int killed;            /* 1: we killed it (watchdog or cancel) */
} sw_child_end;

/* The child's side: runs in the child with its pipe ends (in_fd: commands,
 * out_fd: replies); the return value is its exit status. */
typedef int sw_child_fn(void *ctx, int in_fd, int out_fd);


/* Fork a child that runs fn(ctx, ...) under lim, its stdin /dev/null, its
 * stdout and stderr output_fd (-1: /dev/null), every other descriptor closed
 * but its pipes, terminal signals ignored, in its own process group; on
 * Linux it is killed when the parent dies. stdio is flushed first, so the
 * child never writes the parent's buffers twice. 0 or SW_EIO. */
int sw_sandbox_spawn(sw_child *c, sw_child_fn *fn, void *ctx, const sw_limits *lim, int output_fd,
                     char *err, size_t errlen);

/* The same, with the payload in the jail (spec); without the jail
 * (sw_jail_enabled() is 0) exactly sw_sandbox_spawn. The payload's
 * channel is fd 3 in the child. 0, or SW_EIO with err naming the layer the
 * kernel refused (no user namespaces, no seccomp) and what to do. */
int sw_sandbox_spawn_jailed(sw_child *c, sw_child_fn *fn, void *ctx, const sw_limits *lim, int output_fd,
                            const sw_jail *spec, char *err, size_t errlen);
/* Whether the jail can be built here (tried once, then remembered); 0, or
 * SW_EIO with err naming what the kernel refused. 0 without the jail. */
int sw_sandbox_probe(char *err, size_t errlen);
/* Read a file the jail sends back (sw_jail_send_outputs): at most max
 * bytes into *buf (malloc'ed, NUL-terminated), *len its size; of a larger
 * file its first max bytes (the rest read and dropped). 1 done, 0 the
 * jail had no such regular file, -1 a broken or oversized record. */
int sw_sandbox_read_file(int fd, size_t max, double seconds, char **buf, size_t *len);

/* Read exactly len bytes within `seconds`. 1 done, 0 end of file first (the
 * child is gone), -1 cancelled, -2 timed out, -3 a read error. */
int sw_sandbox_read(int fd, void *buf, size_t len, double seconds);
/* Read what is there, at least one byte, at most max, within `seconds`:
 * the count, or 0 end of file, -1 cancelled, -2 timed out, -3 a read error. */
long sw_sandbox_read_some(int fd, void *buf, size_t max, double seconds);
/* Write all of buf; 0, or -1 when the child is gone (EPIPE is not a signal). */
int sw_sandbox_write(int fd, const void *buf, size_t len);
/* The same for n parts in one message (parts is used up). */
struct iovec;
int sw_sandbox_writev(int fd, struct iovec *parts, int n);

/* Kill the child (SIGKILL to its process group) and reap it. */
void sw_sandbox_kill(sw_child *c, sw_child_end *end);
/* Reap a child expected to exit: wait at most `seconds`, then kill it. */
void sw_sandbox_reap(sw_child *c, double seconds, sw_child_end *end);

/* "exited with status 3", "crashed with SIGSEGV (invalid memory access)",
 * "ran out of CPU time (SIGXCPU)", ... */
void sw_sandbox_describe(const sw_child_end *end, char *buf, size_t len);
/* Seconds on a monotonic clock. */
double sw_sandbox_now(void);

/* orphans.c. Become the subreaper of everything started from here, so a
 * process a submission left running (a daemon out of its session, under
 * --no-sandbox) comes back to this process instead of init. */
void sw_sandbox_adopt_orphans(void);
/* Kill every child of this process still there (call when none should
 * be: every worker reaped), and its children as they come back in turn;
 * the number killed. */
int sw_sandbox_kill_orphans(void);

#endif
