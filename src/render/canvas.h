/* The canvas: a pure-C rasteriser from world coordinates to a grid of
 * character cells (ASCII glyphs, a density ramp, or Braille dots). It knows
 * no ncurses: the TUI paints its cells, `play --ascii` prints them as text,
 * and the unit tests compare them with golden frames.
 *
 * Mapping (the contract the golden frames are worked out from)
 * ------------------------------------------------------------
 * A cell is about twice as tall as it is wide, so one cell spans s world
 * units of x and 2·s units of y. For a view (xmin, xmax, ymin, ymax) on a
 * canvas of cols × rows cells the scale fits the whole view and centres it:
 *     s  = max((xmax - xmin) / cols, (ymax - ymin) / (2·rows)),  k = 1 / s
 *     cx = xmin + (xmax - xmin) / 2,  cy = ymin + (ymax - ymin) / 2
 *     u  = cols / 2 + (x - cx)·k          (columns, growing rightwards)
 *     w  = rows / 2 - (y - cy)·k / 2      (rows, growing downwards: y is up)
 *     col = floor(u), row = floor(w); drawn only when 0 <= u < cols and
 *     0 <= w < rows (NaN, ±inf and overflowing values fail the test).
 * So the view's centre falls on the corner shared by cells (cols/2, rows/2)
 * and its neighbours, and maps to cell (floor(cols/2), floor(rows/2)). The
 * canvas shows the world rectangle cx ± s·cols/2, cy ± s·rows (sw_canvas_visible).
 * In Braille mode the same formulas run on a dot grid of 2·cols × 4·rows:
 * u_dot = cols + (x - cx)·2k, w_dot = 2·rows - (y - cy)·2k; dot (du, dw) lies
 * in cell (du/2, dw/4), so dots are square (s/2 world units each way).
 *
 * Braille cell: U+2800 + bits, standard dot numbering: in a cell, the left
 * column top to bottom is dots 1, 2, 3, 7 (bits 0x01, 0x02, 0x04, 0x40), the
 * right column dots 4, 5, 6, 8 (bits 0x08, 0x10, 0x20, 0x80).
 *
 * Cells and overwriting: each cell holds a glyph (a code point, 0 = none),
 * Braille dots, a style index and a fade level. A later draw overwrites an
 * earlier one in the same cell: writing a glyph clears the cell's dots and
 * writing a dot clears the cell's glyph (dots accumulate with dots). So draw
 * back to front, in this order: trails (SW_STYLE_TRAIL), ghost (exact
 * solution), compare sims, the main sim, warnings. sw_canvas_draw_system
 * itself draws walls, central body, springs, anchors, then particles.
 *
 * (Scene drawing is render/draw.h, the following view render/camera.h,
 * trails render/trails.h.)
 *
 * Lines are clipped to the visible rectangle in double precision (Cohen–
 * Sutherland on world coordinates scaled by 1/4, so no difference can
 * overflow) before anything becomes an int; the clipped end cells are joined
 * by Bresenham's algorithm. Each crossing is interpolated from the other end,
 * so it is exact to rounding when that end is on or near the canvas; a line
 * between two astronomically distant points (a blown-up state) is drawn
 * safely but only approximately. Nothing here allocates after init/resize. */
#ifndef SW_RENDER_CANVAS_H
#define SW_RENDER_CANVAS_H

#include <stddef.h>
#include <stdint.h>

#include "stepwise/scene.h"

/* Style indices: the front end maps each to a colour or attribute. */
enum {
    SW_STYLE_MAIN = 0,      /* the main integrator's particles */
    SW_STYLE_COMPARE1 = 1,  /* first compare integrator */
    SW_STYLE_COMPARE2 = 2,  /* second compare integrator */
    SW_STYLE_GHOST = 3,     /* the exact solution */
    SW_STYLE_SPRING = 4,    /* springs of the main sim */
    SW_STYLE_WALL = 5,      /* walls, ground, anchors, central body */
    SW_STYLE_TRAIL = 6,     /* fading trails */
    SW_STYLE_WARN = 7,      /* warnings */
    SW_STYLE_COUNT = 8
};

