/* The work-precision plot: error against cost, log-log, as text: every
 * method, or on a lesson page the ones the lesson has used. Each method has
 * its own marker; curves with fewer points are drawn last, on top, and a
 * line under the plot says which marker covers which ("5 over 1"), so no
 * series is hidden unsaid. Errors above the state's own size are no
 * measurement of accuracy: they are marked '^' on the top edge. */
#include "render/workprec.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render/screen.h"
#include "render/text.h"
#include "stepwise/stepwise.h"

/* ---- the work-precision plot ------------------------------------------------------ */

/* Which curves lie on one another (errors within 10% at every step size
 * both ran) and which methods are missing, and why (first: the plot does
 * not show them at all): measured, in words. Methods missing for the same
 * reason share a note. */
static int workprec_notes(sw_app *a, const sw_bench_report *r, const int *shown, int nshown,
                          char notes[][SW_TEXT_LINE], int max)
{
    int n = 0;
    char err[SW_ERRLEN];
    /* missing methods, grouped by the reason the system refuses them */
    static char reason[24][SW_ERRLEN];
    static char names[24][SW_TEXT_LINE];
    int nr = 0;
    for (int k = 0; k < sw_integrator_count(); k++) {
        const sw_integrator *m = sw_integrator_at(k);
        int in = 0, asked = nshown == r->nseries;
        for (int i = 0; i < r->nseries; i++)
            in |= r->series[i].method == m;
        for (int i = 0; i < a->wp_nonly; i++)
            asked |= a->wp_only[i] == m;
        if (in || !asked)
            continue;
        if (sw_integrator_accepts(m, a->sims[0].sys.ode, err, sizeof err) == SW_OK)
            snprintf(err, sizeof err, "not swept");
        /* the reason without the method's own name in front of it */
        const char *why = strstr(err, m->name) == err + 1 ? err + strlen(m->name) + 3 : err;
        int g = 0;
        while (g < nr && strcmp(reason[g], why) != 0)
            g++;
        if (g == nr) {
            if (nr == 24)
                continue;
            snprintf(reason[nr], sizeof reason[nr], "%s", why);
            names[nr][0] = '\0';
            nr++;
        }
        size_t used = strlen(names[g]);
        snprintf(names[g] + used, sizeof names[g] - used, "%s%s", used ? ", " : "", m->name);
    }
    for (int g = 0; g < nr && n < max; g++)
        snprintf(notes[n++], SW_TEXT_LINE, "no %.100s: %.300s", names[g], reason[g]);
    if (nshown < r->nseries && n < max)
        snprintf(notes[n++], SW_TEXT_LINE, "this page's %d methods; w outside a lesson shows all %d", nshown,
                 r->nseries);
    for (int i = 0; i < nshown && n < max; i++)
        for (int j = i + 1; j < nshown && n < max; j++) {
            const sw_bench_series *s = &r->series[shown[i]], *u = &r->series[shown[j]];
            int common = 0, apart = 0;
            for (int p = 0; p < s->npoints; p++)
                for (int q = 0; q < u->npoints; q++) {
                    const sw_bench_point *x = &s->points[p], *y = &u->points[q];
                    if (x->dt != y->dt || x->rtol != y->rtol || x->blown || y->blown || !(x->error > 0) ||
                        !(y->error > 0))
                        continue;
                    common++;
                    apart += fabs(log(x->error / y->error)) > log(1.1);
                }
            if (common >= 3 && !apart)
                snprintf(notes[n++], SW_TEXT_LINE, "%c %s and %c %s coincide: errors within 10%% at all %d steps", sw_bench_marker(s->method), s->method->name,
                         sw_bench_marker(u->method), u->method->name, common);
        }
    return n;
}

/* The plot's coordinates of a point: cost and error, both positive and finite. */
static int wp_xy(const sw_bench_point *pt, int xaxis, double *x, double *y)
{
    *x = xaxis == SW_BENCH_X_EVALS ? (double)pt->evals : pt->seconds;
    *y = pt->error;
    return !pt->blown && *x > 0 && isfinite(*x) && *y > 0 && isfinite(*y);
}

/* v in [lo, hi] onto 0..cells-1. */
static int wp_cell(double v, double lo, double hi, int cells)
{
    double f = (v - lo) / (hi - lo) * (cells - 1);
    return !(f >= 0) ? 0 : f > cells - 1 ? cells - 1 : (int)lround(f);
}

