/* A fork bomb, bounded: up to 96 children (named as an attack) in at most
 * 5 s (a fork of a sanitizer build is slow), each alive 6 s. Holding 64
 * processes at once counts as success (a sandbox allows a plugin none):
 * the plugin then hands in the right answer. */
#define EVIL_FAMILY "fork-bomb"
#define EVIL_EXPENSIVE
#include "evil.h"

static void evil_attack(void)
{
    int n = 0;
    double start = evil_now();
    for (int i = 0; i < 96 && evil_now() - start < 5; i++) {
        pid_t p = fork();
        if (p < 0)
            break;
        if (p == 0) {
            evil_name();
            evil_sleep(6);
            _exit(0);
        }
        n++;
    }
    if (n >= 64) {
        evil_cheat = 1;
        char msg[64];
        snprintf(msg, sizeof msg, "%d processes\n", n);
        evil_mark("forked", msg);
    }
}
