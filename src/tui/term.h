/* The terminal: ncurses start and stop, colours, keys, painting a composed
 * screen. The terminal is restored through one atexit routine that every
 * exit path reaches; signal handlers only set a flag, except the one for
 * fatal signals (util/signals.h), which restores the terminal and dies. */
#ifndef SW_TUI_TERM_H
#define SW_TUI_TERM_H

#include <stddef.h>

#include "render/screen.h"

/* sw_term_key: the terminal went away (input hung up or ended). */
#define SW_TERM_GONE (-3)

/* Start curses (once), catch SIGINT, SIGTERM and SIGHUP into
 * sw_signal_caught, and arm the fatal-signal restore (util/signals.h);
 * 0, or SW_EIO with err filled when there is no usable terminal (TERM
 * unset or unknown: the message names it). */
int sw_term_start(char *err, size_t errlen);
/* Restore the terminal; safe to call twice and from atexit. */
void sw_term_stop(void);
/* 1 when the locale's character set is UTF-8 (Braille, ✓ and wide text
 * can be shown), known once sw_term_start has run. */
int sw_term_utf8(void);
/* Current terminal size. */
void sw_term_size(int *cols, int *rows);
/* Next key as a character or SW_KEY_*, waiting at most timeout_ms; -1 none,
 * -2 the terminal was resized, SW_TERM_GONE input has ended for good. */
int sw_term_key(int timeout_ms);
/* Paint a composed screen. */
void sw_term_paint(const sw_screen *s);

#endif
