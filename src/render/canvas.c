/* The canvas rasteriser: world coordinates to character cells (glyphs,
 * density ramp, Braille dots), pure C. Invariant: no double becomes an int
 * before it is known finite and inside the grid, and nothing allocates
 * between init/resize and free. The mapping is specified in canvas.h. */
#include "render/canvas.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stepwise/base.h"
#include "util/utf8.h"

/* Braille bit of dot (row r, column c) within a cell: dots 1,2,3,7 down the
 * left column, 4,5,6,8 down the right (Unicode's Braille Patterns block). */
static const unsigned char braille_bit[4][2] = {
    { 0x01, 0x08 }, { 0x02, 0x10 }, { 0x04, 0x20 }, { 0x40, 0x80 }
};

/* The grid a draw runs on: cells in ASCII mode, dots in Braille mode. */
typedef struct grid {
    int w, h;          /* grid size */
    double hc, hr;     /* grid coordinates of the view's centre */
    double kx, ky;     /* grid units per world unit */
    int dots;          /* 1: a grid point is a Braille dot */
} grid;

static grid grid_of(const sw_canvas *c, int dots)
{
    double k = c->inv_scale;
    grid g;
    g.dots = dots;
    if (dots) {
        g.w = 2 * c->cols, g.h = 4 * c->rows;
        g.hc = c->cols, g.hr = 2.0 * c->rows;
        g.kx = 2.0 * k, g.ky = 2.0 * k;
    } else {
        g.w = c->cols, g.h = c->rows;
        g.hc = c->cols / 2.0, g.hr = c->rows / 2.0;
        g.kx = k, g.ky = k / 2.0;
    }
    return g;
}

/* Grid point of (x, y), or 0 when off the grid. The comparisons fail for NaN
 * and infinities, so the int conversions only ever see [0, w) and [0, h). */
static int to_grid(const grid *g, const sw_canvas *c, double x, double y, int *gc, int *gr)
{
    double u = g->hc + (x - c->cx) * g->kx;
    double w = g->hr - (y - c->cy) * g->ky;
    if (!(u >= 0.0 && u < g->w && w >= 0.0 && w < g->h))
        return 0;
    *gc = (int)u;
    *gr = (int)w;
    return 1;
}

static void put_glyph(sw_canvas *c, int col, int row, uint32_t glyph, int style, int fade)
{
    size_t i = (size_t)row * (size_t)c->cols + (size_t)col;
    c->glyph[i] = glyph;
    c->dots[i] = 0;
    c->style[i] = (unsigned char)style;
    c->fade[i] = (unsigned char)fade;
}

static void put_dot(sw_canvas *c, int dc, int dr, int style, int fade)
{
    size_t i = (size_t)(dr / 4) * (size_t)c->cols + (size_t)(dc / 2);
    c->glyph[i] = 0;
    c->dots[i] |= braille_bit[dr % 4][dc % 2];
    c->style[i] = (unsigned char)style;
    c->fade[i] = (unsigned char)fade;
}

/* A grid point: a dot on a dot grid, a glyph on a cell grid. */
static void plot(sw_canvas *c, const grid *g, int gc, int gr, uint32_t glyph, int style, int fade)
{
    if (g->dots)
        put_dot(c, gc, gr, style, fade);
    else
        put_glyph(c, gc, gr, glyph, style, fade);
}

static void clear_cells(sw_canvas *c)
{
    size_t n = (size_t)c->cols * (size_t)c->rows;
    memset(c->glyph, 0, n * sizeof *c->glyph);
    memset(c->dots, 0, n);
    memset(c->style, 0, n);
    memset(c->fade, 0, n);
}

/* One block holds every per-cell array; NULL when out of memory. */
static int alloc_cells(sw_canvas *c, int cols, int rows)
{
    size_t n = (size_t)cols * (size_t)rows;
    uint32_t *block = malloc(n * (2 * sizeof(uint32_t) + 3));
    if (!block)
        return SW_ENOMEM;
    c->glyph = block;
    c->count = block + n;
    c->dots = (unsigned char *)(block + 2 * n);
    c->style = c->dots + n;
    c->fade = c->style + n;
    c->cols = cols;
    c->rows = rows;
    return SW_OK;
}