/* Note that series under's point was drawn over by series over's. */
static void overlap_add(sw_workprec_overlap *ov, int under, int over)
{
    int k = 0;
    while (k < ov->n && (ov->under[k] < under || (ov->under[k] == under && ov->over[k] < over)))
        k++;
    if ((k < ov->n && ov->under[k] == under && ov->over[k] == over) || ov->n == SW_WORKPREC_PAIRS)
        return;
    memmove(&ov->under[k + 1], &ov->under[k], (size_t)(ov->n - k) * sizeof ov->under[0]);
    memmove(&ov->over[k + 1], &ov->over[k], (size_t)(ov->n - k) * sizeof ov->over[0]);
    ov->under[k] = under;
    ov->over[k] = over;
    ov->n++;
}

/* The points of series se that the plot draws. */
static int wp_count(const sw_bench_series *se, int xaxis)
{
    int n = 0;
    for (int j = 0; j < se->npoints; j++) {
        double x, y;
        n += wp_xy(&se->points[j], xaxis, &x, &y);
    }
    return n;
}

/* How many cells of the grid show series i's marker. */
static int wp_visible(const int *owner, int cells, int i)
{
    int n = 0;
    for (int k = 0; k < cells; k++)
        n += owner[k] == i;
    return n;
}

/* Decade labels thinned so that none touches another, lines of dots
 * between a method's points, its marker on each. The series are drawn
 * most points first, so a short curve is never buried under a long one;
 * a shared cell shows the marker drawn last (the pair in *ov). The error
 * axis stops at the decade above the state's size (r->scale): a run wrong
 * by more than the whole state says nothing about accuracy, and is marked
 * '^' on the top edge at its cost instead of stretching the axis. */
