/* The stability region, from the method's own one-step map: every grid
 * point z = x + iy becomes a mode {λ = z, μ = z̄} (the same test system the
 * meter uses), its growth per step at Δt = 1 is asked of the truth module,
 * and points with ρ <= 1 + SW_TRUTH_NEUTRAL are shaded. Cells are asked
 * first; only cells on the region's edge are refined to Braille dots, so a
 * redraw after a change costs a few thousand small steps and an unchanged
 * frame costs none. */
#include "render/region.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render/camera.h"
#include "render/screen.h"
#include "stepwise/stepwise.h"
#include "util/clock.h"
#include "util/num.h"

void sw_region_free(sw_region *r)
{
    free(r->stable);
    sw_truth_work_free(r->work);
    memset(r, 0, sizeof *r);
}

static int stable_at(sw_region *r, const sw_integrator *m, int order, double x, double y)
{
    return sw_region_growth(r->work, m, order, x, y) <= 1 + SW_TRUTH_NEUTRAL;
}

/* How far the region reaches: the largest |z| on rays through the left half
 * plane (and the imaginary axis) before the first unstable point, up to 50;
 * 0 when every ray is stable that far (an implicit method). */
static double region_extent(sw_region *r, const sw_integrator *m, int order)
{
    double reach = 0;
    int bounded = 0;
    for (int k = 0; k <= 12; k++) {
        double ang = SW_PI / 2 + SW_PI / 2 * k / 12.0, c = cos(ang), s = sin(ang), last = 0;
        int hit = 0;
        for (double d = 0.05; d <= 50; d *= 1.05) {
            if (!stable_at(r, m, order, d * c, d * s)) {
                hit = 1;
                break;
            }
            last = d;
        }
        if (hit) {
            bounded = 1;
            reach = fmax(reach, last);
        }
    }
    return bounded ? reach : 0;
}

/* The world point at the centre of grid point (gc, gr) of a gcols × grows grid. */
static void grid_point(const sw_canvas *c, int gcols, int grows, int gc, int gr, double *x, double *y)
{
    sw_view vis = sw_canvas_visible(c);
    *x = vis.xmin + (gc + 0.5) * (vis.xmax - vis.xmin) / gcols;
    *y = vis.ymax - (gr + 0.5) * (vis.ymax - vis.ymin) / grows;
}

/* Shade the grid from point r->next on, until done or past the budget
 * (seconds; a plugin's every new mode costs a fresh sandboxed child, so its
 * region fills in over several frames). Cells first, then, for built-in
 * methods in Braille mode, the dots of cells on the region's edge. */
static void shade(sw_region *r, const sw_canvas *c, const sw_integrator *m, int order, double budget)
{
    int dots = c->mode == SW_CANVAS_BRAILLE, cols = c->cols, rows = c->rows, ncell = cols * rows;
    int refine = dots && !(m->flags & SW_PLUGIN);
    unsigned char *cell = r->stable, *dot = r->stable + (size_t)ncell;
    double start = sw_clock_now();
    for (; r->next < ncell; r->next++) {
        if ((r->next & 7) == 0 && sw_clock_now() - start > budget)
            return;
        int row = r->next / cols, col = r->next % cols;
        double x, y;
        if (!refine && (m->flags & SW_PLUGIN) && col % 2 == 1) {
            cell[r->next] = cell[r->next - 1]; /* a plugin's grid is two cells wide */
            continue;
        }
        grid_point(c, cols, rows, col, row, &x, &y);
        cell[r->next] = (unsigned char)stable_at(r, m, order, x, y);
    }
    for (; dots && r->next < 2 * ncell; r->next++) {
        if ((r->next & 7) == 0 && sw_clock_now() - start > budget)
            return;
        int k = r->next - ncell, row = k / cols, col = k % cols, v = cell[k], edge = 0;
        for (int dr = -1; dr <= 1 && refine && !edge; dr++)
            for (int dc = -1; dc <= 1; dc++) {
                int rr = row + dr, cc = col + dc;
                if (rr >= 0 && rr < rows && cc >= 0 && cc < cols && cell[rr * cols + cc] != v)
                    edge = 1;
            }
        for (int b = 0; b < 8; b++) {
            int dc = 2 * col + b % 2, dr = 4 * row + b / 2;
            double x, y;
            grid_point(c, 2 * cols, 4 * rows, dc, dr, &x, &y);
            dot[(size_t)dr * (size_t)(2 * cols) + (size_t)dc] =
                edge ? (unsigned char)stable_at(r, m, order, x, y) : (unsigned char)v;
        }
    }
}

