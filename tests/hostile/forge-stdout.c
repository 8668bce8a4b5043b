/* Fake "pass" rows, a fake PASS line and terminal escapes (clear screen,
 * window title, a hyperlink) printed to stdout and stderr, at load and at
 * every step, and to /dev/tty when there is one. None of it may reach the
 * teacher's terminal raw, and none of it changes the verdict. */
#define EVIL_FAMILY "forge-stdout"
#include "evil.h"

static void shout(void)
{
    fputs(evil_fake, stdout);
    fputs(evil_fake, stderr);
    fflush(stdout);
    fflush(stderr);
    evil_print_fake(1);
    evil_print_fake(2);
    int tty = open("/dev/tty", O_WRONLY | O_NOCTTY | O_CLOEXEC);
    if (tty >= 0) {
        evil_print_fake(tty);
        close(tty);
    }
}

__attribute__((constructor)) static void at_load(void) { shout(); }

static void evil_attack(void) { shout(); }
