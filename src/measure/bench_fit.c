/* The order rule: which points of a sweep an observed order may stand on,
 * the least-squares slope over them, or no order and the reason. One rule
 * for every order stepwise prints: bench's table (sw_bench_fit), check's
 * measured order (sw_measure_order), the Δt-halving message and the `w`
 * plot (sw_bench_order_rule). It only reads points, never runs anything. */
#include "measure/bench.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* What the rule needs of the sweep besides its points. */
typedef struct fit_ctx {
    double scale;     /* errors are judged against this */
    double ceiling;   /* errors from ceiling·scale up are not fitted */
    double ref_error; /* the reference's own error (0: an exact solution) */
    int reference;    /* 1 when the truth is a reference run */
} fit_ctx;

static int usable(const sw_bench_point *pt)
{
    return !pt->blown && pt->h > 0 && pt->error > 0 && isfinite(pt->error);
}

/* Usable, at least SW_BENCH_MARGIN above its own floor and the plateau,
 * below the ceiling's share of the state. */
static int clean(const fit_ctx *r, const sw_bench_point *pt, double plateau)
{
    return usable(pt) && pt->error >= SW_BENCH_MARGIN * fmax(pt->floor, plateau) && pt->error < r->ceiling * r->scale;
}

static double local_slope(const sw_bench_point *a, const sw_bench_point *b)
{
    if (!(a->h != b->h))
        return NAN;
    return log(b->error / a->error) / log(b->h / a->h);
}

/* Least-squares slope of ln error against ln h over pts[first..last]:
 * Σ(x - x̄)(y - ȳ) / Σ(x - x̄)², x = ln h, y = ln error. */
static double ls_slope(const sw_bench_point *pts, int first, int last)
{
    int n = last - first + 1;
    double sx = 0, sy = 0, sxy = 0, sxx = 0;
    for (int i = first; i <= last; i++) {
        sx += log(pts[i].h);
        sy += log(pts[i].error);
    }
    for (int i = first; i <= last; i++) {
        double dx = log(pts[i].h) - sx / n;
        sxy += dx * (log(pts[i].error) - sy / n);
        sxx += dx * dx;
    }
    return sxx > 0 ? sxy / sxx : NAN;
}

/* The round-off plateau: the first usable point (not the finest) that no
 * finer usable point falls below SW_BENCH_STALL of; -1 when none. */
static int find_plateau(const sw_bench_point *pts, int n)
{
    for (int i = 0; i < n; i++) {
        if (!usable(&pts[i]))
            continue;
        int later = 0, stalled = 1;
        for (int k = i + 1; k < n; k++) {
            if (!usable(&pts[k]))
                continue;
            later = 1;
            if (pts[k].error < SW_BENCH_STALL * pts[i].error)
                stalled = 0;
        }
        if (later && stalled)
            return i;
    }
    return -1;
}

/* The local slopes over pts[first..last] into *lo, *hi; 1 when the window
 * can carry an order: errors and steps strictly falling, the steps spanning
 * SW_BENCH_MIN_SPAN, the slopes within the band about the fitted *order. */
static int window_ok(const sw_bench_point *pts, int first, int last, double *order, double *lo, double *hi)
{
    int ok = 1;
    *lo = INFINITY;
    *hi = -INFINITY;
    for (int i = first; i < last; i++) {
        if (!(pts[i + 1].error < pts[i].error && pts[i + 1].h < pts[i].h))
            ok = 0;
        double k = local_slope(&pts[i], &pts[i + 1]);
        *lo = fmin(*lo, k);
        *hi = fmax(*hi, k);
    }
    *order = ls_slope(pts, first, last);
    return ok && pts[first].h >= SW_BENCH_MIN_SPAN * pts[last].h && isfinite(*order) &&
           *hi - *lo <= SW_BENCH_BAND_ABS + SW_BENCH_BAND_REL * fabs(*order);
}

