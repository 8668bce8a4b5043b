/* Checks that need a whole page: questions and hints complete, every method
 * able to step the page's system (built once per change of settings), goals
 * the scene can measure, and goals that can never be met on their page
 * (empty ranges, goals that contradict each other, another scene, a lock). */
#include "lesson/parse.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/names.h"

/* ---- building the page's system, to check methods against it -------------------------- */

/* Build the scene with the settings so far (once per change): a build can
 * refuse parameter combinations that each lie in range. */
static int build_check(sw_lp_parser *ps)
{
    if (ps->have_sys && !ps->rebuild)
        return SW_OK;
    sw_lp_where at = ps->at_set.line ? ps->at_set : ps->at_scene.line ? ps->at_scene : (sw_lp_where){ ps->line, 1 };
    if (ps->have_sys)
        sw_system_free(&ps->sys);
    ps->have_sys = 0;
    char why[SW_ERRLEN];
    int rc = sw_system_build(&ps->sys, ps->scene, ps->p, why, sizeof why);
    if (rc == SW_ENOMEM)
        return sw_lp_oom(ps);
    if (rc != SW_OK)
        return sw_lp_fail_at(ps, at.line, at.col, "scene '%s' cannot be built with these parameters: %s; "
                       "expected other values", ps->scene->name, why);
    ps->have_sys = 1;
    ps->rebuild = 0;
    return SW_OK;
}

/* SW_OK when m can step the page's system, else SW_EINVAL with why filled
 * (ps->status stays SW_OK) or the build's error (ps->status set). */
int sw_lp_system_accepts(sw_lp_parser *ps, const sw_integrator *m, char *why, size_t len)
{
    if (build_check(ps) != SW_OK)
        return ps->status;
    return sw_integrator_accepts(m, ps->sys.ode, why, len);
}
/* ---- goals a page can never meet ----------------------------------------------------------
 * A page's goals must all hold at once (the runner latches the page, not
 * each goal). A goal is refused when no value its quantity can take meets
 * it (t < 0, dt > SW_DT_MAX, a parameter outside its range), when it
 * contradicts another goal on the same quantity (t > 5 with t < 4), when it
 * asks for a scene other than the page's (no key changes the scene), and
 * when a lock keeps its quantity at a value that fails it. */

/* A set of reals: [lo, hi] with either end open; empty when lo > hi or a
 * point with an open end. */
typedef struct span { double lo, hi; int lo_open, hi_open; } span;

static const span everything = { -INFINITY, INFINITY, 1, 1 };

static span meet(span a, span b)
{
    span r = a;
    if (b.lo > r.lo || (b.lo == r.lo && b.lo_open)) {
        r.lo = b.lo;
        r.lo_open = b.lo_open;
    }
    if (b.hi < r.hi || (b.hi == r.hi && b.hi_open)) {
        r.hi = b.hi;
        r.hi_open = b.hi_open;
    }
    return r;
}

/* Empty, counting whole numbers only when integer is set. */
static int span_empty(span s, int integer)
{
    if (integer) {
        double lo = ceil(s.lo), hi = floor(s.hi);
        if (s.lo_open && lo == s.lo)
            lo += 1;
        if (s.hi_open && hi == s.hi)
            hi -= 1;
        return lo > hi;
    }
    return s.lo > s.hi || (s.lo == s.hi && (s.lo_open || s.hi_open));
}

/* The values a goal accepts (with goal.c's slack); NE accepts all but a point. */
static span goal_span(const sw_lesson_goal *g)
{
    double v = g->value, slack = 1e-9 * fabs(v);
    switch (g->op) {
    case SW_LOP_LT: return (span){ -INFINITY, v, 1, 1 };
    case SW_LOP_LE: return (span){ -INFINITY, v + slack, 1, 0 };
    case SW_LOP_GT: return (span){ v, INFINITY, 1, 1 };
    case SW_LOP_GE: return (span){ v - slack, INFINITY, 0, 1 };
    case SW_LOP_EQ: return (span){ v - slack, v + slack, 0, 0 };
    case SW_LOP_NEAR: return (span){ v - g->tol - slack, v + g->tol + slack, 0, 0 };
    default: return everything;
    }
}

