/* The screen grid (cells, text, blits) and what a frame keeps between
 * draws. Pure C; the composer (compose.c) lays the screen out the same way
 * in the terminal, in `--ascii` frames and in tests. */
#include "render/screen.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "measure/bench.h"
#include "stepwise/base.h"
#include "util/utf8.h"

int sw_screen_init(sw_screen *s, int cols, int rows, char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    if (cols < 1 || rows < 1 || cols > SW_CANVAS_MAX_SIDE || rows > SW_CANVAS_MAX_SIDE) {
        snprintf(err, errlen, "screen size %dx%d is outside 1..%d per side", cols, rows, SW_CANVAS_MAX_SIDE);
        return SW_EINVAL;
    }
    size_t n = (size_t)cols * (size_t)rows;
    s->cp = malloc(n * sizeof *s->cp);
    s->style = malloc(n);
    s->fade = malloc(n);
    if (!s->cp || !s->style || !s->fade) {
        sw_screen_free(s);
        snprintf(err, errlen, "out of memory for a %dx%d screen", cols, rows);
        return SW_ENOMEM;
    }
    s->cols = cols;
    s->rows = rows;
    sw_screen_clear(s);
    return SW_OK;
}

void sw_screen_free(sw_screen *s)
{
    free(s->cp);
    free(s->style);
    free(s->fade);
    memset(s, 0, sizeof *s);
}

void sw_screen_clear(sw_screen *s)
{
    size_t n = (size_t)s->cols * (size_t)s->rows;
    for (size_t i = 0; i < n; i++)
        s->cp[i] = ' ';
    memset(s->style, SW_STYLE_TEXT, n);
    memset(s->fade, 0, n);
    s->clipped = 0;
}

/* Set one cell; a wide character half overwritten loses its other half. */
static void put_cell(sw_screen *s, int row, int x, uint32_t c, int style)
{
    size_t i = (size_t)row * (size_t)s->cols + (size_t)x;
    if (s->cp[i] == SW_SCREEN_WIDE_TAIL && c != SW_SCREEN_WIDE_TAIL && x > 0)
        s->cp[i - 1] = ' ';
    if (x + 1 < s->cols && s->cp[i + 1] == SW_SCREEN_WIDE_TAIL)
        s->cp[i + 1] = ' ';
    s->cp[i] = c;
    s->style[i] = (unsigned char)style;
    s->fade[i] = 0;
}

int sw_screen_text(sw_screen *s, int row, int col, int width, int style, const char *text)
{
    if (row < 0 || row >= s->rows || col >= s->cols || !text)
        return 0;
    const unsigned char *p = (const unsigned char *)text;
    int n = 0;
    while (*p) {
        const unsigned char *at = p;
        uint32_t c = sw_utf8_next(&p);
        int w = c < 0x20 ? 1 : sw_utf8_width(c);
        if (w == 0)
            continue;
        int x = col + n;
        if (n + w > width || x + w > s->cols) {
            p = at; /* it does not fit: clipped */
            break;
        }
        n += w;
        if (x < 0)
            continue;
        put_cell(s, row, x, c < 0x20 ? ' ' : c, style);
        if (w == 2)
            put_cell(s, row, x + 1, SW_SCREEN_WIDE_TAIL, style);
    }
    if (*p)
        s->clipped++; /* a layout bug: text is fitted or wrapped before it is written */
    return n;
}

void sw_screen_fill(sw_screen *s, int row, int col, int height, int width, int style)
{
    for (int r = row; r < row + height; r++)
        for (int c = col; c < col + width; c++)
            if (r >= 0 && r < s->rows && c >= 0 && c < s->cols) {
                size_t i = (size_t)r * (size_t)s->cols + (size_t)c;
                s->cp[i] = ' ';
                s->style[i] = (unsigned char)style;
                s->fade[i] = 0;
            }
}