static int check_size(int cols, int rows, char *err, size_t errlen)
{
    if (cols < 1 || rows < 1 || cols > SW_CANVAS_MAX_SIDE || rows > SW_CANVAS_MAX_SIDE ||
        (long long)cols * rows > SW_CANVAS_MAX_CELLS) {
        snprintf(err, errlen, "canvas size %dx%d: columns and rows must be 1..%d, at most %d cells",
                 cols, rows, SW_CANVAS_MAX_SIDE, SW_CANVAS_MAX_CELLS);
        return SW_EINVAL;
    }
    return SW_OK;
}

/* Scale and centre for view v at the current size; -1 when v is unusable.
 * s = max(xspan / cols, yspan / (2 rows)); the visible rectangle must be finite. */
static int fit(sw_canvas *c, const sw_view *v)
{
    double sx = v->xmax - v->xmin, sy = v->ymax - v->ymin;
    if (!(isfinite(v->xmin) && isfinite(v->xmax) && isfinite(v->ymin) && isfinite(v->ymax)))
        return -1;
    if (!(sx > 0 && sy > 0 && isfinite(sx) && isfinite(sy)))
        return -1;
    double s = fmax(sx / c->cols, sy / (2.0 * c->rows));
    double cx = v->xmin + sx / 2.0, cy = v->ymin + sy / 2.0;
    double hw = s * c->cols / 2.0, hh = s * c->rows;
    if (!(s > 0 && isfinite(1.0 / s) && isfinite(cx - hw) && isfinite(cx + hw) &&
          isfinite(cy - hh) && isfinite(cy + hh)))
        return -1;
    c->view = *v;
    c->scale = s;
    c->inv_scale = 1.0 / s;
    c->cx = cx;
    c->cy = cy;
    return 0;
}

int sw_canvas_init(sw_canvas *c, int cols, int rows, char *err, size_t errlen)
{
    memset(c, 0, sizeof *c);
    int rc = check_size(cols, rows, err, errlen);
    if (rc != SW_OK)
        return rc;
    if (alloc_cells(c, cols, rows) != SW_OK) {
        snprintf(err, errlen, "out of memory for a %dx%d canvas", cols, rows);
        return SW_ENOMEM;
    }
    c->mode = SW_CANVAS_ASCII;
    sw_view def = { -1.0, 1.0, -1.0, 1.0 };
    fit(c, &def);
    clear_cells(c);
    return SW_OK;
}

int sw_canvas_resize(sw_canvas *c, int cols, int rows, char *err, size_t errlen)
{
    int rc = check_size(cols, rows, err, errlen);
    if (rc != SW_OK)
        return rc;
    sw_canvas old = *c;
    if (alloc_cells(c, cols, rows) != SW_OK) {
        *c = old;
        snprintf(err, errlen, "out of memory for a %dx%d canvas", cols, rows);
        return SW_ENOMEM;
    }
    free(old.glyph);
    if (fit(c, &old.view) != 0) {
        /* a view at the edge of double range may not fit the new shape */
        sw_view def = { -1.0, 1.0, -1.0, 1.0 };
        fit(c, &def);
    }
    clear_cells(c);
    return SW_OK;
}

void sw_canvas_free(sw_canvas *c)
{
    free(c->glyph);
    c->glyph = NULL;
    c->count = NULL;
    c->dots = c->style = c->fade = NULL;
    c->cols = c->rows = 0;
}

void sw_canvas_set_mode(sw_canvas *c, sw_canvas_mode mode)
{
    c->mode = mode == SW_CANVAS_BRAILLE ? SW_CANVAS_BRAILLE : SW_CANVAS_ASCII;
    clear_cells(c);
}

int sw_canvas_set_view(sw_canvas *c, const sw_view *v, char *err, size_t errlen)
{
    sw_canvas trial = *c;
    if (fit(&trial, v) != 0) {
        snprintf(err, errlen, "view x %g..%g, y %g..%g: bounds must be finite with "
                 "xmin < xmax and ymin < ymax", v->xmin, v->xmax, v->ymin, v->ymax);
        return SW_EINVAL;
    }
    *c = trial;
    return SW_OK;
}

sw_view sw_canvas_visible(const sw_canvas *c)
{
    double hw = c->scale * c->cols / 2.0, hh = c->scale * c->rows;
    return (sw_view){ c->cx - hw, c->cx + hw, c->cy - hh, c->cy + hh };
}