/* The values a numeric quantity can take on this page, and whether only
 * whole numbers; 0 when it is not a number with a known range. */
static int quantity_span(const sw_lp_parser *ps, const sw_lesson_goal *g, span *out, int *integer)
{
    *integer = 0;
    switch (g->var) {
    case SW_LV_T: case SW_LV_ERROR: case SW_LV_ERROR_RATIO:
        *out = (span){ 0, INFINITY, 0, 1 };
        break;
    case SW_LV_STEPS: case SW_LV_EVALS: case SW_LV_ACCEPTED: case SW_LV_REJECTED:
        *out = (span){ 0, INFINITY, 0, 1 };
        *integer = 1;
        break;
    case SW_LV_DT:
        *out = (span){ SW_DT_MIN, SW_DT_MAX, 0, 0 };
        break;
    case SW_LV_ENERGY_DRIFT: case SW_LV_DRIFT:
        *out = everything;
        break;
    case SW_LV_PARAM: {
        int k = g->param ? sw_scene_param_index(ps->scene, g->param) : -1;
        if (k < 0)
            return 0;
        const sw_param *pd = &ps->scene->params[k];
        *out = (span){ pd->min, pd->max, 0, 0 };
        *integer = pd->integer;
        break;
    }
    default:
        return 0;
    }
    if (g->absolute) { /* |x|: from the nearest point to zero up to the farthest */
        double lo = out->lo > 0 ? out->lo : out->hi < 0 ? -out->hi : 0;
        double hi = fmax(fabs(out->lo), fabs(out->hi));
        *out = (span){ lo, hi, 0, isinf(hi) };
    }
    return 1;
}

/* How a quantity's range reads in a message. */
static void describe_span(const char *label, span s, char *buf, size_t len)
{
    if (isinf(s.hi))
        snprintf(buf, len, "%s is never below %g", label, s.lo);
    else
        snprintf(buf, len, "%s stays in [%g, %g]", label, s.lo, s.hi);
}

static const char *goal_label(const sw_lesson_goal *g, char *buf, size_t len)
{
    const char *name = g->var == SW_LV_PARAM && g->param ? g->param : sw_lesson_var_name(g->var);
    snprintf(buf, len, g->absolute ? "|%s|" : "%s", name);
    return buf;
}

/* Goals i and j ask about the same quantity. */
static int same_quantity(const sw_lesson_goal *a, const sw_lesson_goal *b)
{
    if (a->var != b->var || a->absolute != b->absolute)
        return 0;
    return a->var != SW_LV_PARAM || (a->param && b->param && strcmp(a->param, b->param) == 0);
}

static int never_met(sw_lp_parser *ps, int i, const char *why, const char *expected)
{
    char text[120];
    sw_lesson_goal_text(&sw_lp_page(ps)->goals[i], text, sizeof text);
    return sw_lp_fail_at(ps, ps->at_goal[i].line, ps->at_goal[i].col, "goal '%s' can never be met: %s; expected %s",
                         text, why, expected);
}

/* 1 when dt = v meets every dt goal up to goal i. */
static int dt_meets(const sw_lesson_page *pg, int i, double v)
{
    sw_lesson_obs obs;
    sw_lesson_obs_init(&obs);
    obs.dt = v;
    for (int j = 0; j <= i; j++)
        if (pg->goals[j].var == SW_LV_DT && !sw_lesson_goal_met(&pg->goals[j], &obs))
            return 0;
    return 1;
}

/* dt changes only by doubling and halving (+ and -), so on a page that
 * starts with dt0 it takes the values dt0 * 2^k within [SW_DT_MIN,
 * SW_DT_MAX]: a goal none of them meets can never be met (dt == 0.3 from 0.1). */
