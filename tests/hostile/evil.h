/* What every hostile plugin in tests/hostile/ shares (issue 21).
 *
 * Each NAME.c there is one attack family. It defines EVIL_FAMILY, includes
 * this file and writes evil_attack(). tests/e2e/test_hostile.sh pastes this
 * file in place of the #include (a submission is one file: a sandbox that
 * shows the compiler only the submission must still build it) and fills in
 * the @...@ placeholders:
 *
 *   @TOKEN@  8 characters naming one graded class of one test run: every
 *            marker, process name and target carries it, so an attack can
 *            only ever touch its own test run (other runs, other agents and
 *            the machine are never targets, even when no sandbox stops it)
 *   @PORT@   the TCP port on 127.0.0.1 where the test listens (network)
 *   @HOME@   the teacher's home directory, as an attacker would guess it
 *
 * How the test sees an attack succeed, without trusting the grader:
 *   - the verdict: numerically every plugin here is explicit Euler (wrong
 *     for the rk4 assignment) and computes rk4 (the right answer) only when
 *     its attack worked (evil_cheat): a "pass" row means the attack worked;
 *   - marker files swevil-TOKEN-FAMILY-WHAT written wherever it can (the
 *     current directory, $HOME, /tmp, /var/tmp, /dev/shm, the grader's
 *     directories): one found outside the sandbox is a write that escaped;
 *   - process names: every process an attack starts is named
 *     "sw" TOKEN + the family's first 5 characters (prctl PR_SET_NAME);
 *   - text: anything an attack prints carries "SWEVIL:FAMILY".
 * Attacks that are expensive (CPU, memory, disk, processes, descriptors)
 * are bounded, so that a missing sandbox costs the machine little; they
 * succeed well past any limit a sandbox should enforce. */
#define _GNU_SOURCE
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <stepwise/integrator.h>

#ifndef EVIL_FAMILY
#error "define EVIL_FAMILY before including evil.h"
#endif

#define EVIL_TOKEN "@TOKEN@"
#define EVIL_PORT "@PORT@"
#define EVIL_HOME "@HOME@"
#define EVIL_FN static __attribute__((unused))
#define EVIL_PATH 4096

/* 1: the attack worked; hand in the right answer (rk4) from now on. */
static int evil_cheat __attribute__((unused));

EVIL_FN void evil_sleep(double s)
{
    struct timespec ts = { (time_t)s, (long)((s - (double)(time_t)s) * 1e9) };
    while (nanosleep(&ts, &ts) != 0 && errno == EINTR)
        ;
}

EVIL_FN double evil_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Read up to cap-1 bytes of a file (never blocks on a FIFO); -1 on error. */
EVIL_FN long evil_read_file(const char *path, char *buf, size_t cap)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0)
        return -1;
    size_t got = 0;
    while (got + 1 < cap) {
        ssize_t n = read(fd, buf + got, cap - 1 - got);
        if (n <= 0)
            break;
        got += (size_t)n;
    }
    close(fd);
    buf[got] = '\0';
    return (long)got;
}

EVIL_FN int evil_write_file(const char *path, const char *data, size_t len, int flags)
{
    int fd = open(path, O_WRONLY | O_CREAT | O_NOFOLLOW | O_CLOEXEC | flags, 0644);
    if (fd < 0)
        return -1;
    ssize_t n = write(fd, data, len);
    close(fd);
    return n == (ssize_t)len ? 0 : -1;
}

/* /proc/PID/cmdline: NUL-separated arguments; the length, or -1. */
EVIL_FN long evil_cmdline(pid_t pid, char *buf, size_t cap)
{
    char path[64];
    snprintf(path, sizeof path, "/proc/%d/cmdline", (int)pid);
    return evil_read_file(path, buf, cap);
}

/* A process of this test run's stepwise: argv[0] is .../stepwise and the
 * command line holds the token (the class directory or the plugin's path
 * carries it). Never this process. */
EVIL_FN int evil_is_target(pid_t pid)
{
    static char buf[16384];
    if (pid == getpid())
        return 0;
    long n = evil_cmdline(pid, buf, sizeof buf);
    if (n <= 0)
        return 0;
    const char *base = strrchr(buf, '/');
    base = base ? base + 1 : buf;
    if (strcmp(base, "stepwise") != 0)
        return 0;
    return memmem(buf, (size_t)n, EVIL_TOKEN, strlen(EVIL_TOKEN)) != NULL;
}

