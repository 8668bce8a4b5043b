/* What every part of the explainer shares (private, explain_int.h): the
 * first rows of a run in memory, and their comparison with the grading
 * tolerances. Below explain.c and explain_state.c, so neither calls the
 * other's way back. */
#include "grade/explain_int.h"

#include <stdio.h>

#include "grade/check.h"
#include "stepwise/stepwise.h"

int xpl_run_rows(const sw_run_desc *d, const sw_integrator *m, const double *p, double dt,
                 const double *y0, int max, xpl_rows *out)
{
    sw_sim s;
    char err[SW_ERRLEN];
    if (sw_sim_init(&s, d->scene, p, m, dt, err, sizeof err) != SW_OK)
        return -1;
    sw_sim_set_tolerances(&s, d->rtol, d->atol);
    if (y0)
        sw_sim_set_state(&s, y0);
    int n = -1;
    if (sw_trace_ncols(&s.sys) == out->ncols) {
        sw_row_source src = { .sim = &s, .spec = d->spec };
        long line;
        for (n = 0; n < max; n++)
            if (sw_row_next(&src, xpl_row(out, n), &line, err, sizeof err) != 1)
                break;
    }
    sw_sim_free(&s);
    return n;
}

int xpl_rows_match(const xpl_rows *a, const xpl_rows *b, int n, const sw_check_tol *tol, int skip,
                   double widen, double *worst)
{
    *worst = 0;
    if (n <= 0)
        return 0;
    for (int i = 0; i < n; i++) {
        const double *x = xpl_row(a, i), *y = xpl_row(b, i);
        for (int c = 0; c < a->ncols; c++) {
            if (c == skip || (c > 0 && tol->ignore && tol->ignore[c]))
                continue;
            double r = c == 0 ? 0 : widen * (tol->col_rtol ? tol->col_rtol[c] : tol->rtol);
            double at = c == 0 ? 0 : widen * (tol->col_atol ? tol->col_atol[c] : tol->atol);
            double ae, re, ratio;
            if (!sw_check_value(y[c], x[c], r, at, &ae, &re, &ratio))
                return 0;
            if (c > 0 && re > *worst)
                *worst = re;
        }
    }
    return 1;
}

void xpl_agree(char *buf, size_t len, double worst)
{
    if (worst == 0)
        snprintf(buf, len, "exactly");
    else
        snprintf(buf, len, "to %.1g", worst);
}
