/* The terminal UI's live loop and the lesson menu: ncurses only through
 * tui/term.h, the picture from render/, the model from app/. */
#ifndef SW_TUI_LOOP_H
#define SW_TUI_LOOP_H

#include <stddef.h>

#include "app/app.h"
#include "app/side.h"

/* What a lesson adds to the loop: its keys first, and a side pane. */
typedef struct sw_play_hooks {
    void *ctx;
    /* Return 1 when the key was the lesson's (page turns, hints, answers). */
    int (*key)(void *ctx, sw_app *a, int key);
    /* Once per frame, after the sims advanced: the pane beside the scene
     * for a terminal `cols` wide, or NULL. */
    const sw_side *(*side)(void *ctx, sw_app *a, int cols);
} sw_play_hooks;

/* Run the terminal UI until q, a signal or an error (hooks NULL: play).
 * SW_OK on q or a signal (sw_signal_caught tells which), else a status with
 * err filled. The terminal is restored and any recording written first. */
int sw_tui_play(sw_app *a, const sw_play_hooks *hooks, char *err, size_t errlen);

/* The lesson menu: n lines, *sel highlighted and always shown (the list
 * scrolls; arrows, PgUp/PgDn, a number typed, Enter). note (NULL: none)
 * is shown at the bottom until a key is pressed: why the last choice did
 * not open. Returns the index chosen (the terminal stays up for the
 * lesson), -1 when the student quit (q, Esc), -2 on a signal or when the
 * terminal went away (sw_signal_caught tells which), -3 with err filled
 * when the terminal cannot start. The terminal is restored before any
 * return but an index. */
int sw_tui_menu(const char *title, const char *const *lines, int n, int *sel, const char *note, char *err,
                size_t errlen);

#endif