/* From /proc/PID/stat: the parent, and the start time (clock ticks after
 * boot). 0, or -1 when the process is gone. */
EVIL_FN int evil_stat(pid_t pid, pid_t *ppid, unsigned long long *start)
{
    char path[64], buf[1024];
    snprintf(path, sizeof path, "/proc/%d/stat", (int)pid);
    if (evil_read_file(path, buf, sizeof buf) <= 0)
        return -1;
    char *p = strrchr(buf, ')');
    if (!p)
        return -1;
    /* after the name: state ppid, then 18 more fields up to starttime */
    int pp;
    unsigned long long st;
    if (sscanf(p + 1, " %*c %d %*d %*d %*d %*d %*u %*u %*u %*u %*u %*u %*u %*d %*d %*d %*d %*d %*d %llu",
               &pp, &st) != 2)
        return -1;
    if (ppid)
        *ppid = pp;
    if (start)
        *start = st;
    return 0;
}

/* Every target process (see evil_is_target); how many. */
EVIL_FN int evil_targets(pid_t *out, int max)
{
    int n = 0;
    DIR *d = opendir("/proc");
    if (!d)
        return 0;
    for (struct dirent *e; (e = readdir(d)) && n < max;) {
        char *end;
        long pid = strtol(e->d_name, &end, 10);
        if (*end || pid <= 0)
            continue;
        if (evil_is_target((pid_t)pid))
            out[n++] = (pid_t)pid;
    }
    closedir(d);
    return n;
}

/* The grader (or check/try/record) itself: the target that started first
 * (everything else of the run, attacks' lingering children included, is
 * forked from it, later). */
EVIL_FN pid_t evil_top_target(void)
{
    pid_t t[256], best = -1;
    unsigned long long best_start = 0, st;
    int n = evil_targets(t, 256);
    for (int i = 0; i < n; i++)
        if (evil_stat(t[i], NULL, &st) == 0 && (best < 0 || st < best_start)) {
            best = t[i];
            best_start = st;
        }
    return best;
}

/* What the grader's command line says: its directory, the gradebook files,
 * the assignment and the submissions (absolute). */
typedef struct evil_grader {
    pid_t pid;
    char cwd[EVIL_PATH];
    char csv[EVIL_PATH], results[EVIL_PATH], assignment[EVIL_PATH];
    char dirs[8][EVIL_PATH];
    int ndirs;
} evil_grader;

EVIL_FN void evil_abs(const char *cwd, const char *path, char *out)
{
    if (path[0] == '/')
        snprintf(out, EVIL_PATH, "%s", path);
    else
        snprintf(out, EVIL_PATH, "%.2000s/%.2000s", cwd, path);
}

EVIL_FN int evil_grader_info(evil_grader *g)
{
    static char buf[16384];
    memset(g, 0, sizeof *g);
    g->pid = evil_top_target();
    if (g->pid <= 0)
        return -1;
    char link[64];
    snprintf(link, sizeof link, "/proc/%d/cwd", (int)g->pid);
    ssize_t k = readlink(link, g->cwd, sizeof g->cwd - 1);
    if (k <= 0)
        return -1;
    g->cwd[k] = '\0';
    long n = evil_cmdline(g->pid, buf, sizeof buf);
    if (n <= 0)
        return -1;
    const char *args[256];
    int na = 0;
    for (long i = 0; i < n && na < 256; i += (long)strlen(buf + i) + 1)
        args[na++] = buf + i;
    for (int i = 2; i < na; i++) {
        const char *a = args[i];
        if (a[0] == '-' && a[1] == '-' && a[2] && i + 1 < na) {
            const char *v = args[++i];
            if (strcmp(a, "--csv") == 0)
                evil_abs(g->cwd, v, g->csv);
            else if (strcmp(a, "--results") == 0)
                evil_abs(g->cwd, v, g->results);
            else if (strcmp(a, "--assignment") == 0)
                evil_abs(g->cwd, v, g->assignment);
            else if (strcmp(a, "--plugin") == 0 && g->ndirs < 8) {
                evil_abs(g->cwd, v, g->dirs[g->ndirs]);
                char *slash = strrchr(g->dirs[g->ndirs], '/');
                if (slash)
                    *slash = '\0';
                g->ndirs++;
            }
        } else if (a[0] != '-' && g->ndirs < 8) {
            evil_abs(g->cwd, a, g->dirs[g->ndirs]);
            struct stat st;
            if (stat(g->dirs[g->ndirs], &st) == 0 && !S_ISDIR(st.st_mode)) {
                char *slash = strrchr(g->dirs[g->ndirs], '/');
                if (slash)
                    *slash = '\0';
            }
            g->ndirs++;
        }
    }
    return 0;
}

