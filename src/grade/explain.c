/* The explaining checker. The first rows of a trace (or of a plugin's run)
 * are held in memory and compared, with the grading tolerances, against
 * runs that make one usual mistake each; the first run that matches every
 * value names the mistake. Data mistakes (rows, time column, digits,
 * precision, units) are tried first, since they need no new run, then the
 * initial state and the energy column (explain_state.c), then mistaken
 * methods (the method row's list, engine/mistakes.c), steps and parameters.
 * Invariant: a variant is reported only when it matches every examined
 * value, never because it is merely closer; rows the assignment's own run
 * matches are never explained. */
#include "grade/explain.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/mistakes.h"
#include "engine/stepper.h"
#include "grade/assignment.h"
#include "grade/explain_int.h"
#include "plugin/plugin.h"
#include "stepwise/stepwise.h"

/* Most work a variant run may take: state components x evaluations. */
#define VARIANT_WORK 2e8



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


static int explain_rows(const xpl_rows *tr, const xpl_rows *ref, const sw_check_tol *tol,
                        sw_explanation *out)
{
    int n = tr->n < ref->n ? tr->n : ref->n, i = 0;
    while (i < n && xpl_row(tr, i)[0] == xpl_row(ref, i)[0])
        i++;
    if (i == n)
        return 0;
    long got = (long)xpl_row(tr, i)[0], want = (long)xpl_row(ref, i)[0];
    double worst;
    xpl_rows shifted = *tr;
    if (i + 1 < ref->n && got == (long)xpl_row(ref, i + 1)[0]) {
        /* A row is missing: the trace's row i is the reference's row i + 1. */
        xpl_rows later = { xpl_row(ref, i + 1), ref->line, ref->n - i - 1, ref->ncols };
        shifted.v = xpl_row(tr, i);
        int m = (tr->n - i < later.n ? tr->n - i : later.n);
        if (xpl_rows_match(&shifted, &later, m, tol, -1, 1.0, &worst) && i > 0 &&
            xpl_rows_match(tr, ref, i, tol, -1, 1.0, &worst)) {
            snprintf(out->kind, sizeof out->kind, "missing-row");
            snprintf(out->message, sizeof out->message, "your trace has no row for step %ld (line %ld "
                     "holds step %ld): every row after it is one row early", want, tr->line[i], got);
            return 1;
        }
        if (i == 0 && xpl_rows_match(&shifted, &later, m, tol, -1, 1.0, &worst)) {
            snprintf(out->kind, sizeof out->kind, "missing-row");
            snprintf(out->message, sizeof out->message, "your trace has no row for step 0 (the "
                     "initial state): it starts at step %ld, so every row is one step off; write "
                     "the state once before the first step", got);
            return 1;
        }
    }
    if (i > 0 && got == (long)xpl_row(ref, i - 1)[0]) {
        snprintf(out->kind, sizeof out->kind, "duplicate-row");
        snprintf(out->message, sizeof out->message, "step %ld appears twice (lines %ld and %ld): "
                 "write each step's row once", got, tr->line[i - 1], tr->line[i]);
        return 1;
    }
    return 0;
}

