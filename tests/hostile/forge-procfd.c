/* Writing to the grader's own output: opens /proc/PID/fd/1 and fd/2 of
 * every process of the test's stepwise (its parent, the grader, check)
 * and writes fake "pass" rows, a fake PASS line and escapes there. The
 * grader's stdout must show none of it. */
#define EVIL_FAMILY "forge-procfd"
#include "evil.h"

static void evil_attack(void)
{
    pid_t t[256];
    int n = evil_targets(t, 256);
    int reached = 0;
    for (int i = 0; i < n; i++)
        for (int fd = 1; fd <= 2; fd++) {
            char path[64];
            snprintf(path, sizeof path, "/proc/%d/fd/%d", (int)t[i], fd);
            int out = open(path, O_WRONLY | O_APPEND | O_NOCTTY | O_CLOEXEC);
            if (out < 0)
                continue;
            evil_print_fake(out);
            close(out);
            reached++;
        }
    if (reached)
        evil_mark("procfd", NULL);
}
