/* Building a student's integrator from C source with the documented flags
 * (docs/plugins.md), in the compiler's jail (or, --no-sandbox, a private
 * directory), under a time limit: the first half of running a student's
 * code, beside its loading and stepping in this folder. */
#include "plugin/plugin_build.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "plugin/plugin.h"
#include "plugin/plugin_box.h"
#include "plugin/plugin_headers.h"
#include "plugin/sandbox.h"
#include "stepwise/base.h"
#include "util/beside.h"
#include "util/clock.h"
#include "util/escape.h"

/* Seconds a compiler may take for one plugin. */
#define BUILD_SECONDS 60.0

static int has_header(const char *dir)
{
    char probe[PATH_MAX + 64];
    snprintf(probe, sizeof probe, "%s/stepwise/integrator.h", dir);
    return access(probe, R_OK) == 0;
}

/* Where <stepwise/integrator.h> is: $STEPWISE_INCLUDE, the source tree the
 * binary sits in, or the installed headers. */
static const char *include_dir(void)
{
    static char dir[PATH_MAX + 16];
    const char *env = getenv("STEPWISE_INCLUDE");
    if (env && *env)
        return env;
    if (sw_beside_binary("include", has_header, dir, sizeof dir))
        return dir;
    return SW_DATADIR "/../../include";
}

/* The compiler's command line inside the jail: the documented flags. */
/* -D_DEFAULT_SOURCE: <math.h>'s M_PI, which students reach for, is not
 * ISO C; glibc declares it (and POSIX's names) with this. */
#define JAIL_FLAGS "-std=c11", "-D_DEFAULT_SOURCE", "-O2", "-g", "-Wall", "-Wextra", "-Wfloat-conversion", "-shared", "-fPIC"
#define SHOWN_FLAGS "-std=c11 -D_DEFAULT_SOURCE -O2 -Wall -shared -fPIC"

typedef struct build_job {
    const char *cc;          /* absolute, resolved outside the jail */
    const char *work;        /* where plugin.c is: the jail's work/ */
    const char *inc;         /* -I flag: ../include in the jail */
} build_job;

