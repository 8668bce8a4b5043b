/* Signalling the grader, harmlessly: SIGURG (ignored by default) to every
 * process of the test's stepwise. A signal that is delivered could as well
 * have been SIGTERM or SIGSTOP (kill-grader.c, stop-grader.c); success here
 * makes the plugin hand in the right answer. */
#define EVIL_FAMILY "signal-probe"
#include "evil.h"

static void evil_attack(void)
{
    pid_t t[256];
    int n = evil_targets(t, 256), sent = 0;
    for (int i = 0; i < n; i++)
        sent += kill(t[i], SIGURG) == 0;
    if (sent) {
        evil_cheat = 1;
        evil_mark("signal", NULL);
    }
}
