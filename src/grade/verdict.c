/* A check from request to verdict. Invariants: a failed plugin (crash,
 * exit, loop, overrun) on either side is a failure, whatever the values
 * say; a header that differs from the assignment is a failure; memory is
 * two rows plus the explainer's bounded prefix. */
#include "grade/verdict.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grade/points.h"
#include "measure/measure.h"
#include "plugin/plugin.h"
#include "stepwise/stepwise.h"

void sw_check_request_init(sw_check_request *req)
{
    memset(req, 0, sizeof *req);
    req->spec.every = 1;
    req->explain = 1;
}

int sw_check_budget(const sw_scene *sc, const double *p, const sw_integrator *m, double dt,
                    const sw_trace_spec *spec, double *work, char *err, size_t errlen)
{
    sw_system sys;
    if (sw_system_build(&sys, sc, p, err, errlen) != SW_OK)
        return SW_EINVAL;
    int dim = sys.ode->dim;
    sw_system_free(&sys);
    double steps = spec->steps > 0 ? (double)spec->steps : ceil(spec->until / dt) + 1;
    double evals = m->evals > 0 ? m->evals : 1;
    if (m->flags & SW_IMPLICIT)
        evals *= 10; /* Newton iterations and linear solves */
    *work = steps * dim * evals;
    if (*work > SW_CHECK_WORK_BUDGET) {
        snprintf(err, errlen, "the run needs %.3g steps x %d state components x %g evaluations "
                 "= %.3g, above the budget of %.3g (docs/trace-format.md, Limits): shorten the "
                 "run, raise dt or use fewer particles", steps, dim, evals, *work,
                 SW_CHECK_WORK_BUDGET);
        return SW_EINVAL;
    }
    return SW_OK;
}

int sw_record_budget(const sw_scene *sc, const double *p, double dt, const sw_trace_spec *spec,
                     char *err, size_t errlen)
{
    sw_system sys;
    if (sw_system_build(&sys, sc, p, err, errlen) != SW_OK)
        return SW_EINVAL;
    int ncols = sw_trace_ncols(&sys);
    sw_system_free(&sys);
    double steps = spec->steps > 0 ? (double)spec->steps : ceil(spec->until / dt) + 1;
    double rows = floor(steps / (double)spec->every) + 2, values = rows * ncols;
    if (values > SW_RECORD_VALUE_BUDGET) {
        snprintf(err, errlen, "the trace would hold %.3g rows x %d columns = %.3g values, above "
                 "the budget of %.3g (docs/trace-format.md, Limits): record every K-th step "
                 "(--every), shorten the run or use fewer particles", rows, ncols, values,
                 SW_RECORD_VALUE_BUDGET);
        return SW_EINVAL;
    }
    return SW_OK;
}

/* ---- words ----------------------------------------------------------------- */

static void colname(const sw_system *sys, int c, char *buf, size_t len)
{
    if (c < 0)
        snprintf(buf, len, "(row)");
    else
        sw_trace_colname(sys, c, buf, len);
}

static void describe_cell(const sw_system *sys, const sw_check_cell *c, char *buf, size_t len)
{
    char name[32], where[40] = "", e[40], g[40];
    colname(sys, c->column, name, sizeof name);
    if (c->line > 0)
        snprintf(where, sizeof where, " (line %ld)", c->line);
    sw_fmt_shortest(e, sizeof e, c->expected);
    sw_fmt_shortest(g, sizeof g, c->got);
    snprintf(buf, len, "step %ld, t = %g, column %s%s: expected %s, got %s (relative error "
             "%.3g)", c->step, c->t, name, where, e, g, c->rel_err);
}

static void run_end(sw_sim *s, sw_run_end *end)
{
    memset(end, 0, sizeof *end);
    end->fault = sw_plugin_failed(s);
    end->blown = s->blown;
    end->step = s->blow_step;
    end->t = s->blow_time;
    snprintf(end->reason, sizeof end->reason, "%s", s->blow_reason);
}

static void words(sw_verdict *v, const sw_system *sys, int is_trace)
{
    const sw_check_result *res = &v->res;
    const sw_check_cell *c = &res->first;
    v->failing_step = -1;
    if (res->have_first) {
        v->failing_step = c->step;
        colname(sys, c->column, v->first_column, sizeof v->first_column);
        if (c->kind == SW_CHECK_VALUE)
            describe_cell(sys, c, v->first, sizeof v->first);
        else if (c->kind == SW_CHECK_MISSING)
            snprintf(v->first, sizeof v->first, "the %s ends after step %ld with %ld rows; the "
                     "reference goes on to step %ld (%ld rows)", is_trace ? "trace" : "plugin run",
                     res->last_step_got, res->rows_got, res->last_step_expected, res->rows_expected);
        else {
            char where[40] = "";
            if (c->line > 0)
                snprintf(where, sizeof where, " on line %ld", c->line);
            snprintf(v->first, sizeof v->first, "the %s goes on past the reference's last step "
                     "%ld: step %ld%s; %ld rows against the reference's %ld",
                     is_trace ? "trace" : "plugin run", res->last_step_expected, c->step, where,
                     res->rows_got, res->rows_expected);
        }
    }
    if (res->have_worst) {
        colname(sys, res->worst.column, v->worst_column, sizeof v->worst_column);
        describe_cell(sys, &res->worst, v->worst, sizeof v->worst);
    }
}

