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
#include "render/phase.h"
#include "render/region.h"
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

/* The cell after a wide character (CJK, emoji: two cells on a terminal):
 * covered by it, painted as nothing. */
#define SW_SCREEN_WIDE_TAIL 0u

typedef struct sw_screen {
    int cols, rows;
    uint32_t *cp;
    unsigned char *style;
    unsigned char *fade;
    int clipped;    /* texts cut at their width or the screen's edge since the last clear */
} sw_screen;

int sw_screen_init(sw_screen *s, int cols, int rows, char *err, size_t errlen);
void sw_screen_free(sw_screen *s);
void sw_screen_clear(sw_screen *s);
/* Write UTF-8 text at (row, col), clipped to width cells and the screen
 * (a clip counts in s->clipped: the composer fits and wraps every text, so
 * a test of every screen asks for none); invalid bytes show as '?'. A wide
 * character takes two cells (the second SW_SCREEN_WIDE_TAIL) and is left
 * out whole when only one is left; combining marks are dropped. Returns the
 * cells written. */
int sw_screen_text(sw_screen *s, int row, int col, int width, int style, const char *text);
/* Fill a rectangle with spaces of a style (overlay backgrounds). */
void sw_screen_fill(sw_screen *s, int row, int col, int height, int width, int style);
/* The screen as UTF-8 text, trailing spaces trimmed, '\n' after every row;
 * returns the length, or 0 (buf "") when it does not fit in len. */
size_t sw_screen_to_text(const sw_screen *s, char *buf, size_t len);

/* Copy a canvas onto the screen at (row0, col0), clipped to the screen. */
void sw_screen_blit(sw_screen *scr, const sw_canvas *c, int row0, int col0);

/* What the picture keeps between frames: canvases, trails, the camera, the
 * phase and region views' caches. */
typedef struct sw_frame {
    sw_canvas canvas;         /* the scene, the phase or the region view (and lane 1) */
    sw_canvas lanes[SW_APP_SIMS - 1]; /* compare side by side: lanes 2 and 3 */
    sw_canvas plot;           /* the graph pane */
    sw_trails trails[SW_APP_SIMS];
    sw_view view;             /* the camera's view now */
    const sw_scene *view_scene;
    double view_p[SW_MAX_PARAMS], view_zoom;
    int view_follow;
    int have_trails;
    int unicode;              /* the terminal shows Braille and arrows (the TUI sets it) */
    unsigned char *keep;      /* which particles are alive (scratch) */
    int keep_cap;
    unsigned char *graph_own; /* which runs take each cell of the graph (scratch) */
    size_t graph_own_cap;
    sw_phase_view phase;
    sw_region region;
} sw_frame;

int sw_frame_init(sw_frame *f, char *err, size_t errlen);
void sw_frame_free(sw_frame *f);
/* Forget the followed view and the trails (after a reset or a new scene). */
void sw_frame_forget(sw_frame *f);
/* Compose the app (and an optional side pane) onto the screen. The help
 * screen is paged: a->help counts pages, and is set back to 0 past the last. */
void sw_frame_compose(sw_frame *f, sw_app *a, const sw_side *side, sw_screen *scr);
/* Push the current positions into the trails (once per frame). */
void sw_frame_push_trails(sw_frame *f, sw_app *a);

/* (overlay.c) The pieces the composer places, each in the rectangle given. */
void sw_draw_graph(sw_frame *f, sw_app *a, sw_screen *scr, int row, int col, int height, int width);
void sw_draw_help(sw_app *a, sw_screen *scr, int row, int col, int height, int width, int in_lesson);
/* (overlay.c) How many pages the help screen takes in a box of that size (0: none fits). */
int sw_help_pages(int height, int width, int in_lesson);
void sw_draw_panel(sw_app *a, sw_screen *scr, int row, int col, int height, int width);
void sw_draw_workprec(sw_app *a, sw_screen *scr, int row, int col, int height, int width);
/* (overlay.c) Write text wrapped to width on rows row.., at most max rows;
 * returns the rows used. */
int sw_screen_wrapped(sw_screen *scr, int row, int col, int width, int max, int style, const char *text);

#endif
