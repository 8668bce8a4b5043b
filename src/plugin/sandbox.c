/* Child processes with limits and a watchdog. Invariants: the parent never
 * blocks on a child without a deadline or the cancel flag; a child never
 * outlives its parent (PR_SET_PDEATHSIG on Linux, end of file on its socket
 * elsewhere); writing to a dead child is an error, never a SIGPIPE. */
#include "plugin/sandbox.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdio.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#ifdef __linux__
#include <sys/prctl.h>
#endif

#include "stepwise/stepwise.h"
#include "util/signals.h"

static volatile sig_atomic_t *cancel_flag;

void sw_sandbox_set_cancel(volatile sig_atomic_t *flag) { cancel_flag = flag; }

/* Also every signal util/signals.h catches (record, play, grade all use it). */
int sw_sandbox_cancelled(void) { return (cancel_flag && *cancel_flag) || sw_signal_caught; }

double sw_sandbox_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void set_limit(int resource, rlim_t value)
{
    struct rlimit rl;
    if (getrlimit(resource, &rl) != 0)
        return;
    if (rl.rlim_max != RLIM_INFINITY && value > rl.rlim_max)
        value = rl.rlim_max;
    rl.rlim_cur = value;
    if (resource == RLIMIT_CPU)
        rl.rlim_max = rl.rlim_max == RLIM_INFINITY || value + 1 <= rl.rlim_max ? value + 1 : rl.rlim_max;
    setrlimit(resource, &rl);
}

/* Everything the child does before running fn: it may only use what it was
 * handed, and nothing it does can reach the parent's terminal or files. */
static void child_setup(int sock, int output_fd, const sw_limits *lim, pid_t parent)
{
    setpgid(0, 0);
#ifdef __linux__
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (getppid() != parent)
        _exit(127); /* the parent died before the line above */
#else
    (void)parent;
#endif
    static const int ignored[] = { SIGINT, SIGQUIT, SIGHUP, SIGTSTP, SIGTTIN, SIGTTOU };
    static const int fatal[] = { SIGTERM, SIGPIPE, SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL,
                                 SIGXCPU, SIGXFSZ, SIGALRM, SIGCHLD };
    for (size_t i = 0; i < sizeof ignored / sizeof ignored[0]; i++)
        signal(ignored[i], SIG_IGN);
    for (size_t i = 0; i < sizeof fatal / sizeof fatal[0]; i++)
        signal(fatal[i], SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, NULL);
    int devnull = open("/dev/null", O_RDWR);
    int out = output_fd >= 0 ? output_fd : devnull;
    if (devnull >= 0)
        dup2(devnull, STDIN_FILENO);
    if (out >= 0) {
        dup2(out, STDOUT_FILENO);
        dup2(out, STDERR_FILENO);
    }
    struct rlimit nofile;
    long maxfd = getrlimit(RLIMIT_NOFILE, &nofile) == 0 && nofile.rlim_cur != RLIM_INFINITY &&
                         nofile.rlim_cur < 65536 ? (long)nofile.rlim_cur : 65536;
    for (long fd = 3; fd < maxfd; fd++)
        if (fd != sock)
            close((int)fd);
    if (lim && lim->cpu_seconds > 0)
        set_limit(RLIMIT_CPU, (rlim_t)(lim->cpu_seconds + 0.999));
#if !defined(__SANITIZE_ADDRESS__) /* ASan reserves terabytes of address space */
    if (lim && lim->memory_bytes > 0)
        set_limit(RLIMIT_AS, (rlim_t)lim->memory_bytes);
#endif
    if (lim && lim->output_bytes > 0)
        set_limit(RLIMIT_FSIZE, (rlim_t)lim->output_bytes);
    set_limit(RLIMIT_CORE, 0);
}

int sw_sandbox_spawn(sw_child *c, sw_child_fn *fn, void *ctx, const sw_limits *lim, int output_fd,
                     char *err, size_t errlen)
{
    memset(c, 0, sizeof *c);
    c->to_child = c->from_child = -1;
    int sv[2];
    if (socketpair(AF_UNIX, SOCK_STREAM, 0, sv) != 0) {
        snprintf(err, errlen, "cannot create a socket pair for a child process: %s", strerror(errno));
        return SW_EIO;
    }
    fflush(NULL);
    pid_t parent = getpid();
    pid_t pid = fork();
    if (pid < 0) {
        snprintf(err, errlen, "cannot start a child process: %s", strerror(errno));
        close(sv[0]);
        close(sv[1]);
        return SW_EIO;
    }
    if (pid == 0) {
        close(sv[0]);
        child_setup(sv[1], output_fd, lim, parent);
        _exit(fn(ctx, sv[1], sv[1]));
    }
    close(sv[1]);
    fcntl(sv[0], F_SETFD, FD_CLOEXEC);
    c->pid = pid;
    c->to_child = c->from_child = sv[0];
    return SW_OK;
}