/* The one-line verdict, most telling fact first. */
static void message(sw_verdict *v, const char *what)
{
    size_t used = 0, len = sizeof v->message;
    char *m = v->message;
    const sw_run_end *plugin = v->got_end.fault ? &v->got_end : v->ref_end.fault ? &v->ref_end : NULL;
    if (v->status == SW_VERDICT_PASS) {
        snprintf(m, len, "PASS: %s matches %s: %ld rows, %ld values within |got - expected| <= "
                 "%g + %g*|expected|%s%s%s", what, v->reference, v->res.rows_compared,
                 v->res.values_compared, v->atol, v->rtol, v->warning[0] ? " (warning: " : "",
                 v->warning, v->warning[0] ? ")" : "");
        return;
    }
    used += (size_t)snprintf(m + used, len - used, "FAIL: %s", what);
    if (plugin)
        used += (size_t)snprintf(m + used, len - used, ": %s", plugin->reason);
    else if (v->ndiffs > 0) {
        const sw_header_diff *d = &v->diffs[0];
        char line[32] = "";
        if (d->line > 0)
            snprintf(line, sizeof line, " (line %ld)", d->line);
        used += (size_t)snprintf(m + used, len - used, ": header differs from the assignment in %d "
                                 "place%s; %s: yours %s%s, the assignment's %s", v->ndiffs,
                                 v->ndiffs == 1 ? "" : "s", d->what, d->got, line, d->want);
    } else
        used += (size_t)snprintf(m + used, len - used, " differs from %s", v->reference);
    if (used < len && v->have_explanation)
        used += (size_t)snprintf(m + used, len - used, "; %s", v->explanation.message);
    else if (used < len && !plugin && v->got_end.blown && !v->ref_end.blown)
        used += (size_t)snprintf(m + used, len - used, "; the plugin's run ended at step %ld (t = %g): %s",
                                 v->got_end.step, v->got_end.t, v->got_end.reason);
    else if (used < len && !plugin && v->first[0])
        used += (size_t)snprintf(m + used, len - used, "; first failure: %s", v->first);
    else if (used < len && !v->comparable)
        used += (size_t)snprintf(m + used, len - used, "; the numbers were not compared (other "
                                 "columns)");
    if (used < len && v->warning[0])
        used += (size_t)snprintf(m + used, len - used, " (warning: %s)", v->warning);
    (void)used;
}

/* ---- tolerances ------------------------------------------------------------- */

typedef struct tol_arrays {
    double *rtol, *atol;
    unsigned char *ignore;
    long *col_failed;
    sw_check_cell *col_first;
    double *col_worst;
    sw_check_tol tol;
} tol_arrays;

static int make_tol(const sw_check_request *req, const sw_system *sys, sw_verdict *v,
                    tol_arrays *t)
{
    const sw_assignment *a = req->assignment;
    v->rtol = req->rtol > 0 ? req->rtol : a ? a->rtol : SW_CHECK_RTOL;
    v->atol = req->atol > 0 ? req->atol : a ? a->atol : SW_CHECK_ATOL;
    sw_coltols all;
    memset(&all, 0, sizeof all);
    if (a)
        all = a->coltols;
    for (int i = 0; i < req->coltols.n && all.n < SW_COLTOL_MAX; i++)
        all.cols[all.n++] = req->coltols.cols[i];
    int n = sw_trace_ncols(sys);
    t->rtol = malloc((size_t)n * (2 * sizeof(double) + 1));
    if (!t->rtol) {
        snprintf(v->error, sizeof v->error, "out of memory for %d columns", n);
        return SW_ENOMEM;
    }
    t->atol = t->rtol + n;
    t->ignore = (unsigned char *)(t->rtol + 2 * n);
    t->col_failed = calloc((size_t)n, sizeof *t->col_failed);
    t->col_first = calloc((size_t)n, sizeof *t->col_first);
    t->col_worst = calloc((size_t)n, sizeof *t->col_worst);
    if (!t->col_failed || !t->col_first || !t->col_worst) {
        snprintf(v->error, sizeof v->error, "out of memory for %d columns", n);
        return SW_ENOMEM;
    }
    t->tol = (sw_check_tol){ v->rtol, v->atol, t->rtol, t->atol, t->ignore, t->col_failed,
                             t->col_first, t->col_worst };
    return sw_coltol_resolve(&all, sys, v->rtol, v->atol, t->rtol, t->atol, t->ignore, v->error,
                             sizeof v->error);
}

