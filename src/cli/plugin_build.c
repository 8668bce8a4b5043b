/* Building a student's integrator from C source: `--plugin my.c` compiles
 * it with the documented flags (docs/plugins.md) into a private temporary
 * directory, under a time limit, and loads the result. The directory and
 * what is in it are removed when stepwise ends, however it ends
 * (util/tmpdir.h: at exit, or by a watcher after a signal or a crash). */
#include "cli/cli.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "plugin/plugin.h"
#include "plugin/sandbox.h"
#include "util/tmpdir.h"

/* Seconds a compiler may take for one plugin. */
#define BUILD_SECONDS 60.0

static char build_dir[PATH_MAX];
static pid_t build_dir_owner;

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
    if (sw_cli_beside_binary("include", has_header, dir, sizeof dir))
        return dir;
    return SW_DATADIR "/../../include";
}

typedef struct build_job {
    const char *cc, *inc, *src, *out, *log;
} build_job;

static int run_compiler(void *ctx, int in, int out)
{
    (void)in;
    (void)out;
    const build_job *j = ctx;
    int fd = open(j->log, O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (fd >= 0) {
        dup2(fd, STDOUT_FILENO);
        dup2(fd, STDERR_FILENO);
        close(fd);
    }
    setenv("LC_ALL", "C", 1); /* plain ASCII quotes in the messages we show */
    char incflag[PATH_MAX + 32];
    snprintf(incflag, sizeof incflag, "-I%s", j->inc);
    execlp(j->cc, j->cc, "-std=c11", "-O2", "-g", "-Wall", "-Wextra", "-shared", "-fPIC", incflag,
           "-o", j->out, j->src, "-lm", (char *)NULL);
    fprintf(stderr, "error: cannot run the compiler '%s': %s\n", j->cc, strerror(errno));
    return 127;
}

/* The first line of the log that says "error", escaped, for a message. */
static void first_error(const char *log, char *buf, size_t len)
{
    FILE *f = fopen(log, "r");
    char line[512];
    buf[0] = '\0';
    while (f && fgets(line, sizeof line, f)) {
        if (strstr(line, "error")) {
            line[strcspn(line, "\n")] = '\0';
            sw_escape(line, 200, buf, len);
            break;
        }
    }
    if (f)
        fclose(f);
    if (!buf[0])
        snprintf(buf, len, "see the compiler's messages");
}

/* Whether a failed build ran into a limit the grader set on the process
 * that builds it (grade's --output, --cpu, --memory are inherited by the
 * compiler): the words for it in buf, else 0. That is the teacher's limit,
 * never the student's compile error. */
static int grader_limit(const char *log, const char *so, const sw_child_end *end, char *buf,
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
    char text[4096] = "";
    FILE *f = fopen(log, "r");
    if (f) {
        size_t n = fread(text, 1, sizeof text - 1, f);
        text[n] = '\0';
        fclose(f);
    }
    for (size_t i = 0; i < sizeof limits / sizeof limits[0]; i++) {
        struct rlimit rl;
        if (getrlimit(limits[i].resource, &rl) != 0 || rl.rlim_cur == RLIM_INFINITY)
            continue;
        struct stat st;
        int full = limits[i].resource == RLIMIT_FSIZE &&
                   ((stat(log, &st) == 0 && (rlim_t)st.st_size >= rl.rlim_cur) ||
                    (stat(so, &st) == 0 && (rlim_t)st.st_size >= rl.rlim_cur));
        if (full || (limits[i].signal && end->signal == limits[i].signal) ||
            strstr(text, limits[i].says)) {
            snprintf(buf, len, "the grader's %s limit of %g %s was reached while building it (the "
                     "compiler counts against it); this says nothing about the plugin: raise %s",
                     limits[i].flag, (double)rl.rlim_cur / limits[i].scale, limits[i].unit,
                     limits[i].flag);
            return 1;
        }
    }
    return 0;
}

int sw_cli_compile_plugin(const char *src, const char *dir, const char *name, char *so,
                          size_t solen, char *err, size_t errlen)
{
    char shown[200], msg[SW_ERRLEN];
    sw_escape(src, 120, shown, sizeof shown);
    struct stat st;
    if (stat(src, &st) != 0 || !S_ISREG(st.st_mode)) {
        snprintf(err, errlen, "--plugin '%s': no such file", shown);
        return SW_EINVAL;
    }
    char log[PATH_MAX + 80];
    snprintf(so, solen, "%s/%s.so", dir, name);
    snprintf(log, sizeof log, "%s/%s.log", dir, name);
    const char *cc = getenv("CC");
    build_job job = { cc && *cc ? cc : "cc", include_dir(), src, so, log };
    sw_child child;
    if (sw_sandbox_spawn(&child, run_compiler, &job, NULL, -1, msg, sizeof msg) != SW_OK) {
        snprintf(err, errlen, "--plugin '%s': %s", shown, msg);
        return SW_EIO;
    }
    /* The compiler reports by its exit status: wait for it, within the limit. */
    sw_child_end end;
    sw_sandbox_reap(&child, BUILD_SECONDS, &end);
    if (end.exited && end.code == 0)
        return SW_OK;
    if (end.killed) {
        snprintf(err, errlen, "--plugin '%s' did not compile within %g s", shown, BUILD_SECONDS);
        return SW_EINVAL;
    }
    if (grader_limit(log, so, &end, msg, sizeof msg)) {
        snprintf(err, errlen, "--plugin '%s' was not built: %s", shown, msg);
        return SW_EIO;
    }
    first_error(log, msg, sizeof msg);
    snprintf(err, errlen, "--plugin '%s' does not compile (%s -std=c11 -O2 -Wall -shared -fPIC): "
             "%s", shown, job.cc, msg);
    return SW_EINVAL;
}

int sw_cli_build_plugin(const char *src, char *so, size_t solen)
{
    static int count;
    char err[SW_ERRLEN + 256], name[16];
    if (!build_dir[0] || build_dir_owner != getpid()) {
        if (sw_tmpdir_make("plugins", build_dir, sizeof build_dir, err, sizeof err) != SW_OK) {
            build_dir[0] = '\0';
            return sw_cli_error("--plugin: %s", err);
        }
        build_dir_owner = getpid();
        count = 0;
    }
    if (count == 64)
        return sw_cli_error("--plugin: at most 64 plugins are built per run");
    snprintf(name, sizeof name, "p%d", count++);
    if (sw_cli_compile_plugin(src, build_dir, name, so, solen, err, sizeof err) != SW_OK)
        return sw_cli_error("%s", err);
    return SW_EXIT_OK;
}