static int check_dt_steps(sw_lp_parser *ps, const sw_lesson_page *pg, int i)
{
    for (int k = -80; k <= 80; k++) {
        double v = ldexp(pg->dt, k);
        if (v >= SW_DT_MIN && v <= SW_DT_MAX && dt_meets(pg, i, v))
            return SW_OK;
    }
    char why[300];
    int alone = 0;
    for (int k = -80; k <= 80 && !alone; k++) {
        double v = ldexp(pg->dt, k);
        sw_lesson_obs obs;
        sw_lesson_obs_init(&obs);
        obs.dt = v;
        alone = v >= SW_DT_MIN && v <= SW_DT_MAX && sw_lesson_goal_met(&pg->goals[i], &obs);
    }
    snprintf(why, sizeof why, "the page starts with dt = %g and + and - only double and halve it, so dt "
             "is %g x 2^k (within [%g, %g]) and no such value meets %s", pg->dt, pg->dt, SW_DT_MIN, SW_DT_MAX,
             alone ? "it together with the dt goals above it" : "it");
    return never_met(ps, i, why, "a dt the page can reach, or another @dt");
}

/* The goals on a number, alone against its range and together. */
static int check_number_goal(sw_lp_parser *ps, const sw_lesson_page *pg, int i)
{
    const sw_lesson_goal *g = &pg->goals[i];
    span dom, all;
    int integer;
    char label[80], why[400];
    if (!quantity_span(ps, g, &dom, &integer))
        return SW_OK;
    goal_label(g, label, sizeof label);
    if (span_empty(meet(dom, goal_span(g)), integer)) {
        describe_span(label, dom, why, sizeof why);
        return never_met(ps, i, why, "a bound inside that range");
    }
    all = dom;
    for (int j = 0; j <= i; j++)
        if (same_quantity(&pg->goals[j], g))
            all = meet(all, goal_span(&pg->goals[j]));
    /* != excludes one value: a contradiction only when nothing else is left */
    int excluded = 0;
    for (int j = 0; j <= i && !span_empty(all, integer); j++) {
        const sw_lesson_goal *h = &pg->goals[j];
        if (same_quantity(h, g) && h->op == SW_LOP_NE) {
            double slack = 1e-9 * fabs(h->value);
            excluded |= all.lo >= h->value - slack && all.hi <= h->value + slack;
        }
    }
    if (!span_empty(all, integer) && !excluded)
        return g->var == SW_LV_DT && pg->restart ? check_dt_steps(ps, pg, i) : SW_OK;
    /* name the earlier goal it contradicts, when one alone does */
    for (int j = 0; j < i; j++) {
        const sw_lesson_goal *h = &pg->goals[j];
        if (!same_quantity(h, g))
            continue;
        span two = meet(meet(dom, goal_span(h)), goal_span(g));
        int clash = span_empty(two, integer);
        if (!clash && (h->op == SW_LOP_NE || g->op == SW_LOP_NE)) {
            const sw_lesson_goal *ne = h->op == SW_LOP_NE ? h : g;
            double slack = 1e-9 * fabs(ne->value);
            clash = two.lo >= ne->value - slack && two.hi <= ne->value + slack;
        }
        if (clash) {
            char other[120];
            sw_lesson_goal_text(h, other, sizeof other);
            snprintf(why, sizeof why, "it contradicts goal '%s' (line %d): a page's goals must hold at once, "
                     "and no %s meets both", other, ps->at_goal[j].line, label);
            return never_met(ps, i, why, "goals that can hold together");
        }
    }
    snprintf(why, sizeof why, "no %s meets it together with the goals above it on %s (a page's goals must "
             "hold at once)", label, label);
    return never_met(ps, i, why, "goals that can hold together");
}

/* Scene and integrator goals: the names a goal accepts among the names possible. */
static int name_accepted(const sw_lesson_goal *g, const char *name)
{
    sw_lesson_obs obs;
    sw_lesson_obs_init(&obs);
    obs.scene = obs.integrator = name;
    return sw_lesson_goal_met(g, &obs);
}

