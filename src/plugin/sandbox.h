/* Child processes for untrusted work (student plugins, graded submissions):
 * fork with CPU-time, memory and output limits, talk over pipes with a
 * watchdog on every wait, and say in words how a child ended. Pure C, no
 * printing; POSIX (Linux: the child also dies with its parent). */
#ifndef SW_PLUGIN_SANDBOX_H
#define SW_PLUGIN_SANDBOX_H

#include <signal.h>
#include <stddef.h>
#include <sys/types.h>

/* Limits applied in the child before it runs anything; 0 means none. */
typedef struct sw_limits {
    double cpu_seconds;    /* RLIMIT_CPU: SIGXCPU past it */
    size_t memory_bytes;   /* RLIMIT_AS: allocations fail past it */
    size_t output_bytes;   /* RLIMIT_FSIZE: files it writes stop growing past it */
} sw_limits;

/* A running child and the parent's ends of its two pipes. */
typedef struct sw_child {
    pid_t pid;             /* 0: none */
    int to_child;          /* the child reads its commands from the other end */
    int from_child;        /* the child writes its replies to the other end */
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

/* A flag a signal handler sets: every wait of this module returns early, as
 * cancelled, once *flag is non-zero, or once util/signals.h has caught a
 * signal (sw_signal_caught). NULL: only the latter. */
void sw_sandbox_set_cancel(volatile sig_atomic_t *flag);
/* Whether the cancel flag is set now. */
int sw_sandbox_cancelled(void);

/* Fork a child that runs fn(ctx, ...) under lim, its stdin /dev/null, its
 * stdout and stderr output_fd (-1: /dev/null), every other descriptor closed
 * but its pipes, terminal signals ignored, in its own process group; on
 * Linux it is killed when the parent dies. stdio is flushed first, so the
 * child never writes the parent's buffers twice. 0 or SW_EIO. */
int sw_sandbox_spawn(sw_child *c, sw_child_fn *fn, void *ctx, const sw_limits *lim, int output_fd,
                     char *err, size_t errlen);

/* Wait until fd is readable, for at most `seconds` (< 0: no limit). 1
 * readable (or at end of file), 0 timed out, -1 cancelled. */
int sw_sandbox_wait(int fd, double seconds);
/* Read exactly len bytes within `seconds`. 1 done, 0 end of file first (the
 * child is gone), -1 cancelled, -2 timed out, -3 a read error. */
int sw_sandbox_read(int fd, void *buf, size_t len, double seconds);
/* Write all of buf; 0, or -1 when the child is gone (EPIPE is not a signal). */
int sw_sandbox_write(int fd, const void *buf, size_t len);

/* Kill the child (SIGKILL to its process group) and reap it. */
void sw_sandbox_kill(sw_child *c, sw_child_end *end);
/* Reap a child expected to exit: wait at most `seconds`, then kill it. */
void sw_sandbox_reap(sw_child *c, double seconds, sw_child_end *end);

/* "exited with status 3", "crashed with SIGSEGV (invalid memory access)",
 * "ran out of CPU time (SIGXCPU)", ... */
void sw_sandbox_describe(const sw_child_end *end, char *buf, size_t len);
/* Seconds on a monotonic clock. */
double sw_sandbox_now(void);

#endif