/* Default glyphs (code points). */
#define SW_GLYPH_MAIN     'o'
#define SW_GLYPH_COMPARE1 'x'
#define SW_GLYPH_COMPARE2 '+'
#define SW_GLYPH_GHOST    '\''
#define SW_GLYPH_ANCHOR   '#'
#define SW_GLYPH_SUN      'O'
#define SW_GLYPH_FLOOR    '='   /* floor and ceiling */
#define SW_GLYPH_SIDE     '|'   /* left and right walls */
#define SW_GLYPH_GHOST_SPRING '.' /* springs of ghost and compare sims */
#define SW_GLYPH_TRAIL_NEW ':'  /* trail, newer half of the buffer (fade 1) */
#define SW_GLYPH_TRAIL_OLD '.'  /* trail, older half of the buffer (fade 2) */
#define SW_GLYPH_HOT      '@'   /* a scene drawn by temperature: the hottest third */
#define SW_GLYPH_COOL     ','   /* ... and the coolest (the middle third is SW_GLYPH_MAIN) */

/* The density ramp: count 0 is ' ' (cell left as it was); a cell holding
 * c >= 1 points gets SW_DENSITY_RAMP[min(9, 1 + floor(log2 c))], i.e.
 * 1 '.', 2-3 ':', 4-7 '-', 8-15 '=', 16-31 '+', 32-63 '*', 64-127 '#',
 * 128-255 '%', 256 and more '@'. */
#define SW_DENSITY_RAMP " .:-=+*#%@"
#define SW_DENSITY_LEVELS 10

typedef enum sw_canvas_mode {
    SW_CANVAS_ASCII = 0,   /* one glyph per cell */
    SW_CANVAS_BRAILLE = 1  /* points and lines as 2×4 dots per cell */
} sw_canvas_mode;

/* Largest canvas accepted, per side and in cells. */
#define SW_CANVAS_MAX_SIDE 10000
#define SW_CANVAS_MAX_CELLS (1 << 24)

typedef struct sw_canvas {
    int cols, rows;
    sw_canvas_mode mode;
    sw_view view;          /* as last set; default (-1, 1, -1, 1) */
    double scale;          /* s: world units per column */
    double inv_scale;      /* 1/s, worked out once per view (not per point) */
    double cx, cy;         /* the view's centre */
    uint32_t *glyph;       /* cols·rows code points, 0 = none; row-major from the top */
    uint32_t *count;       /* density counts, scratch for one density pass */
    unsigned char *dots;   /* Braille bits per cell */
    unsigned char *style;  /* style index per cell */
    unsigned char *fade;   /* 0 = full strength, 1 = newer trail, 2 = older trail */
    int clipped;           /* texts (sw_canvas_text) cut at the canvas's edge since the last clear */
} sw_canvas;

/* Allocate a cols × rows canvas (1..SW_CANVAS_MAX_SIDE each, at most
 * SW_CANVAS_MAX_CELLS cells), blank, ASCII mode, view (-1, 1, -1, 1);
 * 0, SW_EINVAL or SW_ENOMEM with err filled (c is then empty but freeable). */
int sw_canvas_init(sw_canvas *c, int cols, int rows, char *err, size_t errlen);
/* Change the size (terminal resize only): reallocates, keeps mode and view,
 * blanks the canvas; on failure the canvas keeps its old size and cells. */
int sw_canvas_resize(sw_canvas *c, int cols, int rows, char *err, size_t errlen);
/* Free the cells; c may be zeroed or already freed. */
void sw_canvas_free(sw_canvas *c);
/* Set the mode and blank the canvas. */
void sw_canvas_set_mode(sw_canvas *c, sw_canvas_mode mode);
/* Fit and centre view v (finite, xmin < xmax, ymin < ymax, spans finite);
 * 0, or SW_EINVAL with err filled and the old view kept. */
int sw_canvas_set_view(sw_canvas *c, const sw_view *v, char *err, size_t errlen);
/* The world rectangle the whole canvas shows (wider or taller than the view). */
sw_view sw_canvas_visible(const sw_canvas *c);
/* Blank every cell: no glyph, no dots, style 0, fade 0. */
void sw_canvas_clear(sw_canvas *c);