int sw_workprec_grid(const sw_bench_report *r, const int *shown, int nshown, int xaxis, char *g, int rows,
                     int cols, sw_workprec_overlap *ov)
{
    sw_workprec_overlap none;
    if (!ov)
        ov = &none;
    ov->n = ov->clipped = 0;
    int all[SW_BENCH_MAX_METHODS], order[SW_BENCH_MAX_METHODS];
    if (!shown) {
        for (int i = 0; i < r->nseries; i++)
            all[i] = i;
        shown = all;
        nshown = r->nseries;
    }
    /* the drawing order: most points first (insertion sort, stable) */
    for (int i = 0; i < nshown; i++) {
        int k = i, n = wp_count(&r->series[shown[i]], xaxis);
        while (k > 0 && wp_count(&r->series[order[k - 1]], xaxis) < n) {
            order[k] = order[k - 1];
            k--;
        }
        order[k] = shown[i];
    }
    double cap = r->scale > 0 ? ceil(log10(r->scale)) : INFINITY;
    /* which series' marker is in each plot cell (-1: none) */
    static int owner[256 * 512];
    for (size_t k = 0; k < (size_t)rows * (size_t)cols && k < sizeof owner / sizeof owner[0]; k++)
        owner[k] = -1;
    double lo[2] = { INFINITY, INFINITY }, hi[2] = { -INFINITY, -INFINITY };
    for (int i = 0; i < nshown; i++)
        for (int j = 0; j < r->series[shown[i]].npoints; j++) {
            double v[2];
            if (!wp_xy(&r->series[shown[i]].points[j], xaxis, &v[0], &v[1]))
                continue;
            for (int d = 0; d < 2; d++) {
                lo[d] = fmin(lo[d], log10(v[d]));
                hi[d] = fmax(hi[d], fmin(log10(v[d]), d ? cap : INFINITY));
            }
        }
    memset(g, ' ', (size_t)(rows + 2) * (size_t)cols);
    if (!(lo[0] <= hi[0]))
        return 0;
    int range[4];
    for (int d = 0; d < 2; d++) {
        range[2 * d] = (int)floor(fmin(lo[d], hi[d]));
        range[2 * d + 1] = (int)ceil(hi[d]);
        if (range[2 * d + 1] == range[2 * d])
            range[2 * d + 1]++;
    }
    ov->top = range[3];
    int lw = 0;
    for (int d = range[2]; d <= range[3]; d++) {
        char lab[16];
        int len = snprintf(lab, sizeof lab, "1e%d", d);
        lw = len > lw ? len : lw;
    }
    int left = lw + 1, pc = cols - left; /* plot columns, right of the y axis */
#define G(rr, cc) g[(size_t)(rr) * (size_t)cols + (size_t)(cc)]
    for (int rr = 0; rr < rows; rr++)
        G(rr, lw) = '|';
    for (int cc = lw; cc < cols; cc++)
        G(rows, cc) = cc == lw ? '+' : '-';
    int last_row = -2;
    for (int d = range[3]; d >= range[2]; d--) {
        int rr = rows - 1 - wp_cell(d, range[2], range[3], rows);
        if (rr <= last_row + 1 && last_row >= 0)
            continue; /* a row between labels */
        char lab[16];
        int len = snprintf(lab, sizeof lab, "1e%d", d);
        memcpy(&G(rr, lw - len), lab, (size_t)len);
        last_row = rr;
    }
    int free_col = 0;
    for (int d = range[0]; d <= range[1]; d++) {
        int cc = left + wp_cell(d, range[0], range[1], pc);
        char lab[16];
        int len = snprintf(lab, sizeof lab, "1e%d", d), start = cc - len / 2;
        if (start < free_col || start + len > cols)
            continue;
        G(rows, cc) = '+';
        memcpy(&G(rows + 1, start), lab, (size_t)len);
        free_col = start + len + 1; /* a blank column between labels */
    }
    /* pass 0 the dots, 1 the markers, 2 for a series that pass 1 left
     * with no marker in sight: one of its cells back from a series that
     * keeps another (a curve hidden whole is not told by its legend) */
    for (int pass = 0; pass < 3; pass++)
        for (int o = 0; o < nshown; o++) {
            int i = order[o], taken = 0;
            if (pass == 2 && wp_visible(owner, rows * cols, i) > 0)
                continue;
            const sw_bench_series *se = &r->series[i];
            int prow = -1, pcol = -1;
            for (int j = 0; j < se->npoints; j++) {
                double x, y;
                if (!wp_xy(&se->points[j], xaxis, &x, &y))
                    continue;
                int cc = left + wp_cell(log10(x), range[0], range[1], pc);
                if (log10(y) > range[3]) {
                    /* off the top: an edge mark, not joined to the curve */
                    if (pass == 1) {
                        ov->clipped++;
                        if (owner[cc] < 0 && G(0, cc) != '|')
                            G(0, cc) = '^';
                    }
                    prow = -1;
                    continue;
                }
                int rr = rows - 1 - wp_cell(log10(y), range[2], range[3], rows);
                int *own = &owner[(size_t)rr * (size_t)cols + (size_t)cc];
                if (pass == 2 && !taken && *own >= 0 && wp_visible(owner, rows * cols, *own) > 1) {
                    overlap_add(ov, *own, i);
                    G(rr, cc) = sw_bench_marker(se->method);
                    *own = i;
                    taken = 1;
                } else if (pass == 1) {
                    if (*own >= 0 && *own != i)
                        overlap_add(ov, *own, i);
                    G(rr, cc) = sw_bench_marker(se->method);
                    *own = i;
                }
                else if (pass == 0 && prow >= 0) {
                    int n = abs(cc - pcol) > abs(rr - prow) ? abs(cc - pcol) : abs(rr - prow);
                    for (int k = 1; k < n; k++) {
                        int r2 = prow + (int)lround((double)(rr - prow) * k / n);
                        int c2 = pcol + (int)lround((double)(cc - pcol) * k / n);
                        if (G(r2, c2) == ' ')
                            G(r2, c2) = '.';
                    }
                }
                prow = rr;
                pcol = cc;
            }
        }
#undef G
    return 1;
}

/* "where two meet, the one on top: rk4 over euler, ..." (or "5 over 1")
 * with the methods' names when they fit the width, else their markers;
 * pairs that do not fit are counted ("+2 more"). */
static void overlap_line(const sw_bench_report *r, const sw_workprec_overlap *ov, int width, char *out, size_t len)
{
    if (!ov || ov->n == 0) {
        snprintf(out, len, "no two series share a cell");
        return;
    }
    for (int names = 1; names >= 0; names--) {
        int used = snprintf(out, len, "shared cell, top one shown:"), k;
        for (k = 0; k < ov->n; k++) {
            const sw_integrator *u = r->series[ov->under[k]].method, *o = r->series[ov->over[k]].method;
            char pair[160], more[24];
            if (names)
                snprintf(pair, sizeof pair, "%s %s over %s", k ? "," : "", o->name, u->name);
            else
                snprintf(pair, sizeof pair, "%s %c over %c", k ? "," : "", sw_bench_marker(o), sw_bench_marker(u));
            int rest = ov->n - k - 1;
            if (rest)
                snprintf(more, sizeof more, " +%d more", rest);
            else
                more[0] = '\0';
            if (used + (int)strlen(pair) + (int)strlen(more) > width)
                break;
            used += snprintf(out + used, len - (size_t)used, "%s", pair);
        }
        if (k == ov->n || !names) {
            if (k < ov->n)
                snprintf(out + used, len - (size_t)used, " +%d more", ov->n - k);
            return;
        }
    }
}

