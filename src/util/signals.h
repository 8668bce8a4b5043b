/* Interruption by SIGINT, SIGTERM or SIGHUP: the handler only records the
 * signal; long loops poll sw_signal_caught, clean up (terminal, temporary
 * files) and then die of the same signal, as a shell expects.
 * Fatal signals (SIGSEGV, SIGABRT, SIGQUIT, SIGBUS, SIGFPE) while the
 * terminal UI runs: the one handler that does more than set a flag puts the
 * terminal back with async-signal-safe calls only (write, tcsetattr), then
 * the process dies of the signal as it would have. */
#ifndef SW_UTIL_SIGNALS_H
#define SW_UTIL_SIGNALS_H

#include <signal.h>
#include <stddef.h>
#include <termios.h>

/* The number of the last signal caught since sw_signals_catch; 0 none. */
extern volatile sig_atomic_t sw_signal_caught;

/* Catch SIGINT, SIGTERM and SIGHUP from now on (also when they were
 * ignored: a background job's Ctrl-C still stops it cleanly). */
void sw_signals_catch(void);
/* Back to the default action for those signals (a pending one is kept). */
void sw_signals_default(void);
/* Die of sig with its default action (returns only if that does not kill). */
void sw_signals_reraise(int sig);
/* Exit status for a caught signal: 128 + its number, 0 when none. */
int sw_signals_status(void);
/* The terminal went away without a SIGHUP reaching us (a parent swallowed
 * it, or input ended): record it as a hangup, so every loop ends as on
 * SIGHUP and the exit status is 128 + SIGHUP. */
void sw_signals_hangup(void);

/* Longest reset sequence sw_signals_fatal_arm keeps. */
#define SW_SIGNALS_RESET_MAX 256

/* From now on, a fatal signal in this process (not in a forked child)
 * first writes reset[0..len) to fd and sets fd's terminal modes back to
 * *modes, then takes the action it had before (the default: die, with a
 * core where allowed; a sanitizer's report). A fatal signal that was
 * ignored stays ignored. Returns 0, or -1 when reset is too long. */
int sw_signals_fatal_arm(int fd, const struct termios *modes, const char *reset, size_t len);
/* Stop restoring (the terminal is restored already): the actions from
 * before sw_signals_fatal_arm come back. Safe to call when not armed. */
void sw_signals_fatal_disarm(void);

#endif
