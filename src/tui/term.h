/* The terminal: ncurses start and stop, colours, keys, painting a composed
 * screen. The terminal is restored through one atexit routine that every
 * exit path reaches; signal handlers only set a flag. */
#ifndef SW_TERM_H
#define SW_TERM_H

#include <signal.h>

#include "render/screen.h"

/* Set by SIGINT, SIGTERM and SIGHUP; the loop exits when it is non-zero. */
extern volatile sig_atomic_t sw_term_signal;

/* Start curses (once); 0, or SW_EIO with err filled when there is no terminal. */
int sw_term_start(char *err, size_t errlen);
/* Restore the terminal; safe to call twice and from atexit. */
void sw_term_stop(void);
/* Current terminal size. */
void sw_term_size(int *cols, int *rows);
/* Next key as a character or SW_KEY_*, waiting at most timeout_ms; -1 none,
 * -2 the terminal was resized. */
int sw_term_key(int timeout_ms);
/* Paint a composed screen. */
void sw_term_paint(const sw_screen *s);
/* Seconds on a monotonic clock. */
double sw_term_now(void);
/* Exit status for a signal that ended the program (128 + signal number). */
int sw_term_signal_status(void);

#endif