static int check_name_goal(sw_lp_parser *ps, const sw_lesson_page *pg, int i)
{
    const sw_lesson_goal *g = &pg->goals[i];
    char why[300];
    if (g->var == SW_LV_SCENE) {
        if (name_accepted(g, pg->scene->name))
            return SW_OK;
        snprintf(why, sizeof why, "this page shows scene '%s' and no key changes the scene", pg->scene->name);
        return never_met(ps, i, why, "a goal on this page's scene, or '@scene' choosing the one the goal names");
    }
    if (g->var != SW_LV_INTEGRATOR)
        return SW_OK;
    /* some integrator meets every integrator goal so far (the parser has
     * checked that each one named can run this page's system) */
    for (int k = 0; k < sw_integrator_count(); k++) {
        const char *name = sw_integrator_at(k)->name;
        int all = 1;
        for (int j = 0; j <= i && all; j++)
            all = pg->goals[j].var != SW_LV_INTEGRATOR || name_accepted(&pg->goals[j], name);
        if (all)
            return SW_OK;
    }
    for (int j = 0; j < i; j++)
        if (pg->goals[j].var == SW_LV_INTEGRATOR) {
            char other[120];
            sw_lesson_goal_text(&pg->goals[j], other, sizeof other);
            snprintf(why, sizeof why, "it contradicts goal '%s' (line %d): a page's goals must hold at once",
                     other, ps->at_goal[j].line);
            return never_met(ps, i, why, "goals that can hold together");
        }
    return SW_OK;
}

/* What a lock holds fixed for the whole page, as an observation: a locked
 * control keeps the value the page starts with. start_why[var] says why
 * ("" when the quantity is free). */
typedef struct fixed {
    sw_lesson_obs obs;
    char why[SW_LV_COUNT][120];
} fixed;

static void fixed_values(const sw_lesson_page *pg, fixed *f)
{
    memset(f, 0, sizeof *f);
    sw_lesson_obs_init(&f->obs);
    f->obs.scene = pg->scene->name;
    f->obs.integrator = pg->method->name;
    f->obs.dt = pg->dt;
    sw_lock_mask lk = pg->locked;
    if (lk & SW_LOCK_RECORD)
        snprintf(f->why[SW_LV_RECORDED], sizeof f->why[0], "recording is locked on this page (@lock record), "
                 "so a student who resumes here can record nothing");
    if (!pg->restart)
        return; /* the sim goes on as the student left it: nothing else is known */
    if (lk & SW_LOCK_INTEGRATOR)
        snprintf(f->why[SW_LV_INTEGRATOR], sizeof f->why[0], "the integrator is locked and the page starts "
                 "with %s", pg->method->name);
    if ((lk & SW_LOCK_INTEGRATOR) && !(pg->method->flags & SW_ADAPTIVE)) {
        f->obs.accepted = f->obs.rejected = 0;
        snprintf(f->why[SW_LV_ACCEPTED], sizeof f->why[0], "the integrator is locked to %s, which takes fixed "
                 "steps, so no step is accepted or rejected", pg->method->name);
        memcpy(f->why[SW_LV_REJECTED], f->why[SW_LV_ACCEPTED], sizeof f->why[0]);
    }
    if (lk & SW_LOCK_DT) {
        snprintf(f->why[SW_LV_DT], sizeof f->why[0], "dt is locked and the page starts with dt = %g", pg->dt);
        /* obs.error_ratio stays NaN: it needs errors measured at two step sizes */
        snprintf(f->why[SW_LV_ERROR_RATIO], sizeof f->why[0], "dt is locked, and the error ratio needs the "
                 "error at two step sizes");
    }
    if ((lk & SW_LOCK_COMPARE) && pg->compare >= 0) {
        f->obs.compare = pg->compare;
        snprintf(f->why[SW_LV_COMPARE], sizeof f->why[0], "compare is locked and the page turns it %s",
                 pg->compare ? "on" : "off");
    }
    if ((lk & SW_LOCK_GHOST) && pg->ghost >= 0) {
        f->obs.ghost = pg->ghost;
        snprintf(f->why[SW_LV_GHOST], sizeof f->why[0], "the ghost is locked and the page turns it %s",
                 pg->ghost ? "on" : "off");
    }
    if ((lk & SW_LOCK_RUN) && pg->paused >= 0) {
        f->obs.paused = pg->paused;
        snprintf(f->why[SW_LV_PAUSED], sizeof f->why[0], "pause is locked (@lock run) and the page starts %s",
                 pg->paused ? "paused" : "running");
    }
    if ((lk & SW_LOCK_RUN) && pg->paused == 1) {
        /* no key can advance time: pause and single step are taken away */
        static const sw_lesson_var frozen[] = { SW_LV_T, SW_LV_STEPS, SW_LV_ACCEPTED, SW_LV_REJECTED, SW_LV_BLOWN };
        f->obs.t = 0;
        f->obs.steps = f->obs.accepted = f->obs.rejected = 0;
        f->obs.blown = 0;
        for (size_t k = 0; k < sizeof frozen / sizeof frozen[0]; k++)
            snprintf(f->why[frozen[k]], sizeof f->why[0], "the page starts paused at t = 0 and pause and single "
                     "step are locked (@lock run), so time never moves");
    }
    if (lk & SW_LOCK_PARAMS) {
        f->obs.nparams = pg->scene->nparams < SW_MAX_PARAMS ? pg->scene->nparams : SW_MAX_PARAMS;
        for (int k = 0; k < f->obs.nparams; k++) {
            f->obs.param_name[k] = pg->scene->params[k].name;
            f->obs.param_value[k] = pg->p[k];
        }
        snprintf(f->why[SW_LV_PARAM], sizeof f->why[0], "the parameters are locked (@lock params) at the "
                 "page's values");
    }
}

