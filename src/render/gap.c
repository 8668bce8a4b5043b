/* A small difference made visible at any size (80x24 first): a run and its
 * ghost that share a cell are drawn as one "both here" glyph, and the gap
 * between them is written beside the run's marker as a number with its
 * unit. Positions are the state's first 2n numbers for particles and flows
 * alike, in metres. */
#include "render/gap.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static int alive(const sw_system *sys, const double *y, double t, int i)
{
    return !sys->scene || !sys->scene->alive || sys->scene->alive(sys, t, y, i);
}

/* Whether cells (col .. col + len - 1, row) are all on c and blank. */
static int blank(const sw_canvas *c, int col, int row, int len)
{
    if (row < 0 || row >= c->rows || col < 0 || col + len > c->cols)
        return 0;
    for (int k = 0; k < len; k++)
        if (sw_canvas_codepoint(c, col + k, row) != ' ')
            return 0;
    return 1;
}

/* Put text beside cell (col, row), one blank cell between: right, left,
 * then the rows above and below, starting or ending at the marker's column. */
static int place(sw_canvas *c, int col, int row, const char *text, int style)
{
    int len = (int)strlen(text);
    const int spots[6][2] = { { col + 2, row },       { col - 1 - len, row },   { col, row - 1 },
                              { col - len + 1, row - 1 }, { col, row + 1 }, { col - len + 1, row + 1 } };
    for (int k = 0; k < 6; k++) {
        /* the cell before and after stay blank, so the text reads as a label */
        int at = spots[k][0], r = spots[k][1];
        if (blank(c, at, r, len) && (at == 0 || blank(c, at - 1, r, 1) || k >= 2) &&
            (at + len >= c->cols || blank(c, at + len, r, 1))) {
            sw_canvas_text(c, at, r, text, style);
            return 1;
        }
    }
    return 0;
}

static void number(char *buf, size_t len, double d)
{
    if (d >= 100)
        snprintf(buf, len, "%.0f", d);
    else
        snprintf(buf, len, "%.2g", d);
}

double sw_canvas_draw_gap(sw_canvas *c, const sw_system *sys, const double *y, const double *other, double t,
                          const char *label, int style)
{
    int n = sys->n, worst = -1, wcol = 0, wrow = 0;
    double gap = -1;
    if (!y || !other || n > SW_GAP_MARK_MAX)
        return NAN;
    for (int i = 0; i < n; i++) {
        if (!alive(sys, y, t, i))
            continue;
        int c0, r0, c1, r1;
        int on0 = sw_canvas_world_to_cell(c, y[2 * i], y[2 * i + 1], &c0, &r0);
        int on1 = sw_canvas_world_to_cell(c, other[2 * i], other[2 * i + 1], &c1, &r1);
        if (on0 && on1 && c0 == c1 && r0 == r1)
            sw_canvas_put(c, c0, r0, SW_GLYPH_BOTH, style);
        double d = hypot(y[2 * i] - other[2 * i], y[2 * i + 1] - other[2 * i + 1]);
        if (on0 && isfinite(d) && d > gap) {
            gap = d;
            worst = i;
            wcol = c0;
            wrow = r0;
        }
    }
    if (!label || worst < 0 || n > SW_GAP_LABEL_MAX || !(gap > 0)) /* no gap: nothing to say */
        return NAN;
    char num[32], text[3][64];
    number(num, sizeof num, gap);
    snprintf(text[0], sizeof text[0], "gap to %s %s m", label, num);
    snprintf(text[1], sizeof text[1], "%s %s m", label, num);
    snprintf(text[2], sizeof text[2], "%s m", num);
    for (int k = 0; k < 3; k++)
        if (place(c, wcol, wrow, text[k], style))
            return gap;
    return NAN;
}