void sw_canvas_clear(sw_canvas *c)
{
    clear_cells(c);
    c->clipped = 0;
}

int sw_canvas_world_to_cell(const sw_canvas *c, double x, double y, int *col, int *row)
{
    grid g = grid_of(c, 0);
    return to_grid(&g, c, x, y, col, row);
}

/* A point with a fade level: 0 full, 1 newer trail, 2 older trail. */
static void sw_canvas_point_faded(sw_canvas *c, double x, double y, uint32_t glyph, int style, int fade)
{
    grid g = grid_of(c, c->mode == SW_CANVAS_BRAILLE);
    int gc, gr;
    if (to_grid(&g, c, x, y, &gc, &gr))
        plot(c, &g, gc, gr, glyph ? glyph : SW_GLYPH_MAIN, style, fade);
}

void sw_canvas_point(sw_canvas *c, double x, double y, uint32_t glyph, int style)
{
    sw_canvas_point_faded(c, x, y, glyph, style, 0);
}

void sw_canvas_mark(sw_canvas *c, double x, double y, uint32_t glyph, int style)
{
    grid g = grid_of(c, 0);
    int col, row;
    if (to_grid(&g, c, x, y, &col, &row))
        put_glyph(c, col, row, glyph ? glyph : SW_GLYPH_MAIN, style, 0);
}

void sw_canvas_put(sw_canvas *c, int col, int row, uint32_t glyph, int style)
{
    if (col >= 0 && col < c->cols && row >= 0 && row < c->rows)
        put_glyph(c, col, row, glyph, style, 0);
}

void sw_canvas_dot(sw_canvas *c, int dc, int dr, int style, int fade)
{
    if (dc >= 0 && dc < 2 * c->cols && dr >= 0 && dr < 4 * c->rows)
        put_dot(c, dc, dr, style, fade);
}

int sw_canvas_text(sw_canvas *c, int col, int row, const char *text, int style)
{
    const unsigned char *p = (const unsigned char *)text;
    int n = 0, cut = row < 0 || row >= c->rows;
    while (*p) {
        uint32_t cp = sw_utf8_next(&p);
        cut |= col + n < 0 || col + n >= c->cols;
        sw_canvas_put(c, col + n++, row, cp < 0x20 ? ' ' : cp, style);
    }
    c->clipped += cut;
    return n;
}

enum { OUT_LEFT = 1, OUT_RIGHT = 2, OUT_BELOW = 4, OUT_ABOVE = 8 };

static int outcode(double x, double y, const sw_view *r)
{
    int code = 0;
    if (x < r->xmin)
        code |= OUT_LEFT;
    else if (x > r->xmax)
        code |= OUT_RIGHT;
    if (y < r->ymin)
        code |= OUT_BELOW;
    else if (y > r->ymax)
        code |= OUT_ABOVE;
    return code;
}

/* Cohen–Sutherland on finite coordinates no larger than DBL_MAX/4. A crossing
 * is interpolated from the other end, which lies inside the edge crossed:
 * the fraction is in [0, 1] with a non-zero denominator (no NaN, no
 * overflow), and when that end is near the canvas the crossing keeps its
 * precision. Returns 0 when nothing of the segment is inside r. */
static int clip_segment(double *x0, double *y0, double *x1, double *y1, const sw_view *r)
{
    int c0 = outcode(*x0, *y0, r), c1 = outcode(*x1, *y1, r);
    /* two clips per end suffice; the cap only stops rounding ping-pong,
     * after which the ends are on the boundary to rounding (clamped later) */
    for (int iter = 0; iter < 8 && (c0 | c1); iter++) {
        if (c0 & c1)
            return 0;
        int out = c0 ? c0 : c1;
        double *px = c0 ? x0 : x1, *py = c0 ? y0 : y1;
        double qx = c0 ? *x1 : *x0, qy = c0 ? *y1 : *y0, x, y;
        if (out & (OUT_LEFT | OUT_RIGHT)) {
            x = out & OUT_LEFT ? r->xmin : r->xmax;
            y = qy + (*py - qy) * ((x - qx) / (*px - qx));
        } else {
            y = out & OUT_BELOW ? r->ymin : r->ymax;
            x = qx + (*px - qx) * ((y - qy) / (*py - qy));
        }
        *px = x;
        *py = y;
        if (c0)
            c0 = outcode(x, y, r);
        else
            c1 = outcode(x, y, r);
    }
    return !(c0 & c1);
}

