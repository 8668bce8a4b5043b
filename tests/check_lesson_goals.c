/* Lesson goals, questions and observations: every goal form evaluates as
 * documented on made-up observations, every goal variable is covered, goal
 * texts read well, answers complete a page, and a sim's observation carries
 * what the sim knows. Tests run from the repository root. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lesson/lesson.h"

/* Parse text as a lesson named "t.lesson"; returns the status. */
static int parse(const char *text, sw_lesson *l, char *err, size_t errlen)
{
    return sw_lesson_parse("t.lesson", text, strlen(text), l, err, errlen);
}

/* ---- goals ---------------------------------------------------------------------- */

/* Which observation field a case sets before evaluating. */
enum field { F_NONE, F_SCENE, F_INTEGRATOR, F_DT, F_T, F_STEPS, F_EVALS, F_SPEED, F_ENERGY, F_ERROR,
             F_DRIFT, F_RATIO, F_ACCEPTED, F_REJECTED, F_PARAM_C, F_BLOWN, F_COMPARE, F_GHOST,
             F_PAUSED, F_RECORDED, F_PHASE, F_REGION };

static const struct goal_case {
    const char *scene;  /* the page's scene, and any settings after it (goals are checked against them) */
    const char *goal;
    enum field field;
    double value;
    const char *name;   /* for F_SCENE / F_INTEGRATOR */
    int met;
} goal_cases[] = {
    { "spring", "integrator == rk4", F_INTEGRATOR, 0, "rk4", 1 },
    { "spring", "integrator == rk4", F_INTEGRATOR, 0, "euler", 0 },
    { "spring", "integrator is rk4", F_INTEGRATOR, 0, "rk4", 1 },
    { "spring", "integrator != rk4", F_INTEGRATOR, 0, "euler", 1 },
    { "spring", "integrator is not rk4", F_INTEGRATOR, 0, "rk4", 0 },
    { "spring", "integrator in verlet, symplectic-euler", F_INTEGRATOR, 0, "symplectic-euler", 1 },
    { "spring", "integrator in verlet symplectic-euler", F_INTEGRATOR, 0, "rk4", 0 },
    { "spring", "integrator == rk4", F_INTEGRATOR, 0, NULL, 0 },
    { "spring", "scene == spring", F_SCENE, 0, "spring", 1 },
    { "orbit", "scene != spring", F_SCENE, 0, "spring", 0 },  /* (on a spring page lint refuses it) */
    { "spring", "dt >= 0.2", F_DT, 0.05 * 4, NULL, 1 },
    { "spring", "Δt ≥ 0.2", F_DT, 0.1, NULL, 0 },
    { "spring", "dt <= 0.0125", F_DT, 0.1 / 8, NULL, 1 },
    { "spring", "dt <= 0.0125", F_DT, 0.013, NULL, 0 },
    /* dt 0.15 on the page: + and - reach 0.3 (lint refuses a dt no doubling reaches) */
    { "spring\n@dt 0.15", "dt == 0.3", F_DT, 0.1 * 3, NULL, 1 },    /* 0.30000000000000004 */
    { "spring\n@dt 0.15", "dt = 0.3", F_DT, 0.31, NULL, 0 },
    { "spring", "dt != 0.3", F_DT, 0.31, NULL, 1 },
    { "spring", "dt ≠ 0.3", F_DT, 0.1 * 3, NULL, 0 },
    { "spring", "t > 10", F_T, 10.5, NULL, 1 },
    { "spring", "t > 10", F_T, 10, NULL, 0 },
    { "spring", "time < 1", F_T, 0.5, NULL, 1 },
    { "spring", "t < 1", F_T, 1, NULL, 0 },
    { "spring", "t ≤ 1", F_T, 1, NULL, 1 },
    { "spring", "steps >= 5", F_STEPS, 5, NULL, 1 },
    { "spring", "steps >= 5", F_STEPS, 4, NULL, 0 },
    { "spring", "evals > 100", F_EVALS, 101, NULL, 1 },
    { "spring", "evals > 100", F_EVALS, 100, NULL, 0 },
    { "spring", "speed >= 2", F_SPEED, 4, NULL, 1 },
    { "spring", "speed >= 2", F_SPEED, 1, NULL, 0 },
    { "spring", "|energy_drift| < 1%", F_ENERGY, -0.5, NULL, 1 },
    { "spring", "|energy_drift| < 1", F_ENERGY, -1.5, NULL, 0 },
    { "spring", "abs(energy_drift) < 1", F_ENERGY, 0.9, NULL, 1 },
    { "spring", "energy_drift < -10", F_ENERGY, -12, NULL, 1 },
    { "spring", "energy_drift < -10", F_ENERGY, 12, NULL, 0 },
    { "spring", "energy_drift > 50", F_ENERGY, INFINITY, NULL, 1 },  /* a blown-up energy */
    { "spring", "energy_drift < 1", F_ENERGY, NAN, NULL, 0 },       /* not measured: not met */
    { "spring", "energy_drift != 1", F_ENERGY, NAN, NULL, 0 },
    { "spring", "energy_drift == 5", F_ENERGY, INFINITY, NULL, 0 },
    { "spring", "error < 0.01", F_ERROR, 0.001, NULL, 1 },
    { "spring", "error < 0.01", F_ERROR, 0.1, NULL, 0 },
    { "vortex", "drift > 0.3", F_DRIFT, 0.36, NULL, 1 },
    { "vortex", "|drift| < 1e-9", F_DRIFT, 1e-6, NULL, 0 },
    { "vortex", "error_ratio near 2 within 0.3", F_RATIO, 2.08, NULL, 1 },
    { "vortex", "error_ratio near 2 within 0.3", F_RATIO, 2.4, NULL, 0 },
    { "vortex", "error_ratio near 2 within 0.3", F_RATIO, 1.7, NULL, 1 },
    { "vortex", "error_ratio near 16 within 2", F_RATIO, NAN, NULL, 0 },
    { "orbit", "accepted >= 100", F_ACCEPTED, 100, NULL, 1 },
    { "orbit", "accepted >= 100", F_ACCEPTED, 99, NULL, 0 },
    { "orbit", "rejected >= 1", F_REJECTED, 3, NULL, 1 },
    { "orbit", "rejected >= 1", F_REJECTED, 0, NULL, 0 },
    { "spring", "param c >= 60", F_PARAM_C, 200, NULL, 1 },
    { "spring", "param c >= 60", F_PARAM_C, 10, NULL, 0 },
    { "spring", "param c >= 60", F_NONE, 0, NULL, 0 },  /* parameter not in obs */
    { "spring", "blown", F_BLOWN, 1, NULL, 1 },
    { "spring", "blown", F_BLOWN, 0, NULL, 0 },
    { "spring", "not blown", F_BLOWN, 0, NULL, 1 },
    { "spring", "!blown", F_BLOWN, 1, NULL, 0 },
    { "spring", "blown == no", F_BLOWN, 0, NULL, 1 },
    { "spring", "compare", F_COMPARE, 1, NULL, 1 },
    { "spring", "compare == off", F_COMPARE, 1, NULL, 0 },
    { "spring", "ghost is on", F_GHOST, 1, NULL, 1 },
    { "spring", "ghost != on", F_GHOST, 1, NULL, 0 },
    { "spring", "paused", F_PAUSED, 1, NULL, 1 },
    { "spring", "paused == false", F_PAUSED, 1, NULL, 0 },
    { "spring", "recorded", F_RECORDED, 1, NULL, 1 },
    { "spring", "recorded", F_RECORDED, 0, NULL, 0 },
    { "spring", "phase", F_PHASE, 1, NULL, 1 },
    { "spring", "phase", F_PHASE, 0, NULL, 0 },
    { "spring", "not region", F_REGION, 0, NULL, 1 },
    { "spring", "region", F_REGION, 0, NULL, 0 },
};

