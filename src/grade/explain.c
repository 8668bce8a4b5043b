/* The explaining checker. The trace's first rows are held in memory and
 * compared, with the grading tolerances, against runs that make one usual
 * mistake each; the first run that matches every value names the mistake.
 * Data mistakes (rows, time column, digits, precision) are tried first,
 * since they need no new run. Invariant: a variant is reported only when
 * it matches every examined value, never because it is merely closer. */
#include "grade/explain.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/stepper.h"
#include "grade/assignment.h"
#include "stepwise/stepwise.h"

/* Most work a variant run may take: state components x evaluations. */
#define VARIANT_WORK 2e8

/* ---- mistaken methods ---------------------------------------------------- */

/* Midpoint with its second stage at t instead of t + h/2. */
static int mid_at_t(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    int n = ode->dim;
    double *k = SW_WORK(s, 0), *m = SW_WORK(s, 1);
    sw_ode_eval(ode, *t, y, k);
    sw_axpy(n, m, y, 0.5 * h, k);
    sw_ode_eval(ode, *t, m, k);
    sw_axpy(n, y, y, h, k);
    *t += h;
    return 0;
}

/* Heun with its second stage at t instead of t + h. */
static int heun_at_t(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    int n = ode->dim;
    double *k1 = SW_WORK(s, 0), *k2 = SW_WORK(s, 1), *m = SW_WORK(s, 2);
    sw_ode_eval(ode, *t, y, k1);
    sw_axpy(n, m, y, h, k1);
    sw_ode_eval(ode, *t, m, k2);
    for (int i = 0; i < n; i++)
        y[i] += 0.5 * h * (k1[i] + k2[i]);
    *t += h;
    return 0;
}

