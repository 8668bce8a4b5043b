/* Interruption by SIGINT, SIGTERM or SIGHUP: the handler only records the
 * signal; long loops poll sw_signal_caught, clean up (terminal, temporary
 * files) and then die of the same signal, as a shell expects. */
#ifndef SW_UTIL_SIGNALS_H
#define SW_UTIL_SIGNALS_H

#include <signal.h>

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

#endif
