/* Signal set-up in one place (after nnn and Lua: a handler sets a flag and
 * nothing else, so it is async-signal-safe by construction). The fatal-signal
 * handler is the one exception: it restores the terminal with write() and
 * tcsetattr() only, both async-signal-safe, from data prepared when armed. */
#include "util/signals.h"

#include <errno.h>
#include <string.h>
#include <unistd.h>

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

void sw_signals_hangup(void)
{
    if (!sw_signal_caught)
        sw_signal_caught = SIGHUP;
}

/* ---- fatal signals -------------------------------------------------------------------- */

static const int fatal[] = { SIGSEGV, SIGABRT, SIGQUIT, SIGBUS, SIGFPE };
#define NFATAL (sizeof fatal / sizeof fatal[0])

/* Written once by sw_signals_fatal_arm before the handlers go in, only read
 * by the handler: the terminal to restore and how. */
static volatile sig_atomic_t fatal_armed;
static pid_t fatal_owner;
static int fatal_fd = -1;
static struct termios fatal_modes;
static char fatal_reset[SW_SIGNALS_RESET_MAX];
static size_t fatal_reset_len;
static struct sigaction fatal_before[NFATAL];
static int fatal_installed[NFATAL];
/* A stack for the handler, so a stack overflow still restores the terminal. */
static char fatal_stack[64 * 1024];

static void on_fatal(int sig)
{
    int saved_errno = errno;
    /* Only the process that set the terminal up restores it: a child forked
     * to run a plugin inherits this handler but must not touch the screen. */
    if (fatal_armed && getpid() == fatal_owner) {
        fatal_armed = 0;
        for (size_t off = 0; off < fatal_reset_len;) {
            ssize_t n = write(fatal_fd, fatal_reset + off, fatal_reset_len - off);
            if (n > 0)
                off += (size_t)n;
            else if (n < 0 && errno == EINTR)
                continue;
            else
                break;
        }
        tcsetattr(fatal_fd, TCSANOW, &fatal_modes);
    }
    /* The action from before (default: die; a sanitizer: its report), now,
     * with the signal unblocked (SA_NODEFER). A fault raised by the CPU
     * would also come back on return; raise() covers kill and abort. */
    for (size_t i = 0; i < NFATAL; i++)
        if (fatal[i] == sig) {
            sigaction(sig, &fatal_before[i], NULL);
            break;
        }
    raise(sig);
    errno = saved_errno;
}

int sw_signals_fatal_arm(int fd, const struct termios *modes, const char *reset, size_t len)
{
    if (len > sizeof fatal_reset)
        return -1;
    sw_signals_fatal_disarm();
    fatal_owner = getpid();
    fatal_fd = fd;
    fatal_modes = *modes;
    memcpy(fatal_reset, reset, len);
    fatal_reset_len = len;
    stack_t ss;
    memset(&ss, 0, sizeof ss);
    ss.ss_sp = fatal_stack;
    ss.ss_size = sizeof fatal_stack;
    sigaltstack(&ss, NULL);
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_fatal;
    sa.sa_flags = SA_NODEFER | SA_ONSTACK;
    sigemptyset(&sa.sa_mask);
    for (size_t i = 0; i < NFATAL; i++) {
        fatal_installed[i] = 0;
        if (sigaction(fatal[i], NULL, &fatal_before[i]) != 0 || fatal_before[i].sa_handler == SIG_IGN)
            continue; /* an ignored SIGQUIT stays ignored: nothing dies, nothing to restore */
        if (sigaction(fatal[i], &sa, NULL) == 0)
            fatal_installed[i] = 1;
    }
    fatal_armed = 1;
    return 0;
}

void sw_signals_fatal_disarm(void)
{
    fatal_armed = 0;
    for (size_t i = 0; i < NFATAL; i++)
        if (fatal_installed[i]) {
            sigaction(fatal[i], &fatal_before[i], NULL);
            fatal_installed[i] = 0;
        }
}