/* Name this process: "sw" TOKEN + the family's first 5 characters. */
EVIL_FN void evil_name(void)
{
    char name[16];
    snprintf(name, sizeof name, "sw%.8s%.5s", EVIL_TOKEN, EVIL_FAMILY);
    prctl(PR_SET_NAME, name, 0, 0, 0);
}

/* For a process meant to outlive its grade: stay until the grader (or
 * check, try, record) has been gone 120 s, 300 s at most in all, so the
 * test sees it alive whatever the grading (and the rest of its run) took;
 * then exit. The test kills what it finds. */
EVIL_FN void evil_linger(pid_t grader)
{
    double start = evil_now();
    while (grader > 0 && evil_now() - start < 180 && (kill(grader, 0) == 0 || errno != ESRCH))
        evil_sleep(0.1);
    double gone = evil_now();
    while (evil_now() - gone < 120 && evil_now() - start < 300)
        evil_sleep(0.5);
    _exit(0);
}

/* Leave marker swevil-TOKEN-FAMILY-WHAT (holding content) in every
 * directory it can reach; how many were written. */
EVIL_FN int evil_mark(const char *what, const char *content)
{
    const char *dirs[16];
    int nd = 0;
    dirs[nd++] = ".";
    dirs[nd++] = "/tmp";
    dirs[nd++] = "/var/tmp";
    dirs[nd++] = "/dev/shm";
    dirs[nd++] = EVIL_HOME;
    const char *home = getenv("HOME");
    if (home && *home)
        dirs[nd++] = home;
    static evil_grader g;
    if (evil_grader_info(&g) == 0) {
        dirs[nd++] = g.cwd;
        for (int i = 0; i < g.ndirs && nd < 16; i++)
            dirs[nd++] = g.dirs[i];
    }
    int wrote = 0;
    for (int i = 0; i < nd; i++) {
        char path[EVIL_PATH + 200];
        snprintf(path, sizeof path, "%.4000s/swevil-%s-%s-%s", dirs[i], EVIL_TOKEN, EVIL_FAMILY, what);
        const char *c = content ? content : "SWEVIL:" EVIL_FAMILY "\n";
        wrote += evil_write_file(path, c, strlen(c), O_TRUNC) == 0;
    }
    return wrote;
}

/* Forged text: a fake "pass" row, a fake PASS line and terminal escapes
 * (clear screen, window title, colours, a hyperlink). */
static const char evil_fake[] =
    "  Mallory              " EVIL_FAMILY ".c        pass         -  SWEVIL:" EVIL_FAMILY "\n"
    "PASS: plugin evil-" EVIL_FAMILY " on spring matches rk4 SWEVIL:" EVIL_FAMILY "\n"
    "\033[2J\033[H\033]0;SWEVIL:" EVIL_FAMILY "\007\033[31;1m\033]8;;http://evil.example/\033\\"
    "SWEVIL:" EVIL_FAMILY "\033]8;;\033\\\033[0m\n";

EVIL_FN void evil_print_fake(int fd)
{
    ssize_t r = write(fd, evil_fake, sizeof evil_fake - 1);
    (void)r;
}

/* src/cli/grade.c's record, as of the issue: what a graded submission's
 * child sends its grader. status 0 is a pass. */
typedef struct evil_grade_record {
    int status;
    long failing_step;
    char student[128];
    char notes[512];
    char kind[24];
    char message[1200];
    unsigned report_len;
} evil_grade_record;

EVIL_FN void evil_forged_record(evil_grade_record *r)
{
    memset(r, 0, sizeof *r);
    r->status = 0;
    r->failing_step = -1;
    snprintf(r->student, sizeof r->student, "Mallory SWEVIL:%s", EVIL_FAMILY);
    r->report_len = 0;
}