static void free_tol(tol_arrays *t)
{
    free(t->rtol);
    free(t->col_failed);
    free(t->col_first);
    free(t->col_worst);
}

/* ---- points ------------------------------------------------------------------ */

/* Whether the assignment pays for the stability limit. */
static int pays_stability(const sw_assignment *a)
{
    for (int i = 0; a && i < a->points.n; i++)
        if (a->points.items[i].kind == SW_POINTS_STABILITY)
            return 1;
    return 0;
}

/* The assignment's checks, scored from what the check found. */
static void score(sw_verdict *v, const sw_check_request *req, const sw_system *sys,
                  const tol_arrays *t, const sw_integrator *ref)
{
    const sw_assignment *a = req->assignment;
    if (!a)
        return;
    char header[700] = "", rows[600] = "";
    size_t used = 0;
    for (int i = 0; i < v->ndiffs && i < SW_VERDICT_DIFFS && used < sizeof header; i++) {
        const sw_header_diff *d = &v->diffs[i];
        char line[32] = "";
        if (d->line > 0)
            snprintf(line, sizeof line, " (line %ld)", d->line);
        used += (size_t)snprintf(header + used, sizeof header - used, "%s%s: yours %s%s, the "
                                 "assignment's %s", i ? "; " : "", d->what, d->got, line, d->want);
    }
    const sw_run_end *pf = v->got_end.fault ? &v->got_end : v->ref_end.fault ? &v->ref_end : NULL;
    int rows_differ = v->res.rows_expected != v->res.rows_got || (t && t->col_failed[0] > 0);
    if (rows_differ && v->res.have_first && v->res.first.column <= 0)
        snprintf(rows, sizeof rows, "%s", v->first);
    /* the method's limit measured as the plugin's was (an honest
     * symplectic Euler or Verlet gets the figure of its method, not 15 %
     * less): measure() put it beside the plugin's */
    double want_stab = ref && req->plugin && v->have_measure ? v->ref_stability : NAN;
    sw_score_facts f = {
        .is_plugin = req->plugin != NULL,
        .usable = sys != NULL && t != NULL,
        .error = v->error,
        .ndiffs = v->ndiffs,
        .header_words = header,
        .comparable = v->comparable,
        .fault = pf ? pf->reason : NULL,
        .fault_is_limit = pf && pf->fault == SW_PF_LIMIT,
        .rows_differ = rows_differ,
        .rows_words = rows,
        .sys = sys,
        .col_failed = t ? t->col_failed : NULL,
        .col_first = t ? t->col_first : NULL,
        .col_worst = t ? t->col_worst : NULL,
        .explanation = v->have_explanation ? v->explanation.message : NULL,
        .order = v->have_measure ? v->order : NAN,
        .expected_order = ref ? (double)ref->order : NAN,
        .stability = v->have_measure ? v->stability : NAN,
        .expected_stability = want_stab,
        .stability_decided = v->stability_decided,
        .stability_given = v->stability_given,
        .measure_note = v->measure_note,
    };
    sw_points_score(&a->points, &f, &v->score);
}

static sw_verdict_status error(sw_verdict *v, const char *msg)
{
    if (msg != v->error)
        snprintf(v->error, sizeof v->error, "%s", msg);
    v->status = SW_VERDICT_ERROR;
    snprintf(v->message, sizeof v->message, "ERROR: %.1500s", v->error);
    return v->status;
}

/* ---- a trace ----------------------------------------------------------------- */

static void fill_desc(sw_run_desc *d, const sw_scene *sc, const double *p, const sw_integrator *m,
                      double dt, const sw_trace_spec *spec, double rtol, double atol)
{
    d->scene = sc;
    memcpy(d->p, p, sizeof d->p);
    d->method = m;
    d->dt = dt;
    d->spec = *spec;
    d->rtol = rtol;
    d->atol = atol;
}