int sw_sandbox_wait(int fd, double seconds)
{
    double deadline = seconds >= 0 ? sw_sandbox_now() + seconds : 0;
    for (;;) {
        if (sw_sandbox_cancelled())
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

int sw_sandbox_read(int fd, void *buf, size_t len, double seconds)
{
    double deadline = seconds >= 0 ? sw_sandbox_now() + seconds : -1;
    char *p = buf;
    size_t got = 0;
    while (got < len) {
        double left = seconds >= 0 ? deadline - sw_sandbox_now() : -1;
        if (seconds >= 0 && left < 0)
            left = 0;
        int w = sw_sandbox_wait(fd, left);
        if (w < 0)
            return -1;
        if (w == 0)
            return -2;
        ssize_t n = read(fd, p + got, len - got);
        if (n == 0)
            return 0;
        if (n < 0) {
            if (errno == EINTR || errno == EAGAIN)
                continue;
            return errno == ECONNRESET ? 0 : -3;
        }
        got += (size_t)n;
    }
    return 1;
}

int sw_sandbox_write(int fd, const void *buf, size_t len)
{
    const char *p = buf;
    while (len > 0) {
        ssize_t n = send(fd, p, len, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return -1;
        p += n;
        len -= (size_t)n;
    }
    return 0;
}

static void fill_end(int status, sw_child_end *end)
{
    if (WIFEXITED(status)) {
        end->exited = 1;
        end->code = WEXITSTATUS(status);
    } else if (WIFSIGNALED(status))
        end->signal = WTERMSIG(status);
}

static void close_child(sw_child *c)
{
    if (c->to_child >= 0)
        close(c->to_child);
    if (c->from_child >= 0 && c->from_child != c->to_child)
        close(c->from_child);
    c->to_child = c->from_child = -1;
    c->pid = 0;
}

void sw_sandbox_kill(sw_child *c, sw_child_end *end)
{
    sw_child_end dummy;
    if (!end)
        end = &dummy;
    memset(end, 0, sizeof *end);
    if (c->pid > 0) {
        int status;
        pid_t rc = waitpid(c->pid, &status, WNOHANG);
        if (rc == 0) {
            kill(-c->pid, SIGKILL);
            kill(c->pid, SIGKILL);
            while ((rc = waitpid(c->pid, &status, 0)) < 0 && errno == EINTR)
                ;
            end->killed = 1;
        }
        if (rc == c->pid)
            fill_end(status, end);
        if (end->killed && end->signal != SIGKILL)
            end->killed = 0; /* it ended by itself just before */
        kill(-c->pid, SIGKILL); /* anything it left running in its group */
    }
    close_child(c);
}

void sw_sandbox_reap(sw_child *c, double seconds, sw_child_end *end)
{
    memset(end, 0, sizeof *end);
    if (c->pid <= 0) {
        close_child(c);
        return;
    }
    double deadline = sw_sandbox_now() + seconds;
    for (;;) {
        int status;
        pid_t rc = waitpid(c->pid, &status, WNOHANG);
        if (rc == c->pid) {
            fill_end(status, end);
            kill(-c->pid, SIGKILL);
            close_child(c);
            return;
        }
        if (rc < 0 && errno != EINTR)
            break;
        if (sw_sandbox_now() >= deadline || sw_sandbox_cancelled())
            break;
        struct timespec ts = { 0, 2000000 };
        nanosleep(&ts, NULL);
    }
    sw_sandbox_kill(c, end);
}

static const char *signal_words(int sig, const char **name)
{
    switch (sig) {
    case SIGSEGV: *name = "SIGSEGV"; return "invalid memory access";
    case SIGBUS: *name = "SIGBUS"; return "bus error: a misaligned or unmapped access";
    case SIGABRT: *name = "SIGABRT"; return "abort(): a failed assert or a corrupted heap";
    case SIGFPE: *name = "SIGFPE"; return "arithmetic exception: integer division by zero?";
    case SIGILL: *name = "SIGILL"; return "illegal instruction";
    case SIGXCPU: *name = "SIGXCPU"; return "ran out of its CPU time";
    case SIGXFSZ: *name = "SIGXFSZ"; return "wrote more output than allowed";
    case SIGKILL: *name = "SIGKILL"; return "killed";
    case SIGTERM: *name = "SIGTERM"; return "terminated";
    case SIGPIPE: *name = "SIGPIPE"; return "wrote to a closed pipe";
    case SIGTRAP: *name = "SIGTRAP"; return "trap: a breakpoint or a sanitizer";
    default: *name = "a signal"; return "killed by a signal";
    }
}

void sw_sandbox_describe(const sw_child_end *end, char *buf, size_t len)
{
    const char *name;
    if (end->exited)
        snprintf(buf, len, "exited with status %d", end->code);
    else if (end->signal == SIGXCPU)
        snprintf(buf, len, "ran out of its CPU time (SIGXCPU)");
    else if (end->signal == SIGXFSZ)
        snprintf(buf, len, "wrote more output than allowed (SIGXFSZ)");
    else if (end->killed)
        snprintf(buf, len, "was stopped (SIGKILL)");
    else if (end->signal) {
        const char *words = signal_words(end->signal, &name);
        if (strcmp(name, "a signal") == 0)
            snprintf(buf, len, "was killed by signal %d", end->signal);
        else
            snprintf(buf, len, "crashed with %s (%s)", name, words);
    } else
        snprintf(buf, len, "ended");
}