/* Whether grid point (x, y) of a gc × gr grid (cells, or Braille dots) is
 * on the region's edge: stable, with an unstable point among its eight
 * neighbours (the grid's border is no edge). */
static int on_edge(const unsigned char *g, int gc, int gr, int x, int y)
{
    if (!g[(size_t)y * (size_t)gc + (size_t)x])
        return 0;
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            int xx = x + dx, yy = y + dy;
            if (xx >= 0 && xx < gc && yy >= 0 && yy < gr && !g[(size_t)yy * (size_t)gc + (size_t)xx])
                return 1;
        }
    return 0;
}

/* Which side of the edge line a cell shows: wholly outside (nothing
 * shaded), on the line, or wholly inside. */
enum { SIDE_OUT, SIDE_EDGE, SIDE_IN };

static int cell_side(const sw_region *r, const sw_canvas *c, int col, int row)
{
    const unsigned char *cell = r->stable, *dot = r->stable + (size_t)c->cols * (size_t)c->rows;
    if (c->mode != SW_CANVAS_BRAILLE)
        return !cell[row * c->cols + col] ? SIDE_OUT
               : on_edge(cell, c->cols, c->rows, col, row) ? SIDE_EDGE : SIDE_IN;
    int stable = 0, edge = 0;
    for (int b = 0; b < 8; b++) {
        int dc = 2 * col + b % 2, dr = 4 * row + b / 2;
        stable += dot[(size_t)dr * (size_t)(2 * c->cols) + (size_t)dc];
        edge |= on_edge(dot, 2 * c->cols, 4 * c->rows, dc, dr);
    }
    return stable == 0 ? SIDE_OUT : edge ? SIDE_EDGE : SIDE_IN;
}

/* The column a mark at world x, in cell (col, row), is drawn in: its own
 * when that cell is on the mark's side of the edge line (wholly outside
 * for a mark that grows, wholly inside for one that does not), else the
 * nearest cell of its row that is, up to SW_REGION_NUDGE columns away.
 * Near the origin a lightly damped mode's path runs within a cell of the
 * edge: without this a mark just outside and one just inside share the
 * edge's cell and look the same. */
static int mark_col(const sw_region *r, const sw_canvas *c, double x, int col, int row, int grows)
{
    int want = grows ? SIDE_OUT : SIDE_IN;
    if (cell_side(r, c, col, row) == want)
        return col;
    sw_view vis = sw_canvas_visible(c);
    double w = (vis.xmax - vis.xmin) / c->cols, off = x - (vis.xmin + (col + 0.5) * w);
    for (int d = 1; d <= SW_REGION_NUDGE; d++)
        for (int k = 0; k < 2; k++) {
            /* the nearer of the two first: the side the mark lies towards */
            int cc = col + ((off >= 0) == (k == 0) ? d : -d);
            if (cc >= 0 && cc < c->cols && cell_side(r, c, cc, row) == want)
                return cc;
        }
    return col;
}

/* Cells taken by labels and marks, so that no label touches another or a
 * mark: a label needs its own cells and one free cell on either side. */
#define TAKEN_MAX 256 /* marks (up to 2 per mode, SW_TRUTH_MODES modes) and labels */
typedef struct taken {
    int n;
    int row[TAKEN_MAX], c0[TAKEN_MAX], c1[TAKEN_MAX]; /* cells c0..c1 of row */
} taken;

static void take(taken *t, int row, int c0, int c1)
{
    if (t->n < TAKEN_MAX) {
        t->row[t->n] = row;
        t->c0[t->n] = c0;
        t->c1[t->n] = c1;
        t->n++;
    }
}

/* Write a label at (col, row) when it fits the canvas and keeps a free cell
 * from every label and mark; returns whether it was written. */
static int label(sw_canvas *c, taken *t, int col, int row, const char *text)
{
    int len = (int)strlen(text);
    if (row < 0 || row >= c->rows || col < 0 || col + len > c->cols)
        return 0;
    /* never over the picture: a label only where the canvas is blank */
    for (int k = 0; k < len; k++)
        if (sw_canvas_codepoint(c, col + k, row) != ' ')
            return 0;
    for (int k = 0; k < t->n; k++)
        if (t->row[k] == row && t->c0[k] <= col + len && t->c1[k] >= col - 1)
            return 0;
    sw_canvas_text(c, col, row, text, SW_STYLE_DIM);
    take(t, row, col, col + len - 1);
    return 1;
}