static sw_verdict_status check_trace(const sw_check_request *req, sw_verdict *v)
{
    sw_trace_reader got, ref;
    sw_sim sim;
    int have_ref = 0, have_sim = 0;
    sw_row_source src_e = { 0 }, src_g = { 0 };
    tol_arrays tol = { 0 };
    sw_run_desc desc;
    char msg[SW_ERRLEN + SW_TRACE_PATH_MAX];
    v->trace = req->trace;
    if (sw_trace_read_open(&got, req->trace, msg, sizeof msg) != SW_OK)
        return error(v, msg);
    const sw_trace_meta *gm = &got.meta;
    snprintf(v->student, sizeof v->student, "%s", gm->student);
    snprintf(v->notes, sizeof v->notes, "%s", gm->notes);
    snprintf(v->scene, sizeof v->scene, "%s", gm->scene->name);
    v->dt = gm->dt;
    v->ncols = got.ncols;
    v->comparable = 1;
    const sw_assignment *a = req->assignment;
    int rc = SW_OK;
    if (req->against) {
        v->against = req->against;
        v->dt = NAN;
        snprintf(v->reference, sizeof v->reference, "the trace %s", req->against);
        rc = sw_trace_read_open(&ref, req->against, msg, sizeof msg);
        have_ref = rc == SW_OK;
        if (rc == SW_OK && (ref.meta.scene != gm->scene || ref.ncols != got.ncols)) {
            snprintf(msg, sizeof msg, "%s:%ld: a '%s' trace with %d columns cannot be compared "
                     "with %s, a '%s' trace with %d columns", req->trace, gm->scene_line,
                     gm->scene->name, got.ncols, req->against, ref.meta.scene->name, ref.ncols);
            rc = SW_EINVAL;
        }
        if (rc == SW_OK && ref.meta.events != gm->events) {
            snprintf(msg, sizeof msg, "%s was recorded with events %s and %s with events %s: runs "
                     "that meet events differently cannot be compared (record with --events %s)",
                     req->trace, sw_events_mode_name(gm->events), req->against,
                     sw_events_mode_name(ref.meta.events), sw_events_mode_name(ref.meta.events));
            rc = SW_EINVAL;
        }
        if (rc == SW_OK)
            rc = sw_trace_read_header(&ref, msg, sizeof msg);
        src_e.reader = &ref;
    } else {
        const sw_integrator *m = req->reference;
        if (a) {
            v->assignment = a->path;
            v->ndiffs = sw_assignment_diff(a, gm, &got.sys, v->diffs, SW_VERDICT_DIFFS, &v->comparable);
            if (!m)
                m = sw_assignment_method(a, gm);
            fill_desc(&desc, a->meta.scene, a->meta.p, m, a->meta.dt, &a->meta.spec, a->meta.rtol,
                      a->meta.atol);
        } else {
            if (!m)
                m = gm->method;
            fill_desc(&desc, gm->scene, gm->p, m, gm->dt, &gm->spec, gm->rtol, gm->atol);
        }
        double work;
        const char *file = a ? a->path : req->trace;
        long line = a ? a->meta.steps_line : gm->steps_line;
        if (m && sw_check_budget(desc.scene, desc.p, m, desc.dt, &desc.spec, &work, msg, sizeof msg) != SW_OK) {
            char inner[SW_ERRLEN];
            snprintf(inner, sizeof inner, "%.200s", msg);
            snprintf(msg, sizeof msg, "%.200s:%ld: %s", file, line > 0 ? line : 1, inner);
            rc = SW_EINVAL;
        } else if (!v->comparable) {
            rc = SW_OK; /* header differences only */
        } else if (a) {
            rc = sw_assignment_sim(a, m, &sim, msg, sizeof msg);
        } else
            rc = sw_trace_meta_sim(&got, &sim, m, msg, sizeof msg);
        have_sim = rc == SW_OK && v->comparable;
        if (have_sim) {
            snprintf(v->method, sizeof v->method, "%s", sim.method->name);
            if (a)
                snprintf(v->reference, sizeof v->reference, "%s on %s as the assignment %.200s sets it",
                         sim.method->name, desc.scene->name, a->path);
            else
                snprintf(v->reference, sizeof v->reference, "%s on %s, regenerated from the "
                         "trace's metadata%s", sim.method->name, v->scene,
                         req->reference ? " with --reference" : "");
            src_e.sim = &sim;
            src_e.spec = desc.spec;
        } else if (rc == SW_OK)
            snprintf(v->reference, sizeof v->reference, "the assignment %.200s", a->path);
    }
    if (rc == SW_OK)
        rc = sw_trace_read_header(&got, msg, sizeof msg);
    if (rc == SW_OK && got.ignored[0])
        snprintf(v->warning, sizeof v->warning, "column%s %.100s ignored: not in a %s trace",
                 strchr(got.ignored, ',') ? "s" : "", got.ignored, gm->scene->name);
    if (rc == SW_OK)
        rc = make_tol(req, &got.sys, v, &tol);
    if (rc != SW_OK && !v->error[0])
        snprintf(v->error, sizeof v->error, "%s", msg);
    if (rc == SW_OK && (have_sim || have_ref)) {
        src_g.reader = &got;
        rc = sw_check_compare_tol(&src_e, &src_g, got.ncols, &tol.tol, &v->res, msg, sizeof msg);
        if (rc != SW_OK)
            snprintf(v->error, sizeof v->error, "%s", msg);
    } else if (rc == SW_OK)
        v->res.pass = 0;
    if (rc == SW_OK) {
        if (have_sim)
            run_end(&sim, &v->ref_end);
        words(v, &got.sys, 1);
        int pass = v->res.pass && v->ndiffs == 0 && v->comparable && v->ref_end.fault == SW_PF_NONE;
        v->status = pass ? SW_VERDICT_PASS : SW_VERDICT_FAIL;
        if (!pass && req->explain && have_sim && v->ref_end.fault == SW_PF_NONE &&
            !(desc.method->flags & SW_PLUGIN)) {
            sw_explanation ex;
            if (sw_explain(req->trace, &desc, &tol.tol, &ex, msg, sizeof msg) == 1) {
                v->explanation = ex;
                v->have_explanation = 1;
            }
        }
        if (v->ref_end.fault != SW_PF_NONE)
            v->failing_step = v->ref_end.step;
        score(v, req, &got.sys, &tol, NULL);
        message(v, req->trace);
    }
    free_tol(&tol);
    if (have_sim)
        sw_sim_free(&sim);
    if (have_ref)
        sw_trace_read_close(&ref);
    sw_trace_read_close(&got);
    return rc == SW_OK ? v->status : error(v, v->error);
}

