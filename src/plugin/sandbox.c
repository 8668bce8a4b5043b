/* Child processes with limits and a watchdog, jailed where asked. A jailed
 * child is three processes: the first leaves the namespaces and builds the
 * jail's root, the second is the jail's init (PID 1: when it ends, the
 * kernel kills everything in the jail), the third locks itself down and
 * runs the payload. Invariants: the parent never blocks on a child without
 * a deadline or the cancel flag; no child outlives its parent
 * (PR_SET_PDEATHSIG down the chain); writing to a dead child is an error,
 * never a SIGPIPE. */
#define _GNU_SOURCE /* namespaces, setresuid, pipe2, sethostname: Linux-only by design */
#include "plugin/sandbox.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <stdint.h>
#include <stdlib.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/uio.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "stepwise/stepwise.h"
#include "util/escape.h"
#include "util/fds.h"
#include "util/signals.h"
#include "util/tmpdir.h"

/* A message about the jail into err: formatted whole, then fitted to
 * errlen after a whole word and marked "...", where snprintf would stop
 * mid-word ("... and seccomp (docs/sandbox.m"). */
#if defined(__GNUC__)
__attribute__((format(printf, 3, 4)))
#endif
static void say(char *err, size_t errlen, const char *fmt, ...)
{
    char whole[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(whole, sizeof whole, fmt, ap);
    va_end(ap);
    sw_escape_fit(whole, 1, SIZE_MAX, 1, err, errlen);
}

/* A child whose set-up failed ends at once with this status ("exited with
 * status 125"): it never runs with a limit or a descriptor short. */
#define SETUP_FAILED 125

static void setup_or_exit(int ok)
{
    if (!ok)
        _exit(SETUP_FAILED);
}

static void set_limit(int resource, rlim_t value)
{
    struct rlimit rl;
    setup_or_exit(getrlimit(resource, &rl) == 0);
    if (rl.rlim_max != RLIM_INFINITY && value > rl.rlim_max)
        value = rl.rlim_max;
    rl.rlim_cur = value;
    /* CPU time: the hard limit one second above, so SIGXCPU comes before
     * the kill. Memory: the hard limit too, so that nothing the child
     * starts (a grader's worker its compiler) can raise it again. The
     * file size stays soft: the jail's set-up copies the submission and
     * the headers in, and a build writes its .so, beyond a small --output
     * (the build's own output is held to it after, and its scratch disk to
     * half the memory: plugin_build.c). */
    if (resource == RLIMIT_CPU)
        rl.rlim_max = rl.rlim_max == RLIM_INFINITY || value + 1 <= rl.rlim_max ? value + 1 : rl.rlim_max;
    else if (resource == RLIMIT_AS)
        rl.rlim_max = value;
    setup_or_exit(setrlimit(resource, &rl) == 0);
}

/* Everything the child does before running fn: it may only use what it was
 * handed, and nothing it does can reach the parent's terminal or files. Its
 * channel becomes descriptor 3; the rest above 2 are closed. */
static void child_setup(int sock, int output_fd, const sw_limits *lim, int keep)
{
    setup_or_exit(setpgid(0, 0) == 0 || getpgid(0) == getpid());
    static const int ignored[] = { SIGINT, SIGQUIT, SIGHUP, SIGTSTP, SIGTTIN, SIGTTOU };
    static const int fatal[] = { SIGTERM, SIGPIPE, SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL,
                                 SIGXCPU, SIGXFSZ, SIGALRM, SIGCHLD, SIGSYS };
    for (size_t i = 0; i < sizeof ignored / sizeof ignored[0]; i++)
        signal(ignored[i], SIG_IGN);
    for (size_t i = 0; i < sizeof fatal / sizeof fatal[0]; i++)
        signal(fatal[i], SIG_DFL);
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, NULL);
    int devnull = open("/dev/null", O_RDWR);
    int out = output_fd >= 0 ? output_fd : devnull;
    setup_or_exit(devnull >= 0 && dup2(devnull, STDIN_FILENO) == STDIN_FILENO);
    setup_or_exit(dup2(out, STDOUT_FILENO) == STDOUT_FILENO && dup2(out, STDERR_FILENO) == STDERR_FILENO);
    if (sock != 3) {
        setup_or_exit(dup2(sock, 3) == 3);
        close(sock);
    }
    setup_or_exit(fcntl(3, F_SETFD, 0) == 0);
    sw_close_fds(keep + 1, NULL, 0);
    if (lim && lim->cpu_seconds > 0)
        set_limit(RLIMIT_CPU, (rlim_t)(lim->cpu_seconds + 0.999));
#if !defined(__SANITIZE_ADDRESS__) /* ASan reserves terabytes of address space */
    if (lim && lim->memory_bytes > 0)
        set_limit(RLIMIT_AS, (rlim_t)lim->memory_bytes);
#endif
    if (lim && lim->output_bytes > 0)
        set_limit(RLIMIT_FSIZE, (rlim_t)lim->output_bytes);
    set_limit(RLIMIT_CORE, 0);
    set_limit(RLIMIT_NOFILE, SW_CHILD_FILES);
}

