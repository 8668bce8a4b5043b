/* Tracing the grader: PTRACE_SEIZE, PTRACE_INTERRUPT and PTRACE_DETACH on
 * every process of the test's stepwise (the parent first among them). A
 * tracer can rewrite its tracee's memory and registers (the plugin
 * made check exit 0 this way); here attaching at all counts as success and
 * the plugin hands in the right answer, leaving its tracee unharmed. */
#define EVIL_FAMILY "ptrace-parent"
#include "evil.h"
#include <sys/ptrace.h>

static void evil_attack(void)
{
    pid_t t[256];
    int n = evil_targets(t, 256), traced = 0;
    for (int i = 0; i < n; i++) {
        if (ptrace(PTRACE_SEIZE, t[i], NULL, NULL) != 0)
            continue;
        traced++;
        if (ptrace(PTRACE_INTERRUPT, t[i], NULL, NULL) == 0) {
            int status;
            waitpid(t[i], &status, __WALL);
        }
        ptrace(PTRACE_DETACH, t[i], NULL, NULL);
    }
    if (traced) {
        evil_cheat = 1;
        evil_mark("ptrace", NULL);
    }
}