/* Write text into the tick row ticks (cols wide) at col, when it fits and
 * keeps a blank column from what is there. */
static void tick_label(char *ticks, int cols, int col, const char *text)
{
    int len = (int)strlen(text);
    if (col < 0 || col + len > cols)
        return;
    for (int k = col - 1; k <= col + len; k++)
        if (k >= 0 && k < cols && ticks[k] != ' ')
            return;
    memcpy(ticks + col, text, (size_t)len);
}

static void axes(const sw_region *r, sw_canvas *c, taken *t, char *ticks, size_t tickslen)
{
    int tcols = c->cols < (int)tickslen - 1 ? c->cols : (int)tickslen - 1;
    memset(ticks, ' ', (size_t)tcols);
    ticks[tcols] = '\0';
    sw_view vis = sw_canvas_visible(c);
    int oc, orow, have_origin = 0;
    /* the axes as glyphs in either mode (a Braille line would blur into the shading) */
    if (sw_canvas_world_to_cell(c, 0, 0, &oc, &orow)) {
        have_origin = 1;
        /* (not over the edge line: where it runs along an axis, the line
         * is the news) */
        for (int k = 0; k < c->cols; k++)
            if (cell_side(r, c, k, orow) != SIDE_EDGE)
                sw_canvas_put(c, k, orow, '-', SW_STYLE_WALL);
        for (int k = 0; k < c->rows; k++)
            if (cell_side(r, c, oc, k) != SIDE_EDGE)
                sw_canvas_put(c, oc, k, '|', SW_STYLE_WALL);
        sw_canvas_put(c, oc, orow, '+', SW_STYLE_WALL);
    }
    int col, row;
    /* the axes' names first: "Im" left of the axis, clear of the tick labels right of it */
    if (sw_canvas_world_to_cell(c, 0, vis.ymax - c->scale, &col, &row) && c->rows > 2)
        label(c, t, col + 1, 0, "Im");
    if (sw_canvas_world_to_cell(c, vis.xmax - c->scale, 0, &col, &row) && row > 0)
        label(c, t, c->cols - 2, row - 1, "Re");
    /* unit ticks, labelled where there is room */
    double step = pow(10, floor(log10(fmax(vis.ymax, 1e-9) / 1.5)));
    if (vis.ymax / step > 5)
        step *= 2;
    /* every k-th tick of the real axis labelled, k such that the labels never touch */
    int every = 1;
    if (have_origin) {
        int c1, r1, widest = 0;
        for (double v = step; v < vis.xmax && v / step < 20; v += step) {
            char lab[16];
            int len = snprintf(lab, sizeof lab, "%g", -v);
            widest = len > widest ? len : widest;
        }
        double cells = sw_canvas_world_to_cell(c, -step, 0, &c1, &r1) ? (double)(oc - c1) : 1;
        static const int ks[] = { 1, 2, 4, 5, 10, 20 };
        for (size_t i = 0; i < sizeof ks / sizeof ks[0]; i++) {
            every = ks[i];
            if (cells * every >= widest + 1)
                break;
        }
    }
    /* (first, before the positive side's numbers it may displace) the numbers' axis named at their row's end too: the picture's own
     * "Re" is left out where the shading fills its place */
    tick_label(ticks, tcols, tcols - 3, "Re");
    int n = 0;
    if (have_origin)
        tick_label(ticks, tcols, oc, "0");
    for (double v = step; v < vis.xmax && v / step < 20; v += step) {
        char lab[16];
        int len;
        n++;
        for (int sgn = -1; sgn <= 1; sgn += 2)
            if (sw_canvas_world_to_cell(c, sgn * v, 0, &col, &row) && cell_side(r, c, col, row) != SIDE_EDGE)
                sw_canvas_put(c, col, row, '+', SW_STYLE_WALL);
        /* the real axis's labels under the picture, in their own row (the
         * regions lie on the negative side, where the shading is) */
        len = snprintf(lab, sizeof lab, "%g", -v);
        if (n % every == 0 && sw_canvas_world_to_cell(c, -v, 0, &col, &row))
            tick_label(ticks, tcols, col - len / 2, lab);
        len = snprintf(lab, sizeof lab, "%g", v);
        if (n % every == 0 && sw_canvas_world_to_cell(c, v, 0, &col, &row))
            tick_label(ticks, tcols, col - len / 2, lab);
        /* (the top and bottom rows are kept for the arrows of marks beyond them) */
        if (v < vis.ymax && sw_canvas_world_to_cell(c, 0, v, &col, &row) && row >= 1 && row <= c->rows - 2) {
            if (cell_side(r, c, col, row) != SIDE_EDGE)
                sw_canvas_put(c, col, row, '+', SW_STYLE_WALL);
            snprintf(lab, sizeof lab, "%gi", v);
            label(c, t, col + 1, row, lab);
        }
    }
}