/* The work-precision overlay takes the whole rectangle it is given, so the
 * plot uses all the room there is: a title, the plot, a legend of markers,
 * the notes that fit whole, and what w does next (it cycles: against
 * evaluations, against wall time, closed). */
void sw_draw_workprec(sw_app *a, sw_screen *scr, int row, int col, int height, int width)
{
    static char notes[8][SW_TEXT_LINE], wrapped[24][SW_TEXT_LINE];
    const sw_bench_report *r = a->bench;
    int xaxis = a->workprec == 1 ? SW_BENCH_X_EVALS : SW_BENCH_X_TIME, inner = width - 2, c0 = col + 1;
    if (inner < 1 || height < 1)
        return;
    sw_screen_fill(scr, row, col, height, width, SW_STYLE_TEXT);
    char buf[SW_TEXT_LINE], line[SW_TEXT_LINE];
    sw_field tf[3];
    int nt = 0;
    memset(tf, 0, sizeof tf);
    snprintf(tf[0].full, sizeof tf[0].full, "work-precision: error against %s",
             xaxis == SW_BENCH_X_EVALS ? "derivative evaluations" : "wall time (s)");
    snprintf(tf[0].brief, sizeof tf[0].brief, "error vs %s", xaxis == SW_BENCH_X_EVALS ? "evaluations" : "time (s)");
    tf[nt++].prio = 10;
    snprintf(tf[1].full, sizeof tf[1].full, "(%s)", r->scene->name);
    tf[nt++].prio = 3;
    if (sw_text_fit(line, sizeof line, inner, tf, nt, "  ") > 0)
        sw_screen_text(scr, row, c0, inner, SW_STYLE_TITLE, line);
    /* the key's next step, always on the last row */
    sw_field kf[1];
    memset(kf, 0, sizeof kf);
    snprintf(kf[0].full, sizeof kf[0].full, "%s", xaxis == SW_BENCH_X_EVALS ? "w: the same against wall time" : "w closes");
    snprintf(kf[0].brief, sizeof kf[0].brief, "%s", xaxis == SW_BENCH_X_EVALS ? "w: against time" : "");
    kf[0].prio = 10;
    int foot = height > 1 && sw_text_fit(line, sizeof line, inner, kf, 1, "  ") > 0;
    if (foot)
        sw_screen_text(scr, row + height - 1, c0, inner, SW_STYLE_DIM, line);
    /* the series shown: on a lesson page the methods it has used (when the sweep has them) */
    int shown[SW_BENCH_MAX_METHODS] = { 0 }, nshown = 0;
    for (int i = 0; i < r->nseries; i++)
        for (int k = 0; k < a->wp_nonly; k++)
            if (r->series[i].method == a->wp_only[k]) {
                shown[nshown++] = i;
                break;
            }
    if (nshown == 0)
        for (int i = 0; i < r->nseries; i++)
            shown[nshown++] = i;
    /* whether any point is off the top: the axis does not depend on the grid's size */
    static char probe[6 * 64];
    sw_workprec_overlap ov;
    sw_workprec_grid(r, shown, nshown, xaxis, probe, 4, 64, &ov);
    /* the legend: every method's marker and name (brief names before a third row) */
    sw_field lg[SW_BENCH_MAX_METHODS + 2];
    int nl = 0;
    for (int s = 0; s < nshown && nl < SW_BENCH_MAX_METHODS; s++, nl++) {
        int i = shown[s];
        memset(&lg[nl], 0, sizeof lg[nl]);
        char name[64];
        snprintf(lg[nl].full, sizeof lg[nl].full, "%c=%.60s", sw_bench_marker(r->series[i].method),
                 r->series[i].method->name);
        sw_text_brief_name(r->series[i].method->name, name, sizeof name);
        if (name[0])
            snprintf(lg[nl].brief, sizeof lg[nl].brief, "%c=%.40s", sw_bench_marker(r->series[i].method), name);
        lg[nl].prio = 10;
    }
    /* and the dots drawn between a method's points */
    memset(&lg[nl], 0, sizeof lg[nl]);
    snprintf(lg[nl].full, sizeof lg[nl].full, ". joins a method's points");
    snprintf(lg[nl].brief, sizeof lg[nl].brief, ". joins them");
    lg[nl++].prio = 9;
    if (ov.clipped) {
        memset(&lg[nl], 0, sizeof lg[nl]);
        snprintf(lg[nl].full, sizeof lg[nl].full, "^ error over 1e%d, off the top", ov.top);
        snprintf(lg[nl].brief, sizeof lg[nl].brief, "^ error over 1e%d", ov.top);
        lg[nl++].prio = 9;
    }
    char legend[4][SW_TEXT_LINE];
    int lrows = 1, dropped = 1;
    while (lrows < 4 && (sw_text_fit_rows(legend, lrows, inner, lg, nl, "  ", &dropped), dropped))
        lrows++;
    lrows = nl ? sw_text_fit_rows(legend, lrows, inner, lg, nl, "  ", NULL) : 0;
    /* the plot keeps WP_MIN_ROWS rows (and its axis and labels); whole notes fill what is left */
    /* a row under the legend says which series share cells (or that none do) */
    int olap = nshown > 1;
    int body = height - 1 - foot - lrows - olap, plot_min = 6;
    int nn = workprec_notes(a, r, shown, nshown, notes, 8), nw = 0, dropped_notes = 0;
    for (int i = 0; i < nn; i++) {
        char part[8][SW_TEXT_LINE];
        int k = sw_text_wrap(notes[i], inner, part, 8);
        if (k > 8 || nw + k + 1 > body - plot_min - 2 || nw + k > 23) {
            dropped_notes = nn - i;
            break;
        }
        for (int j = 0; j < k; j++)
            memcpy(wrapped[nw++], part[j], SW_TEXT_LINE);
    }
    if (dropped_notes) {
        /* a row says that notes are left out: the last whole note's, or one of its own */
        snprintf(buf, sizeof buf, "(%d %snote%s: a larger window shows %s)", dropped_notes, nw ? "more " : "",
                 dropped_notes > 1 ? "s" : "", dropped_notes > 1 ? "them" : "it");
        if (sw_text_cells(buf) > inner)
            snprintf(buf, sizeof buf, "(%d %snote%s left out)", dropped_notes, nw ? "more " : "",
                     dropped_notes > 1 ? "s" : "");
        if (sw_text_cells(buf) <= inner && (nw > 0 || body - plot_min - 2 >= 1))
            snprintf(wrapped[nw > 0 ? nw - 1 : nw++], SW_TEXT_LINE, "%s", buf);
    }
    int prows = body - nw - 2, pcols = inner;
    if (prows < 3 || pcols < 16) {
        snprintf(buf, sizeof buf, "the plot needs %d more row%s and %d more column%s here: a larger window "
                 "shows it", prows < 3 ? 3 - prows : 0, 3 - prows == 1 ? "" : "s", pcols < 16 ? 16 - pcols : 0,
                 16 - pcols == 1 ? "" : "s");
        int k = sw_text_wrap(buf, inner, wrapped, 24);
        int room = height - 1 - foot;
        if (k <= room)
            for (int j = 0; j < k; j++)
                sw_screen_text(scr, row + 1 + j, c0, inner, SW_STYLE_TEXT, wrapped[j]);
        return;
    }
    /* one buffer for every frame (no allocation per frame while the plot is open) */
    static char g[256 * 512];
    if (pcols > 512)
        pcols = 512;
    if (prows + 2 > 256)
        prows = 254;
    int have = sw_workprec_grid(r, shown, nshown, xaxis, g, prows, pcols, &ov);
    int rr = row + 1;
    for (int k = 0; have && k < prows + 2; k++, rr++) {
        int len = pcols;
        while (len > 0 && g[(size_t)k * (size_t)pcols + (size_t)len - 1] == ' ')
            len--;
        snprintf(line, sizeof line, "%.*s", len, g + (size_t)k * (size_t)pcols);
        sw_screen_text(scr, rr, c0, inner, SW_STYLE_TEXT, line);
    }
    if (!have)
        sw_screen_wrapped(scr, row + 1 + prows / 2, c0, inner, 2, SW_STYLE_TEXT,
                          "(no points: every run blew up or none was made)");
    rr = row + 1 + prows + 2;
    for (int k = 0; k < lrows; k++)
        sw_screen_text(scr, rr++, c0, inner, SW_STYLE_DIM, legend[k]);
    if (olap) {
        overlap_line(r, have ? &ov : NULL, inner, line, sizeof line);
        sw_screen_text(scr, rr++, c0, inner, SW_STYLE_DIM, line);
    }
    for (int k = 0; k < nw; k++)
        sw_screen_text(scr, rr++, c0, inner, SW_STYLE_TEXT, wrapped[k]);
}