/* Cell (col, row) of world point (x, y) by the mapping above; 1 when on the
 * canvas, else 0 and *col, *row untouched. Works in cells in both modes. */
int sw_canvas_world_to_cell(const sw_canvas *c, double x, double y, int *col, int *row);

/* A point: in ASCII mode the cell gets glyph (0: 'o'); in Braille mode its
 * dot is set (glyph unused). Off-canvas or non-finite points are skipped. */
void sw_canvas_point(sw_canvas *c, double x, double y, uint32_t glyph, int style);
/* A marker: the cell gets glyph (0: 'o') in either mode (anchors, sun, particles). */
void sw_canvas_mark(sw_canvas *c, double x, double y, uint32_t glyph, int style);
/* A line from (x0, y0) to (x1, y1), clipped; glyph 0 picks one by the on-screen
 * direction: '-' when |dy| <= 0.4|dx|, '|' when |dx| <= 0.4|dy|, else '/' when
 * dx, dy have the same sign and '\' otherwise. Braille mode sets dots instead.
 * A line with a non-finite endpoint draws nothing. */
void sw_canvas_line(sw_canvas *c, double x0, double y0, double x1, double y1,
                    uint32_t glyph, int style);
/* Density pass over n points xy[2i], xy[2i+1]: count points per cell, then
 * write the ramp glyph (see SW_DENSITY_RAMP) into each cell with count >= 1,
 * in either mode; empty cells are left as they were. */
void sw_canvas_density(sw_canvas *c, const double *xy, int n, int style);
/* Whether point i is drawn (ctx is the caller's). */
typedef int sw_canvas_keep_fn(const void *ctx, int i);
/* The same over the points keep accepts (keep NULL: all). */
void sw_canvas_density_where(sw_canvas *c, const double *xy, int n, sw_canvas_keep_fn *keep,
                             const void *ctx, int style);
/* A layer of n points xy[2i], xy[2i+1] that keep accepts (NULL: all),
 * each drawn as sw_canvas_point_faded (dots = 1: its Braille dot) or
 * sw_canvas_mark (dots = 0: glyph in its cell) would draw it with that
 * fade, in order, with the mapping worked out once: a point's cost, not a
 * call's. */
void sw_canvas_layer(sw_canvas *c, const double *xy, int n, sw_canvas_keep_fn *keep, const void *ctx,
                     int dots, uint32_t glyph, int style, int fade);

/* Cell-level drawing (axes, labels, the region's shading): a glyph into
 * cell (col, row); a Braille dot (dc, dr) of the 2·cols × 4·rows dot grid;
 * text from (col, row) rightwards. Cells off the canvas are skipped;
 * sw_canvas_text returns the characters in text. */
void sw_canvas_put(sw_canvas *c, int col, int row, uint32_t glyph, int style);
void sw_canvas_dot(sw_canvas *c, int dc, int dr, int style, int fade);
int sw_canvas_text(sw_canvas *c, int col, int row, const char *text, int style);

/* Code point shown in (col, row): the glyph, else U+2800 + dots when any
 * dot is set, else ' ' (also for cells off the canvas). */
uint32_t sw_canvas_codepoint(const sw_canvas *c, int col, int row);
/* Style index of (col, row); 0 for blank or off-canvas cells. */
int sw_canvas_style(const sw_canvas *c, int col, int row);
/* Fade level of (col, row): 0 full, 1 newer trail, 2 older trail. */
int sw_canvas_fade(const sw_canvas *c, int col, int row);
/* Bytes sw_canvas_to_text may need, NUL included. */
size_t sw_canvas_text_size(const sw_canvas *c);
/* The canvas as text: each row as UTF-8 with trailing spaces removed, then
 * '\n' (the last row too). Returns the text's length without the NUL; the
 * text is written only when it fits (len > that length), else buf gets ""
 * (when len > 0) and nothing else. */
size_t sw_canvas_to_text(const sw_canvas *c, char *buf, size_t len);

#endif