size_t sw_screen_to_text(const sw_screen *s, char *buf, size_t len)
{
    size_t out = 0;
    for (int r = 0; r < s->rows; r++) {
        int last = s->cols - 1;
        while (last >= 0 && s->cp[(size_t)r * (size_t)s->cols + (size_t)last] == ' ')
            last--;
        for (int c = 0; c <= last; c++) {
            char u[4];
            uint32_t cp = s->cp[(size_t)r * (size_t)s->cols + (size_t)c];
            if (cp == SW_SCREEN_WIDE_TAIL)
                continue; /* the wide character before it covers this cell */
            int k = sw_utf8_encode(cp, u);
            if (out + (size_t)k + 2 > len) {
                if (len)
                    buf[0] = '\0';
                return 0;
            }
            memcpy(buf + out, u, (size_t)k);
            out += (size_t)k;
        }
        if (out + 2 > len) {
            if (len)
                buf[0] = '\0';
            return 0;
        }
        buf[out++] = '\n';
    }
    buf[out] = '\0';
    return out;
}

int sw_frame_init(sw_frame *f, char *err, size_t errlen)
{
    memset(f, 0, sizeof *f);
    if (sw_canvas_init(&f->canvas, 80, 20, err, errlen) != SW_OK)
        return SW_ENOMEM;
    if (sw_canvas_init(&f->plot, 40, 6, err, errlen) != SW_OK) {
        sw_canvas_free(&f->canvas);
        return SW_ENOMEM;
    }
    return SW_OK;
}

void sw_frame_free(sw_frame *f)
{
    sw_canvas_free(&f->canvas);
    sw_canvas_free(&f->plot);
    for (int i = 0; i < SW_APP_SIMS - 1; i++)
        sw_canvas_free(&f->lanes[i]);
    free(f->keep);
    f->keep = NULL;
    free(f->graph_own);
    f->graph_own = NULL;
    f->graph_own_cap = 0;
    f->keep_cap = 0;
    sw_phase_view_free(&f->phase);
    sw_region_free(&f->region);
    for (int i = 0; i < SW_APP_SIMS; i++)
        sw_trails_free(&f->trails[i]);
    f->have_trails = 0;
}

void sw_frame_forget(sw_frame *f)
{
    f->view_scene = NULL;
    for (int i = 0; f->have_trails && i < SW_APP_SIMS; i++)
        sw_trails_clear(&f->trails[i]);
}

/* Trails follow at most this many particles, for this many frames. */
#define TRAIL_POINTS 2000
#define TRAIL_FRAMES 90

void sw_frame_push_trails(sw_frame *f, sw_app *a)
{
    if (!a->trails)
        return;
    if (!f->have_trails) {
        char err[SW_ERRLEN];
        for (int i = 0; i < SW_APP_SIMS; i++)
            if (sw_trails_init(&f->trails[i], TRAIL_POINTS, TRAIL_FRAMES, err, sizeof err) != SW_OK)
                return;
        f->have_trails = 1;
    }
    for (int i = 0; i < a->nsims; i++)
        sw_trails_push_system(&f->trails[i], &a->sims[i].sys, a->sims[i].sys.y, a->sims[i].t);
}

void sw_screen_blit(sw_screen *scr, const sw_canvas *c, int row0, int col0)
{
    scr->clipped += c->clipped;
    for (int r = 0; r < c->rows; r++)
        for (int k = 0; k < c->cols; k++) {
            int y = row0 + r, x = col0 + k;
            if (y < 0 || y >= scr->rows || x < 0 || x >= scr->cols)
                continue;
            size_t i = (size_t)y * (size_t)scr->cols + (size_t)x;
            scr->cp[i] = sw_canvas_codepoint(c, k, r);
            scr->style[i] = (unsigned char)sw_canvas_style(c, k, r);
            scr->fade[i] = (unsigned char)sw_canvas_fade(c, k, r);
        }
}