/* Die with the parent; 0, or -1 when it is gone already. Cleared by a
 * change of credentials: set again after one. */
static int die_with(pid_t parent)
{
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    return getppid() == parent ? 0 : -1;
}

int sw_sandbox_spawn(sw_child *c, sw_child_fn *fn, void *ctx, const sw_limits *lim, int output_fd,
                     char *err, size_t errlen)
{
    memset(c, 0, sizeof *c);
    c->to_child = c->from_child = c->status_fd = -1;
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
        if (die_with(parent) != 0)
            _exit(127);
        child_setup(sv[1], output_fd, lim, 3);
        _exit(fn(ctx, 3, 3));
    }
    close(sv[1]);
    fcntl(sv[0], F_SETFD, FD_CLOEXEC);
    c->pid = pid;
    c->to_child = c->from_child = sv[0];
    return SW_OK;
}

/* ---- the jail's three processes ---------------------------------------------- */

/* What the jail's set-up tells the parent on the sync socket: 'U' (left the
 * namespaces: map the user), 'K' (locked down, the payload starts), or
 * 'X' and this. */
typedef struct jail_failure {
    int err;
    char step[120];
} jail_failure;

static void send_failure(int fd, int err, const char *step)
{
    jail_failure f = { err, "" };
    snprintf(f.step, sizeof f.step, "%s", step ? step : "");
    char tag = 'X';
    if (write(fd, &tag, 1) == 1 && write(fd, &f, sizeof f) == (ssize_t)sizeof f)
        return;
}

static void exit_at_once(int status, void *arg)
{
    (void)arg;
    _exit(status);
}

/* The jail's init: starts the payload, reaps whatever ends in the jail,
 * and reports how the payload ended. NS (uid 0): PID 1, and when it
 * exits, the kernel kills every process left in the jail. UID (the jail's
 * user id): the payload becomes that user, and every process of that user
 * is killed once the payload ended. */
static void jail_init(sw_child_fn *fn, void *ctx, const sw_limits *lim, int output_fd,
                      const sw_jail *spec, int sock, int sync, int status, unsigned uid)
{
    if (die_with(getppid()) != 0)
        _exit(127);
    if (!uid)
        sethostname("stepwise", 8);
    pid_t me = getpid();
    pid_t payload = fork();
    if (payload < 0) {
        send_failure(sync, errno, "fork of the payload");
        _exit(127);
    }
    if (payload == 0) {
        close(status);
        if (die_with(uid ? me : 1) != 0)
            _exit(127);
        const char *step = NULL;
        /* sync kept at 4 until the lockdown is reported, the channel at 3 */
        int sync_hi = fcntl(sync, F_DUPFD, 10), sock_hi = fcntl(sock, F_DUPFD, 10);
        close(sync);
        close(sock);
        if (sync_hi < 0 || sock_hi < 0 || dup2(sync_hi, 4) != 4)
            _exit(127);
        close(sync_hi);
        if (uid) {
            int rc = sw_jail_become(uid, &step);
            if (rc != 0) {
                send_failure(4, rc, step);
                _exit(127);
            }
            if (die_with(me) != 0) /* cleared by the change of user */
                _exit(127);
        }
        child_setup(sock_hi, output_fd, lim, 4);
        set_limit(RLIMIT_NPROC, SW_CHILD_PROCS);
        int rc = sw_jail_lockdown(spec->profile, &step);
        if (rc != 0) {
            send_failure(4, rc, step);
            _exit(127);
        }
        char tag = 'K';
        if (write(4, &tag, 1) != 1)
            _exit(127);
        close(4);
        /* A payload that calls exit() ends at once with its status: no exit
         * handler inherited from this program (a sanitizer's leak check
         * would stop the world with ptrace, which the filter forbids). */
        on_exit(exit_at_once, NULL);
        _exit(fn(ctx, 3, 3));
    }
    close(sync);
    int st = 0;
    for (;;) {
        int any;
        pid_t w = waitpid(-1, &any, 0);
        if (w == payload) {
            st = any;
            break;
        }
        if (w < 0 && errno != EINTR)
            _exit(127);
    }
    sw_jail_send_outputs(spec, sock);
    if (uid)
        sw_jail_kill_user(uid);
    int32_t report = st;
    if (write(status, &report, sizeof report) != (ssize_t)sizeof report)
        _exit(127);
    _exit(0);
}