double sw_region_scale(double reach, double largest)
{
    if (!(largest > 0) || !isfinite(largest))
        return reach;
    if (1.25 * largest >= reach / 2)
        return fmax(reach, 1.25 * largest);
    return fmax(1.25 * largest, reach / 1000);
}

/* Each mark's edge on its ray, for method m (the directions of λ and μ
 * of every mode; Δt only scales along them). A plugin's would cost a
 * sandboxed child per point: none (NaN). */
static void ray_edges(sw_region *r, const sw_app *a, const sw_integrator *m, int order)
{
    if (!a->have_spec || (r->edge_method == m && r->edge_t == a->spec_t && r->edge_n == a->spec.n))
        return;
    for (int k = 0; k < a->spec.n; k++) {
        const sw_mode *md = &a->spec.mode[k];
        int plugin = (m->flags & SW_PLUGIN) != 0;
        r->edge[2 * k] = plugin ? NAN : sw_region_edge_on_ray(r->work, m, order, md->re, md->im);
        r->edge[2 * k + 1] = plugin ? NAN : sw_region_edge_on_ray(r->work, m, order, md->pre, md->pim);
    }
    r->edge_method = m;
    r->edge_t = a->spec_t;
    r->edge_n = a->spec.n;
}

/* The largest |Δt·λ| over the modes, or SW_REGION_PAST times the farthest
 * edge on their rays when that lies beyond them (0: none), so that the
 * view chosen holds where the marks cross the edge and where the first
 * doubling of Δt past it puts them (at most twice the edge's distance). */
static double largest_mark(const sw_app *a, const sw_region *r)
{
    double largest = 0;
    for (int k = 0; a->have_spec && k < a->spec.n; k++) {
        const sw_mode *md = &a->spec.mode[k];
        largest = fmax(largest, fmax(hypot(md->re, md->im), hypot(md->pre, md->pim)) * a->dt);
        for (int j = 0; j < 2; j++)
            if (isfinite(r->edge[2 * k + j]) && SW_REGION_PAST * r->edge[2 * k + j] > largest)
                largest = SW_REGION_PAST * r->edge[2 * k + j];
    }
    return largest;
}

