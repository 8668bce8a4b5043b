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

/* The lesson menu: n lines, *sel highlighted (arrows, digits, Enter).
 * Returns the index chosen, -1 when the student quit (q, Esc), -2 on a
 * signal; SW_EIO-style negative status below -2 is never returned: a
 * terminal that cannot start gives -3 with err filled. The terminal is
 * restored before it returns. */
int sw_tui_menu(const char *title, const char *const *lines, int n, int *sel, char *err, size_t errlen);

#endif