static int check_goals(sw_lp_parser *ps, const sw_lesson_page *pg)
{
    fixed *f = malloc(sizeof *f);
    if (!f)
        return sw_lp_oom(ps);
    fixed_values(pg, f);
    int rc = SW_OK;
    for (int i = 0; i < pg->ngoals && rc == SW_OK; i++) {
        const sw_lesson_goal *g = &pg->goals[i];
        if (f->why[g->var][0] && !sw_lesson_goal_met(g, &f->obs)) {
            char why[200];
            int k = g->var == SW_LV_PARAM && g->param ? sw_scene_param_index(pg->scene, g->param) : -1;
            if (k >= 0)
                snprintf(why, sizeof why, "the parameters are locked (@lock params) and the page sets %s = %g",
                         g->param, pg->p[k]);
            else
                snprintf(why, sizeof why, "%s", f->why[g->var]);
            rc = never_met(ps, i, why, "an @unlock or another goal");
        } else if (g->var == SW_LV_SCENE || g->var == SW_LV_INTEGRATOR) {
            rc = check_name_goal(ps, pg, i);
        } else if (g->var >= SW_LV_BLOWN) {
            for (int j = 0; j < i; j++)
                if (pg->goals[j].var == g->var && (pg->goals[j].value != 0) != (g->value != 0)) {
                    char other[120], why[240];
                    sw_lesson_goal_text(&pg->goals[j], other, sizeof other);
                    snprintf(why, sizeof why, "it contradicts goal '%s' (line %d): a page's goals must hold "
                             "at once", other, ps->at_goal[j].line);
                    rc = never_met(ps, i, why, "goals that can hold together");
                    break;
                }
        } else {
            rc = check_number_goal(ps, pg, i);
        }
    }
    free(f);
    return rc;
}

/* ---- pages --------------------------------------------------------------------------------------- */