#define NGOALS ((int)(sizeof goal_cases / sizeof goal_cases[0]))

static void obs_base(sw_lesson_obs *obs, const char *scene)
{
    sw_lesson_obs_init(obs);
    obs->scene = scene;
    obs->integrator = "euler";
    obs->dt = 0.1;
    obs->t = 5;
    obs->speed = 1;
}

START_TEST(goal_cases_evaluate)
{
    const struct goal_case *c = &goal_cases[_i];
    char text[256], err[SW_LESSON_ERRLEN];
    snprintf(text, sizeof text, "title: T\n--- p\n@scene %s\nx\n@goal %s\n@hint h\n", c->scene, c->goal);
    sw_lesson l;
    ck_assert_msg(parse(text, &l, err, sizeof err) == SW_OK, "%s: %s", c->goal, err);
    const sw_lesson_goal *g = &l.pages[0].goals[0];
    sw_lesson_obs obs;
    obs_base(&obs, c->scene);
    switch (c->field) {
    case F_SCENE: obs.scene = c->name; break;
    case F_INTEGRATOR: obs.integrator = c->name; break;
    case F_DT: obs.dt = c->value; break;
    case F_T: obs.t = c->value; break;
    case F_STEPS: obs.steps = (long)c->value; break;
    case F_EVALS: obs.evals = (long)c->value; break;
    case F_SPEED: obs.speed = c->value; break;
    case F_ENERGY: obs.energy_drift = c->value; break;
    case F_ERROR: obs.error = c->value; break;
    case F_DRIFT: obs.drift = c->value; break;
    case F_RATIO: obs.error_ratio = c->value; break;
    case F_ACCEPTED: obs.accepted = (long)c->value; break;
    case F_REJECTED: obs.rejected = (long)c->value; break;
    case F_PARAM_C:
        obs.nparams = 2;
        obs.param_name[0] = "k";
        obs.param_value[0] = 1e4;
        obs.param_name[1] = "c";
        obs.param_value[1] = c->value;
        break;
    case F_BLOWN: obs.blown = (int)c->value; break;
    case F_COMPARE: obs.compare = (int)c->value; break;
    case F_GHOST: obs.ghost = (int)c->value; break;
    case F_PAUSED: obs.paused = (int)c->value; break;
    case F_RECORDED: obs.recorded = (int)c->value; break;
    case F_PHASE: obs.phase = (int)c->value; break;
    case F_REGION: obs.region = (int)c->value; break;
    case F_NONE: break;
    }
    ck_assert_msg(sw_lesson_goal_met(g, &obs) == c->met, "goal '%s' (case %d) should %sbe met", c->goal, _i,
                  c->met ? "" : "not ");
    sw_lesson_free(&l);
}
END_TEST