/* The first child: leave the namespaces, wait to be mapped, build the
 * root, start the init and wait for it. UID: make the jail's directory
 * instead, and remove it once the init ended. */
static void jail_first(sw_child_fn *fn, void *ctx, const sw_limits *lim, int output_fd,
                       const sw_jail *spec, int sock, int sync, int status, pid_t parent, sw_jail_kind kind)
{
    if (die_with(parent) != 0)
        _exit(127);
    setpgid(0, 0);
    /* Copying the submission in is the jail's work, not the submission's:
     * not under the file-size limit the caller may have (grade's --output);
     * the payload gets its own limits. */
    struct rlimit fsize;
    if (getrlimit(RLIMIT_FSIZE, &fsize) == 0) {
        fsize.rlim_cur = fsize.rlim_max;
        setrlimit(RLIMIT_FSIZE, &fsize);
    }
    const char *step = NULL;
    unsigned uid = 0;
    char dir[512] = "";
    int rc, claim = -1;
    if (kind == SW_JAIL_UID) {
        rc = sw_jail_build_uid(spec, dir, sizeof dir, &uid, &claim, &step);
    } else {
        rc = sw_jail_unshare(&step);
        char tag = 'U';
        if (rc != 0) {
            send_failure(sync, rc, step);
            _exit(127);
        }
        if (write(sync, &tag, 1) != 1 || read(sync, &tag, 1) != 1 || tag != 'M')
            _exit(127);
        rc = sw_jail_build(spec, &step);
    }
    if (rc != 0) {
        send_failure(sync, rc, step);
        if (dir[0])
            sw_tmpdir_remove(dir);
        sw_jail_release_uid(uid, claim);
        _exit(127);
    }
    /* A change of credentials (the user namespace's setresuid) clears the
     * parent-death signal: set it again, or this process and the jail
     * would outlive a caller killed from now on. */
    if (die_with(parent) != 0)
        _exit(127);
    /* Nothing of the caller's stays open in the jail (its files, a
     * temporary directory's keep-alive pipe): only the three channels,
     * and the claim on the jail's user id, which the init lets go of. */
    int keep[4] = { sock, sync, status, claim };
    sw_close_fds(3, keep, claim >= 0 ? 4 : 3);
    pid_t init = fork();
    if (init < 0) {
        send_failure(sync, errno, "fork of the jail's init");
        _exit(127);
    }
    if (init == 0) {
        if (claim >= 0) /* the claim is this process's to hold: the jail could let it go */
            close(claim);
        jail_init(fn, ctx, lim, output_fd, spec, sock, sync, status, uid);
    }
    close(sock);
    close(sync);
    close(status);
    for (;;) {
        int st;
        pid_t w = waitpid(init, &st, 0);
        if (w == init || (w < 0 && errno != EINTR))
            break;
    }
    if (uid) {
        sw_jail_kill_user(uid); /* the init killed before it could */
        sw_jail_release_uid(uid, claim);
        if (chdir("/") == 0)
            sw_tmpdir_remove(dir); /* the parent does it when this is killed first */
    }
    _exit(0);
}

/* What a refusal says the jail needs. */
#define JAIL_NEEDS                                                                                         \
    "it needs Linux seccomp and user namespaces, or where they are refused, root and Landlock "          \
    "(docs/sandbox.md)"

/* The parent's side of the set-up: map the user, wait for the lockdown.
 * *refused: 1 when the kernel refused the namespaces themselves. */
