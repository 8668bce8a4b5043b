/* Stopping the grader: SIGSTOP to every process of the test's stepwise,
 * once. A stopped grader hangs the whole class; the test notices a stopped
 * grader, reports it and sends SIGCONT, so the rest is still checked.
 * Graded in a class of its own (with honest classmates). */
#define EVIL_FAMILY "stop-grader"
#include "evil.h"

static void evil_attack(void)
{
    pid_t t[256];
    int n = evil_targets(t, 256), sent = 0;
    for (int i = 0; i < n; i++)
        sent += kill(t[i], SIGSTOP) == 0;
    if (sent)
        evil_mark("sigstop", NULL);
}