/* Checks that need the whole page: questions, hints, methods against the system, locks. */
int sw_lp_end_page(sw_lp_parser *ps)
{
    sw_lesson_page *pg = sw_lp_page(ps);
    if (!pg)
        return SW_OK;
    if (sw_lp_flush_block(ps) != SW_OK)
        return ps->status;
    sw_lesson_question *q = &pg->question;
    if (q->text) {
        if (q->nanswers < 2)
            return sw_lp_fail_at(ps, q->line, 1, "this question has %d answer%s; expected at least two "
                           "'@answer X) TEXT | FEEDBACK' lines", q->nanswers, q->nanswers == 1 ? "" : "s");
        if (ps->correct < 0)
            return sw_lp_fail_at(ps, q->line, 1, "this question has no @correct line; expected '@correct X' "
                           "naming the right answer");
        if (ps->correct >= q->nanswers)
            return sw_lp_fail_at(ps, ps->at_correct.line, ps->at_correct.col, "@correct %c names no answer; "
                           "expected one of a to %c", 'a' + ps->correct, 'a' + q->nanswers - 1);
        q->correct = ps->correct;
    } else if (ps->correct >= 0) {
        return sw_lp_fail_at(ps, ps->at_correct.line, 1, "@correct without a @question");
    }
    for (int i = 0; i < pg->ngoals; i++)
        if (!pg->goals[i].hint)
            return sw_lp_fail_at(ps, ps->at_goal[i].line, ps->at_goal[i].col, "this goal has no hint; expected "
                           "a '@hint TEXT' line after it saying what to press");
    if (!ps->nblocks && !q->text)
        return sw_lp_fail_at(ps, pg->line, 1, "page '%s' has no text; expected a few lines for the student",
                       pg->title);
    if (ps->out->npages == 1 && !ps->scene) {
        char names[300];
        sw_scene_names(names, sizeof names);
        return sw_lp_fail_at(ps, pg->line, 1, "the first page chooses no scene; expected '@scene NAME' "
                       "(one of %s)", names);
    }
    sw_lp_where at_m = ps->at_integrator.line ? ps->at_integrator : ps->at_scene.line ? ps->at_scene : (sw_lp_where){ pg->line, 1 };
    char why[SW_ERRLEN];
    if (sw_lp_system_accepts(ps, ps->method, why, sizeof why) != SW_OK) {
        if (ps->status != SW_OK)
            return ps->status;
        return sw_lp_fail_at(ps, at_m.line, at_m.col, "%s cannot run scene '%s': %s", ps->method->name,
                       ps->scene->name, why);
    }
    for (int i = 0; i < pg->ncompare_with; i++)
        if (sw_lp_system_accepts(ps, pg->compare_with[i], why, sizeof why) != SW_OK) {
            if (ps->status != SW_OK)
                return ps->status;
            return sw_lp_fail_at(ps, ps->at_compare.line, ps->at_compare.col, "@compare: %s", why);
        }
    /* Error needs an exact solution or a reference run; some scenes have an
     * exact solution for some parameters only (bounce: no drag). */
    const sw_scene *sc = ps->scene;
    for (int i = 0; i < pg->ngoals; i++) {
        /* Energy drift is relative to the starting energy, so it needs one. */
        if (pg->goals[i].var == SW_LV_ENERGY_DRIFT && sc->energy) {
            double e0 = sc->energy(&ps->sys, ps->sys.y);
            if (!(fabs(e0) > 0 && isfinite(e0)))
                return sw_lp_fail_at(ps, ps->at_goal[i].line, ps->at_goal[i].col, "scene '%s' starts with zero "
                               "energy with these parameters, so its energy drift (relative to the start) "
                               "is undefined; expected other parameters or another goal", sc->name);
        }
        if (!(sc->exact && !sc->reference) ||
            (pg->goals[i].var != SW_LV_ERROR && pg->goals[i].var != SW_LV_ERROR_RATIO))
            continue;
        double *scratch = malloc((size_t)ps->sys.ode->dim * sizeof *scratch);
        if (!scratch)
            return sw_lp_oom(ps);
        int exact = sc->exact(&ps->sys, 0.0, scratch) == 0;
        free(scratch);
        if (!exact)
            return sw_lp_fail_at(ps, ps->at_goal[i].line, ps->at_goal[i].col, "scene '%s' has no exact solution "
                           "with these parameters and no reference run, so a goal on %s can never be met; "
                           "expected other parameters or another goal", sc->name,
                           sw_lesson_var_name(pg->goals[i].var));
    }
    /* a page that picks its scene and no step runs at the scene's default
     * step for the parameters it sets (water's follows its stability limit) */
    if (ps->at_scene.line && !ps->at_dt.line)
        ps->dt = sw_scene_dt(ps->scene, ps->p);
    pg->scene = ps->scene;
    memcpy(pg->p, ps->p, sizeof pg->p);
    pg->method = ps->method;
    pg->dt = ps->dt;
    pg->locked = ps->locked;
    if (check_goals(ps, pg) != SW_OK)
        return ps->status;
    pg->blocks = NULL;
    if (ps->nblocks) {
        sw_lesson_block *b = sw_lp_alloc(ps->out, (size_t)ps->nblocks * sizeof *b);
        if (!b)
            return sw_lp_oom(ps);
        memcpy(b, ps->blocks, (size_t)ps->nblocks * sizeof *b);
        pg->blocks = b;
    }
    pg->nblocks = ps->nblocks;
    return SW_OK;
}