/* ---- a plugin ---------------------------------------------------------------- */

/* The graded run's end under m (0), or -1 where m cannot run it. */
static int run_end_state(const sw_integrator *m, const sw_measure_probe *pr, double *y, int dim)
{
    sw_sim s;
    char err[SW_ERRLEN];
    if (sw_sim_init(&s, pr->scene, pr->p, m, pr->dt, err, sizeof err) != SW_OK)
        return -1;
    int ok = s.sys.ode->dim == dim;
    while (ok && s.steps < pr->graded_steps && !s.blown)
        sw_sim_step_until(&s, pr->stop_at);
    ok = ok && !s.blown && s.steps == pr->graded_steps;
    if (ok)
        memcpy(y, s.sys.y, (size_t)dim * sizeof *y);
    sw_sim_free(&s);
    return ok ? 0 : -1;
}

/* A built-in explicit fixed-step method of lower order than ref whose run
 * ends within the tolerance of ref's (the run cannot tell it from ref), or
 * NULL. (Implicit ones are no witnesses the explicit ones are not, and on
 * a large system cost a factorisation a step.) */
static const sw_integrator *run_cannot_tell(const sw_verdict *v, const sw_integrator *ref, const sw_measure_probe *pr,
                                            int dim)
{
    double *want = malloc(2 * (size_t)dim * sizeof *want), *got = want ? want + dim : NULL;
    const sw_integrator *same = NULL;
    if (!want || run_end_state(ref, pr, want, dim) != 0) {
        free(want);
        return NULL;
    }
    for (int i = 0; !same && i < sw_integrator_count(); i++) {
        const sw_integrator *m = sw_integrator_at(i);
        if (m->order >= ref->order || (m->flags & (SW_ADAPTIVE | SW_PLUGIN | SW_IMPLICIT)) ||
            run_end_state(m, pr, got, dim) != 0)
            continue;
        int within = 1;
        for (int k = 0; within && k < dim; k++)
            within = fabs(got[k] - want[k]) <= v->atol + v->rtol * fabs(want[k]);
        same = within ? m : NULL;
    }
    free(want);
    return same;
}

/* Where the graded run cannot show an order (the plugin's failed with
 * `why`), as the reference method's own measure on it says (errors at
 * round-off, events at step ends, no reference to measure against): the
 * order on the undamped spring instead, as before the probe, believed only
 * where the graded values matched (the spring is a system a plugin could
 * tell apart). 1 with v->order set, 0 with v->measure_note saying why not. */
