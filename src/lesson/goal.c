/* Goals, questions and observations: what a lesson page asks of the live
 * sim and how it is judged. Invariant: a NaN observation never meets a goal,
 * so a quantity the app cannot measure yet reads as "not yet", never "done". */
#include "lesson/lesson.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The names a teacher writes, in sw_lesson_var order. */
static const char *const var_names[SW_LV_COUNT] = {
    "scene", "integrator", "dt", "t", "steps", "evals", "speed", "energy_drift", "error", "drift",
    "error_ratio", "accepted", "rejected", "param", "blown", "compare", "ghost", "paused", "recorded",
    "phase", "region",
};

/* How a variable reads in the ✓/✗ list. */
static const char *const var_labels[SW_LV_COUNT] = {
    "scene", "integrator", "dt", "t", "steps", "derivative evaluations", "speed", "energy drift",
    "error", "invariant drift", "error ratio", "accepted steps", "rejected steps", "parameter",
    "blown", "compare", "ghost", "paused", "recorded", "the phase view", "the stability-region view",
};

const char *sw_lesson_var_name(sw_lesson_var v)
{
    return v >= 0 && v < SW_LV_COUNT ? var_names[v] : NULL;
}

int sw_lesson_var_find(const char *name)
{
    for (int i = 0; i < SW_LV_COUNT; i++)
        if (strcmp(name, var_names[i]) == 0)
            return i;
    if (strcmp(name, "\xCE\x94t") == 0) /* Δt */
        return SW_LV_DT;
    if (strcmp(name, "time") == 0)
        return SW_LV_T;
    return -1;
}

void sw_lesson_obs_init(sw_lesson_obs *obs)
{
    memset(obs, 0, sizeof *obs);
    obs->dt = obs->t = obs->speed = NAN;
    obs->energy_drift = obs->error = obs->drift = obs->error_ratio = NAN;
    for (int i = 0; i < SW_MAX_PARAMS; i++)
        obs->param_value[i] = NAN;
}

void sw_lesson_obs_from_sim(sw_lesson_obs *obs, const sw_sim *sim)
{
    const sw_scene *sc = sim->sys.scene;
    obs->scene = sc->name;
    obs->integrator = sim->method->name;
    obs->dt = sim->dt;
    obs->t = sim->t;
    obs->steps = sim->steps;
    obs->evals = sw_sim_evals(sim);
    obs->blown = sim->blown != 0;
    obs->energy_drift = sw_sim_energy_drift(sim);
    obs->drift = sw_sim_drift(sim);
    sw_sim_step_counts(sim, &obs->accepted, &obs->rejected);
    obs->nparams = sc->nparams < SW_MAX_PARAMS ? sc->nparams : SW_MAX_PARAMS;
    for (int i = 0; i < obs->nparams; i++) {
        obs->param_name[i] = sc->params[i].name;
        obs->param_value[i] = sim->sys.p[i];
    }
}

static double number_of(const sw_lesson_goal *g, const sw_lesson_obs *obs)
{
    switch (g->var) {
    case SW_LV_DT: return obs->dt;
    case SW_LV_T: return obs->t;
    case SW_LV_STEPS: return (double)obs->steps;
    case SW_LV_EVALS: return (double)obs->evals;
    case SW_LV_SPEED: return obs->speed;
    case SW_LV_ENERGY_DRIFT: return obs->energy_drift;
    case SW_LV_ERROR: return obs->error;
    case SW_LV_DRIFT: return obs->drift;
    case SW_LV_ERROR_RATIO: return obs->error_ratio;
    case SW_LV_ACCEPTED: return (double)obs->accepted;
    case SW_LV_REJECTED: return (double)obs->rejected;
    case SW_LV_PARAM:
        for (int i = 0; i < obs->nparams && i < SW_MAX_PARAMS; i++)
            if (g->param && obs->param_name[i] && strcmp(obs->param_name[i], g->param) == 0)
                return obs->param_value[i];
        return NAN;
    default: return NAN;
    }
}

static int flag_of(const sw_lesson_goal *g, const sw_lesson_obs *obs)
{
    switch (g->var) {
    case SW_LV_BLOWN: return obs->blown != 0;
    case SW_LV_COMPARE: return obs->compare != 0;
    case SW_LV_GHOST: return obs->ghost != 0;
    case SW_LV_PAUSED: return obs->paused != 0;
    case SW_LV_PHASE: return obs->phase != 0;
    case SW_LV_REGION: return obs->region != 0;
    default: return obs->recorded != 0;
    }
}

