/* The terminal: ncurses start and stop, colours, keys, painting a composed
 * screen. The terminal is restored through one atexit routine that every
 * exit path reaches; signal handlers only set a flag. */
#ifndef SW_TUI_TERM_H
#define SW_TUI_TERM_H

#include <stddef.h>

#include "render/screen.h"

/* Start curses (once) and catch SIGINT, SIGTERM and SIGHUP into
 * sw_signal_caught (util/signals.h); 0, or SW_EIO with err filled when
 * there is no terminal. */
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

#endif