/* The compiler on WORK/plugin.c, its messages in WORK/build.log. */
static int run_compiler(void *ctx, int in, int out)
{
    (void)in;
    const build_job *j = ctx;
    fcntl(out, F_SETFD, FD_CLOEXEC); /* the compiler gets no channel */
    if (chdir(j->work) != 0)
        return 127;
    int fd = open("build.log", O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    if (fd >= 0) {
        dup2(fd, STDOUT_FILENO);
        dup2(fd, STDERR_FILENO);
    }
    char inc[PATH_MAX + 4];
    snprintf(inc, sizeof inc, "-I%s", j->inc);
    char *const argv[] = { (char *)j->cc, JAIL_FLAGS, inc, "-o", "plugin.so", "plugin.c", "-lm", NULL };
    /* LC_ALL=C: plain ASCII quotes in the messages we show */
    /* its scratch is where it works (/work, or a UID jail's work/) */
    char cwd[PATH_MAX], tmpdir[PATH_MAX + 8], home[PATH_MAX + 8];
    if (!getcwd(cwd, sizeof cwd))
        return 127;
    snprintf(tmpdir, sizeof tmpdir, "TMPDIR=%s", cwd);
    snprintf(home, sizeof home, "HOME=%s", cwd);
    char *const envp[] = { "PATH=/usr/bin:/bin", tmpdir, "LC_ALL=C", home, NULL };
    execve(j->cc, argv, envp);
    fprintf(stderr, "error: cannot run the compiler '%s': %s\n", j->cc, strerror(errno));
    return 127;
}

/* The compiler named by $CC (default cc), as an absolute path with links
 * resolved, so that it runs in the jail: 0, or -1 with err. */
static int find_compiler(char *out, size_t len, char *err, size_t errlen)
{
    const char *cc = getenv("CC");
    if (!cc || !*cc)
        cc = "cc";
    char found[PATH_MAX];
    found[0] = '\0';
    if (strchr(cc, '/'))
        snprintf(found, sizeof found, "%s", cc);
    else {
        const char *path = getenv("PATH");
        char dirs[4096];
        snprintf(dirs, sizeof dirs, "%s", path && *path ? path : "/usr/bin:/bin");
        for (char *save = NULL, *d = strtok_r(dirs, ":", &save); d && !found[0]; d = strtok_r(NULL, ":", &save)) {
            char cand[PATH_MAX];
            snprintf(cand, sizeof cand, "%s/%s", d, cc);
            if (access(cand, X_OK) == 0)
                snprintf(found, sizeof found, "%s", cand);
        }
    }
    if (!found[0] || !realpath(found, out) || strlen(out) >= len) {
        char shown[120];
        sw_escape(cc, 60, shown, sizeof shown);
        snprintf(err, errlen, "no C compiler '%s' found (set CC, or install gcc)", shown);
        return -1;
    }
    return 0;
}

/* The first line of the log that says `what` ("error", ": warning:"),
 * escaped, into buf ("" when none); how many lines say it. */
static int first_line(const char *log, const char *src, const char *what, char *buf, size_t len)
{
    int count = 0;
    buf[0] = '\0';
    /* the compiler saw the student's file as plugin.c: the message names it as they did */
    const char *slash = strrchr(src, '/');
    const char *base = slash ? slash + 1 : src;
    for (const char *line = log; line && *line;) {
        const char *end = strchr(line, '\n');
        size_t n = end ? (size_t)(end - line) : strlen(line);
        char one[512];
        if (n > 9 && strncmp(line, "plugin.c:", 9) == 0)
            snprintf(one, sizeof one, "%.100s:%.*s", base, (int)(n - 9 < 400 ? n - 9 : 400), line + 9);
        else
            snprintf(one, sizeof one, "%.*s", (int)(n < sizeof one ? n : sizeof one - 1), line);
        /* Without user namespaces the jail is Landlock's: a path outside
         * it that exists is "Permission denied" to #include, __has_include
         * or a #pragma, one that does not "No such file", which would tell
         * a student what exists on the grading machine. Both read as the
         * namespace jail's, where nothing outside exists. */
        char *denied = strstr(one, ": Permission denied");
        if (denied)
            snprintf(denied, sizeof one - (size_t)(denied - one), ": No such file or directory");
        if (strstr(one, what) && count++ == 0)
            sw_escape(one, 200, buf, len);
        line = end ? end + 1 : NULL;
    }
    return count;
}

static void first_error(const char *log, const char *src, char *buf, size_t len)
{
    if (!first_line(log, src, "error", buf, len))
        snprintf(buf, len, "see the compiler's messages");
}

static int write_new(const char *path, const char *data, size_t len);

/* Read path whole (at most max bytes, a regular file, never a link) into
 * *buf; 1, or 0 when there is none. */
static int read_fd(int fd, size_t max, char **buf, size_t *len)
{
    struct stat st;
    *buf = NULL;
    *len = 0;
    if (fd < 0 || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || (size_t)st.st_size > max ||
        !(*buf = malloc((size_t)st.st_size + 1)))
        return 0;
    ssize_t n = pread(fd, *buf, (size_t)st.st_size, 0);
    *len = n > 0 ? (size_t)n : 0;
    (*buf)[*len] = '\0';
    return 1;
}

static int read_whole(const char *path, size_t max, char **buf, size_t *len)
{
    int fd = open(path, O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    int rc = read_fd(fd, max, buf, len);
    if (fd >= 0)
        close(fd);
    return rc;
}

/* Without the jail (--no-sandbox): the compiler works in DIR/NAME.d, a
 * private directory holding a copy of the source; its files are read back
 * and the directory removed. */
static int plain_work(const char *dir, const char *name, const sw_jail *spec, char *work, size_t len)
{
    if ((size_t)snprintf(work, len, "%s/%s.d", dir, name) >= len) {
        errno = ENAMETOOLONG;
        return -1;
    }
    if (mkdir(work, 0700) != 0)
        return -1;
    for (int i = 0; i < spec->nin; i++) {
        char path[PATH_MAX + 200], *text;
        size_t text_len;
        if (!read_fd(spec->in[i].fd, SW_JAIL_FILE_MAX, &text, &text_len))
            return -1;
        snprintf(path, sizeof path, "%s/%s", work, spec->in[i].name);
        int rc = write_new(path, text, text_len);
        free(text);
        if (rc != 0)
            return -1;
    }
    return 0;
}

static void plain_done(const char *work, const sw_jail *spec, char **out, size_t *out_len, char **log,
                       size_t *log_len)
{
    char path[PATH_MAX + 200];
    snprintf(path, sizeof path, "%s/plugin.so", work);
    read_whole(path, SW_JAIL_FILE_MAX, out, out_len);
    snprintf(path, sizeof path, "%s/build.log", work);
    read_whole(path, (size_t)1 << 20, log, log_len);
    for (int i = 0; i < spec->nin + spec->nout; i++) {
        snprintf(path, sizeof path, "%s/%s", work, i < spec->nin ? spec->in[i].name : spec->out[i - spec->nin]);
        unlink(path);
    }
    rmdir(work);
}

/* Write len bytes to a new file path (never following a link). */
static int write_new(const char *path, const char *data, size_t len)
{
    int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (fd < 0)
        return -1;
    size_t done = 0;
    while (done < len) {
        ssize_t n = write(fd, data + done, len - done);
        if (n <= 0) {
            close(fd);
            return -1;
        }
        done += (size_t)n;
    }
    return close(fd);
}

/* Whether a failed build ran into a limit the grader set on the process
 * that builds it (grade's --output, --cpu, --memory are inherited by the
 * compiler): the words for it in buf, else 0. That is the teacher's limit,
 * never the student's compile error. */
static int grader_limit(const char *log, size_t out_len, const sw_child_end *end, char *buf,
                        size_t len)
{
    static const struct {
        int resource, signal;     /* the rlimit, and the signal past it (0: none) */
        const char *says;         /* what the compiler says when it hits the limit */
        const char *flag, *unit;  /* grade's option, and its unit */
        double scale;             /* bytes or seconds per unit */
    } limits[] = {
        { RLIMIT_FSIZE, SIGXFSZ, "File size limit exceeded", "--output", "KiB", 1024 },
        { RLIMIT_CPU, SIGXCPU, "CPU time limit exceeded", "--cpu", "s", 1 },
        { RLIMIT_AS, 0, "emory exhausted", "--memory", "MiB", 1024 * 1024 },
        { RLIMIT_AS, 0, "out of memory", "--memory", "MiB", 1024 * 1024 },
    };
    const char *text = log ? log : "";
    for (size_t i = 0; i < sizeof limits / sizeof limits[0]; i++) {
        struct rlimit rl;
        if (getrlimit(limits[i].resource, &rl) != 0 || rl.rlim_cur == RLIM_INFINITY)
            continue;
        int full = limits[i].resource == RLIMIT_FSIZE && (rlim_t)out_len >= rl.rlim_cur;
        if (full || (limits[i].signal && end->signal == limits[i].signal) ||
            strstr(text, limits[i].says)) {
            snprintf(buf, len, "the compiler reached the grader's %s limit of %g %s while building it "
                     "(the teacher's %s sets it; a source that needs more of the compiler, such as a "
                     "huge initialiser, table or macro expansion, should be made smaller)",
                     limits[i].flag, (double)rl.rlim_cur / limits[i].scale, limits[i].unit,
                     limits[i].flag);
            return 1;
        }
    }
    return 0;
}

/* The files handed to the compiler: the source as plugin.c, then its
 * headers by their own names (plugin_headers.h); 0, or -1 with err. */
static int open_inputs(const char *src, int shared, sw_jail *spec, sw_headers *hd, char *err, size_t errlen)
{
    struct stat st;
    int fd = open(src, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0 || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        snprintf(err, errlen, "no such file (a plugin's source is a regular file)");
        if (fd >= 0)
            close(fd);
        return -1;
    }
    spec->in[spec->nin++] = (sw_jail_file){ .fd = fd, .name = "plugin.c" };
    size_t total = (size_t)st.st_size;
    if (sw_headers_find(src, shared, hd, err, errlen) != 0)
        return -1;
    for (int i = 0; i < hd->n && total <= SW_PLUGIN_SOURCE_MAX; i++) {
        char one[120];
        sw_escape(hd->name[i], 60, one, sizeof one);
        if ((fd = sw_headers_open(hd, i)) < 0 || fstat(fd, &st) != 0) {
            snprintf(err, errlen, "its header '%s' cannot be read: %s", one, strerror(errno));
            if (fd >= 0)
                close(fd);
            return -1;
        }
        spec->in[spec->nin++] = (sw_jail_file){ .fd = fd, .name = hd->name[i] };
        total += (size_t)st.st_size;
    }
    if (total > SW_PLUGIN_SOURCE_MAX) {
        snprintf(err, errlen, "the source%s %s %.1f MiB; a plugin's source with its headers may be at most "
                 "%zu MiB", hd->n ? " and its headers" : "", hd->n ? "are" : "is",
                 (double)total / 1048576, SW_PLUGIN_SOURCE_MAX >> 20);
        return -1;
    }
    return 0;
}

static void close_inputs(sw_jail *spec)
{
    for (int i = 0; i < spec->nin; i++)
        close(spec->in[i].fd);
    if (spec->include_fd >= 0)
        close(spec->include_fd);
}

/* A missing header where the folder's headers were withheld: why, for the
 * student and the teacher. */
static void withheld_hint(const sw_headers *hd, const char *log, char *buf, size_t len)
{
    size_t n = strlen(buf);
    if (hd->withheld && log && strstr(log, ".h: No such file or directory"))
        snprintf(buf + n, len - n, " (its folder holds %d .c files, so the .h files beside it were not "
                 "used: a folder's headers go with its one .c, or with every .c where all are one student's; "
                 "give each student a folder)", hd->sources);
}

int sw_plugin_compile(const char *src, const char *shown_as, int shared, const char *dir, const char *name,
                      char *so, size_t solen, sw_build_warnings *warn, char *err, size_t errlen)
{
    if (warn) {
        warn->count = 0;
        warn->first[0] = '\0';
    }
    char shown[200], msg[SW_ERRLEN + 160], cc[PATH_MAX];
    sw_escape(shown_as ? shown_as : src, 120, shown, sizeof shown);
    sw_jail spec = { .profile = SW_JAIL_COMPILE, .include_fd = -1, .out = { "plugin.so", "build.log" },
                     .nout = 2, .disk_bytes = (size_t)64 << 20 };
    sw_headers hd;
    if (open_inputs(src, shared, &spec, &hd, msg, sizeof msg) != 0) {
        close_inputs(&spec);
        snprintf(err, errlen, "'%s': %s", shown, msg);
        return SW_EINVAL;
    }
    if (find_compiler(cc, sizeof cc, msg, sizeof msg) != 0) {
        close_inputs(&spec);
        snprintf(err, errlen, "'%s': %s", shown, msg);
        return SW_EIO;
    }
    char inc[PATH_MAX + 32];
    snprintf(inc, sizeof inc, "%.*s/stepwise", PATH_MAX, include_dir());
    spec.include_fd = open(inc, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    /* Under grade, the build is the submission's own work: it gets what
     * is left of --cpu (sw_plugin_limits), never more than a build's own
     * limit. */
    sw_limits own;
    sw_plugin_limits(&own);
    int by_cpu = own.cpu_seconds > 0 && own.cpu_seconds < BUILD_SECONDS;
    sw_limits lim = { .cpu_seconds = by_cpu ? own.cpu_seconds : BUILD_SECONDS,
                      .memory_bytes = (size_t)2048 << 20, .output_bytes = (size_t)64 << 20 };
    /* Under a grader's --memory (this process's hard limit), the build's
     * scratch disk, memory that limit does not count, is at most half of it. */
    struct rlimit as;
    if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_max != RLIM_INFINITY && as.rlim_max / 2 < spec.disk_bytes)
        spec.disk_bytes = (size_t)(as.rlim_max / 2);
    char work[PATH_MAX];
    /* jailed: work/ is the current directory, the headers beside it */
    build_job job = { cc, ".", "../include" };
    if (!sw_jail_enabled()) {
        job.work = work;
        job.inc = include_dir();
        if (plain_work(dir, name, &spec, work, sizeof work) != 0) {
            close_inputs(&spec);
            snprintf(err, errlen, "'%s': cannot copy it to build it: %s", shown, strerror(errno));
            return SW_EIO;
        }
    }
    sw_child child;
    int rc = sw_sandbox_spawn_jailed(&child, run_compiler, &job, &lim, -1, &spec, msg, sizeof msg);
    close_inputs(&spec);
    if (rc != SW_OK) {
        snprintf(err, errlen, "'%s': %s", shown, msg);
        return SW_EIO;
    }
    char log_path[PATH_MAX + 80], *out = NULL, *log = NULL;
    size_t out_len = 0, log_len = 0;
    snprintf(so, solen, "%s/%s.so", dir, name);
    snprintf(log_path, sizeof log_path, "%s/%s.log", dir, name);
    sw_child_end end;
    double started = sw_clock_now();
    if (sw_jail_enabled()) {
        /* the jail's init sends both once the compiler ended */
        int got = sw_sandbox_read_file(child.from_child, SW_JAIL_FILE_MAX, BUILD_SECONDS, &out, &out_len);
        if (got >= 0)
            got = sw_sandbox_read_file(child.from_child, (size_t)1 << 20, BUILD_SECONDS, &log, &log_len);
        if (got < 0) {
            free(out);
            out = NULL;
        }
    }
    sw_sandbox_reap(&child, BUILD_SECONDS, &end);
    if (!sw_jail_enabled())
        plain_done(work, &spec, &out, &out_len, &log, &log_len);
    struct rlimit fsize; /* the grader's --output holds for the built plugin too */
    int fits = getrlimit(RLIMIT_FSIZE, &fsize) != 0 || fsize.rlim_cur == RLIM_INFINITY ||
               (rlim_t)out_len < fsize.rlim_cur;
    int ok = end.exited && end.code == 0 && out && fits && write_new(so, out, out_len) == 0;
    if (log && (fits || (rlim_t)log_len < fsize.rlim_cur))
        write_new(log_path, log, log_len);
    free(out);
    if (ok) {
        if (warn && log)
            warn->count = first_line(log, src, ": warning:", warn->first, sizeof warn->first);
        free(log);
        return SW_OK;
    }
    if (by_cpu && !end.killed &&
        ((!end.exited && end.signal == SIGXCPU) || (log && strstr(log, "CPU time limit exceeded")))) {
        free(log);
        snprintf(err, errlen, "'%s' did not compile within the submission's CPU time: the compiler "
                 "used all %.3g s left of it (the submission's CPU-time limit, --cpu: it counts its own processes "
                 "only, the compiler's included)", shown, lim.cpu_seconds);
        return SW_EINVAL;
    }
    /* out of the wall clock's 60 s: killed, or its output given up on
     * (its jail then ends without a word) */
    int late = !(out_len > 0) && !(log && log[0]) && sw_clock_now() - started >= BUILD_SECONDS;
    if (end.killed || late) {
        free(log);
        snprintf(err, errlen, "'%s' did not compile within the grader's limit of %g s of wall-clock time (on a "
                 "machine this busy, grade with fewer --jobs)", shown, BUILD_SECONDS);
        return SW_EIO;
    }
    if (!end.exited && end.signal == SIGXCPU) {
        free(log);
        snprintf(err, errlen, "'%s' did not compile within the grader's limit of %g s of CPU time", shown,
                 BUILD_SECONDS);
        return SW_EINVAL;
    }
    /* a compiler that said what is wrong with the source before a limit
     * stopped it (a binary file included, its log past --output in the
     * uid jail, red team 4): its first error, as the namespace jail shows */
    char said[8];
    int has_error = log && first_line(log, src, "error", said, sizeof said) > 0;
    if (!has_error && grader_limit(log, out_len, &end, msg, sizeof msg)) {
        free(log);
        snprintf(err, errlen, "'%s' was not built: %s", shown, msg);
        return SW_EIO;
    }
    if (!log || !log[0] || strstr(log, "No space left on device")) {
        /* its scratch disk full: the log, written there, may be lost too */
        snprintf(err, errlen, "'%s' was not built: the compiler %s; a build's scratch space is "
                 "%zu MiB here (half the teacher's --memory, at most 64; a source that needs more, such "
                 "as a huge initialiser, should be made smaller)",
                 shown, log && log[0] ? "ran out of scratch space" : "stopped without a message",
                 spec.disk_bytes >> 20);
        free(log);
        return SW_EIO;
    }
    first_error(log, src, msg, sizeof msg);
    withheld_hint(&hd, log, msg, sizeof msg);
    free(log);
    snprintf(err, errlen, "'%s' does not compile (%s " SHOWN_FLAGS "): %s", shown, cc, msg);
    return SW_EINVAL;
}