static int order_on_spring(sw_verdict *v, const sw_integrator *plugin, const sw_integrator *ref,
                           const sw_measure_probe *pr, const char *why, int dim)
{
    sw_measure_probe as_ref = *pr;
    as_ref.graded_y = NULL; /* the plugin's last state is not the reference's */
    as_ref.whole = NULL;
    double ref_order;
    char rwhy[SW_ERRLEN];
    if (sw_measure_order_on(ref, &as_ref, &ref_order, NULL, rwhy, sizeof rwhy) == SW_OK) {
        snprintf(v->measure_note, sizeof v->measure_note, "order not measured: %.540s", why);
        return 0;
    }
    if (v->status != SW_VERDICT_PASS) {
        snprintf(v->measure_note, sizeof v->measure_note, "order not measured: the graded run cannot show an "
                 "order (%.120s), and the spring's is believed only where the graded values match", rwhy);
        return 0;
    }
    /* matching values say nothing of the order where a lower order's
     * values match too (midpoint is exact under gravity alone) */
    const sw_integrator *same = run_cannot_tell(v, ref, pr, dim);
    if (same) {
        snprintf(v->measure_note, sizeof v->measure_note, "order not measured: on this run %.20s (order %d) ends "
                 "within the tolerance of %.20s too, so neither it nor the spring (a system a plugin can tell "
                 "apart) shows the plugin's order: grade order on a run that shows it", same->name, same->order,
                 ref->name);
        return 0;
    }
    char swhy[600];
    if (sw_measure_order(plugin, &v->order, NULL, swhy, sizeof swhy) != SW_OK) {
        v->order = NAN;
        snprintf(v->measure_note, sizeof v->measure_note, "order not measured: %.540s", swhy);
        return 0;
    }
    v->order_on_spring = 1;
    return 1;
}

/* The stability point without the plugin's own figure: whether its limit
 * is the method's within SW_POINTS_STABILITY_MARGIN, in at most two runs
 * of it (sw_measure_stability_match) in a host of their own, on a fresh
 * grader's budget. The figure's bisection (about 10^5 steps of RK4)
 * ran a slow honest RK4 out of that budget. */
static void decide_stability(sw_verdict *v, const sw_integrator *plugin, const sw_integrator *ref,
                             long graded_steps)
{
    sw_stability_match mt;
    char why[600];
    double rel = SW_POINTS_STABILITY_MARGIN, pct = 100 * rel;
    size_t n = sizeof v->measure_note;
    /* a host afresh, its budget whole: the order's sweep used the last one's */
    sw_plugin_grader_runs(0);
    sw_plugin_grader_runs(1);
    /* what its own runs took so far (its builds and every part's graded
     * run, reaped): more than this graded run's alone, so in its favour */
    double own = sw_plugin_own_cpu();
    if (sw_measure_stability_match(plugin, ref, rel, &mt, why, sizeof why) != SW_OK) {
        /* Out of the grader's budget B after k steps: at its graded runs'
         * pace a step or near it, the plugin is slow everywhere, and the
         * grader's budget, not the plugin, is short: the point is not
         * counted against it. Much slower a step here than there, it is
         * its own doing (a plugin can tell the spring apart; red team 4:
         * the pace --cpu allowed, not the one it had, let it through). */
        double cpu = sw_plugin_cpu_limit();
        if (mt.budget && cpu > 0 && sw_measure_pace_holds(own, graded_steps, SW_GRADER_CPU(cpu), mt.steps)) {
            v->stability_decided = v->stability_given = 1;
            snprintf(v->measure_note, n, "stability not measured: the grader could not finish measuring your "
                     "method's stability within its own budget (4 x --cpu + 30 s of CPU time, never yours); "
                     "your graded values and your order match %s's, so this point is not counted against you",
                     ref->name);
        } else if (mt.budget)
            snprintf(v->measure_note, n, "stability not measured: the plugin ran out of the grader's CPU "
                     "budget (4 x --cpu + 30 s) in %ld steps of the test spring, more than %g times slower a "
                     "step than its graded runs (%ld steps here in %.3g s of CPU with its build): a method that "
                     "is slower only where it is measured gets no stability point", mt.steps,
                     SW_MEASURE_PACE_SLACK, graded_steps, own);
        else
            snprintf(v->measure_note, n, "stability not measured: %.540s", why);
        return;
    }
    v->ref_stability = mt.limit;
    v->stability_decided = 1;
    v->stability_given = mt.match;
    const char *r = ref->name;
    if (mt.kind == 1 && mt.match)
        snprintf(v->measure_note, n, "stability: none, as %s's (unstable even at omega*dt = %.4g)", r, mt.outside);
    else if (mt.kind == 1)
        snprintf(v->measure_note, n, "stability: stable at omega*dt = %.4g, where %s is not (it has no stability "
                 "limit)", mt.outside, r);
    else if (mt.kind == 2 && mt.match)
        snprintf(v->measure_note, n, "stability: unbounded, as %s's (stable at omega*dt = %.4g)", r, mt.inside);
    else if (mt.kind == 2)
        snprintf(v->measure_note, n, "stability: unstable at omega*dt = %.4g, where %s is stable (it has no "
                 "step-size limit)", mt.inside, r);
    else if (mt.match)
        snprintf(v->measure_note, n, "stability limit within %g %% of %s's (omega*dt = %.4g, measured the same "
                 "way): stable at %.4g, unstable at %.4g", pct, r, mt.limit, mt.inside, mt.outside);
    else if (mt.held_inside == 0)
        snprintf(v->measure_note, n, "stability limit below %s's: unstable at omega*dt = %.4g, %g %% under its "
                 "limit %.4g", r, mt.inside, pct, mt.limit);
    else
        snprintf(v->measure_note, n, "stability limit above %s's: stable at omega*dt = %.4g, %g %% over its "
                 "limit %.4g", r, mt.outside, pct, mt.limit);
}