static int jail_handshake(pid_t pid, int sync, int *refused, char *err, size_t errlen)
{
    *refused = 0;
    char tag = 0, why[SW_ERRLEN];
    double limit = 10.0;
    int rc = sw_sandbox_read(sync, &tag, 1, limit);
    if (rc == 1 && tag == 'U') {
        if (sw_jail_map_user(pid, why, sizeof why) != 0) {
            say(err, errlen, "the sandbox could not be set up: %s", why);
            return SW_EIO;
        }
        tag = 'M';
        if (sw_sandbox_write(sync, &tag, 1) != 0)
            rc = 0;
        else
            rc = sw_sandbox_read(sync, &tag, 1, limit);
    }
    if (rc == 1 && tag == 'K')
        return SW_OK;
    jail_failure f;
    if (rc == 1 && tag == 'X' && sw_sandbox_read(sync, &f, sizeof f, limit) == 1) {
        f.step[sizeof f.step - 1] = '\0';
        *refused = strncmp(f.step, "unshare(", 8) == 0;
        if (strcmp(f.step, SW_JAIL_STEP_SUBMISSION) == 0 && (f.err == EFBIG || f.err == ENOSPC)) {
            snprintf(err, errlen, "the submission is too large to run: a plugin's file (.c or .so) may be at "
                     "most %zu MiB, and its build must fit its scratch space", SW_JAIL_FILE_MAX >> 20);
            return SW_EINVAL;
        }
        say(err, errlen, "the sandbox could not be set up: %.120s failed (%s); %s", f.step, strerror(f.err),
            JAIL_NEEDS);
        return SW_EIO;
    }
    snprintf(err, errlen, "the sandbox could not be set up (its first process %s)",
             rc == -2 ? "did not answer within 10 s" : rc == -1 ? "was interrupted" : "ended");
    return SW_EIO;
}

static int spawn_jail(sw_child *c, sw_child_fn *fn, void *ctx, const sw_limits *lim, int output_fd,
                      const sw_jail *spec, sw_jail_kind kind, int *refused, char *err, size_t errlen)
{
    memset(c, 0, sizeof *c);
    c->to_child = c->from_child = c->status_fd = -1;
    int sv[2], sync[2], status[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0) {
        snprintf(err, errlen, "cannot create a socket pair for a child process: %s", strerror(errno));
        return SW_EIO;
    }
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sync) != 0) {
        snprintf(err, errlen, "cannot create a socket pair for a child process: %s", strerror(errno));
        close(sv[0]);
        close(sv[1]);
        return SW_EIO;
    }
    if (pipe2(status, O_CLOEXEC) != 0) {
        snprintf(err, errlen, "cannot create a pipe for a child process: %s", strerror(errno));
        close(sv[0]); close(sv[1]); close(sync[0]); close(sync[1]);
        return SW_EIO;
    }
    fflush(NULL);
    pid_t parent = getpid();
    pid_t pid = fork();
    if (pid == 0) {
        close(sv[0]);
        close(sync[0]);
        close(status[0]);
        jail_first(fn, ctx, lim, output_fd, spec, sv[1], sync[1], status[1], parent, kind);
    }
    close(sv[1]);
    close(sync[1]);
    close(status[1]);
    if (pid < 0) {
        snprintf(err, errlen, "cannot start a child process: %s", strerror(errno));
        close(sv[0]); close(sync[0]); close(status[0]);
        return SW_EIO;
    }
    c->pid = pid;
    c->to_child = c->from_child = sv[0];
    c->status_fd = status[0];
    c->uid_jail = kind == SW_JAIL_UID;
    int rc = jail_handshake(pid, sync[0], refused, err, errlen);
    close(sync[0]);
    if (rc != SW_OK) {
        sw_child_end end;
        sw_sandbox_kill(c, &end);
    }
    return rc;
}

