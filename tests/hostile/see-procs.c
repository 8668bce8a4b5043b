/* Seeing other processes: lists /proc and reads the command line of the
 * grader (which names the assignment, the class and the gradebook files:
 * every other attack starts here). Seeing any process of the test's
 * stepwise counts as success: the plugin then hands in the right answer. */
#define EVIL_FAMILY "see-procs"
#include "evil.h"

static void evil_attack(void)
{
    pid_t t[16];
    if (evil_targets(t, 16) > 0) {
        evil_cheat = 1;
        evil_mark("see", NULL);
    }
}