/* The order on the graded run itself (the probe), the stability limit on
 * the spring once that order is the reference's: the spring is a system
 * of its own, which a plugin could tell from its graded run
 * (docs/grading.md, "What a measured figure stands on"); where the
 * assignment pays for the limit, the point is decided instead. */
static void measure(sw_verdict *v, const sw_integrator *plugin, const sw_integrator *ref,
                    const sw_sim *graded, const sw_trace_spec *spec, int decide)
{
    v->have_measure = 1;
    v->claimed_order = plugin->order;
    v->order = v->stability = NAN;
    char why[600];
    int whole = 0;
    sw_measure_probe pr = { .scene = graded->sys.scene, .p = graded->sys.p, .dt = graded->dt,
                            .stop_at = spec->steps > 0 ? 0.0 : spec->until,
                            .graded_steps = graded->steps, .graded_y = graded->sys.y, .whole = &whole };
    /* a graded run too long to run again is not */
    if ((double)graded->steps * sw_measure_step_work(&graded->sys, plugin) > SW_MEASURE_FREE)
        pr.graded_y = NULL;
    if (sw_measure_order_on(plugin, &pr, &v->order, NULL, why, sizeof why) != SW_OK &&
        !order_on_spring(v, plugin, ref, &pr, why, graded->sys.ode->dim))
        return;
    /* the method's order read on part of the graded run (or without
     * running it again) is believed only where the graded values match,
     * as the spring's: a method that changes after that part shows there */
    if (!whole && !v->order_on_spring && v->status != SW_VERDICT_PASS &&
        fabs(v->order - ref->order) < SW_POINTS_ORDER_MARGIN) {
        snprintf(v->measure_note, sizeof v->measure_note, "order not measured: it reads %.3g (%.20s's) on test runs "
                 "shorter than the run checked, and such an order counts only where your values match the "
                 "reference's", v->order, ref->name);
        v->order = NAN;
        return;
    }
    if (!(fabs(v->order - ref->order) < SW_POINTS_ORDER_MARGIN)) {
        snprintf(v->measure_note, sizeof v->measure_note, "stability not measured: your order on the run "
                 "checked (%.3g) is not %s's (%d), and the limit is measured only for a method of that order",
                 v->order, ref->name, ref->order);
        return;
    }
    /* the limit is measured on a spring of its own, which a plugin can
     * tell from its graded run (run the assignment's method there, another
     * of the same order on the graded run): believed, as the spring's
     * order is, only where the graded values match */
    if (v->status != SW_VERDICT_PASS) {
        snprintf(v->measure_note, sizeof v->measure_note, "stability not measured: it is measured only "
                 "where your values match the reference's (the limit is found on a test spring, where a "
                 "method could act otherwise)");
        return;
    }
    if (decide) {
        decide_stability(v, plugin, ref, graded->steps);
        return;
    }
    double wdt;
    int kind;
    if (sw_measure_stability(plugin, &wdt, &kind, why, sizeof why) != SW_OK)
        snprintf(v->measure_note, sizeof v->measure_note, "stability not measured: %.200s", why);
    else {
        v->stability = kind == 1 ? 0.0 : kind == 2 ? INFINITY : wdt;
        v->stability_kind = kind;
        /* beside it, the method's own measured as a plugin is (a student
         * compares figures of one measure, not a measure with theory) */
        if (sw_measure_stability_as_plugin(ref, &wdt, &kind, why, sizeof why) == SW_OK)
            v->ref_stability = kind == 1 ? 0.0 : kind == 2 ? INFINITY : wdt;
    }
}