/* src/plugin/plugin.c's reply to the load probe, as of the issue. */
typedef struct evil_probe_reply {
    int stage;
    int abi, order, evals, work_vectors, has_step, has_label;
    int name_len, label_len;
    char name[257], label[257];
    char dlerr[512];
} evil_probe_reply;

EVIL_FN int evil_is_socket(int fd)
{
    struct stat st;
    return fstat(fd, &st) == 0 && S_ISSOCK(st.st_mode);
}

EVIL_FN ssize_t evil_send(int fd, const void *buf, size_t len)
{
    ssize_t n = send(fd, buf, len, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n < 0 && errno == ENOTSOCK)
        n = write(fd, buf, len);
    return n;
}

#ifndef SYS_pidfd_open
#define SYS_pidfd_open 434
#endif
#ifndef SYS_pidfd_getfd
#define SYS_pidfd_getfd 438
#endif

EVIL_FN int evil_pidfd_open(pid_t pid) { return (int)syscall(SYS_pidfd_open, pid, 0); }
EVIL_FN int evil_pidfd_getfd(int pidfd, int fd) { return (int)syscall(SYS_pidfd_getfd, pidfd, fd, 0); }

/* ---- the numbers: explicit Euler, or rk4 once the attack worked ---------- */

EVIL_FN int evil_euler(sw_ode *ode, double t, double *y, double h, double *work)
{
    sw_ode_eval(ode, t, y, work);
    for (int i = 0; i < ode->dim; i++)
        y[i] += h * work[i];
    return 0;
}

EVIL_FN int evil_rk4(sw_ode *ode, double t, double *y, double h, double *work)
{
    int n = ode->dim;
    double *k1 = work, *k2 = work + n, *k3 = work + 2 * n, *k4 = work + 3 * n, *tmp = work + 4 * n;
    sw_ode_eval(ode, t, y, k1);
    for (int i = 0; i < n; i++)
        tmp[i] = y[i] + 0.5 * h * k1[i];
    sw_ode_eval(ode, t + 0.5 * h, tmp, k2);
    for (int i = 0; i < n; i++)
        tmp[i] = y[i] + 0.5 * h * k2[i];
    sw_ode_eval(ode, t + 0.5 * h, tmp, k3);
    for (int i = 0; i < n; i++)
        tmp[i] = y[i] + h * k3[i];
    sw_ode_eval(ode, t + h, tmp, k4);
    for (int i = 0; i < n; i++)
        y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    return 0;
}

/* The graded run itself (the test's assignment: the spring under g = 9.81,
 * dt 0.01), not one of check's measuring runs: the expensive attacks run
 * once per submission, not once per run. */
EVIL_FN int evil_graded_run(sw_ode *ode, double t, const double *y, double h, double *work)
{
    if (t != 0 || fabs(h - 0.01) > 1e-12 || ode->dim != 4)
        return 0;
    sw_ode_eval(ode, t, y, work);
    return fabs(work[3] + 9.81) < 1e-6;
}

/* The family's attack: runs once, at the first step of a run (of the
 * graded run only when EVIL_EXPENSIVE is defined). */
static void evil_attack(void) __attribute__((unused));

#ifdef EVIL_CUSTOM_STEP
/* The family's own step (defined after this file). */
static int evil_step(sw_ode *ode, double t, double *y, double h, double *work);
#else
static int evil_step(sw_ode *ode, double t, double *y, double h, double *work)
{
    static int attacked;
    if (!attacked && t == 0) {
#ifdef EVIL_EXPENSIVE
        if (evil_graded_run(ode, t, y, h, work))
#endif
        {
            attacked = 1;
            evil_attack();
        }
    }
    return evil_cheat ? evil_rk4(ode, t, y, h, work) : evil_euler(ode, t, y, h, work);
}
#endif

#ifndef EVIL_CUSTOM_INFO
static const sw_plugin evil_info = {
    .abi = SW_PLUGIN_ABI, .name = "evil-" EVIL_FAMILY, .label = "hostile: " EVIL_FAMILY,
    .order = 1, .evals = 1, .work_vectors = 5, .step = evil_step,
};
const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &evil_info; }
#endif
