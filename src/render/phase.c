/* Drawing the phase view. The plot box is normalised (q across the width, v
 * up the height), so an orbit fills it whatever the units; the box is the
 * exact orbit's (or the reference path's) with a margin, times the zoom,
 * and it does not follow the runs: a path that spirals out leaves it and
 * is marked at its edge. */
#include "render/phase.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render/camera.h"

void sw_phase_view_free(sw_phase_view *ph)
{
    free(ph->state);
    memset(ph, 0, sizeof *ph);
}

/* Forget the cached orbit and range (a new scene, parameters or coordinate). */
static void forget(sw_phase_view *ph)
{
    ph->scene = NULL;
    ph->n = 0;
    ph->have_range = 0;
}

/* The closed form's orbit over [0, cover]: one sample per step of cover/N. */
static void exact_orbit(sw_phase_view *ph, sw_app *a, double cover)
{
    const sw_system *sys = &a->truth.sys;
    int dim = sys->ode->dim;
    ph->n = 0;
    ph->cover = cover;
    if (dim > ph->state_dim) {
        double *s = realloc(ph->state, (size_t)dim * sizeof *s);
        if (!s)
            return;
        ph->state = s;
        ph->state_dim = dim;
    }
    for (int k = 0; k < SW_PHASE_EXACT; k++) {
        double t = cover * k / (SW_PHASE_EXACT - 1), q, v;
        if (sys->scene->exact(sys, t, ph->state) != 0)
            break;
        if (sw_phase_point(sys, ph->state, a->phase_particle, a->phase_coord, &q, &v)) {
            ph->q[ph->n] = q;
            ph->v[ph->n] = v;
            ph->n++;
        }
    }
}

static void box_add(double *lo, double *hi, double x)
{
    if (isfinite(x)) {
        *lo = fmin(*lo, x);
        *hi = fmax(*hi, x);
    }
}

/* The frame: the exact orbit's box, else the reference path's, else the
 * runs' own first stretch, with 25% margin; spans never zero. */
static void update_range(sw_phase_view *ph, sw_app *a)
{
    double q0 = INFINITY, q1 = -INFINITY, v0 = INFINITY, v1 = -INFINITY;
    const sw_phase_hist *ref = &a->phase[SW_APP_SIMS];
    if (ph->n > 1) {
        for (int k = 0; k < ph->n; k++)
            box_add(&q0, &q1, ph->q[k]), box_add(&v0, &v1, ph->v[k]);
    } else if (ref->count > 1) {
        for (int k = 0; k < ref->count; k++)
            box_add(&q0, &q1, ref->q[k]), box_add(&v0, &v1, ref->v[k]);
    } else {
        /* no truth: the main run over its first report time frames the view (grown, not after) */
        const sw_phase_hist *h = &a->phase[0];
        if (ph->have_range && a->sims[0].t > a->scene->duration)
            return;
        for (int k = 0; k < h->count; k++)
            box_add(&q0, &q1, h->q[k]), box_add(&v0, &v1, h->v[k]);
    }
    if (!(q1 >= q0) || !(v1 >= v0))
        return;
    double mq = 0.25 * (q1 - q0), mv = 0.25 * (v1 - v0);
    if (!(mq > 0))
        mq = fmax(1e-3, 0.25 * fabs(q0));
    if (!(mv > 0))
        mv = fmax(1e-3, 0.25 * fabs(v0));
    if (ph->have_range && ref->count > 1 && ph->n <= 1) {
        /* a reference path grows the frame as it comes in */
        q0 = fmin(q0 - mq, ph->qmin), q1 = fmax(q1 + mq, ph->qmax);
        v0 = fmin(v0 - mv, ph->vmin), v1 = fmax(v1 + mv, ph->vmax);
        ph->qmin = q0, ph->qmax = q1, ph->vmin = v0, ph->vmax = v1;
        return;
    }
    ph->qmin = q0 - mq;
    ph->qmax = q1 + mq;
    ph->vmin = v0 - mv;
    ph->vmax = v1 + mv;
    ph->have_range = 1;
}