/* The ceiling as the messages write it: 1e-2, or 0.5. */
static const char *ceiling_text(const fit_ctx *r, char *buf, size_t len)
{
    double e = round(log10(r->ceiling));
    if (r->ceiling == pow(10.0, e))
        snprintf(buf, len, "1e%d", (int)e);
    else
        snprintf(buf, len, "%g", r->ceiling);
    return buf;
}

/* Why there is no order, when the clean points are pts[first..last]
 * (last < first: none), into s->no_order and s->why. */
static void diagnose(const fit_ctx *r, sw_bench_series *s, const sw_bench_point *pts, int npts, int first,
                     int last)
{
    int n = last < 0 ? 0 : last - first + 1, fine = n > SW_BENCH_MIN_FIT ? last - SW_BENCH_MIN_FIT + 1 : first;
    /* the finest points that could carry an order: SW_BENCH_MIN_FIT, more
     * while their steps span less than SW_BENCH_MIN_SPAN */
    while (fine > first && !(pts[fine].h >= SW_BENCH_MIN_SPAN * pts[last].h))
        fine--;
    char past[80] = "", ceil_txt[24];
    int never_fell = 0; /* the plateau holds every point, and is no floor of the machine's */
    double plateau_lo = 0, plateau_hi = 0;
    if (s->plateau >= 0) {
        const char *what = r->reference && s->floor <= SW_BENCH_MARGIN * r->ref_error
                               ? " (the reference's accuracy)"
                           : s->floor <= SW_BENCH_ROUNDOFF * (pts[s->plateau].floor - r->ref_error) ? " (round-off)"
                                                                                                    : "";
        /* the plateau's own errors, not the floor assumed beside them */
        double lo = INFINITY, hi = 0;
        for (int i = s->plateau; i < npts; i++)
            if (usable(&pts[i])) {
                lo = fmin(lo, pts[i].error);
                hi = fmax(hi, pts[i].error);
            }
        /* from the first point on, or never under the ceiling: no
         * step makes the run accurate */
        never_fell = !what[0] && hi > 0;
        for (int i = 0; never_fell && i < s->plateau && !(lo >= r->ceiling * r->scale); i++)
            never_fell = !usable(&pts[i]);
        plateau_lo = lo;
        plateau_hi = hi;
        if (!(hi > 0))
            snprintf(past, sizeof past, "the error stops falling%s", what);
        else if (hi < 1.05 * lo)
            snprintf(past, sizeof past, "the error stops falling at %.1e%s", hi, what);
        else
            snprintf(past, sizeof past, "the error stops falling at %.1e to %.1e%s", lo, hi, what);
    } else {
        /* no plateau, but finer points within SW_BENCH_MARGIN of their floor */
        for (int i = last < 0 ? 0 : last + 1; i < npts && !past[0]; i++)
            if (usable(&pts[i]) && pts[i].error < SW_BENCH_MARGIN * pts[i].floor)
                snprintf(past, sizeof past, "the error reaches round-off (%.1e)", pts[i].error);
    }
    if (n >= 2) {
        s->slope_min = INFINITY;
        s->slope_max = -INFINITY;
        for (int i = fine; i < last; i++) {
            double k = local_slope(&pts[i], &pts[i + 1]);
            s->slope_min = fmin(s->slope_min, k);
            s->slope_max = fmax(s->slope_max, k);
        }
    }
    int monotone = 1, steps_fall = 1; /* over those finest points */
    for (int i = fine; i < last; i++) {
        if (!(pts[i + 1].error < pts[i].error))
            monotone = 0;
        if (!(pts[i + 1].h < pts[i].h))
            steps_fall = 0;
    }
    if (n <= 0) {
        s->no_order = past[0] ? SW_BENCH_ORDER_PAST : SW_BENCH_ORDER_FEW;
        if (past[0] && never_fell && plateau_hi < 1.05 * plateau_lo)
            snprintf(s->why, sizeof s->why, "the error stays at %.1e as the step shrinks: the method does "
                     "not converge", plateau_hi);
        else if (past[0] && never_fell)
            snprintf(s->why, sizeof s->why, "the error stays between %.1e and %.1e as the step shrinks: the "
                     "method does not converge", plateau_lo, plateau_hi);
        else if (past[0])
            snprintf(s->why, sizeof s->why, "past the asymptotic range: %s", past);
        else
            snprintf(s->why, sizeof s->why, "no point between round-off and %s of the state",
                     ceiling_text(r, ceil_txt, sizeof ceil_txt));
    } else if (n < SW_BENCH_MIN_FIT && past[0]) {
        s->no_order = SW_BENCH_ORDER_PAST;
        snprintf(s->why, sizeof s->why, "past the asymptotic range: %s, only %d clean point%s above it (%d needed)",
                 past, n, n == 1 ? "" : "s", SW_BENCH_MIN_FIT);
    } else if (n < SW_BENCH_MIN_FIT) {
        s->no_order = SW_BENCH_ORDER_FEW;
        snprintf(s->why, sizeof s->why, "only %d point%s between round-off and %s of the state (%d needed)", n,
                 n == 1 ? "" : "s", ceiling_text(r, ceil_txt, sizeof ceil_txt), SW_BENCH_MIN_FIT);
    } else if (!steps_fall || pts[first].h < 1.25 * pts[last].h) {
        s->no_order = SW_BENCH_ORDER_STEPS;
        snprintf(s->why, sizeof s->why, "the steps do not shrink steadily as the tolerance tightens (mean step "
                 "%.3g to %.3g over the finest points): the error cannot be read against them", pts[fine].h,
                 pts[last].h);
    } else if (pts[first].h < SW_BENCH_MIN_SPAN * pts[last].h) {
        s->no_order = SW_BENCH_ORDER_FEW;
        snprintf(s->why, sizeof s->why, "the clean points' steps span only a factor %.2f (%.0f needed)",
                 pts[first].h / pts[last].h, SW_BENCH_MIN_SPAN);
    } else if (!monotone) {
        s->no_order = SW_BENCH_ORDER_MONOTONE;
        snprintf(s->why, sizeof s->why, "the finest errors do not fall steadily (local slopes %.2f to %.2f)",
                 s->slope_min, s->slope_max);
    } else if (past[0]) {
        s->no_order = SW_BENCH_ORDER_PAST;
        snprintf(s->why, sizeof s->why, "past the asymptotic range: %s before the local slopes agree (%.2f to %.2f)",
                 past, s->slope_min, s->slope_max);
    } else {
        s->no_order = SW_BENCH_ORDER_SLOPES;
        snprintf(s->why, sizeof s->why, "not yet in the asymptotic range: the local slopes at the finest steps "
                 "run from %.2f to %.2f", s->slope_min, s->slope_max);
    }
}