/* Each variable is reachable by some true and some false case above. */
START_TEST(goal_cases_cover_every_variable)
{
    int seen_true[SW_LV_COUNT] = { 0 }, seen_false[SW_LV_COUNT] = { 0 };
    char text[256], err[SW_LESSON_ERRLEN];
    for (int i = 0; i < NGOALS; i++) {
        snprintf(text, sizeof text, "title: T\n--- p\n@scene %s\nx\n@goal %s\n@hint h\n", goal_cases[i].scene,
                 goal_cases[i].goal);
        sw_lesson l;
        ck_assert_int_eq(parse(text, &l, err, sizeof err), SW_OK);
        int v = l.pages[0].goals[0].var;
        (goal_cases[i].met ? seen_true : seen_false)[v] = 1;
        sw_lesson_free(&l);
    }
    for (int v = 0; v < SW_LV_COUNT; v++)
        ck_assert_msg(seen_true[v] && seen_false[v], "variable %s lacks a true or a false case",
                      sw_lesson_var_name((sw_lesson_var)v));
}
END_TEST

START_TEST(goal_text_reads_well)
{
    static const struct { const char *scene, *goal, *text; } cases[] = {
        { "spring", "integrator == rk4", "integrator is rk4" },
        { "spring", "integrator != euler", "integrator is not euler" },
        { "spring", "integrator in verlet symplectic-euler rk4", "integrator is verlet, symplectic-euler or rk4" },
        { "spring", "dt >= 0.2", "dt >= 0.2" },
        { "spring", "dt = 0.16", "dt = 0.16" },
        { "spring", "|energy_drift| < 1%", "|energy drift| < 1 %" },
        { "spring", "t > 10", "t > 10" },
        { "vortex", "error_ratio near 4 within 0.5", "error ratio within 0.5 of 4" },
        { "spring", "blown", "the sim has blown up" },
        { "spring", "not blown", "the sim has not blown up" },
        { "spring", "ghost", "ghost is on" },
        { "spring", "compare == off", "compare is off" },
        { "spring", "paused", "the sim is paused" },
        { "spring", "recorded", "a trace has been recorded" },
        { "spring", "param c >= 60", "c >= 60" },
        { "orbit", "rejected >= 1", "rejected steps >= 1" },
    };
    char text[256], err[SW_LESSON_ERRLEN], out[128];
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        snprintf(text, sizeof text, "title: T\n--- p\n@scene %s\nx\n@goal %s\n@hint h\n", cases[i].scene,
                 cases[i].goal);
        sw_lesson l;
        ck_assert_msg(parse(text, &l, err, sizeof err) == SW_OK, "%s", err);
        sw_lesson_goal_text(&l.pages[0].goals[0], out, sizeof out);
        ck_assert_str_eq(out, cases[i].text);
        /* Truncation keeps the buffer a string. */
        char tiny[5];
        sw_lesson_goal_text(&l.pages[0].goals[0], tiny, sizeof tiny);
        ck_assert_uint_le(strlen(tiny), 4);
        sw_lesson_free(&l);
    }
}
END_TEST

START_TEST(goal_var_lookup)
{
    for (int v = 0; v < SW_LV_COUNT; v++)
        ck_assert_int_eq(sw_lesson_var_find(sw_lesson_var_name((sw_lesson_var)v)), v);
    ck_assert_int_eq(sw_lesson_var_find("Δt"), SW_LV_DT);
    ck_assert_int_eq(sw_lesson_var_find("time"), SW_LV_T);
    ck_assert_int_eq(sw_lesson_var_find("energy"), -1);
    ck_assert_ptr_null(sw_lesson_var_name(SW_LV_COUNT));
}
END_TEST

/* ---- questions and pages ------------------------------------------------------------ */

