/* The live loop shared by `play` and the lesson runner. */
#ifndef SW_PLAY_H
#define SW_PLAY_H

#include "app/app.h"
#include "render/screen.h"

/* What a lesson adds to the loop: its keys first, and a side pane. */
typedef struct sw_play_hooks {
    void *ctx;
    /* Return 1 when the key was the lesson's (page turns, hints, answers). */
    int (*key)(void *ctx, sw_app *a, int key);
    /* Once per frame, after the sims advanced: the pane beside the scene
     * for a terminal `cols` wide, or NULL. */
    const sw_side *(*side)(void *ctx, sw_app *a, int cols);
} sw_play_hooks;

/* Run the terminal UI until q or a signal; returns the exit status. */
int sw_play_loop(sw_app *a, sw_play_hooks *hooks);

#endif