static double fit(const fit_ctx *r, sw_bench_series *s)
{
    int npts;
    sw_bench_point *pts = (sw_bench_point *)sw_bench_order_points(s, &npts);
    s->order = s->slope_min = s->slope_max = NAN;
    s->asymptotic = 0;
    s->nfit = 0;
    s->no_order = SW_BENCH_ORDER_OK;
    s->why[0] = '\0';
    s->floor = 0;
    for (int i = 0; i < s->npoints; i++)
        s->points[i].in_fit = 0;
    for (int i = 0; i < npts; i++) {
        pts[i].in_fit = 0;
        if (usable(&pts[i]))
            s->floor = fmax(s->floor, pts[i].floor);
    }
    s->plateau = find_plateau(pts, npts);
    int end = s->plateau >= 0 ? s->plateau : npts; /* points before end may be fitted */
    double plateau = 0;
    for (int i = end; i < npts; i++)
        if (usable(&pts[i]))
            plateau = fmax(plateau, pts[i].error);
    s->floor = fmax(s->floor, plateau);
    /* The clean points: the contiguous run that ends at the finest one. */
    int last = -1, first;
    for (int i = end - 1; i >= 0 && last < 0; i--)
        if (clean(r, &pts[i], plateau))
            last = i;
    first = last;
    while (first > 0 && clean(r, &pts[first - 1], plateau))
        first--;
    s->ncandidates = last < 0 ? 0 : last - first + 1;
    /* The longest window [start, last] that carries an order. */
    int best = -1;
    double order = NAN, lo = NAN, hi = NAN;
    for (int start = first; last >= 0 && start <= last - SW_BENCH_MIN_FIT + 1 && best < 0; start++) {
        double o, l, h;
        if (window_ok(pts, start, last, &o, &l, &h)) {
            best = start;
            order = o;
            lo = l;
            hi = h;
        }
    }
    if (s->method && (s->method->flags & SW_ADAPTIVE) && npts == 0 && s->npoints > 0) {
        s->no_order = SW_BENCH_ORDER_FEW;
        snprintf(s->why, sizeof s->why, "its formula was not run on fixed steps (the order is read from "
                 "those, never from the controlled runs)");
        return s->order;
    }
    if (best < 0) {
        diagnose(r, s, pts, npts, first, last);
        return s->order;
    }
    if (!(order >= SW_BENCH_MIN_ORDER)) {
        s->no_order = SW_BENCH_ORDER_FLAT;
        snprintf(s->why, sizeof s->why, "the error does not fall as the step does (slope %.2f)", order);
        return s->order;
    }
    if (s->method && s->method->order > 0 && order > s->method->order + SW_BENCH_ABOVE) {
        s->no_order = SW_BENCH_ORDER_ABOVE;
        snprintf(s->why, sizeof s->why, "the error falls faster than order %d can for long (slope %.2f over "
                 "the finest steps): its h^%d term is not yet the largest, or vanishes here",
                 s->method->order, order, s->method->order);
        s->slope_min = lo;
        s->slope_max = hi;
        return s->order;
    }
    for (int i = best; i <= last; i++)
        pts[i].in_fit = 1;
    s->nfit = last - best + 1;
    s->order = order;
    s->slope_min = lo;
    s->slope_max = hi;
    s->asymptotic = 1;
    return s->order;
}