/* Grid coordinate of a clipped end: clipping leaves it inside the grid up to
 * rounding, which the clamp absorbs (the negated tests also catch NaN). */
static int clamp_cell(double u, int n)
{
    if (!(u >= 0.0))
        return 0;
    if (!(u <= n - 1.0))
        return n - 1;
    return (int)u;
}

void sw_canvas_line(sw_canvas *c, double x0, double y0, double x1, double y1,
                    uint32_t glyph, int style)
{
    if (!(isfinite(x0) && isfinite(y0) && isfinite(x1) && isfinite(y1)))
        return;
    /* Work at a quarter scale: |coordinates| <= DBL_MAX/4, so no difference
     * of two of them overflows. */
    double ax = 0.25 * x0, ay = 0.25 * y0, bx = 0.25 * x1, by = 0.25 * y1;
    double dx = bx - ax, dy = by - ay;
    if (!glyph) {
        /* on-screen direction: the aspect correction makes world angles true */
        if (fabs(dy) <= 0.4 * fabs(dx))
            glyph = '-';
        else if (fabs(dx) <= 0.4 * fabs(dy))
            glyph = '|';
        else
            glyph = (dx > 0) == (dy > 0) ? '/' : '\\';
    }
    grid g = grid_of(c, c->mode == SW_CANVAS_BRAILLE);
    /* A segment inside one grid point (a spring of a long chain is shorter
     * than a cell): that point, as the general path below would plot it. */
    double u0 = g.hc + (x0 - c->cx) * g.kx, w0 = g.hr - (y0 - c->cy) * g.ky;
    double u1 = g.hc + (x1 - c->cx) * g.kx, w1 = g.hr - (y1 - c->cy) * g.ky;
    /* (both ends checked in range before either is made an int) */
    if (u0 >= 0.0 && u0 < g.w && w0 >= 0.0 && w0 < g.h && u1 >= 0.0 && u1 < g.w && w1 >= 0.0 && w1 < g.h &&
        (int)u0 == (int)u1 && (int)w0 == (int)w1) {
        plot(c, &g, (int)u0, (int)w0, glyph, style, 0);
        return;
    }
    sw_view vis = sw_canvas_visible(c);
    sw_view quarter = { 0.25 * vis.xmin, 0.25 * vis.xmax, 0.25 * vis.ymin, 0.25 * vis.ymax };
    if (!clip_segment(&ax, &ay, &bx, &by, &quarter))
        return;
    int c0 = clamp_cell(g.hc + (4.0 * ax - c->cx) * g.kx, g.w);
    int r0 = clamp_cell(g.hr - (4.0 * ay - c->cy) * g.ky, g.h);
    int c1 = clamp_cell(g.hc + (4.0 * bx - c->cx) * g.kx, g.w);
    int r1 = clamp_cell(g.hr - (4.0 * by - c->cy) * g.ky, g.h);
    /* Bresenham over all octants (error term e = dxi + dyi, dyi <= 0). */
    int dxi = abs(c1 - c0), sxi = c0 < c1 ? 1 : -1;
    int dyi = -abs(r1 - r0), syi = r0 < r1 ? 1 : -1;
    int e = dxi + dyi;
    for (;;) {
        plot(c, &g, c0, r0, glyph, style, 0);
        if (c0 == c1 && r0 == r1)
            break;
        int e2 = 2 * e;
        if (e2 >= dyi) {
            e += dyi;
            c0 += sxi;
        }
        if (e2 <= dxi) {
            e += dxi;
            r0 += syi;
        }
    }
}

static uint32_t ramp_glyph(uint32_t count)
{
    int level = 1;
    while (count >= 2 && level < SW_DENSITY_LEVELS - 1) {
        count >>= 1;
        level++;
    }
    return (unsigned char)SW_DENSITY_RAMP[level];
}