int sw_lesson_goal_met(const sw_lesson_goal *g, const sw_lesson_obs *obs)
{
    if (g->var == SW_LV_SCENE || g->var == SW_LV_INTEGRATOR) {
        const char *now = g->var == SW_LV_SCENE ? obs->scene : obs->integrator;
        if (!now)
            return 0;
        int found = 0;
        for (int i = 0; i < g->nnames && i < SW_LESSON_MAX_NAMES; i++)
            if (g->names[i] && strcmp(now, g->names[i]) == 0)
                found = 1;
        return g->op == SW_LOP_NE ? !found : found;
    }
    if (g->var >= SW_LV_BLOWN)
        return flag_of(g, obs) == (g->value != 0);
    double x = number_of(g, obs);
    if (isnan(x))
        return 0;
    if (g->absolute)
        x = fabs(x);
    /* The slack is relative to the teacher's number, which is finite, so an
     * infinite observation compares as infinitely large, never as equal. */
    double v = g->value, slack = 1e-9 * fabs(v);
    switch (g->op) {
    case SW_LOP_EQ: return fabs(x - v) <= slack;
    case SW_LOP_NE: return !(fabs(x - v) <= slack);
    case SW_LOP_LT: return x < v;
    case SW_LOP_LE: return x <= v + slack;
    case SW_LOP_GT: return x > v;
    case SW_LOP_GE: return x >= v - slack;
    case SW_LOP_NEAR: return fabs(x - v) <= g->tol + slack;
    default: return 0;
    }
}

void sw_lesson_goal_text(const sw_lesson_goal *g, char *buf, size_t len)
{
    if (!buf || !len)
        return;
    buf[0] = '\0';
    int on = g->value != 0;
    switch (g->var) {
    case SW_LV_SCENE:
    case SW_LV_INTEGRATOR: {
        size_t used = 0;
        int w = snprintf(buf, len, "%s is %s", var_labels[g->var], g->op == SW_LOP_NE ? "not " : "");
        used = w > 0 ? (size_t)w : 0;
        for (int i = 0; i < g->nnames && i < SW_LESSON_MAX_NAMES && used < len; i++) {
            const char *sep = i == 0 ? "" : i == g->nnames - 1 ? " or " : ", ";
            w = snprintf(buf + used, len - used, "%s%s", sep, g->names[i] ? g->names[i] : "?");
            used += w > 0 ? (size_t)w : 0;
        }
        return;
    }
    case SW_LV_BLOWN:
        snprintf(buf, len, on ? "the sim has blown up" : "the sim has not blown up");
        return;
    case SW_LV_COMPARE:
    case SW_LV_GHOST:
        snprintf(buf, len, "%s is %s", var_labels[g->var], on ? "on" : "off");
        return;
    case SW_LV_PAUSED:
        snprintf(buf, len, on ? "the sim is paused" : "the sim is running");
        return;
    case SW_LV_RECORDED:
        snprintf(buf, len, on ? "a trace has been recorded" : "no trace recorded");
        return;
    case SW_LV_PHASE:
    case SW_LV_REGION:
        snprintf(buf, len, "%s is %s", var_labels[g->var], on ? "on" : "off");
        return;
    default:
        break;
    }
    const char *label = g->var == SW_LV_PARAM && g->param ? g->param
                      : g->var >= 0 && g->var < SW_LV_COUNT ? var_labels[g->var] : "?";
    const char *unit = g->var == SW_LV_ENERGY_DRIFT ? " %" : "";
    char term[64];
    snprintf(term, sizeof term, g->absolute ? "|%s|" : "%s", label);
    if (g->op == SW_LOP_NEAR) {
        snprintf(buf, len, "%s within %g%s of %g%s", term, g->tol, unit, g->value, unit);
        return;
    }
    static const char *const ops[] = { "=", "!=", "<", "<=", ">", ">=" };
    const char *op = g->op >= SW_LOP_EQ && g->op <= SW_LOP_GE ? ops[g->op] : "?";
    snprintf(buf, len, "%s %s %g%s", term, op, g->value, unit);
}

int sw_lesson_answer(const sw_lesson_page *page, int letter, const char **feedback)
{
    const sw_lesson_question *q = &page->question;
    if (!q->text) {
        *feedback = "this page has no question";
        return SW_EINVAL;
    }
    int index = letter >= 'a' && letter <= 'z' ? letter - 'a' : letter >= 'A' && letter <= 'Z' ? letter - 'A' : -1;
    if (index < 0 || index >= q->nanswers) {
        *feedback = "no such answer: choose one of the letters shown";
        return SW_EINVAL;
    }
    *feedback = q->answers[index].feedback;
    return index == q->correct;
}

int sw_lesson_page_complete(const sw_lesson_page *page, const sw_lesson_obs *obs, int answered_correctly)
{
    if (page->question.text && !answered_correctly)
        return 0;
    for (int i = 0; i < page->ngoals; i++)
        if (!sw_lesson_goal_met(&page->goals[i], obs))
            return 0;
    return 1;
}