void sw_phase_range(const sw_phase_view *ph, const sw_app *a, double *q0, double *q1, double *v0, double *v1)
{
    double qc = (ph->qmin + ph->qmax) / 2, qh = (ph->qmax - ph->qmin) / 2 * a->zoom;
    double vc = (ph->vmin + ph->vmax) / 2, vh = (ph->vmax - ph->vmin) / 2 * a->zoom;
    *q0 = qc - qh, *q1 = qc + qh, *v0 = vc - vh, *v1 = vc + vh;
}

/* (q, v) to the canvas's normalised plane: [0, cols] × [0, 2·rows]. */
static void to_plane(const sw_canvas *c, const double r[4], double q, double v, double *x, double *y)
{
    *x = (q - r[0]) / (r[1] - r[0]) * c->cols;
    *y = (v - r[2]) / (r[3] - r[2]) * 2.0 * c->rows;
}

/* A path, from the first point at or after time since (-INFINITY: all). */
static void draw_path(sw_canvas *c, const double r[4], const double *q, const double *v, const double *t, int n,
                      int start, int cap, double since, uint32_t glyph, int style)
{
    double px = NAN, py = NAN;
    int first = 0;
    while (t && first < n - 1 && t[(start + first) % cap] < since)
        first++;
    for (int k = first; k < n; k++) {
        int i = (start + k) % cap;
        double x, y;
        to_plane(c, r, q[i], v[i], &x, &y);
        if (k > first)
            sw_canvas_line(c, px, py, x, y, glyph, style);
        else
            sw_canvas_point(c, x, y, glyph, style);
        px = x, py = y;
    }
}

static const uint32_t sim_glyph[SW_APP_SIMS] = { SW_GLYPH_MAIN, SW_GLYPH_COMPARE1, SW_GLYPH_COMPARE2 };

uint32_t sw_phase_path_glyph(int i)
{
    /* the main run's path is dotted, its present point 'o'; the others
     * draw both with their glyph */
    return i == 0 ? '.' : sim_glyph[i];
}
static const int sim_style[SW_APP_SIMS] = { SW_STYLE_MAIN, SW_STYLE_COMPARE1, SW_STYLE_COMPARE2 };

/* Write text at (col, row) when every cell under it is blank or an axis
 * stroke (never over a path or a mark). */
static void name_at(sw_canvas *c, int col, int row, const char *text)
{
    int len = (int)strlen(text);
    if (row < 0 || row >= c->rows || col < 0 || col + len > c->cols)
        return;
    for (int k = 0; k < len; k++) {
        uint32_t g = sw_canvas_codepoint(c, col + k, row);
        if (g != ' ' && g != '-' && g != '|')
            return;
    }
    sw_canvas_text(c, col, row, text, SW_STYLE_WALL);
}

/* Which axis is which: the coordinate's name at the right end of the
 * horizontal axis (or the bottom row), its rate's at the top of the
 * vertical one (or the left column), each with the value at that end. */
static void axis_names(sw_canvas *c, const sw_app *a, const double r[4], double x0, double y0)
{
    const char *q, *qu, *v, *vu;
    sw_phase_names(a->phase_coord, &q, &qu, &v, &vu);
    char lab[48];
    int row = r[2] < 0 && r[3] > 0 ? c->rows - 1 - (int)floor(y0 / 2.0) : c->rows - 1;
    int len = snprintf(lab, sizeof lab, "%s %.3g >", q, r[1]);
    name_at(c, c->cols - len, row - 1 >= 0 ? row - 1 : row, lab);
    int col = r[0] < 0 && r[1] > 0 ? (int)floor(x0) : 0;
    snprintf(lab, sizeof lab, "^ %s %.3g", v, r[3]);
    name_at(c, col + 1 < c->cols ? col + 1 : col, 0, lab);
}