int sw_region_draw(sw_region *r, sw_canvas *c, sw_app *a, double *worst, int *outside, int *shown, char *why,
                   size_t whylen)
{
    const sw_integrator *m = a->sims[0].method;
    *worst = NAN;
    *outside = *shown = 0;
    r->ticks[0] = r->gauge[0] = '\0';
    r->ratio = NAN;
    r->beyond = 0;
    if (m->flags & SW_ADAPTIVE) {
        snprintf(why, whylen, "%s chooses its own steps, so it has no fixed stability region: pick a fixed-step "
                 "method (i)", m->name);
        return -1;
    }
    if (!r->work && !(r->work = sw_truth_work_new())) {
        snprintf(why, whylen, "out of memory");
        return -1;
    }
    sw_app_meter meter;
    sw_app_stability(a, &meter); /* refreshes the spectrum as the state moves */
    int order = a->have_spec ? a->spec.order : a->sims[0].sys.ode->order;
    if (order != 1 && order != 2)
        order = a->sims[0].sys.kind == SW_SYS_FLOW ? 1 : 2;
    if (r->extent_method != m || r->extent_order != order) {
        /* (a plugin's reach would cost a thousand sandboxed children: its
         * view is the default one, z zooms out) */
        r->extent = (m->flags & SW_PLUGIN) ? 0 : region_extent(r, m, order);
        r->extent_method = m;
        r->extent_order = order;
    }
    double reach = r->extent > 0 ? fmax(3.0, 1.15 * r->extent) : 3.0;
    ray_edges(r, a, m, order);
    double largest = largest_mark(a, r);
    if (!r->fit_valid || r->fit_gen != a->view_gen || r->fit_method != m || r->fit_order != order ||
        r->fit_cols != c->cols) {
        /* world units per column, as the canvas fits a square ±half: kept
         * while the page is open, whatever Δt does, so that a row more or
         * less for the text below moves no axis and a mark's move is true */
        double fit_half = sw_region_scale(reach, largest);
        r->fit_half = fit_half;
        r->fit = fmax(2 * fit_half / c->cols, fit_half / c->rows);
        r->fit_gen = a->view_gen;
        r->fit_method = m;
        r->fit_order = order;
        r->fit_cols = c->cols;
        r->fit_rows = c->rows;
        r->fit_valid = 1;
    }
    double s = r->fit * a->zoom;
    /* the origin at a cell's centre (a row is two columns tall): the marks
     * on either side of an axis land in cells that mirror each other */
    double sx = c->cols % 2 == 0 ? s / 2 : 0, sy = r->fit_rows % 2 == 0 ? s : 0;
    /* the top as for the rows the scale was chosen with: a row more or less
     * below (a message line in the status block) moves no axis */
    double top = s * r->fit_rows + sy;
    sw_view v = { -s * c->cols / 2 + sx, s * c->cols / 2 + sx, top - 2 * s * c->rows, top };
    char err[SW_ERRLEN];
    sw_canvas_set_view(c, &v, err, sizeof err);
    int dots = c->mode == SW_CANVAS_BRAILLE;
    if (r->method != m || r->order != order || r->cols != c->cols || r->rows != c->rows || r->dots != dots ||
        r->half != s) {
        size_t need = (size_t)c->cols * (size_t)c->rows * 9;
        if (need > r->cap) {
            unsigned char *st = realloc(r->stable, need);
            if (!st) {
                snprintf(why, whylen, "out of memory");
                return -1;
            }
            r->stable = st;
            r->cap = need;
        }
        memset(r->stable, 0, need);
        r->next = 0;
        r->method = m;
        r->order = order;
        r->cols = c->cols;
        r->rows = c->rows;
        r->dots = dots;
        r->half = s;
    }
    int total = c->cols * c->rows * (dots ? 2 : 1);
    if (r->next < total)
        shade(r, c, m, order, (m->flags & SW_PLUGIN) ? SW_REGION_BUDGET : INFINITY);
    r->progress = (double)r->next / total;
    sw_canvas_clear(c);
    const unsigned char *cell = r->stable, *dot = r->stable + (size_t)c->cols * (size_t)c->rows;
    /* the inside half-toned, its edge a solid line: where the edge runs
     * along an axis or a mark's path, the line is what tells them apart */
    if (dots) {
        for (int dr = 0; dr < 4 * c->rows; dr++)
            for (int dc = 0; dc < 2 * c->cols; dc++)
                if (dot[(size_t)dr * (size_t)(2 * c->cols) + (size_t)dc] &&
                    ((dc + dr) % 2 == 0 || on_edge(dot, 2 * c->cols, 4 * c->rows, dc, dr)))
                    sw_canvas_dot(c, dc, dr, SW_STYLE_GHOST, 0);
    } else {
        for (int row = 0; row < c->rows; row++)
            for (int col = 0; col < c->cols; col++)
                if (cell[row * c->cols + col])
                    sw_canvas_put(c, col, row, on_edge(cell, c->cols, c->rows, col, row) ? SW_REGION_EDGE : ':',
                                  SW_STYLE_GHOST);
    }
    taken t = { 0 };
    if (!a->have_spec) {
        axes(r, c, &t, r->ticks, sizeof r->ticks);
        snprintf(why, whylen, "no eigenvalues of %s's linearisation here to mark", a->scene->name);
        return 0;
    }
    if (a->spec.n == 0) {
        /* the meter's "x1 neutral" and this view say the same thing */
        axes(r, c, &t, r->ticks, sizeof r->ticks);
        if (a->spec.growing)
            snprintf(why, whylen, "nothing to mark: %s's %d mode%s grow%s by the physics (an eigenvalue λ with Re λ > 0), not by the "
                     "method", a->scene->name, a->spec.growing, a->spec.growing == 1 ? "" : "s",
                     a->spec.growing == 1 ? "s" : "");
        else
            snprintf(why, whylen, "no marks: every mode of %s has eigenvalue λ = 0 here, free motion under a "
                     "constant force, which every method carries at ×1 per step: neutral", a->scene->name);
        return 0;
    }
    /* the marks: each mode's λ·Δt and μ·Δt, glyph by the mode's own growth */
    double xy[4 * SW_TRUTH_MODES];
    unsigned char grows[2 * SW_TRUTH_MODES];
    int nm = 0;
    double dt = a->dt, rho_max = 0;
    /* each mode's growth, asked again only when the method, dt or the spectrum change */
    if (r->marks_method != m || r->marks_dt != dt || r->marks_t != a->spec_t || r->marks_n != a->spec.n) {
        for (int k = 0; k < a->spec.n; k++) {
            sw_spectrum one = a->spec;
            one.n = 1;
            one.mode[0] = a->spec.mode[k];
            r->marks_rho[k] = sw_truth_growth_with(r->work, m, &one, dt, NULL);
        }
        r->marks_method = m;
        r->marks_dt = dt;
        r->marks_t = a->spec_t;
        r->marks_n = a->spec.n;
    }
    for (int k = 0; k < a->spec.n; k++) {
        double rho = r->marks_rho[k];
        rho_max = isnan(rho) || rho > rho_max ? rho : rho_max;
        const sw_mode *md = &a->spec.mode[k];
        double pts[2][2] = { { md->re * dt, md->im * dt }, { md->pre * dt, md->pim * dt } };
        for (int j = 0; j < 2; j++) {
            xy[2 * nm] = pts[j][0];
            xy[2 * nm + 1] = pts[j][1];
            grows[nm] = !(rho <= 1 + SW_TRUTH_NEUTRAL);
            nm++;
        }
    }
    /* the marks' cells first, each on its side of the edge line: labels
     * keep clear of them (a mark wins over a label) */
    int mcol[2 * SW_TRUTH_MODES], mrow[2 * SW_TRUTH_MODES];
    for (int k = 0; k < nm; k++) {
        mrow[k] = -1;
        if (sw_canvas_world_to_cell(c, xy[2 * k], xy[2 * k + 1], &mcol[k], &mrow[k])) {
            mcol[k] = mark_col(r, c, xy[2 * k], mcol[k], mrow[k], grows[k]);
            take(&t, mrow[k], mcol[k], mcol[k]);
        } else
            mrow[k] = -1;
    }
    axes(r, c, &t, r->ticks, sizeof r->ticks);
    for (int k = 0; k < nm; k++) {
        int col = mcol[k], row = mrow[k];
        *outside += grows[k];
        if (row < 0)
            continue;
        /* a growing mode on top of a stable one in the same cell */
        if (!grows[k] && sw_canvas_codepoint(c, col, row) == 'X')
            continue;
        sw_canvas_put(c, col, row, grows[k] ? 'X' : '*', grows[k] ? SW_STYLE_WARN : SW_STYLE_MAIN);
        (*shown)++;
    }
    /* marks past the view: arrows at its edge, their distance said under
     * the picture (a number here would be written over the shading) */
    sw_canvas_offscreen(c, xy, nm, NULL, SW_STYLE_WARN, 0);
    sw_view vis = sw_canvas_visible(c);
    r->beyond = 0;
    for (int k = 0; k < nm; k++) {
        double x = xy[2 * k], y = xy[2 * k + 1];
        if (isfinite(x) && isfinite(y) && !(x >= vis.xmin && x < vis.xmax && y > vis.ymin && y <= vis.ymax))
            r->beyond = fmax(r->beyond, hypot(x, y));
    }
    /* the worst mark against its edge, along its ray */
    r->ratio = NAN;
    r->ratio_grows = 0;
    for (int k = 0; k < nm; k++) {
        double e = r->edge[k], d = hypot(xy[2 * k], xy[2 * k + 1]);
        double q = e == 0 ? INFINITY : isinf(e) ? 0 : d / e;
        if (!isnan(q) && (isnan(r->ratio) || q > r->ratio)) {
            r->ratio = q;
            r->ratio_grows = grows[k];
        }
    }
    if (isnan(r->ratio))
        r->gauge[0] = '\0';
    else
        sw_region_gauge(r->gauge, sizeof r->gauge, c->cols, r->ratio, r->ratio_grows);
    *worst = rho_max;
    why[0] = '\0';
    return 0;
}