START_TEST(question_answers_and_completion)
{
    const char *text = "title: T\n--- p\n@scene spring\nx\n@goal t >= 1\n@hint Run.\n"
                       "@question Which?\n@answer a) One | Not one.\n@answer B) Two | Yes, two.\n"
                       "@answer c) Three|four | Bars inside | text are fine.\n@correct b\n@hint Think.\n"
                       "--- q\nNo question here.\n";
    sw_lesson l;
    char err[SW_LESSON_ERRLEN];
    ck_assert_msg(parse(text, &l, err, sizeof err) == SW_OK, "%s", err);
    const sw_lesson_page *pg = &l.pages[0];
    ck_assert_int_eq(pg->question.nanswers, 3);
    ck_assert_int_eq(pg->question.correct, 1);
    ck_assert_str_eq(pg->question.hint, "Think.");
    ck_assert_str_eq(pg->question.answers[2].text, "Three|four");
    ck_assert_str_eq(pg->question.answers[2].feedback, "Bars inside | text are fine.");
    const char *fb = NULL;
    ck_assert_int_eq(sw_lesson_answer(pg, 'a', &fb), 0);
    ck_assert_str_eq(fb, "Not one.");
    ck_assert_int_eq(sw_lesson_answer(pg, 'b', &fb), 1);
    ck_assert_str_eq(fb, "Yes, two.");
    ck_assert_int_eq(sw_lesson_answer(pg, 'B', &fb), 1);
    ck_assert_int_eq(sw_lesson_answer(pg, 'd', &fb), SW_EINVAL);
    ck_assert_ptr_nonnull(fb);
    ck_assert_int_eq(sw_lesson_answer(pg, 0x10000, &fb), SW_EINVAL);
    ck_assert_int_eq(sw_lesson_answer(&l.pages[1], 'a', &fb), SW_EINVAL);

    sw_lesson_obs obs;
    obs_base(&obs, "spring");
    obs.t = 2;
    ck_assert_int_eq(sw_lesson_page_complete(pg, &obs, 0), 0);  /* not answered */
    ck_assert_int_eq(sw_lesson_page_complete(pg, &obs, 1), 1);
    obs.t = 0.5;
    ck_assert_int_eq(sw_lesson_page_complete(pg, &obs, 1), 0);  /* goal not met */
    ck_assert_int_eq(sw_lesson_page_complete(&l.pages[1], &obs, 0), 1);  /* nothing asked */
    sw_lesson_free(&l);
}
END_TEST

/* The observation a sim fills: checked against the sim's own fields. */
START_TEST(obs_from_sim_fills_what_a_sim_knows)
{
    sw_sim s;
    char err[SW_ERRLEN];
    const sw_scene *sc = sw_scene_find("spring");
    ck_assert_int_eq(sw_sim_init(&s, sc, NULL, sw_integrator_find("euler"), 0.02, err, sizeof err), SW_OK);
    sw_sim_run_until(&s, 1.0);
    sw_lesson_obs obs;
    sw_lesson_obs_init(&obs);
    obs.ghost = 1;
    sw_lesson_obs_from_sim(&obs, &s);
    ck_assert_str_eq(obs.scene, "spring");
    ck_assert_str_eq(obs.integrator, "euler");
    ck_assert_double_eq(obs.dt, 0.02);
    ck_assert_double_eq(obs.t, s.t);
    ck_assert_int_eq(obs.steps, 50);
    ck_assert_int_eq(obs.evals, 50);  /* Euler: one evaluation per step */
    ck_assert_int_eq(obs.blown, 0);
    ck_assert_double_eq(obs.energy_drift, sw_sim_energy_drift(&s));
    ck_assert(isnan(obs.drift));      /* the spring has no invariant */
    ck_assert(isnan(obs.error));      /* left to the app */
    ck_assert_int_eq(obs.ghost, 1);   /* app fields untouched */
    ck_assert_int_eq(obs.nparams, sc->nparams);
    ck_assert_str_eq(obs.param_name[0], "k");
    ck_assert_double_eq(obs.param_value[0], 10);
    sw_sim_free(&s);
}
END_TEST

Suite *make_lesson_goals_suite(void);
Suite *make_lesson_goals_suite(void)
{
    Suite *s = suite_create("lesson_goals");
    TCase *tc = tcase_create("goals");
    tcase_add_loop_test(tc, goal_cases_evaluate, 0, NGOALS);
    tcase_add_test(tc, goal_cases_cover_every_variable);
    tcase_add_test(tc, goal_text_reads_well);
    tcase_add_test(tc, goal_var_lookup);
    tcase_add_test(tc, question_answers_and_completion);
    tcase_add_test(tc, obs_from_sim_fills_what_a_sim_knows);
    suite_add_tcase(s, tc);
    return s;
}