/* RK4 with stage times c2, c3, c4 and k3 from a step of c3k·h along k2. */
static int rk4_variant(sw_stepper *s, sw_ode *ode, double *t, double *y, double h, double c2,
                       double c3, double c4, double k3_step)
{
    int n = ode->dim;
    double *k1 = SW_WORK(s, 0), *k2 = SW_WORK(s, 1), *k3 = SW_WORK(s, 2), *k4 = SW_WORK(s, 3),
           *m = SW_WORK(s, 4);
    sw_ode_eval(ode, *t, y, k1);
    sw_axpy(n, m, y, 0.5 * h, k1);
    sw_ode_eval(ode, *t + c2 * h, m, k2);
    sw_axpy(n, m, y, k3_step * h, k2);
    sw_ode_eval(ode, *t + c3 * h, m, k3);
    sw_axpy(n, m, y, h, k3);
    sw_ode_eval(ode, *t + c4 * h, m, k4);
    for (int i = 0; i < n; i++)
        y[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    *t += h;
    return 0;
}

static int rk4_at_t(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    return rk4_variant(s, ode, t, y, h, 0.0, 0.0, 0.0, 0.5);
}

static int rk4_k3_full(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    return rk4_variant(s, ode, t, y, h, 0.5, 0.5, 1.0, 1.0);
}

typedef struct mistake {
    const char *base;        /* the method it is a mistaken version of */
    int time_only;           /* shows only on a time-dependent scene */
    const char *kind;
    sw_integrator method;
    const char *hint;
} mistake;

static const mistake mistakes[] = {
    { "midpoint", 1, "stage-time", { "midpoint (stage at t)", "", 2, 2, SW_EXPLICIT, 0, 2, mid_at_t, "" },
      "midpoint with its second stage evaluated at t instead of t + h/2" },
    { "heun", 1, "stage-time", { "heun (stage at t)", "", 2, 2, SW_EXPLICIT, 0, 3, heun_at_t, "" },
      "Heun with its second stage evaluated at t instead of t + h" },
    { "rk4", 1, "stage-time", { "rk4 (stages at t)", "", 4, 4, SW_EXPLICIT, 0, 5, rk4_at_t, "" },
      "rk4 with every stage evaluated at the step's start t: k2 and k3 belong at t + h/2, k4 at t + h" },
    { "rk4", 0, "k3-full-step", { "rk4 (k3 from a full step)", "", 4, 4, SW_EXPLICIT, 0, 5, rk4_k3_full, "" },
      "rk4 with k3 taken at y + h*k2 instead of y + h/2*k2" },
};

/* ---- rows in memory ----------------------------------------------------- */

typedef struct rowset {
    double *v;           /* n rows of ncols */
    long *line;
    int n, ncols;
} rowset;

static double *row_at(const rowset *r, int i) { return r->v + (size_t)i * (size_t)r->ncols; }

/* Up to max rows of a run into out (already sized); returns the rows made,
 * or -1 when the run cannot start or has other columns. */
static int run_rows(const sw_run_desc *d, const sw_integrator *m, const double *p, double dt,
                    int max, rowset *out)
{
    sw_sim s;
    char err[SW_ERRLEN];
    if (sw_sim_init(&s, d->scene, p, m, dt, err, sizeof err) != SW_OK)
        return -1;
    sw_sim_set_tolerances(&s, d->rtol, d->atol);
    int n = -1;
    if (sw_trace_ncols(&s.sys) == out->ncols) {
        sw_row_source src = { .sim = &s, .spec = d->spec };
        long line;
        for (n = 0; n < max; n++)
            if (sw_row_next(&src, row_at(out, n), &line, err, sizeof err) != 1)
                break;
    }
    sw_sim_free(&s);
    return n;
}

/* Whether every value of the first n rows of a and b passes tol (column
 * skip left out, -1 none; each tolerance multiplied by widen); *worst is
 * the largest relative difference over the values compared. */
static int rows_match(const rowset *a, const rowset *b, int n, const sw_check_tol *tol, int skip,
                      double widen, double *worst)
{
    *worst = 0;
    if (n <= 0)
        return 0;
    for (int i = 0; i < n; i++) {
        const double *x = row_at(a, i), *y = row_at(b, i);
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

/* ---- data mistakes -------------------------------------------------------- */

/* Significant digits %.Ng needs to print v so that it reads back exactly. */
static int digits_of(double v)
{
    char buf[40];
    for (int p = 1; p < 17; p++) {
        snprintf(buf, sizeof buf, "%.*g", p, v);
        if (strtod(buf, NULL) == v)
            return p;
    }
    return 17;
}

static void agree(char *buf, size_t len, double worst)
{
    if (worst == 0)
        snprintf(buf, len, "exactly");
    else
        snprintf(buf, len, "to %.1g", worst);
}

static int explain_rows(const rowset *tr, const rowset *ref, const sw_check_tol *tol,
                        sw_explanation *out)
{
    int n = tr->n < ref->n ? tr->n : ref->n, i = 0;
    while (i < n && row_at(tr, i)[0] == row_at(ref, i)[0])
        i++;
    if (i == n)
        return 0;
    long got = (long)row_at(tr, i)[0], want = (long)row_at(ref, i)[0];
    double worst;
    rowset shifted = *tr;
    if (i + 1 < ref->n && got == (long)row_at(ref, i + 1)[0]) {
        /* A row is missing: the trace's row i is the reference's row i + 1. */
        rowset later = { row_at(ref, i + 1), ref->line, ref->n - i - 1, ref->ncols };
        shifted.v = row_at(tr, i);
        int m = (tr->n - i < later.n ? tr->n - i : later.n);
        if (rows_match(&shifted, &later, m, tol, -1, 1.0, &worst) && i > 0 &&
            rows_match(tr, ref, i, tol, -1, 1.0, &worst)) {
            snprintf(out->kind, sizeof out->kind, "missing-row");
            snprintf(out->message, sizeof out->message, "your trace has no row for step %ld (line %ld "
                     "holds step %ld): every row after it is one row early", want, tr->line[i], got);
            return 1;
        }
        if (i == 0 && rows_match(&shifted, &later, m, tol, -1, 1.0, &worst)) {
            snprintf(out->kind, sizeof out->kind, "missing-row");
            snprintf(out->message, sizeof out->message, "your trace has no row for step 0 (the "
                     "initial state): it starts at step %ld, so every row is one step off; write "
                     "the state once before the first step", got);
            return 1;
        }
    }
    if (i > 0 && got == (long)row_at(ref, i - 1)[0]) {
        snprintf(out->kind, sizeof out->kind, "duplicate-row");
        snprintf(out->message, sizeof out->message, "step %ld appears twice (lines %ld and %ld): "
                 "write each step's row once", got, tr->line[i - 1], tr->line[i]);
        return 1;
    }
    return 0;
}

static int explain_format(const rowset *tr, const rowset *ref, const sw_run_desc *want,
                          const sw_check_tol *tol, sw_explanation *out)
{
    int n = tr->n < ref->n ? tr->n : ref->n;
    double worst;
    char how[40];
    /* The t column one step off, every other column right. */
    if (n > 1 && rows_match(tr, ref, n, tol, 1, 1.0, &worst)) {
        double d = row_at(tr, 1)[1] - row_at(ref, 1)[1];
        int same = fabs(fabs(d) - want->dt) <= 1e-6 * want->dt;
        for (int i = 1; same && i < n; i++)
            same = fabs(row_at(tr, i)[1] - row_at(ref, i)[1] - d) <= 1e-6 * want->dt;
        if (same) {
            snprintf(out->kind, sizeof out->kind, "time-shift");
            snprintf(out->message, sizeof out->message, "your t column is one step %s (the row "
                     "for step n has t = (n %s 1)*dt), while every other value matches: write t "
                     "%s you advance it", d > 0 ? "ahead" : "behind", d > 0 ? "+" : "-",
                     d > 0 ? "before" : "after");
            return 1;
        }
    }
    /* Too few digits, and single precision: look at the numbers themselves. */
    int most = 0, values = 0, floats = 0;
    for (int i = 0; i < n; i++)
        for (int c = 2; c < tr->ncols; c++) {
            double v = row_at(tr, i)[c];
            if (!isfinite(v) || v == 0 || v == floor(v))
                continue;
            int d = digits_of(v);
            most = d > most ? d : most;
            values++;
            /* A float: exactly one (printed with %.17g), or its shortest
             * text (%.9g) reads back as this value. */
            char buf[40];
            snprintf(buf, sizeof buf, "%.9g", (double)(float)v);
            floats += (double)(float)v == v || strtod(buf, NULL) == v;
        }
    if (values < 4)
        return 0;
    if (most <= 12 && rows_match(tr, ref, n, tol, -1, 0.6 * pow(10.0, 10 - most), &worst)) {
        agree(how, sizeof how, worst);
        snprintf(out->kind, sizeof out->kind, "digits");
        snprintf(out->message, sizeof out->message, "your values have at most %d significant "
                 "digits%s and match %s %s: print with %%.17g so they round-trip", most,
                 most <= 6 ? " (as printf's %g prints them)" : "", want->method->name, how);
        out->agreement = worst;
        return 1;
    }
    int m = n < 50 ? n : 50;
    if (floats >= values * 9 / 10 && most > 6 && rows_match(tr, ref, m, tol, -1, 1e5, &worst)) {
        agree(how, sizeof how, worst);
        snprintf(out->kind, sizeof out->kind, "single-precision");
        snprintf(out->message, sizeof out->message, "your values are single-precision floats "
                 "(each one is exactly a float) and match %s only %s: compute and print in double "
                 "precision", want->method->name, how);
        out->agreement = worst;
        return 1;
    }
    return 0;
}

/* ---- variant runs ------------------------------------------------------- */

static void method_hint(const sw_integrator *want, const sw_integrator *got, char *buf, size_t len)
{
    if (strcmp(got->name, "symplectic-euler") == 0 && strcmp(want->name, "euler") == 0)
        snprintf(buf, len, "did you update v before x? (Euler moves x with the old v)");
    else if (strcmp(got->name, "euler") == 0 && strcmp(want->name, "symplectic-euler") == 0)
        snprintf(buf, len, "did you move x with the old v? (symplectic Euler updates v first, "
                 "then x with the new v)");
    else
        snprintf(buf, len, "did you implement %s (%s) instead of %s?", got->name, got->label,
                 want->name);
}

static int time_dependent(const sw_run_desc *d)
{
    sw_system sys;
    char err[SW_ERRLEN];
    if (sw_system_build(&sys, d->scene, d->p, err, sizeof err) != SW_OK)
        return 0;
    int n = sys.ode->dim, differs = 0;
    double *a = malloc(2 * (size_t)n * sizeof *a);
    if (a) {
        sys.ode->deriv(sys.ode->ctx, 0.0, sys.y, a);
        sys.ode->deriv(sys.ode->ctx, 0.37 * d->scene->duration + 0.1, sys.y, a + n);
        for (int i = 0; i < n && !differs; i++)
            differs = a[i] != a[n + i];
    }
    free(a);
    sw_system_free(&sys);
    return differs;
}

static int try_variant(const rowset *tr, rowset *scratch, const sw_run_desc *d,
                       const sw_integrator *m, const double *p, double dt, const sw_check_tol *tol,
                       double *worst)
{
    int got = run_rows(d, m, p, dt, tr->n, scratch);
    return got == tr->n && rows_match(tr, scratch, got, tol, -1, 1.0, worst);
}

static int explain_runs(const rowset *tr, rowset *scratch, const sw_run_desc *d,
                        const sw_trace_meta *said, const sw_check_tol *tol, sw_explanation *out)
{
    double worst;
    char how[40], hint[200], num[40], want_num[40];
    for (int i = 0; i < sw_integrator_count(); i++) {
        const sw_integrator *m = sw_integrator_at(i);
        if (m == d->method || (m->flags & SW_PLUGIN) ||
            !try_variant(tr, scratch, d, m, d->p, d->dt, tol, &worst))
            continue;
        agree(how, sizeof how, worst);
        method_hint(d->method, m, hint, sizeof hint);
        snprintf(out->kind, sizeof out->kind, "method");
        if (strcmp(said->integrator, d->method->name) == 0)
            snprintf(out->message, sizeof out->message, "your header says %s, but your numbers "
                     "match %s %s: %s", said->integrator, m->name, how, hint);
        else
            snprintf(out->message, sizeof out->message, "your numbers match %s %s: %s", m->name,
                     how, hint);
        out->agreement = worst;
        return 1;
    }
    for (int k = 0; k < 2; k++) {
        double dt = k == 0 ? 2 * d->dt : 0.5 * d->dt;
        if (!(dt >= SW_DT_MIN && dt <= SW_DT_MAX) || !try_variant(tr, scratch, d, d->method, d->p, dt, tol, &worst))
            continue;
        sw_fmt_shortest(num, sizeof num, dt);
        sw_fmt_shortest(want_num, sizeof want_num, d->dt);
        snprintf(out->kind, sizeof out->kind, "dt");
        snprintf(out->message, sizeof out->message, "your numbers match %s with dt = %s, %s the "
                 "assignment's %s", d->method->name, num, k == 0 ? "twice" : "half", want_num);
        out->agreement = worst;
        return 1;
    }
    int timed = -1;
    for (size_t i = 0; i < sizeof mistakes / sizeof mistakes[0]; i++) {
        const mistake *mk = &mistakes[i];
        if (strcmp(mk->base, d->method->name) != 0)
            continue;
        if (mk->time_only && timed < 0)
            timed = time_dependent(d);
        if ((mk->time_only && !timed) || !try_variant(tr, scratch, d, &mk->method, d->p, d->dt, tol, &worst))
            continue;
        agree(how, sizeof how, worst);
        snprintf(out->kind, sizeof out->kind, "%s", mk->kind);
        snprintf(out->message, sizeof out->message, "your numbers match %s %s%s", mk->hint, how,
                 mk->time_only ? " (this scene changes with time, so stage times matter)" : "");
        out->agreement = worst;
        return 1;
    }
    const sw_scene *sc = d->scene;
    /* Candidates: the value the trace's header gives, the default, and the
     * assignment's value doubled, halved, times and over ten. */
    static const double factors[] = { -1, 0, 2, 0.5, 10, 0.1 };
    for (int i = 0; i < sc->nparams; i++) {
        const sw_param *pd = &sc->params[i];
        for (size_t f = 0; f < sizeof factors / sizeof factors[0]; f++) {
            double p[SW_MAX_PARAMS];
            double v = factors[f] < 0 ? (said->scene == sc ? said->p[i] : d->p[i])
                     : factors[f] == 0 ? pd->def : d->p[i] * factors[f];
            if (pd->integer || v == d->p[i] || !(v >= pd->min && v <= pd->max))
                continue;
            memcpy(p, d->p, sizeof p);
            p[i] = v;
            if (!try_variant(tr, scratch, d, d->method, p, d->dt, tol, &worst))
                continue;
            sw_fmt_shortest(num, sizeof num, v);
            sw_fmt_shortest(want_num, sizeof want_num, d->p[i]);
            snprintf(out->kind, sizeof out->kind, "parameter");
            snprintf(out->message, sizeof out->message, "your numbers match %s = %s (the assignment "
                     "has %s = %s)", pd->name, num, pd->name, want_num);
            out->agreement = worst;
            return 1;
        }
    }
    return 0;
}

/* ---- the whole --------------------------------------------------------------- */

int sw_explain(const char *path, const sw_run_desc *want, const sw_check_tol *tol,
               sw_explanation *out, char *err, size_t errlen)
{
    memset(out, 0, sizeof *out);
    out->agreement = NAN;
    sw_trace_reader r;
    int rc = sw_trace_read_open(&r, path, err, errlen);
    if (rc != SW_OK)
        return rc;
    rc = sw_trace_read_header(&r, err, errlen);
    int ncols = r.ncols, dim = r.sys.ode->dim;
    /* Rows examined: bounded in count, values and the work of one run. */
    double every = (double)want->spec.every, evals = want->method->evals > 0 ? want->method->evals : 1;
    double by_work = VARIANT_WORK / (every * dim * evals * 6.0);
    int max = SW_EXPLAIN_ROWS;
    if (max > 2000000 / ncols)
        max = 2000000 / ncols;
    if (max > by_work)
        max = (int)by_work;
    if (max < 2)
        max = 2;
    rowset tr = { malloc((size_t)max * (size_t)ncols * sizeof(double)),
                  malloc((size_t)max * sizeof(long)), 0, ncols };
    rowset ref = { malloc((size_t)(max + 1) * (size_t)ncols * sizeof(double)), NULL, 0, ncols };
    if (!tr.v || !tr.line || !ref.v) {
        snprintf(err, errlen, "out of memory for %d rows of %d values", max, ncols);
        rc = SW_ENOMEM;
    }
    while (rc == SW_OK && tr.n < max) {
        int got = sw_trace_read_row(&r, row_at(&tr, tr.n), err, errlen);
        if (got < 0)
            rc = got;
        if (got <= 0)
            break;
        tr.line[tr.n++] = r.line;
    }
    sw_trace_meta said = r.meta;
    sw_trace_read_close(&r);
    int found = 0;
    if (rc == SW_OK && tr.n > 0) {
        ref.n = run_rows(want, want->method, want->p, want->dt, max + 1, &ref);
        if (ref.n > 0) {
            found = explain_rows(&tr, &ref, tol, out);
            if (!found && ref.n >= tr.n)
                found = explain_format(&tr, &ref, want, tol, out);
        }
        /* Variant runs compare row for row, so only when no row is missing. */
        if (!found && ref.n >= 0)
            found = explain_runs(&tr, &ref, want, &said, tol, out);
    }
    free(tr.v);
    free(tr.line);
    free(ref.v);
    return rc == SW_OK ? found : rc;
}
