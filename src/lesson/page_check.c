/* Checks that need a whole page: questions and hints complete, every method
 * able to step the page's system (built once per change of settings), goals
 * the scene can measure, and goals a lock would make impossible. */
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
    pg->scene = ps->scene;
    memcpy(pg->p, ps->p, sizeof pg->p);
    pg->method = ps->method;
    pg->dt = ps->dt;
    pg->locked = ps->locked;
    /* A locked control keeps the value the page starts with; a goal that
     * value fails can never be met. */
    for (int i = 0; i < pg->ngoals && pg->restart; i++) {
        const sw_lesson_goal *g = &pg->goals[i];
        sw_lesson_obs obs;
        sw_lesson_obs_init(&obs);
        obs.integrator = pg->method->name;
        obs.dt = pg->dt;
        char start[80] = "";
        if (g->var == SW_LV_INTEGRATOR && (pg->locked & SW_LOCK_INTEGRATOR))
            snprintf(start, sizeof start, "the integrator is locked and the page starts with %s",
                     pg->method->name);
        else if (g->var == SW_LV_DT && (pg->locked & SW_LOCK_DT))
            snprintf(start, sizeof start, "dt is locked and the page starts with dt = %g", pg->dt);
        if (start[0] && !sw_lesson_goal_met(g, &obs)) {
            char text[120];
            sw_lesson_goal_text(g, text, sizeof text);
            return sw_lp_fail_at(ps, ps->at_goal[i].line, ps->at_goal[i].col, "goal '%s' can never be met: %s; "
                           "expected an @unlock or another goal", text, start);
        }
    }
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
