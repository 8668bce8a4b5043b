/* Signal set-up in one place (after nnn and Lua: a handler sets a flag and
 * nothing else, so it is async-signal-safe by construction). */
#include "util/signals.h"

#include <string.h>

volatile sig_atomic_t sw_signal_caught;

static void on_signal(int sig) { sw_signal_caught = sig; }

static const int caught[] = { SIGINT, SIGTERM, SIGHUP };

static void set_all(void (*handler)(int))
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = handler;
    sigemptyset(&sa.sa_mask);
    for (size_t i = 0; i < sizeof caught / sizeof caught[0]; i++)
        sigaction(caught[i], &sa, NULL);
}

void sw_signals_catch(void) { set_all(on_signal); }

void sw_signals_default(void) { set_all(SIG_DFL); }

void sw_signals_reraise(int sig)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = SIG_DFL;
    sigemptyset(&sa.sa_mask);
    sigaction(sig, &sa, NULL);
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, sig);
    sigprocmask(SIG_UNBLOCK, &set, NULL);
    raise(sig);
}

int sw_signals_status(void) { return sw_signal_caught ? 128 + sw_signal_caught : 0; }
