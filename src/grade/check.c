/* Trace checking: two row sources in lockstep, compared value by value.
 * Invariant: memory is two rows, whatever the length of the run; every row
 * of both sources is read, so a malformed line anywhere is reported. */
#include "grade/check.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "stepwise/base.h"

int sw_row_next(sw_row_source *src, double *row, long *line, char *err, size_t errlen)
{
    if (src->reader) {
        int rc = sw_trace_read_row(src->reader, row, err, errlen);
        *line = src->reader->line;
        return rc;
    }
    sw_sim *s = src->sim;
    *line = 0;
    if (src->started) {
        if (sw_trace_done(s, &src->spec))
            return 0;
        do {
            int rc = sw_trace_step(s, &src->spec, err, errlen);
            if (rc != SW_OK)
                return rc;
        } while (!sw_trace_due(s, &src->spec));
    }
    src->started = 1;
    sw_trace_row_values(s, row);
    return 1;
}

int sw_check_value(double expected, double got, double rtol, double atol,
                   double *abs_err, double *rel_err, double *ratio)
{
    if (!isfinite(expected) || !isfinite(got)) {
        int same = (isnan(expected) && isnan(got)) || expected == got;
        *abs_err = *rel_err = *ratio = same ? 0.0 : INFINITY;
        return same;
    }
    double diff = fabs(got - expected), tol = atol + rtol * fabs(expected);
    if (diff == 0) { /* a passing trace's usual cell: no divisions (each quotient below is 0) */
        *abs_err = *rel_err = *ratio = 0.0;
        return 0 <= tol;
    }
    double scale = fmax(fabs(expected), rtol > 0 ? atol / rtol : 0.0);
    *abs_err = diff;
    *rel_err = scale > 0 ? diff / scale : (diff > 0 ? INFINITY : 0.0);
    *ratio = tol > 0 ? diff / tol : (diff > 0 ? INFINITY : 0.0);
    return diff <= tol;
}

static void note_failure(sw_check_result *res, const sw_check_cell *cell)
{
    res->pass = 0;
    if (!res->have_first) {
        res->first = *cell;
        res->have_first = 1;
    }
}

static void compare_row(sw_check_result *res, const double *e, const double *g, int ncols,
                        long line, const sw_check_tol *tol)
{
    sw_check_cell cell = { .kind = SW_CHECK_VALUE, .line = line, .step = (long)e[0], .t = e[1] };
    for (int c = 0; c < ncols; c++) {
        if (c > 0 && tol->ignore && tol->ignore[c])
            continue;
        /* The step column must match exactly: it says which rows line up. */
        double r = c == 0 ? 0.0 : tol->col_rtol ? tol->col_rtol[c] : tol->rtol;
        double a = c == 0 ? 0.0 : tol->col_atol ? tol->col_atol[c] : tol->atol;
        cell.column = c;
        cell.expected = e[c];
        cell.got = g[c];
        int ok = sw_check_value(e[c], g[c], r, a, &cell.abs_err, &cell.rel_err, &cell.ratio);
        res->values_compared++;
        if (!ok) {
            res->values_failed++;
            note_failure(res, &cell);
            if (tol->col_failed && tol->col_failed[c]++ == 0 && tol->col_first)
                tol->col_first[c] = cell;
        }
        if (c == 0)
            continue;
        if (tol->col_worst) {
            double d = e[c] == g[c] || (isnan(e[c]) && isnan(g[c])) ? 0.0
                       : isfinite(e[c]) && isfinite(g[c]) ? fabs(g[c] - e[c]) / (1 + fabs(e[c])) : INFINITY;
            if (!(d <= tol->col_worst[c]))
                tol->col_worst[c] = d;
        }
        if (!(cell.abs_err <= res->max_abs))
            res->max_abs = cell.abs_err;
        if (!(cell.rel_err <= res->max_rel))
            res->max_rel = cell.rel_err;
        /* Exact matches are no "largest error": worst stays empty until one differs. */
        if (cell.ratio > 0 && (!res->have_worst || cell.ratio > res->worst.ratio)) {
            res->worst = cell;
            res->have_worst = 1;
        }
    }
}

int sw_check_compare(sw_row_source *expected, sw_row_source *got, int ncols, double rtol,
                     double atol, sw_check_result *res, char *err, size_t errlen)
{
    sw_check_tol tol = { .rtol = rtol, .atol = atol };
    return sw_check_compare_tol(expected, got, ncols, &tol, res, err, errlen);
}

int sw_check_compare_tol(sw_row_source *expected, sw_row_source *got, int ncols,
                         const sw_check_tol *tol, sw_check_result *res, char *err, size_t errlen)
{
    memset(res, 0, sizeof *res);
    res->pass = 1;
    res->last_step_expected = res->last_step_got = -1;
    double *e = malloc(2 * (size_t)ncols * sizeof *e);
    if (!e) {
        snprintf(err, errlen, "out of memory for two rows of %d values", ncols);
        return SW_ENOMEM;
    }
    double *g = e + ncols;
    int more_e = 1, more_g = 1, rc = SW_OK;
    while (more_e || more_g) {
        long line_e = 0, line_g = 0;
        if (more_e) {
            rc = sw_row_next(expected, e, &line_e, err, errlen);
            if (rc < 0)
                break;
            more_e = rc;
        }
        if (more_g) {
            rc = sw_row_next(got, g, &line_g, err, errlen);
            if (rc < 0)
                break;
            more_g = rc;
        }
        rc = SW_OK;
        if (more_e) {
            res->rows_expected++;
            res->last_step_expected = (long)e[0];
        }
        if (more_g) {
            res->rows_got++;
            res->last_step_got = (long)g[0];
        }
        if (more_e && more_g) {
            res->rows_compared++;
            compare_row(res, e, g, ncols, line_g, tol);
        } else if (more_e || more_g) {
            const double *row = more_e ? e : g;
            sw_check_cell cell = { .kind = more_e ? SW_CHECK_MISSING : SW_CHECK_EXTRA,
                                   .line = more_g ? line_g : 0, .step = (long)row[0], .t = row[1],
                                   .column = -1, .expected = NAN, .got = NAN,
                                   .abs_err = INFINITY, .rel_err = INFINITY, .ratio = INFINITY };
            note_failure(res, &cell);
        }
    }
    free(e);
    return rc;
}