int sw_sandbox_spawn_jailed(sw_child *c, sw_child_fn *fn, void *ctx, const sw_limits *lim, int output_fd,
                            const sw_jail *spec, char *err, size_t errlen)
{
    if (!spec || !sw_jail_enabled())
        return sw_sandbox_spawn(c, fn, ctx, lim, output_fd, err, errlen);
    int refused = 0;
    sw_jail_kind kind = sw_jail_kind_now();
    int rc = spawn_jail(c, fn, ctx, lim, output_fd, spec, kind, &refused, err, errlen);
    if (rc != SW_OK && kind == SW_JAIL_NS && refused && sw_jail_uid_allowed()) {
        /* No user namespaces here (a container's profile refuses them): as
         * root, the jail of a user of its own serves instead, from now on. */
        sw_jail_kind_set(SW_JAIL_UID);
        rc = spawn_jail(c, fn, ctx, lim, output_fd, spec, SW_JAIL_UID, &refused, err, errlen);
    }
    return rc;
}

/* The probe's payload: the layers a plugin's host installs, tried here;
 * exit status 0, or 3 with what failed on the channel. */
static int layers_work(void *ctx, int in, int out)
{
    (void)ctx;
    (void)in;
    const char *step = NULL;
    int rc = sw_jail_compute_layers(&step);
    if (rc == 0)
        return 0;
    jail_failure f = { rc, "" };
    snprintf(f.step, sizeof f.step, "%s", step ? step : "");
    if (write(out, &f, sizeof f) != (ssize_t)sizeof f)
        return 3;
    return 3;
}

int sw_sandbox_probe(char *err, size_t errlen)
{
    static int known; /* 1 works, -1 does not */
    static char why[2 * SW_ERRLEN]; /* the longest reason whole, its docs/sandbox.md included */
    if (!sw_jail_enabled())
        return SW_OK;
    if (!known) {
        sw_child c;
        sw_jail spec = { .profile = SW_JAIL_COMPUTE, .include_fd = -1 };
        known = sw_sandbox_spawn_jailed(&c, layers_work, NULL, NULL, -1, &spec, why, sizeof why) == SW_OK ? 1 : -1;
        if (known == 1) {
            jail_failure f;
            int got = sw_sandbox_read(c.from_child, &f, sizeof f, 10.0);
            sw_child_end end;
            sw_sandbox_reap(&c, 5.0, &end);
            if (got == 1) {
                f.step[sizeof f.step - 1] = '\0';
                say(why, sizeof why, "the sandbox could not be set up: %.120s failed (%s); %s", f.step,
                    strerror(f.err), JAIL_NEEDS);
                known = -1;
            } else if (!end.exited || end.code != 0) {
                snprintf(why, sizeof why, "the sandbox could not be set up: its probe did not finish");
                known = -1;
            }
        }
    }
    if (known < 0)
        say(err, errlen, "%s", why);
    return known > 0 ? SW_OK : SW_EIO;
}


static void fill_end(int status, sw_child_end *end)
{
    if (WIFEXITED(status)) {
        end->exited = 1;
        end->code = WEXITSTATUS(status);
    } else if (WIFSIGNALED(status))
        end->signal = WTERMSIG(status);
}

/* A jailed child's payload: how it ended, as its init reported it (a wait
 * status it must be able to be), over what the first process did. */
static void jail_end(sw_child *c, sw_child_end *end)
{
    int32_t st;
    if (c->status_fd < 0)
        return;
    ssize_t n = read(c->status_fd, &st, sizeof st);
    if (n != (ssize_t)sizeof st || !(WIFEXITED(st) || WIFSIGNALED(st)))
        return; /* killed before it could say: keep what we saw */
    memset(end, 0, sizeof *end);
    fill_end(st, end);
}

static void close_child(sw_child *c)
{
    if (c->uid_jail && c->pid > 0) {
        char dir[512];
        sw_jail_uid_dir(c->pid, dir, sizeof dir);
        sw_tmpdir_remove(dir);
        c->uid_jail = 0;
    }
    if (c->status_fd >= 0)
        close(c->status_fd);
    c->status_fd = -1;
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
        if (c->status_fd >= 0) {
            int was_killed = end->killed;
            jail_end(c, end);
            if (was_killed && end->signal == 0 && !end->exited)
                end->killed = 1;
        }
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
            jail_end(c, end);
            kill(-c->pid, SIGKILL);
            close_child(c);
            return;
        }
        if (rc < 0 && errno != EINTR)
            break;
        if (sw_sandbox_now() >= deadline || sw_signal_caught != 0)
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
    case SIGSYS: *name = "SIGSYS"; return "a system call the sandbox forbids: a plugin may only compute "
                                          "(no files, processes, threads or network)";
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