void sw_canvas_layer(sw_canvas *c, const double *xy, int n, sw_canvas_keep_fn *keep, const void *ctx,
                     int dots, uint32_t glyph, int style, int fade)
{
    grid g = grid_of(c, dots);
    if (!glyph)
        glyph = SW_GLYPH_MAIN;
    if (!keep && !dots) { /* the common case, with nothing but the mapping and the store in the loop */
        double hc = g.hc, hr = g.hr, kx = g.kx, ky = g.ky, cx = c->cx, cy = c->cy, w = g.w, h = g.h;
        for (int i = 0; i < n; i++) {
            double u = hc + (xy[2 * i] - cx) * kx, v = hr - (xy[2 * i + 1] - cy) * ky;
            if (u >= 0.0 && u < w && v >= 0.0 && v < h)
                put_glyph(c, (int)u, (int)v, glyph, style, fade);
        }
        return;
    }
    for (int i = 0; i < n; i++) {
        int gc, gr;
        if (keep && !keep(ctx, i))
            continue;
        if (to_grid(&g, c, xy[2 * i], xy[2 * i + 1], &gc, &gr))
            plot(c, &g, gc, gr, glyph, style, fade);
    }
}

/* Count the points that keep accepts, then write the ramp. */
void sw_canvas_density_where(sw_canvas *c, const double *xy, int n, sw_canvas_keep_fn *keep,
                             const void *ctx, int style)
{
    size_t cells = (size_t)c->cols * (size_t)c->rows;
    memset(c->count, 0, cells * sizeof *c->count);
    grid g = grid_of(c, 0);
    for (int i = 0; i < n; i++) {
        int col, row;
        if (keep && !keep(ctx, i))
            continue;
        if (to_grid(&g, c, xy[2 * i], xy[2 * i + 1], &col, &row))
            c->count[(size_t)row * (size_t)c->cols + (size_t)col]++;
    }
    for (int row = 0; row < c->rows; row++)
        for (int col = 0; col < c->cols; col++) {
            uint32_t k = c->count[(size_t)row * (size_t)c->cols + (size_t)col];
            if (k)
                put_glyph(c, col, row, ramp_glyph(k), style, 0);
        }
}

void sw_canvas_density(sw_canvas *c, const double *xy, int n, int style)
{
    sw_canvas_density_where(c, xy, n, NULL, NULL, style);
}

uint32_t sw_canvas_codepoint(const sw_canvas *c, int col, int row)
{
    if (col < 0 || row < 0 || col >= c->cols || row >= c->rows)
        return ' ';
    size_t i = (size_t)row * (size_t)c->cols + (size_t)col;
    if (c->glyph[i])
        return c->glyph[i];
    return c->dots[i] ? 0x2800u + c->dots[i] : (uint32_t)' ';
}

int sw_canvas_style(const sw_canvas *c, int col, int row)
{
    if (col < 0 || row < 0 || col >= c->cols || row >= c->rows)
        return 0;
    return c->style[(size_t)row * (size_t)c->cols + (size_t)col];
}

int sw_canvas_fade(const sw_canvas *c, int col, int row)
{
    if (col < 0 || row < 0 || col >= c->cols || row >= c->rows)
        return 0;
    return c->fade[(size_t)row * (size_t)c->cols + (size_t)col];
}

size_t sw_canvas_text_size(const sw_canvas *c)
{
    return (size_t)c->rows * ((size_t)c->cols * 4 + 1) + 1;
}

/* Write the text into out when out is not NULL; return its length either way. */
static size_t emit_text(const sw_canvas *c, char *out)
{
    size_t len = 0;
    for (int row = 0; row < c->rows; row++) {
        int end = c->cols;
        while (end > 0 && sw_canvas_codepoint(c, end - 1, row) == ' ')
            end--;
        for (int col = 0; col < end; col++) {
            char b[4];
            int k = sw_utf8_encode(sw_canvas_codepoint(c, col, row), b);
            if (out)
                memcpy(out + len, b, (size_t)k);
            len += (size_t)k;
        }
        if (out)
            out[len] = '\n';
        len++;
    }
    return len;
}

size_t sw_canvas_to_text(const sw_canvas *c, char *buf, size_t len)
{
    size_t need = emit_text(c, NULL);
    if (buf && len > need) {
        emit_text(c, buf);
        buf[need] = '\0';
    } else if (buf && len > 0) {
        buf[0] = '\0';
    }
    return need;
}