static sw_verdict_status check_plugin(const sw_check_request *req, sw_verdict *v)
{
    const sw_assignment *a = req->assignment;
    const sw_scene *sc = a ? a->meta.scene : req->scene;
    const double *p = a ? a->meta.p : req->p;
    double dt = a ? a->meta.dt : req->dt;
    sw_trace_spec spec = a ? a->meta.spec : req->spec;
    const sw_integrator *ref = req->reference ? req->reference : a ? a->methods[0] : NULL;
    char msg[SW_ERRLEN + 64];
    if (a)
        v->assignment = a->path;
    snprintf(v->plugin, sizeof v->plugin, "%s", req->plugin->name);
    snprintf(v->scene, sizeof v->scene, "%s", sc->name);
    if (!ref)
        return error(v, "check: the plugin form needs --reference NAME or --assignment FILE");
    snprintf(v->method, sizeof v->method, "%s", ref->name);
    v->dt = dt;
    v->comparable = 1;
    double work;
    if (sw_check_budget(sc, p, ref, dt, &spec, &work, msg, sizeof msg) != SW_OK) {
        char inner[SW_ERRLEN + 64];
        snprintf(inner, sizeof inner, "check: %.200s", msg);
        return error(v, inner);
    }
    sw_sim ref_sim, got_sim;
    if (sw_sim_init(&ref_sim, sc, p, ref, dt, msg, sizeof msg) != SW_OK)
        return error(v, msg);
    if (sw_sim_init(&got_sim, sc, p, req->plugin, dt, msg, sizeof msg) != SW_OK) {
        sw_sim_free(&ref_sim);
        return error(v, msg);
    }
    double rtol = a ? a->meta.rtol : SW_RTOL_DEFAULT, atol = a ? a->meta.atol : SW_ATOL_DEFAULT;
    sw_sim_set_tolerances(&ref_sim, rtol, atol);
    sw_sim_set_tolerances(&got_sim, rtol, atol);
    v->ncols = sw_trace_ncols(&ref_sim.sys);
    snprintf(v->reference, sizeof v->reference, "%s on %s with the same settings", ref->name, sc->name);
    tol_arrays tol = { 0 };
    int rc = make_tol(req, &ref_sim.sys, v, &tol);
    if (rc == SW_OK) {
        sw_row_source src_e = { .sim = &ref_sim, .spec = spec };
        sw_row_source src_g = { .sim = &got_sim, .spec = spec };
        rc = sw_check_compare_tol(&src_e, &src_g, v->ncols, &tol.tol, &v->res, msg, sizeof msg);
        if (rc != SW_OK)
            snprintf(v->error, sizeof v->error, "check: %s", msg);
    }
    if (rc == SW_OK) {
        run_end(&ref_sim, &v->ref_end);
        run_end(&got_sim, &v->got_end);
        v->claimed_evals = req->plugin->evals;
        long taken = got_sim.steps;
        v->counted_evals = taken > 0 ? (double)sw_sim_evals(&got_sim) / (double)taken : NAN;
        words(v, &ref_sim.sys, 0);
        int pass = v->res.pass && v->got_end.fault == SW_PF_NONE;
        v->status = pass ? SW_VERDICT_PASS : SW_VERDICT_FAIL;
        if (v->got_end.fault != SW_PF_NONE)
            v->failing_step = v->got_end.step;
        /* the graded run is over: what the plugin runs from here on is
         * the grader's own work, on its budget (sw_plugin_grader_runs) */
        sw_plugin_grader_runs(1);
        if (req->measure && v->got_end.fault == SW_PF_NONE)
            measure(v, req->plugin, ref, &got_sim, &spec, pays_stability(a));
        v->limit = v->got_end.fault == SW_PF_LIMIT || v->got_end.fault == SW_PF_TIMEOUT;
        /* The same "why" as a trace gets: the plugin's first rows, run
         * afresh, against the usual mistakes. A crash, an overrun or a
         * run that ended (a step that returned an error, a state gone
         * non-finite) is its own answer. */
        if (!pass && req->explain && v->got_end.fault == SW_PF_NONE &&
            v->ref_end.fault == SW_PF_NONE && !v->got_end.blown) {
            sw_run_desc desc;
            sw_explanation ex;
            fill_desc(&desc, sc, p, ref, dt, &spec, rtol, atol);
            if (sw_explain_run(req->plugin, &desc, &tol.tol, &ex, msg, sizeof msg) == 1) {
                v->explanation = ex;
                v->have_explanation = 1;
            }
        }
        sw_plugin_grader_runs(0);
        score(v, req, &ref_sim.sys, &tol, ref);
        char what[120];
        snprintf(what, sizeof what, "plugin %s on %s", v->plugin, v->scene);
        message(v, what);
    }
    free_tol(&tol);
    sw_sim_free(&got_sim);
    sw_sim_free(&ref_sim);
    return rc == SW_OK ? v->status : error(v, v->error);
}

sw_verdict_status sw_check_run(const sw_check_request *req, sw_verdict *v)
{
    memset(v, 0, sizeof *v);
    v->failing_step = -1;
    v->order = v->stability = v->ref_stability = NAN;
    v->dt = NAN;
    sw_verdict_status st = req->trace ? check_trace(req, v) : check_plugin(req, v);
    if (st == SW_VERDICT_ERROR)
        score(v, req, NULL, NULL, NULL);
    return st;
}