const sw_bench_point *sw_bench_order_points(const sw_bench_series *s, int *n)
{
    int fixed = s->method && (s->method->flags & SW_ADAPTIVE);
    *n = fixed ? s->nfixed : s->npoints;
    return fixed ? s->fixed : s->points;
}

const char *sw_bench_no_order_text(const sw_bench_series *s)
{
    return s->no_order == SW_BENCH_ORDER_OK ? "" : s->why;
}


double sw_bench_fit(const sw_bench_report *r, sw_bench_series *s)
{
    fit_ctx c = { r->scale, SW_BENCH_CEILING, r->ref_error, r->source == SW_BENCH_REFERENCE };
    return fit(&c, s);
}

double sw_bench_roundoff(double scale, long steps)
{
    return scale * (1e-13 + 4e-16 * (double)steps);
}

double sw_bench_order_rule(const double *h, const double *error, const long *steps, int n, double scale,
                           double ceiling, sw_bench_series *s)
{
    memset(s, 0, sizeof *s);
    s->npoints = n < 0 ? 0 : n > SW_BENCH_MAX_POINTS ? SW_BENCH_MAX_POINTS : n;
    for (int i = 0; i < s->npoints; i++) {
        sw_bench_point *pt = &s->points[i];
        pt->dt = pt->h = h[i];
        pt->error = error[i];
        pt->steps = steps[i];
        pt->blown = !isfinite(error[i]);
        pt->floor = sw_bench_roundoff(scale, steps[i]);
    }
    fit_ctx c = { scale, ceiling, 0.0, 0 };
    return fit(&c, s);
}