int sw_phase_draw(sw_phase_view *ph, sw_canvas *c, sw_app *a, int unicode)
{
    (void)unicode;
    if (ph->scene != a->scene || memcmp(ph->p, a->p, sizeof ph->p) != 0 || ph->particle != a->phase_particle ||
        ph->coord != a->phase_coord) {
        forget(ph);
        ph->scene = a->scene;
        memcpy(ph->p, a->p, sizeof ph->p);
        ph->particle = a->phase_particle;
        ph->coord = a->phase_coord;
    }
    int exact = a->have_truth && a->truth.source == SW_TRUTH_EXACT && a->scene->exact;
    double want = fmax(a->scene->duration, a->sims[0].t);
    if (exact && (ph->n == 0 || want > ph->cover))
        exact_orbit(ph, a, 1.5 * want);
    update_range(ph, a);
    char err[SW_ERRLEN];
    sw_view v = { 0, (double)c->cols, 0, 2.0 * c->rows };
    sw_canvas_set_view(c, &v, err, sizeof err);
    sw_canvas_clear(c);
    if (!ph->have_range)
        return 0;
    double r[4];
    sw_phase_range(ph, a, &r[0], &r[1], &r[2], &r[3]);
    /* axes through zero where zero is in the frame */
    double x0, y0;
    to_plane(c, r, 0, 0, &x0, &y0);
    if (r[2] < 0 && r[3] > 0)
        sw_canvas_line(c, 0, y0, c->cols, y0, '-', SW_STYLE_WALL);
    if (r[0] < 0 && r[1] > 0)
        sw_canvas_line(c, x0, 0, x0, 2.0 * c->rows, '|', SW_STYLE_WALL);
    /* the exact solution first, then the runs' recent paths over it (the
     * last 60% of a report time: a few turns, so each method's present
     * orbit reads apart from its past), the main one last: a run that
     * keeps to the exact curve, or near it, is seen, not hidden under it
     * (issue 37: symplectic Euler's closed curve was); then where each run
     * is now */
    if (ph->n > 1)
        draw_path(c, r, ph->q, ph->v, NULL, ph->n, 0, SW_PHASE_EXACT, -INFINITY, SW_GLYPH_GHOST, SW_STYLE_GHOST);
    const sw_phase_hist *ref = &a->phase[SW_APP_SIMS];
    if (!exact && ref->count > 1)
        draw_path(c, r, ref->q, ref->v, NULL, ref->count, (ref->head - ref->count + SW_PHASE_HIST) % SW_PHASE_HIST,
                  SW_PHASE_HIST, -INFINITY, SW_GLYPH_GHOST, SW_STYLE_GHOST);
    double since = a->sims[0].t - 0.6 * a->scene->duration;
    double now[2 * SW_APP_SIMS];
    int left = 0;
    for (int i = a->nsims - 1; i >= 0; i--) {
        const sw_phase_hist *h = &a->phase[i];
        int start = (h->head - h->count + SW_PHASE_HIST) % SW_PHASE_HIST;
        draw_path(c, r, h->q, h->v, h->t, h->count, start, SW_PHASE_HIST, since,
                  c->mode == SW_CANVAS_BRAILLE ? 0 : sw_phase_path_glyph(i), sim_style[i]);
    }
    for (int i = a->nsims - 1; i >= 0; i--) {
        const sw_phase_hist *h = &a->phase[i];
        now[2 * i] = now[2 * i + 1] = NAN;
        if (h->count > 0) {
            int last = (h->head - 1 + SW_PHASE_HIST) % SW_PHASE_HIST;
            to_plane(c, r, h->q[last], h->v[last], &now[2 * i], &now[2 * i + 1]);
            sw_canvas_mark(c, now[2 * i], now[2 * i + 1], sim_glyph[i], sim_style[i]);
        }
    }
    for (int i = 0; i < a->nsims; i++)
        left += sw_canvas_offscreen(c, &now[2 * i], 1, NULL, sim_style[i], 0);
    axis_names(c, a, r, x0, y0);
    return left;
}
