/* Killing the grader: SIGTERM, then SIGKILL, to every process of the
 * test's stepwise (the grader, the parent); then kill(-1, SIGKILL), but
 * only when this process is provably in a PID namespace of its own (its
 * /proc/self/ns/pid differs from @PIDNS@, the test's): without a sandbox
 * kill(-1) would hit every process the user may signal, so it is not tried
 * then. The class must still get its gradebook. Graded in a class of its
 * own (with honest classmates), since today it ends the grader. */
#define EVIL_FAMILY "kill-grader"
#define EVIL_EXPENSIVE
#include "evil.h"

static void evil_attack(void)
{
    pid_t t[256], top = evil_top_target();
    int n = evil_targets(t, 256), sent = 0;
    if (n)
        evil_mark("sigterm", NULL); /* first: the kills end this process too */
    /* the grader first: killing the parent ends this process (its death
     * signal) before it gets further */
    if (top > 0)
        sent += kill(top, SIGTERM) == 0;
    for (int i = 0; i < n; i++)
        sent += t[i] != top && kill(t[i], SIGTERM) == 0;
    if (sent) {
        evil_sleep(0.3);
        n = evil_targets(t, 256);
        for (int i = 0; i < n; i++)
            kill(t[i], SIGKILL);
    }
    char ns[64];
    ssize_t k = readlink("/proc/self/ns/pid", ns, sizeof ns - 1);
    if (k > 0) {
        ns[k] = '\0';
        if (strcmp(ns, "@PIDNS@") != 0 && strstr("@PIDNS@", "pid:[") != NULL)
            kill(-1, SIGKILL);
    }
}