static int explain_format(const xpl_rows *tr, const xpl_rows *ref, const sw_run_desc *want,
                          const sw_check_tol *tol, sw_explanation *out)
{
    int n = tr->n < ref->n ? tr->n : ref->n;
    double worst;
    char how[40];
    /* The t column one step off, every other column right. */
    if (n > 1 && xpl_rows_match(tr, ref, n, tol, 1, 1.0, &worst)) {
        double d = xpl_row(tr, 1)[1] - xpl_row(ref, 1)[1];
        int same = fabs(fabs(d) - want->dt) <= 1e-6 * want->dt;
        for (int i = 1; same && i < n; i++)
            same = fabs(xpl_row(tr, i)[1] - xpl_row(ref, i)[1] - d) <= 1e-6 * want->dt;
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
            double v = xpl_row(tr, i)[c];
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
    if (most <= 12 && xpl_rows_match(tr, ref, n, tol, -1, 0.6 * pow(10.0, 10 - most), &worst)) {
        xpl_agree(how, sizeof how, worst);
        snprintf(out->kind, sizeof out->kind, "digits");
        snprintf(out->message, sizeof out->message, "your values have at most %d significant "
                 "digits%s and match %s %s: print with %%.17g so they round-trip", most,
                 most <= 6 ? " (as printf's %g prints them)" : "", want->method->name, how);
        out->agreement = worst;
        return 1;
    }
    int m = n < 50 ? n : 50;
    if (floats >= values * 9 / 10 && most > 6 && xpl_rows_match(tr, ref, m, tol, -1, 1e5, &worst)) {
        xpl_agree(how, sizeof how, worst);
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

/* What to ask a student whose numbers for want match got: the row's own
 * question when got is the method students write instead (its twin). */
static void method_hint(const sw_integrator *want, const sw_integrator *got, char *buf, size_t len)
{
    if (want->twin && want->twin_hint && strcmp(got->name, want->twin) == 0)
        snprintf(buf, len, "%s", want->twin_hint);
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

static int try_variant(const xpl_rows *tr, xpl_rows *scratch, const sw_run_desc *d,
                       const sw_integrator *m, const double *p, double dt, const sw_check_tol *tol,
                       double *worst)
{
    int got = xpl_run_rows(d, m, p, dt, NULL, tr->n, scratch);
    return got == tr->n && xpl_rows_match(tr, scratch, got, tol, -1, 1.0, worst);
}

/* A mistaken version of the method, another method, dt doubled or halved.
 * The mistaken versions come first: on a linear system (the projectile with
 * drag) Verlet recomputing a(x, v) is a two-stage second-order Runge-Kutta
 * method and so gives midpoint's numbers, and a student set Verlet more
 * likely wrote a Verlet. said is the trace's header, NULL for a plugin's run. */
static int explain_methods(const xpl_rows *tr, xpl_rows *scratch, const sw_run_desc *d,
                           const sw_trace_meta *said, const sw_check_tol *tol, sw_explanation *out)
{
    double worst;
    char how[40], hint[200], num[40], want_num[40];
    int timed = -1;
    for (const sw_mistake *mk = d->method->mistakes; mk && mk->kind; mk++) {
        if (mk->time_only && timed < 0)
            timed = time_dependent(d);
        if ((mk->time_only && !timed) || !try_variant(tr, scratch, d, &mk->method, d->p, d->dt, tol, &worst))
            continue;
        xpl_agree(how, sizeof how, worst);
        snprintf(out->kind, sizeof out->kind, "%s", mk->kind);
        snprintf(out->message, sizeof out->message, "your numbers match %s (%s)%s%s%s", mk->hint, how,
                 mk->time_only ? " (this scene changes with time, so stage times matter)" : "",
                 mk->fix ? ": " : "", mk->fix ? mk->fix : "");
        out->agreement = worst;
        return 1;
    }
    for (int i = 0; i < sw_integrator_count(); i++) {
        const sw_integrator *m = sw_integrator_at(i);
        if (m == d->method || (m->flags & SW_PLUGIN) ||
            !try_variant(tr, scratch, d, m, d->p, d->dt, tol, &worst))
            continue;
        xpl_agree(how, sizeof how, worst);
        method_hint(d->method, m, hint, sizeof hint);
        snprintf(out->kind, sizeof out->kind, "method");
        if (said && strcmp(said->integrator, d->method->name) == 0)
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
    return 0;
}

/* Another parameter value. Candidates: the value the trace's header gives,
 * the default, and the assignment's value doubled, halved, times and over
 * ten. */
static int explain_params(const xpl_rows *tr, xpl_rows *scratch, const sw_run_desc *d,
                          const sw_trace_meta *said, const sw_check_tol *tol, sw_explanation *out)
{
    static const double factors[] = { -1, 0, 2, 0.5, 10, 0.1 };
    const sw_scene *sc = d->scene;
    double worst;
    char num[40], want_num[40];
    for (int i = 0; i < sc->nparams; i++) {
        const sw_param *pd = &sc->params[i];
        for (size_t f = 0; f < sizeof factors / sizeof factors[0]; f++) {
            double p[SW_MAX_PARAMS];
            double v = factors[f] < 0 ? (said && said->scene == sc ? said->p[i] : d->p[i])
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

/* Rows examined for a run of want with ncols columns and dim state
 * components: bounded in count, values and the work of one run. */
static int rows_budget(const sw_run_desc *want, int ncols, int dim)
{
    double every = (double)want->spec.every, evals = want->method->evals > 0 ? want->method->evals : 1;
    double by_work = VARIANT_WORK / (every * dim * evals * 6.0);
    int max = SW_EXPLAIN_ROWS;
    if (max > 2000000 / ncols)
        max = 2000000 / ncols;
    if (max > by_work)
        max = (int)by_work;
    return max < 2 ? 2 : max;
}

/* Every finder in turn on the rows tr (at most max of them). */
static int explain_all(const xpl_rows *tr, int max, const sw_run_desc *want,
                       const sw_trace_meta *said, const sw_check_tol *tol, sw_explanation *out,
                       char *err, size_t errlen)
{
    int ncols = tr->ncols;
    xpl_rows ref = { malloc((size_t)(max + 1) * (size_t)ncols * sizeof(double)), NULL, 0, ncols };
    xpl_rows scratch = { malloc((size_t)(max + 1) * (size_t)ncols * sizeof(double)), NULL, 0, ncols };
    if (!ref.v || !scratch.v) {
        free(ref.v);
        free(scratch.v);
        snprintf(err, errlen, "out of memory for %d rows of %d values", max, ncols);
        return SW_ENOMEM;
    }
    int found = 0;
    double worst;
    ref.n = xpl_run_rows(want, want->method, want->p, want->dt, NULL, max + 1, &ref);
    if (ref.n > 0 && tr->n > 0) {
        found = explain_rows(tr, &ref, tol, out);
        /* Rows the assignment's own run matches leave nothing to explain. */
        if (!found && ref.n >= tr->n && xpl_rows_match(tr, &ref, tr->n, tol, -1, 1.0, &worst))
            goto done;
        if (!found && ref.n >= tr->n)
            found = explain_format(tr, &ref, want, tol, out);
        /* Before the initial state: positions in cm differ at row 0 too,
         * and "x0 = 150 in yours, 1.5" would hide the factor. */
        if (!found && ref.n >= tr->n)
            found = xpl_units(tr, &ref, want, tol, out);
        sw_explanation start;
        memset(&start, 0, sizeof start);
        start.agreement = NAN;
        if (!found && ref.n >= tr->n && xpl_initial_state(tr, &ref, want, tol, &start)) {
            /* The initial state differs: no method or step explains that,
             * a parameter may (it is the better answer: "pluck = 0.6"). */
            found = explain_params(tr, &scratch, want, said, tol, out);
            if (!found) {
                *out = start;
                found = 1;
            }
            goto done;
        }
        if (!found && ref.n >= tr->n)
            found = xpl_energy(tr, &ref, want, tol, out);
    }
    /* Variant runs compare row for row, so only when no row is missing. */
    if (!found && ref.n >= 0)
        found = explain_methods(tr, &scratch, want, said, tol, out) ||
                explain_params(tr, &scratch, want, said, tol, out);
done:
    free(ref.v);
    free(scratch.v);
    return found;
}

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
    int ncols = r.ncols, max = rows_budget(want, ncols, r.sys.ode->dim);
    xpl_rows tr = { malloc((size_t)max * (size_t)ncols * sizeof(double)),
                    malloc((size_t)max * sizeof(long)), 0, ncols };
    if (!tr.v || !tr.line) {
        snprintf(err, errlen, "out of memory for %d rows of %d values", max, ncols);
        rc = SW_ENOMEM;
    }
    while (rc == SW_OK && tr.n < max) {
        int got = sw_trace_read_row(&r, xpl_row(&tr, tr.n), err, errlen);
        if (got < 0)
            rc = got;
        if (got <= 0)
            break;
        tr.line[tr.n++] = r.line;
    }
    sw_trace_meta said = r.meta;
    sw_trace_read_close(&r);
    int found = 0;
    if (rc == SW_OK && tr.n > 0)
        found = explain_all(&tr, max, want, &said, tol, out, err, errlen);
    free(tr.v);
    free(tr.line);
    return rc == SW_OK ? found : rc;
}

int sw_explain_run(const sw_integrator *got, const sw_run_desc *want, const sw_check_tol *tol,
                   sw_explanation *out, char *err, size_t errlen)
{
    memset(out, 0, sizeof *out);
    out->agreement = NAN;
    sw_sim s;
    int rc = sw_sim_init(&s, want->scene, want->p, got, want->dt, err, errlen);
    if (rc != SW_OK)
        return rc;
    sw_sim_set_tolerances(&s, want->rtol, want->atol);
    int ncols = sw_trace_ncols(&s.sys), max = rows_budget(want, ncols, s.sys.ode->dim);
    xpl_rows tr = { malloc((size_t)max * (size_t)ncols * sizeof(double)),
                    calloc((size_t)max, sizeof(long)), 0, ncols };
    if (!tr.v || !tr.line) {
        snprintf(err, errlen, "out of memory for %d rows of %d values", max, ncols);
        rc = SW_ENOMEM;
    }
    sw_row_source src = { .sim = &s, .spec = want->spec };
    long line;
    /* A run that fails part way gives the rows it made. */
    while (rc == SW_OK && tr.n < max && !sw_plugin_failed(&s) &&
           sw_row_next(&src, xpl_row(&tr, tr.n), &line, err, errlen) == 1)
        tr.n++;
    int failed = sw_plugin_failed(&s) != SW_PF_NONE;
    sw_sim_free(&s);
    int found = 0;
    if (rc == SW_OK && tr.n > 0 && !failed)
        found = explain_all(&tr, max, want, NULL, tol, out, err, errlen);
    free(tr.v);
    free(tr.line);
    return rc == SW_OK ? found : rc;
}
