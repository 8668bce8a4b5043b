/* The whole terminal as a grid of cells (code point + style), composed
 * without a terminal: the ncurses view paints it, `play --frames --ascii`
 * prints it, and tests read it. */
#ifndef SW_RENDER_SCREEN_H
#define SW_RENDER_SCREEN_H

#include <stddef.h>
#include <stdint.h>

#include "app/app.h"
#include "app/side.h"
#include "render/camera.h"
#include "render/canvas.h"
#include "render/draw.h"
#include "render/trails.h"

/* Styles past the canvas's own (SW_STYLE_*). */
enum {
    SW_STYLE_TEXT = SW_STYLE_COUNT, /* plain text */
    SW_STYLE_STATUS,                /* status lines */
    SW_STYLE_TITLE,                 /* titles, the lesson's headings */
    SW_STYLE_OK,                    /* a goal met */
    SW_STYLE_BAD,                   /* a goal not met, blow-up banner */
    SW_STYLE_DIM,                   /* key hints */
    SW_STYLE_ALL
};

/* Smallest terminal the UI draws in; below it, a message. */
#define SW_MIN_COLS 60
#define SW_MIN_ROWS 16

typedef struct sw_screen {
    int cols, rows;
    uint32_t *cp;
    unsigned char *style;
    unsigned char *fade;
} sw_screen;

int sw_screen_init(sw_screen *s, int cols, int rows, char *err, size_t errlen);
void sw_screen_free(sw_screen *s);
void sw_screen_clear(sw_screen *s);
/* Write UTF-8 text at (row, col), clipped to width cells and the screen;
 * invalid bytes show as '?'. Returns the cells written. */
int sw_screen_text(sw_screen *s, int row, int col, int width, int style, const char *text);
/* Fill a rectangle with spaces of a style (overlay backgrounds). */
void sw_screen_fill(sw_screen *s, int row, int col, int height, int width, int style);
/* The screen as UTF-8 text, trailing spaces trimmed, '\n' after every row;
 * returns the length, or 0 (buf "") when it does not fit in len. */
size_t sw_screen_to_text(const sw_screen *s, char *buf, size_t len);

/* What the picture keeps between frames: canvas, trails, followed view. */
typedef struct sw_frame {
    sw_canvas canvas;
    sw_canvas plot;           /* the graph pane */
    sw_trails trails[SW_APP_SIMS];
    sw_view view;
    const sw_scene *view_scene;
    int have_trails;
} sw_frame;

int sw_frame_init(sw_frame *f, char *err, size_t errlen);
void sw_frame_free(sw_frame *f);
/* Forget the followed view and the trails (after a reset or a new scene). */
void sw_frame_forget(sw_frame *f);
/* Compose the app (and an optional side pane) onto the screen. */
void sw_frame_compose(sw_frame *f, sw_app *a, const sw_side *side, sw_screen *scr);
/* Push the current positions into the trails (once per frame). */
void sw_frame_push_trails(sw_frame *f, sw_app *a);

#endif
