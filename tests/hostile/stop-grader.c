/* Stopping the grader: SIGSTOP to every process of the test's stepwise,
 * once (in the graded run). A stopped grader hangs the whole class; the test notices a stopped
 * grader, reports it and sends SIGCONT, so the rest is still checked.
 * Graded in a class of its own (with honest classmates). */
#define EVIL_FAMILY "stop-grader"
#define EVIL_EXPENSIVE
#include "evil.h"

static void evil_attack(void)
{
    pid_t t[256], top = evil_top_target();
    int n = evil_targets(t, 256);
    if (n)
        evil_mark("sigstop", NULL); /* first: a stopped parent stops this process too */
    if (top > 0)
        kill(top, SIGSTOP); /* the grader first */
    for (int i = 0; i < n; i++)
        if (t[i] != top)
            kill(t[i], SIGSTOP);
}
