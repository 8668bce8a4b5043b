/* Every figure the texts quote to a student or a teacher, computed from the
 * library: one table, one row per claim. A row names its file and an exact
 * snippet of the text with the figure marked {like this}; the test finds the
 * snippet (so editing the text forces editing the row), parses the figure as
 * written, computes it from the library (runs, the truth module, the
 * stability lab, the live app) and compares within a tolerance that matches
 * how the text rounds it. A claim that is a formula (no {figure}) is
 * compared with the formula's value at the lesson's parameters.
 *
 * Snippets match with every run of white space as one space, and in a
 * lesson file a comment line's leading '#' is dropped, so a snippet may run
 * across the comment header's lines. A guard test asks for a row for every
 * number in the texts that reads like a quoted figure.
 *
 * CK_RUN_SUITE=claims SW_CLAIMS_PRINT=1 build/check_stepwise prints every
 * row's written and computed values (for authors); SW_TEST_QUICK skips
 * computing the rows that bisect for a stability limit. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "app/app.h"
#include "app/runner.h"
#include "lesson/lesson.h"
#include "lab/bench.h"
#include "lab/check.h"
#include "lab/stability.h"
#include "sim/truth.h"
#include "sim/watch.h"
#include "stepwise/stepwise.h"

/* ---- scenes, runs and lesson pages ------------------------------------- */

/* The texts, from the repository root (the tests run there). */
#define L1 "lessons/01-flow-fields.lesson"
#define L2 "lessons/02-euler.lesson"
#define L3 "lessons/03-particles-with-mass.lesson"
#define L4 "lessons/04-forces.lesson"
#define L5 "lessons/05-springs.lesson"
#define L6 "lessons/06-runge-kutta.lesson"
#define L7 "lessons/07-implicit.lesson"
#define L8 "lessons/08-energy-orbits.lesson"
#define L9 "lessons/09-adaptive.lesson"
#define L10 "lessons/10-homework.lesson"
#define GUIDE "lessons/README.md"
#define README "README.md"
#define MAN "docs/stepwise.1"
#define STAB "docs/stability.md"
#define INTEGRATORS "src/engine/integrators.c"

/* Parameters of scene `name`: its defaults, then "NAME=VALUE" assignments
 * separated by spaces (NULL or "": none). */
static const sw_scene *scene_p(const char *name, const char *sets, double *p)
{
    const sw_scene *sc = sw_scene_find(name);
    ck_assert_msg(sc != NULL, "no scene %s", name);
    sw_scene_defaults(sc, p);
    char buf[256], err[SW_ERRLEN];
    snprintf(buf, sizeof buf, "%s", sets ? sets : "");
    for (char *tok = strtok(buf, " "); tok; tok = strtok(NULL, " "))
        ck_assert_msg(sw_scene_set(sc, p, tok, err, sizeof err) == SW_OK, "%s", err);
    return sc;
}

static double param(const char *scene, const char *name)
{
    double p[SW_MAX_PARAMS];
    const sw_scene *sc = scene_p(scene, NULL, p);
    int i = sw_scene_param_index(sc, name);
    ck_assert_msg(i >= 0, "%s has no parameter %s", scene, name);
    return p[i];
}

static const sw_integrator *method(const char *name)
{
    const sw_integrator *m = sw_integrator_find(name);
    ck_assert_msg(m != NULL, "no integrator %s", name);
    return m;
}

static void sim_init(sw_sim *s, const char *scene, const char *sets, const char *m, double dt)
{
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    const sw_scene *sc = scene_p(scene, sets, p);
    ck_assert_msg(sw_sim_init(s, sc, p, method(m), dt, err, sizeof err) == SW_OK, "%s", err);
}

/* Whole steps until t reaches T (as the app steps: whole steps of dt). */
static void steps_to(sw_sim *s, double T)
{
    while (!s->blown && s->t < T - 1e-9 * s->dt)
        sw_sim_step(s);
}

/* The energy drift in percent (sw_sim_energy_drift, as the status line
 * shows it) after whole steps to T. */
static double drift_at(const char *scene, const char *sets, const char *m, double dt, double T)
{
    sw_sim s;
    sim_init(&s, scene, sets, m, dt);
    steps_to(&s, T);
    ck_assert_msg(!s.blown, "%s on %s at dt %g blew up at t = %g", m, scene, dt, s.blow_time);
    double d = sw_sim_energy_drift(&s);
    sw_sim_free(&s);
    return d;
}

/* The first time the drift passes `level` percent (level > 0: rises above,
 * level < 0: falls below), stepping up to T; NaN if it never does. */
static double time_drift_passes(const char *scene, const char *sets, const char *m, double dt, double level,
                                double T)
{
    sw_sim s;
    sim_init(&s, scene, sets, m, dt);
    double when = NAN;
    while (!s.blown && s.t < T) {
        sw_sim_step(&s);
        double d = sw_sim_energy_drift(&s);
        if (level > 0 ? d > level : d < level) {
            when = s.t;
            break;
        }
    }
    sw_sim_free(&s);
    return when;
}

/* The largest |drift| over whole steps to T. */
static double max_abs_drift(const char *scene, const char *sets, const char *m, double dt, double T)
{
    sw_sim s;
    sim_init(&s, scene, sets, m, dt);
    double worst = 0;
    while (!s.blown && s.t < T - 1e-9 * dt) {
        sw_sim_step(&s);
        worst = fmax(worst, fabs(sw_sim_energy_drift(&s)));
    }
    ck_assert(!s.blown);
    sw_sim_free(&s);
    return worst;
}

/* The time a run blows up (NaN: not by T). */
static double blow_time(const char *scene, const char *sets, const char *m, double dt, double T)
{
    sw_sim s;
    sim_init(&s, scene, sets, m, dt);
    steps_to(&s, T);
    double when = s.blown ? s.blow_time : NAN;
    sw_sim_free(&s);
    return when;
}

/* The spectrum of a scene's linearisation at its start. */
static sw_spectrum spectrum0(const char *scene, const char *sets)
{
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    const sw_scene *sc = scene_p(scene, sets, p);
    sw_system sys;
    ck_assert_msg(sw_system_build(&sys, sc, p, err, sizeof err) == SW_OK, "%s", err);
    sw_spectrum sp;
    ck_assert_int_eq(sw_truth_spectrum(&sys, 0.0, sys.y, &sp), 0);
    sw_system_free(&sys);
    return sp;
}

/* Growth per step ρ of method m at dt on the scene's worst mode at its start. */
static double growth0(const char *scene, const char *sets, const char *m, double dt)
{
    sw_spectrum sp = spectrum0(scene, sets);
    return sw_truth_growth_all(method(m), &sp, dt, NULL);
}

/* The largest stable step in theory at the scene's start. */
static double limit0(const char *scene, const char *sets, const char *m)
{
    sw_spectrum sp = spectrum0(scene, sets);
    int unbounded;
    return sw_truth_limit(method(m), &sp, SW_DT_MAX, &unbounded);
}

/* Theory and measurement of the stability lab (what `stepwise stability`
 * prints). */
static sw_stability_result stability(const char *scene, const char *sets, const char *m)
{
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    const sw_scene *sc = scene_p(scene, sets, p);
    sw_stability_config c;
    sw_stability_config_default(&c);
    sw_stability_result r;
    ck_assert_msg(sw_stability_find(sc, p, method(m), &c, &r, err, sizeof err) == SW_OK, "%s", err);
    return r;
}

/* A lesson page as the student meets it: the runner opens the page of
 * lesson file `file` by its title, with the page's (and earlier pages')
 * settings applied. */
static void lesson_page(sw_runner *r, sw_app *a, const char *file, const char *title)
{
    char err[SW_LESSON_ERRLEN];
    const char *path = file;
    sw_lesson lesson;
    ck_assert_msg(sw_lesson_load(path, &lesson, err, sizeof err) == SW_OK, "%s", err);
    int page = -1;
    for (int i = 0; i < lesson.npages; i++)
        if (strcmp(lesson.pages[i].title, title) == 0)
            page = i;
    sw_lesson_free(&lesson);
    ck_assert_msg(page >= 0, "%s has no page '%s'", file, title);
    ck_assert_msg(sw_runner_start(r, a, path, page, err, sizeof err) == SW_OK, "%s", err);
    a->paused = 0;
}

static void page_free(sw_runner *r, sw_app *a)
{
    sw_app_free(a);
    sw_runner_free(r);
}

/* Press a key as the student would (locks ignored: the claim is about what
 * the key shows, not whether the page allows it). */
static void act(sw_app *a, sw_action action, int arg)
{
    unsigned locked = a->locked;
    a->locked = 0;
    sw_app_apply(a, action, arg);
    a->locked = locked;
}

/* The error ratio the status line shows after k presses of '-' from the
 * page's set-up (NaN when the app shows no order). */
static double page_ratio(const char *file, const char *title, const char *integrator, int k)
{
    sw_runner r;
    sw_app a;
    lesson_page(&r, &a, file, title);
    if (integrator)
        ck_assert_int_eq(sw_app_set_method(&a, method(integrator)), SW_OK);
    for (int i = 0; i < k; i++)
        act(&a, SW_ACT_DT_HALVE, 0);
    double ratio = a.error_ratio;
    page_free(&r, &a);
    return ratio;
}

/* The ratio the status line prints after k presses of '-', read as an
 * order or not: the errors at the larger and the smaller Δt. */
static double page_shown_ratio(const char *file, const char *title, const char *integrator, int k)
{
    sw_runner r;
    sw_app a;
    lesson_page(&r, &a, file, title);
    if (integrator)
        ck_assert_int_eq(sw_app_set_method(&a, method(integrator)), SW_OK);
    for (int i = 0; i < k; i++)
        act(&a, SW_ACT_DT_HALVE, 0);
    double ratio = a.nmeas == 2 ? a.meas_err[0] / a.meas_err[1] : NAN;
    page_free(&r, &a);
    return ratio;
}

/* The error the app measures at the report time for the page's scene. */
static double page_error(const char *file, const char *title, const char *m, double dt)
{
    sw_runner r;
    sw_app a;
    lesson_page(&r, &a, file, title);
    double e = sw_app_measure(&a, method(m), dt);
    page_free(&r, &a);
    return e;
}

/* The digit key that picks a method, from the controls' key table; NaN: none. */
static double key_of(const char *name)
{
    for (int d = 0; d <= 9; d++) {
        const sw_control *control;
        int arg;
        if (sw_key_lookup('0' + d, SW_CTX_PLAY, &control, &arg) && control->action == SW_ACT_PICK_METHOD &&
            sw_integrator_at(arg - 1) && strcmp(sw_integrator_at(arg - 1)->name, name) == 0)
            return d;
    }
    return NAN;
}

/* Δt after k presses of + (double) or - (halve) from the page's set-up. */
static double page_dt_after(const char *file, const char *title, sw_action action, int k)
{
    sw_runner r;
    sw_app a;
    lesson_page(&r, &a, file, title);
    for (int i = 0; i < k; i++)
        act(&a, action, 0);
    double dt = a.dt;
    page_free(&r, &a);
    return dt;
}

/* Derivative evaluations per step of m on a scene, measured over n steps
 * after the first. */
static double evals_per_step(const char *scene, const char *sets, const char *m, double dt, int n)
{
    sw_sim s;
    sim_init(&s, scene, sets, m, dt);
    sw_sim_step(&s); /* a first step may evaluate what later steps reuse */
    long e1 = sw_sim_evals(&s);
    for (int i = 0; i < n; i++)
        sw_sim_step(&s);
    double r = (double)(sw_sim_evals(&s) - e1) / (double)n;
    sw_sim_free(&s);
    return r;
}

/* Order measured by halving dt: log2 of the error ratio at the report time
 * against the truth module. */
static double order_by_halving(const char *scene, const char *sets, const char *m, double dt)
{
    double p[SW_MAX_PARAMS], err2[2];
    const sw_scene *sc = scene_p(scene, sets, p);
    double T = sc->duration;
    double *truth = malloc(4096 * sizeof *truth);
    ck_assert_int_eq(sw_truth_state(sc, p, T, truth), 0);
    for (int i = 0; i < 2; i++) {
        sw_sim s;
        sim_init(&s, scene, sets, m, dt / (1 << i));
        ck_assert_int_eq(sw_sim_run_until(&s, T), 0);
        err2[i] = sw_truth_error(s.sys.ode->dim, s.sys.y, truth);
        sw_sim_free(&s);
    }
    free(truth);
    return log2(err2[0] / err2[1]);
}

/* Radius of vortex particle i over its start after whole steps to T. */
static double vortex_radius_growth(const char *m, double dt, double T)
{
    sw_sim s;
    sim_init(&s, "vortex", NULL, m, dt);
    double r0 = hypot(s.sys.y[0], s.sys.y[1]);
    steps_to(&s, T);
    double r = hypot(s.sys.y[0], s.sys.y[1]);
    sw_sim_free(&s);
    return r / r0;
}

static long steps_for(const char *scene, const char *sets, const char *m, double dt, double T)
{
    sw_sim s;
    sim_init(&s, scene, sets, m, dt);
    ck_assert_int_eq(sw_sim_run_until(&s, T), 0);
    long n = s.steps;
    sw_sim_free(&s);
    return n;
}

#define TWO_PI 6.283185307179586

/* ---- lesson 1 ---------------------------------------------------------- */

static double l1_omega(void) { return param("vortex", "omega"); }
/* One turn: 2π over the rotation rate, read off the linearisation (±iω). */
static double l1_turn(void)
{
    sw_spectrum sp = spectrum0("vortex", NULL);
    return TWO_PI / fabs(sp.mode[0].im);
}
static double l1_gyre_swing(void) { return TWO_PI / param("gyre", "omega"); }

/* ---- lesson 2 ---------------------------------------------------------- */

static double l2_factor(void) { return growth0("vortex", NULL, "euler", 0.1); }
static double l2_factor_formula(void) { return sqrt(1 + 0.1 * 0.1 * pow(l1_omega(), 2)); }
static double l2_turn_steps(void) { return (double)steps_for("vortex", NULL, "euler", 0.1, TWO_PI); }
static double l2_power(void) { return pow(1.005, 63); }
static double l2_turn_growth(void) { return vortex_radius_growth("euler", 0.1, TWO_PI); }
static double l2_sqrt116(void) { return sqrt(1 + 0.4 * 0.4); }
static double l2_factor04(void) { return growth0("vortex", NULL, "euler", 0.4); }
static double l2_turn_steps04(void) { return (double)steps_for("vortex", NULL, "euler", 0.4, TWO_PI); }
static double l2_turn_growth04(void) { return vortex_radius_growth("euler", 0.4, TWO_PI); }
/* One Euler step's error halving Δt: the local error's order (2 for O(Δt²)). */
static double l2_local_order(void)
{
    double err[2];
    for (int i = 0; i < 2; i++) {
        sw_sim s;
        double h = 0.01 / (1 << i), truth[400];
        sim_init(&s, "vortex", NULL, "euler", h);
        sw_sim_step(&s);
        ck_assert_int_eq(sw_truth_state(s.sys.scene, s.sys.p, s.t, truth), 0);
        err[i] = sw_truth_error(s.sys.ode->dim, s.sys.y, truth);
        sw_sim_free(&s);
    }
    return log2(err[0] / err[1]);
}
static double l2_global_order(void) { return order_by_halving("vortex", NULL, "euler", 0.01); }
static double l2_report_time(void) { return sw_scene_find("vortex")->duration; }
static double l2_ratio1(void) { return page_ratio(L2, "Measure the order", NULL, 1); }
static double l2_ratio2(void) { return page_ratio(L2, "Measure the order", NULL, 2); }
static double l2_ratio3(void) { return page_ratio(L2, "Measure the order", NULL, 3); }
static double l2_err(double dt) { return page_error(L2, "Measure the order", "euler", dt); }
static double l2_err05(void) { return l2_err(0.05); }
static double l2_err025(void) { return l2_err(0.025); }
static double l2_err0125(void) { return l2_err(0.0125); }
static double l2_midpoint_order(void) { return order_by_halving("vortex", NULL, "midpoint", 0.05); }
static double l2_rk4_order(void) { return order_by_halving("vortex", NULL, "rk4", 0.1); }

/* ---- lesson 3 ---------------------------------------------------------- */

/* How far Euler's ball lands from the exact one at t = 2 (the status
 * line's error: the largest state difference). */
static double l3_miss(void)
{
    sw_runner r;
    sw_app a;
    lesson_page(&r, &a, L3, "Euler in phase space");
    steps_to(&a.sims[0], 2.0);
    double e = sw_app_error(&a, 0);
    page_free(&r, &a);
    return e;
}
static double l3_miss_position(void)
{
    sw_sim s;
    double truth[4];
    sim_init(&s, "projectile", NULL, "euler", 0.05);
    steps_to(&s, 2.0);
    ck_assert_int_eq(sw_truth_state(s.sys.scene, s.sys.p, s.t, truth), 0);
    double d = hypot(s.sys.y[0] - truth[0], s.sys.y[1] - truth[1]);
    sw_sim_free(&s);
    return d;
}
static double l3_omega(void) { return spectrum0("spring", "c=0").largest; }
static double l3_omega_dt(void) { return l3_omega() * 0.02; }
/* Energy factor per step: the square of the amplitude's growth ρ. */
static double l3_energy_factor(void) { return pow(growth0("spring", "c=0", "euler", 0.02), 2); }
static double l3_steps_per_second(void) { return (double)steps_for("spring", "c=0", "euler", 0.02, 1.0); }
static double l3_time_to_50(void) { return time_drift_passes("spring", "c=0", "euler", 0.02, 50, 10); }
static double l3_k(void) { return param("spring", "k"); }
static double l3_m(void) { return param("spring", "m"); }
static double l3_beads(void) { return param("chain", "n"); }
static double dim_of(const char *scene)
{
    sw_sim s;
    sim_init(&s, scene, NULL, "rk4", 0.01);
    double d = s.sys.ode->dim;
    sw_sim_free(&s);
    return d;
}
static double l3_chain_dim(void) { return dim_of("chain"); }
static double l3_chain_positions(void) { return dim_of("chain") / 2; }
static double l3_particle_dim(void) { return dim_of("projectile"); }
static double l3_3d(void) { return 2 * 3; }

/* ---- lesson 4 ---------------------------------------------------------- */

static double l4_e(void) { return param("bounce", "e"); }
/* One ball dropped from 4 m in the bounce scene (its own contact with
 * restitution e), stepped finely: the top of its first hop. */
static double bounce_height(const char *sets)
{
    sw_sim s;
    sim_init(&s, "bounce", sets, "rk4", 1e-4);
    double y[4] = { 5.0, 4.0, 0.0, 0.0 }, top = 0;
    sw_sim_set_state(&s, y);
    int bounced = 0;
    while (s.t < 3.0) {
        sw_sim_step(&s);
        if (s.sys.y[3] > 0)
            bounced = 1;
        if (bounced)
            top = fmax(top, s.sys.y[1]);
        if (bounced && s.sys.y[3] < 0)
            break;
    }
    sw_sim_free(&s);
    return top;
}
static double l4_bounce_height(void) { return bounce_height("n=1"); }
static double l4_perfect(void) { return bounce_height("n=1 e=1") / 4; }
static double l4_dead(void) { return bounce_height("n=1 e=0"); }
static double l4_e_height(void) { return 4 * l4_e(); }
static double l4_e_squared(void) { return l4_e() * l4_e(); }
static double l4_ratio(void) { return page_ratio(L4, "A bounce breaks the order", NULL, 1); }
static double l4_smooth_ratio(void) { return pow(2, order_by_halving("projectile", NULL, "rk4", 0.05)); }
static double l4_report_time(void) { return sw_scene_find("bounce")->duration; }

/* ---- lesson 5 ---------------------------------------------------------- */

#define STIFF "k=10000 c=10"
static double l5_k(void) { return param("spring", "k"); }
static double l5_c(void) { return param("spring", "c"); }
static double l5_m(void) { return param("spring", "m"); }
/* Swings in ten seconds: ten over the damped period 2π/ω_d (the
 * linearisation's imaginary part). */
static double l5_swings(void) { return 10 * fabs(spectrum0("spring", NULL).mode[0].im) / TWO_PI; }
static double l5_stiff_omega(void) { return spectrum0("spring", STIFF).largest; }
static double l5_euler_energy_factor(void) { return pow(growth0("spring", STIFF, "euler", 0.005), 2); }
static double l5_arith(void) { return 1 - 10 * 0.005 + 10000 * 0.005 * 0.005; }
static double l5_blow(void) { return blow_time("spring", STIFF, "euler", 0.005, 10); }
static double l5_critical(void) { return 2 * sqrt(10000 * l5_m()); }
/* The decay rate of the critically damped spring's modes: -Re λ. */
static double l5_crit_rate(void)
{
    sw_spectrum sp = spectrum0("spring", "k=10000 c=200");
    double worst = 0;
    for (int i = 0; i < sp.n; i++)
        worst = fmax(worst, -sp.mode[i].re);
    return worst;
}
static double l5_crit_growth(void) { return growth0("spring", "k=10000 c=200", "euler", 0.005); }
static double l5_crit_arith(void) { return fabs(1 - 100 * 0.005); }
static double l5_crit_first_step(void)
{
    sw_sim s;
    sim_init(&s, "spring", "k=10000 c=200", "euler", 0.005);
    sw_sim_step(&s);
    double d = sw_sim_energy_drift(&s);
    sw_sim_free(&s);
    return d;
}
static double l5_huge_rate(void) { return spectrum0("spring", "k=10000 c=5000").largest; }
static double l5_huge_limit(void) { return limit0("spring", "k=10000 c=5000", "euler"); }
static double l5_huge_smaller(void) { return 0.005 / l5_huge_limit(); }
static double l5_light_limit(void) { return limit0("spring", STIFF, "euler"); }
static double l5_light_arith(void) { return 10.0 / 10000.0; }
static double l5_steps(void) { return (double)steps_for("spring", STIFF, "euler", 0.000625, 1.0); }
/* (At Δt = 0.005 Euler blows up on this spring; the steps are counted on
 * the critically damped one, which it runs.) */
static double l5_steps_ratio(void)
{
    return l5_steps() / (double)steps_for("spring", "k=10000 c=200", "euler", 0.005, 1.0);
}
static double l5_undamped_factor(void) { return pow(growth0("spring", "k=10000 c=0", "euler", 0.000625), 2); }
static double l5_undamped_formula(void) { return 1 + pow(100 * 0.000625, 2); }
static double l5_undamped_limit(void) { return limit0("spring", "k=10000 c=0", "euler"); }
/* RK4's limit in ω·Δt on an undamped oscillator. */
static double rk4_wdt(void) { return limit0("spring", "k=1 c=0", "rk4"); }
static double two_root_two(void) { return 2 * sqrt(2); }
static double l5_wdt(void) { return l5_stiff_omega() * 0.005; }

/* ---- lesson 6 ---------------------------------------------------------- */

static double l6_ratio_mid(void) { return page_ratio(L6, "Midpoint is second order", NULL, 1); }
static double l6_ratio_rk4(void) { return page_ratio(L6, "RK4", "rk4", 1); }
static double l6_err(const char *m, double dt) { return page_error(L6, "Error against cost", m, dt); }
static double l6_err_euler(void) { return l6_err("euler", 0.0125); }
static double l6_err_mid(void) { return l6_err("midpoint", 0.025); }
static double l6_err_rk4(void) { return l6_err("rk4", 0.05); }
static double evals_to(const char *scene, const char *sets, const char *m, double dt, double T)
{
    sw_sim s;
    sim_init(&s, scene, sets, m, dt);
    ck_assert_int_eq(sw_sim_run_until(&s, T), 0);
    double e = (double)sw_sim_evals(&s);
    sw_sim_free(&s);
    return e;
}
static double l6_steps_euler(void) { return (double)steps_for("vortex", NULL, "euler", 0.0125, TWO_PI); }
static double l6_steps_mid(void) { return (double)steps_for("vortex", NULL, "midpoint", 0.025, TWO_PI); }
static double l6_steps_rk4(void) { return (double)steps_for("vortex", NULL, "rk4", 0.05, TWO_PI); }
static double l6_evals_euler(void) { return evals_to("vortex", NULL, "euler", 0.0125, TWO_PI); }
static double l6_evals_mid(void) { return evals_to("vortex", NULL, "midpoint", 0.025, TWO_PI); }
static double l6_evals_rk4(void) { return evals_to("vortex", NULL, "rk4", 0.05, TWO_PI); }
static double l6_gain(void) { return l6_err_euler() / l6_err_rk4(); }
static double l6_rk4_evals(void) { return evals_per_step("vortex", NULL, "rk4", 0.05, 10); }
static double l6_euler_evals(void) { return evals_per_step("vortex", NULL, "euler", 0.05, 10); }
static double l6_mid_evals(void) { return evals_per_step("vortex", NULL, "midpoint", 0.05, 10); }
static double l6_rk4_gain(void) { return pow(2, order_by_halving("vortex", NULL, "rk4", 0.1)); }
static double l6_euler_gain(void) { return pow(2, order_by_halving("vortex", NULL, "euler", 0.01)); }
static double l6_limit100(void) { return limit0("spring", "k=10000 c=0", "rk4"); }
static double l6_report_time(void) { return sw_scene_find("vortex")->duration; }

/* ---- lesson 7 ---------------------------------------------------------- */

static double l7_k(void) { return param("stiff-spring", "k"); }
static double l7_fast(void) { return spectrum0("stiff-spring", NULL).largest; }
/* The swing: the slowest mode of the linearisation at the start. */
static sw_mode l7_swing_mode(void)
{
    sw_spectrum sp = spectrum0("stiff-spring", NULL);
    ck_assert_int_ge(sp.n, 2);
    return sp.mode[sp.n - 1];
}
static double l7_slow(void)
{
    sw_mode md = l7_swing_mode();
    return hypot(md.re, md.im);
}
static double verlet_wdt(void) { return limit0("spring", "k=1 c=0", "verlet"); }
static double l7_verlet_theory(void) { return stability("stiff-spring", NULL, "verlet").theory; }
static double l7_verlet_measured(void) { return stability("stiff-spring", NULL, "verlet").dt; }
/* Verlet's limit on the swing alone, over its limit on the whole pendulum. */
static double l7_swing_longer(void)
{
    sw_spectrum sp = spectrum0("stiff-spring", NULL);
    sw_spectrum swing = sp;
    swing.n = 1;
    swing.mode[0] = l7_swing_mode();
    swing.largest = l7_slow();
    int unbounded;
    return sw_truth_limit(method("verlet"), &swing, SW_DT_MAX, &unbounded) /
           sw_truth_limit(method("verlet"), &sp, SW_DT_MAX, &unbounded);
}
static double l7_verlet_blow(void) { return blow_time("stiff-spring", NULL, "verlet", 0.04, 10); }
static double l7_be_drift(void) { return -drift_at("stiff-spring", NULL, "implicit-euler", 0.04, 2.5); }
static double l7_be_fraction(void) { return l7_be_drift() / 100; }
static double l7_lin_drift(void) { return -drift_at("stiff-spring", NULL, "linear-implicit-euler", 0.04, 2.5); }
static double energy_after_steps(const char *m, double dt, int n)
{
    sw_sim s;
    sim_init(&s, "stiff-spring", NULL, m, dt);
    for (int i = 0; i < n; i++)
        sw_sim_step(&s);
    ck_assert(!s.blown);
    double e = sw_sim_energy(&s);
    sw_sim_free(&s);
    return e;
}
static double l7_e0(void) { return energy_after_steps("linear-implicit-euler", 1.0, 0); }
static double l7_e1(void) { return energy_after_steps("linear-implicit-euler", 1.0, 1); }
/* Backward Euler's energy change in its first step at Δt = 1 (< 0: loses). */
static double l7_be_step(void)
{
    return energy_after_steps("implicit-euler", 1.0, 1) - energy_after_steps("implicit-euler", 1.0, 0);
}
static double zero(void) { return 0; }
static double l7_be_damping(void) { return growth0("spring", "k=10000 c=0", "implicit-euler", 0.04); }
static double l7_be_damping_formula(void) { return 1 / sqrt(1 + pow(100 * 0.04, 2)); }
/* One Newton step against Newton to rounding on the (linear) spring. */
static double l7_linear_same(void)
{
    sw_sim a, b;
    sim_init(&a, "spring", "c=0", "implicit-euler", 0.04);
    sim_init(&b, "spring", "c=0", "linear-implicit-euler", 0.04);
    double worst = 0;
    for (int i = 0; i < 250; i++) {
        sw_sim_step(&a);
        sw_sim_step(&b);
        worst = fmax(worst, sw_truth_error(4, a.sys.y, b.sys.y));
    }
    sw_sim_free(&a);
    sw_sim_free(&b);
    return worst;
}
static double rounding(void) { return 1e-12; }
static double l7_im_drift(void) { return max_abs_drift("stiff-spring", NULL, "implicit-midpoint", 0.04, 5); }
static double l7_im_limit(void) { return stability("stiff-spring", NULL, "implicit-midpoint").dt; }

/* ---- lesson 8 ---------------------------------------------------------- */

/* Kepler's period from the energy: a = -μ/2E, T = 2π√(a³/μ). */
static double orbit_period(const char *sets)
{
    sw_sim s;
    double p[SW_MAX_PARAMS];
    sim_init(&s, "orbit", sets, "rk4", 0.01);
    scene_p("orbit", sets, p);
    double mu = p[sw_scene_param_index(s.sys.scene, "mu")], a = -mu / (2 * sw_sim_energy(&s));
    sw_sim_free(&s);
    return TWO_PI * sqrt(a * a * a / mu);
}
static double l8_e(void) { return param("orbit", "e"); }
static double l8_period(void) { return orbit_period(NULL); }
static double l8_rk4_5(void) { return time_drift_passes("orbit", NULL, "rk4", 0.2, -5, 200); }
static double l8_rk4_5_orbits(void) { return l8_rk4_5() / l8_period(); }
static double l8_rk4_200(void) { return -drift_at("orbit", NULL, "rk4", 0.2, 200); }
static double l8_verlet(void) { return max_abs_drift("orbit", NULL, "verlet", 0.05, 200); }
static double l8_invariant(void)
{
    sw_sim s;
    sim_init(&s, "orbit", NULL, "verlet", 0.05);
    steps_to(&s, 60);
    double d = fabs(sw_sim_drift(&s));
    sw_sim_free(&s);
    return d;
}
static double l8_euler_1(void) { return drift_at("orbit", NULL, "euler", 0.05, 1); }
static double l8_euler_27(void) { return drift_at("orbit", NULL, "euler", 0.05, 27); }
static double l8_euler_1_fraction(void) { return l8_euler_1() / 100; }
static double l8_rk4_31(void) { return -drift_at("orbit", NULL, "rk4", 0.2, 31); }
static double l8_euler_half(void) { return time_drift_passes("orbit", NULL, "euler", 0.05, 50, 100); }
static double l8_verlet_evals(void) { return evals_per_step("orbit", NULL, "verlet", 0.05, 20); }
static double l8_rk4_evals(void) { return evals_per_step("orbit", NULL, "rk4", 0.05, 20); }
/* Verlet's step with RK4's evaluations per second at Δt = 0.2. */
static double l8_same_work(void) { return 0.2 * l8_verlet_evals() / l8_rk4_evals(); }

/* ---- lesson 9 ---------------------------------------------------------- */

#define ECC "e=0.9"
/* Apoapsis over periapsis distance, and the speeds the other way round,
 * from the true state at t = 0 (periapsis) and half a period. */
static double l9_dist_ratio(void)
{
    double p[SW_MAX_PARAMS], y0[4], y1[4];
    const sw_scene *sc = scene_p("orbit", ECC, p);
    ck_assert_int_eq(sw_truth_state(sc, p, 0, y0), 0);
    ck_assert_int_eq(sw_truth_state(sc, p, orbit_period(ECC) / 2, y1), 0);
    return hypot(y1[0], y1[1]) / hypot(y0[0], y0[1]);
}
static double l9_speed_ratio(void)
{
    double p[SW_MAX_PARAMS], y0[4], y1[4];
    const sw_scene *sc = scene_p("orbit", ECC, p);
    ck_assert_int_eq(sw_truth_state(sc, p, 0, y0), 0);
    ck_assert_int_eq(sw_truth_state(sc, p, orbit_period(ECC) / 2, y1), 0);
    return hypot(y0[2], y0[3]) / hypot(y1[2], y1[3]);
}
static double l9_arith(void) { return (1 + 0.9) / (1 - 0.9); }
static double two_orbits(void) { return 2 * orbit_period(ECC); }
static double l9_rk4_evals(void)
{
    sw_sim s;
    sim_init(&s, "orbit", ECC, "rk4", 0.05);
    steps_to(&s, two_orbits());
    double e = (double)sw_sim_evals(&s);
    sw_sim_free(&s);
    return e;
}
static double l9_rk4_drift(void) { return drift_at("orbit", ECC, "rk4", 0.05, two_orbits()); }
typedef struct rk45_run { double accepted, rejected, evals, drift; } rk45_run;
static rk45_run l9_rk45(double dt)
{
    sw_sim s;
    sim_init(&s, "orbit", ECC, "rk45", dt);
    double T = two_orbits(), worst = 0;
    while (!s.blown && T - s.t > 1e-9) {
        sw_sim_step_until(&s, T);
        worst = fmax(worst, fabs(sw_sim_energy_drift(&s)));
    }
    ck_assert(!s.blown);
    long acc, rej;
    sw_sim_step_counts(&s, &acc, &rej);
    rk45_run r = { (double)acc, (double)rej, (double)sw_sim_evals(&s), worst };
    sw_sim_free(&s);
    return r;
}
static double l9_acc04(void) { return l9_rk45(0.4).accepted; }
static double l9_rej04(void) { return l9_rk45(0.4).rejected; }
static double l9_evals04(void) { return l9_rk45(0.4).evals; }
static double l9_drift04(void) { return l9_rk45(0.4).drift; }
static double l9_acc005(void) { return l9_rk45(0.05).accepted; }
static double l9_rej005(void) { return l9_rk45(0.05).rejected; }
/* rk45's evaluations: per accepted step once under way (a smooth flow, no
 * rejections), and in its first step (every stage new). */
static double adaptive_per_step(const char *m)
{
    sw_sim s;
    sim_init(&s, "vortex", "n=1", m, 0.05);
    sw_sim_step(&s);
    long e1 = sw_sim_evals(&s);
    for (int i = 0; i < 20; i++)
        sw_sim_step(&s);
    long acc, rej;
    sw_sim_step_counts(&s, &acc, &rej);
    ck_assert_int_eq(rej, 0);
    double r = (double)(sw_sim_evals(&s) - e1) / (double)(acc - 1);
    sw_sim_free(&s);
    return r;
}
static double l9_rk45_per_step(void) { return adaptive_per_step("rk45"); }
static double l9_rk45_stages(void)
{
    sw_sim s;
    sim_init(&s, "vortex", "n=1", "rk45", 0.05);
    sw_sim_step(&s);
    double e = (double)sw_sim_evals(&s);
    sw_sim_free(&s);
    return e;
}
static double dop853_per_step(void) { return adaptive_per_step("dop853"); }
static double ord_dop853(void) { return method("dop853")->order; }
static double reference_order(void) { return sw_truth_reference_method()->order; }
/* An adaptive run of the e = 0.9 orbit to two orbits at largest step 0.4
 * and tolerances (rtol, atol): its evaluations and its error against Kepler. */
static void l9_adaptive(const char *m, double rtol, double atol, double *evals, double *error)
{
    sw_sim s;
    double p[SW_MAX_PARAMS], truth[4];
    const sw_scene *sc = scene_p("orbit", ECC, p);
    sim_init(&s, "orbit", ECC, m, 0.4);
    sw_sim_set_tolerances(&s, rtol, atol);
    ck_assert_int_eq(sw_sim_run_until(&s, two_orbits()), 0);
    ck_assert_int_eq(sw_truth_state(sc, p, s.t, truth), 0);
    *evals = (double)sw_sim_evals(&s);
    *error = sw_truth_error(4, s.sys.y, truth);
    sw_sim_free(&s);
}
static double l9_sim_rtol(void)
{
    sw_sim s;
    sim_init(&s, "orbit", ECC, "rk45", 0.4);
    double r = s.rtol;
    sw_sim_free(&s);
    return r;
}
static double l9_rk45_error(void)
{
    double evals, error;
    l9_adaptive("rk45", SW_RTOL_DEFAULT, SW_ATOL_DEFAULT, &evals, &error);
    return error;
}
static double l9_rk45_error_over_rtol(void) { return l9_rk45_error() / SW_RTOL_DEFAULT; }
static double l9_proportion(void)
{
    double evals, tight;
    l9_adaptive("rk45", 1e-8, 1e-11, &evals, &tight);
    return (tight / 1e-8) / l9_rk45_error_over_rtol();
}
static double l9_dop853_vs_rk45(void)
{
    double e1, e2, error;
    l9_adaptive("dop853", SW_RTOL_DEFAULT, SW_ATOL_DEFAULT, &e1, &error);
    l9_adaptive("rk45", SW_RTOL_DEFAULT, SW_ATOL_DEFAULT, &e2, &error);
    return e1 / e2;
}
static double l9_tight(const char *m, int want_error)
{
    double evals, error;
    l9_adaptive(m, 1e-10, 1e-13, &evals, &error);
    return want_error ? error : evals;
}
static double l9_tight_dop853_evals(void) { return l9_tight("dop853", 0); }
static double l9_tight_dop853_error(void) { return l9_tight("dop853", 1); }
static double l9_tight_rk45_evals(void) { return l9_tight("rk45", 0); }
static double l9_tight_rk45_error(void) { return l9_tight("rk45", 1); }
static double place_of(const char *name)
{
    for (int i = 0; i < sw_integrator_count(); i++)
        if (strcmp(sw_integrator_at(i)->name, name) == 0)
            return i + 1;
    return NAN;
}
static double l9_dop853_place(void) { return place_of("dop853"); }
static double l9_dop853_after_rk45(void) { return place_of("dop853") - place_of("rk45"); }
static double l9_rk45_order(void) { return method("rk45")->order; }

/* ---- lesson 10 --------------------------------------------------------- */

static double l10_ratio(const char *m)
{
    return page_ratio(L10, "Check your order", m, 1);
}
static double l10_ratio_mid(void) { return l10_ratio("midpoint"); }
static double l10_ratio_rk4(void) { return l10_ratio("rk4"); }
static double l10_ratio_euler1(void) { return page_shown_ratio(L10, "Check your order", "euler", 1); }
static double l10_ratio_euler2(void) { return page_shown_ratio(L10, "Check your order", "euler", 2); }
static double l10_ratio_euler5(void) { return page_ratio(L10, "Check your order", "euler", 5); }
/* Euler's amplitude error over the run, e^(ω²ΔtT/2) - 1: its ratio when Δt
 * halves, at the exponent the page's spring has at Δt = 0.02. */
static double l10_exponent(void)
{
    return pow(spectrum0("spring", NULL).largest, 2) * 0.02 * sw_scene_find("spring")->duration / 2;
}
static double l10_ratio_formula(void)
{
    double x = l10_exponent();
    return (exp(x) - 1) / (exp(x / 2) - 1);
}
static double l10_duration(void) { return sw_scene_find("spring")->duration; }

/* Midpoint against Heun, the largest state difference over the run. */
static double mid_vs_heun(const char *scene)
{
    sw_sim a, b;
    sim_init(&a, scene, NULL, "midpoint", 0.01);
    sim_init(&b, scene, NULL, "heun", 0.01);
    double worst = 0, T = a.sys.scene->duration;
    while (a.t < T - 1e-9) {
        sw_sim_step(&a);
        sw_sim_step(&b);
        worst = fmax(worst, sw_truth_error(a.sys.ode->dim, a.sys.y, b.sys.y));
    }
    sw_sim_free(&a);
    sw_sim_free(&b);
    return worst;
}
static double l10_spring_same(void) { return mid_vs_heun("spring"); }
static double l10_chain_differ(void) { return mid_vs_heun("chain"); }
static double check_tolerance(void) { return SW_CHECK_ATOL + SW_CHECK_RTOL; }

/* ---- README ------------------------------------------------------------ */

/* The order each method shows when Δt halves on the default (damped)
 * spring, from a step in its asymptotic range (the error at the report time
 * against the closed form). */
static double order_on_spring(const char *m) { return order_by_halving("spring", NULL, m, 0.01); }
/* First-order methods reach their asymptotic range at smaller steps. */
static double order1_on_spring(const char *m) { return order_by_halving("spring", NULL, m, 0.0005); }
static double ord_euler(void) { return order1_on_spring("euler"); }
static double ord_symplectic(void) { return order1_on_spring("symplectic-euler"); }
static double ord_midpoint(void) { return order_on_spring("midpoint"); }
static double ord_heun(void) { return order_on_spring("heun"); }
static double ord_rk4(void) { return order_by_halving("spring", NULL, "rk4", 0.04); }
static double ord_verlet(void) { return order_on_spring("verlet"); }
static double ord_be(void) { return order1_on_spring("implicit-euler"); }
static double ord_lbe(void) { return order1_on_spring("linear-implicit-euler"); }
static double ord_im(void) { return order_on_spring("implicit-midpoint"); }
static double table_order(const char *m) { return method(m)->order; }
static double ord_rk45(void) { return table_order("rk45"); }
/* Evaluations per step on the stiff pendulum (nonlinear: Newton iterates). */
static double ev(const char *m) { return evals_per_step("stiff-spring", NULL, m, 0.005, 50); }
static double ev_euler(void) { return ev("euler"); }
static double ev_symplectic(void) { return ev("symplectic-euler"); }
static double ev_midpoint(void) { return ev("midpoint"); }
static double ev_heun(void) { return ev("heun"); }
static double ev_rk4(void) { return ev("rk4"); }
static double ev_verlet(void) { return ev("verlet"); }
static double ev_be(void) { return ev("implicit-euler"); }
static double ev_lbe(void) { return ev("linear-implicit-euler"); }
static double ev_im(void) { return ev("implicit-midpoint"); }
/* Euler's energy on the undamped ω = 1 spring after N = 50 steps of h = 0.1,
 * against (1 + h²)^N. */
static double euler_energy_growth(void)
{
    sw_sim s;
    sim_init(&s, "spring", "k=1 m=1 c=0 stretch=0.2", "euler", 0.1);
    for (int i = 0; i < 50; i++)
        sw_sim_step(&s);
    double r = 1 + sw_sim_energy_drift(&s) / 100;
    sw_sim_free(&s);
    return r;
}
static double euler_energy_formula(void) { return pow(1 + 0.1 * 0.1, 50); }
static double symplectic_wdt(void) { return limit0("spring", "k=1 c=0", "symplectic-euler"); }
static double verlet_measured_wdt(void) { return stability("spring", "k=1 c=0", "verlet").dt; }
static double rk4_measured_wdt(void) { return stability("spring", "k=1 c=0", "rk4").dt; }
static double spring_zeta(void) { return l5_c() / (2 * sqrt(l5_k() * l5_m())); }
static double spring_omega(void) { return sqrt(l5_k() / l5_m()); }
static double euler_damped_over_zeta(void) { return limit0("spring", NULL, "euler") * spring_omega() / spring_zeta(); }
static double rk4_damped(void) { return limit0("spring", NULL, "rk4") * spring_omega(); }
static double rk4_damped_measured(void) { return stability("spring", NULL, "rk4").dt * spring_omega(); }
/* Backward Euler on the stiff pendulum: the largest ω·Δt in 1, 10, ... 1e4
 * up to which no step in 20 raised the energy (1e4: Δt = 100). */
static double be_never_gains(void)
{
    double ok = 0;
    for (double wdt = 1; wdt <= 1e4 * 1.0001; wdt *= 10) {
        sw_sim s;
        sim_init(&s, "stiff-spring", NULL, "implicit-euler", wdt / 100);
        double e = sw_sim_energy(&s);
        int rose = 0;
        for (int i = 0; i < 20 && !rose; i++) {
            if (sw_sim_step(&s))
                rose = 1;
            double e1 = sw_sim_energy(&s);
            rose |= e1 > e + 1e-12 * fabs(e);
            e = e1;
        }
        sw_sim_free(&s);
        if (rose)
            break;
        ok = wdt;
    }
    return ok;
}
static double lesson_count(void)
{
    sw_lesson_entry *e;
    int n;
    char err[SW_LESSON_ERRLEN];
    ck_assert_int_eq(sw_lesson_list("lessons", &e, &n, err, sizeof err), SW_OK);
    sw_lesson_list_free(e, n);
    return n;
}

/* ---- man page and docs/stability.md ------------------------------------ */

static double dt_min(void) { return SW_DT_MIN; }
static double dt_max(void) { return SW_DT_MAX; }
static double rtol_default(void) { return SW_RTOL_DEFAULT; }
static double atol_default(void) { return SW_ATOL_DEFAULT; }
static double check_rtol(void) { return SW_CHECK_RTOL; }
static double check_atol(void) { return SW_CHECK_ATOL; }
static sw_stability_config stab_config(void)
{
    sw_stability_config c;
    sw_stability_config_default(&c);
    return c;
}
static double stab_samples(void) { return stab_config().samples; }
static double stab_low(void) { return stab_config().low; }
static double stab_rel_tol(void) { return 100 * stab_config().rel_tol; }
/* Euler's theory on the undamped spring is "none": it grows already at the
 * smallest |λ|·Δt probed. */
static double euler_grows_at_low(void)
{
    return growth0("spring", "k=1 c=0", "euler", stab_low()) > 1 ? stab_low() : NAN;
}
/* Backward Euler's theory limit is unbounded: no growth up to this Δt. */
static double be_unbounded_to(void)
{
    sw_spectrum sp = spectrum0("spring", "k=1 c=0");
    int unbounded = 0;
    double h = sw_truth_limit(method("implicit-euler"), &sp, SW_DT_MAX, &unbounded);
    return unbounded ? h : NAN;
}
/* The horizon in periods of the stiffest mode (a slow spring, ω = 0.1,
 * where the periods dominate) and in report times (a stiff one). */
static double horizon_periods(void)
{
    const sw_scene *sc = sw_scene_find("spring");
    return sw_truth_horizon(sc, 0.1) / (TWO_PI / 0.1);
}
static double horizon_reports(void)
{
    const sw_scene *sc = sw_scene_find("spring");
    return sw_truth_horizon(sc, 1e4) / sc->duration;
}
/* The growth over the horizon at which it counts as visible: bisect ρ. */
static double visible_growth(void)
{
    double lo = 1, hi = 1.01, dt = 1, horizon = 100;
    for (int i = 0; i < 200; i++) {
        double mid = 0.5 * (lo + hi);
        if (sw_truth_growth_visible(mid, dt, horizon))
            hi = mid;
        else
            lo = mid;
    }
    return pow(hi, horizon / dt);
}
static double raised_level(const char *scene, const char *m)
{
    sw_sim s;
    sim_init(&s, scene, NULL, m, 0.01);
    double r = sw_watch_raised_level(&s);
    sw_sim_free(&s);
    return r;
}
static double raised_plain(void) { return raised_level("spring", "rk4"); }
static double raised_symplectic(void) { return raised_level("spring", "verlet"); }
static double raised_orbit(void) { return raised_level("orbit", "rk4"); }
/* M past this is the run blowing up: feed the watch a jump. */
static double watch_bound(void)
{
    double lo = 1, hi = 1e6;
    for (int i = 0; i < 100; i++) {
        double mid = sqrt(lo * hi);
        sw_watch w;
        sw_watch_init(&w, 1.0, 1e9);
        sw_watch_add(&w, 0.0, 1.0);
        if (sw_watch_add(&w, 0.01, mid) == SW_WATCH_BOUND)
            hi = mid;
        else
            lo = mid;
    }
    return hi;
}
static double watch_windows(void) { return SW_WATCH_WINDOWS; }

/* ---- scenes' summary and teaches --------------------------------------- */

static double vortex_growth(void) { return growth0("vortex", NULL, "euler", 0.3); }
static double vortex_formula(void) { return sqrt(1 + 0.3 * 0.3); }
static double spring_energy_growth(void) { return pow(growth0("spring", "c=0", "euler", 0.05), 2); }
static double spring_energy_formula(void) { return 1 + 10 * 0.05 * 0.05; }
static double orbit_period_mu4(void) { return orbit_period("mu=4"); }
static double orbit_period_formula(void) { return TWO_PI / sqrt(4); }
static double projectile_ratio(void) { return pow(2, order_by_halving("projectile", NULL, "euler", 0.01)); }
static double bounce_order(void) { return log2(l4_ratio()); }

static double l3_formula(void) { return 1 + pow(l3_omega() * 0.02, 2); }
static double two_hundred(void) { return 200; }
static double two(void) { return 2; }
static double l6_twenty_eight(void) { return 0.28 * 100; }
static double key_be(void) { return key_of("implicit-euler"); }
static double key_lbe(void) { return key_of("linear-implicit-euler"); }
static double key_im(void) { return key_of("implicit-midpoint"); }
static double key_verlet(void) { return key_of("verlet"); }
static double key_euler(void) { return key_of("euler"); }
static double key_rk4(void) { return key_of("rk4"); }
static double key_rk45(void) { return key_of("rk45"); }

/* ---- the pages on the phase and stability-region views (issue 13) ---- */

static double l3_phase_euler(void) { return drift_at("spring", "c=0", "euler", 0.02, 10); }
static double l3_phase_be(void) { return -drift_at("spring", "c=0", "implicit-euler", 0.02, 10); }
static double l3_phase_se(void) { return max_abs_drift("spring", "c=0", "symplectic-euler", 0.02, 10); }
/* The damped stiff spring's oscillating mode (λ with Im λ > 0). */
static sw_mode l5_mode(void)
{
    sw_spectrum sp = spectrum0("spring", STIFF);
    ck_assert_int_ge(sp.n, 1);
    sw_mode md = sp.mode[0];
    if (md.im < 0)
        md.im = -md.im, md.pim = -md.pim;
    return md;
}
static double l5_lambda_re(void) { return l5_mode().re; }
static double l5_lambda_im(void) { return l5_mode().im; }
static double l5_half_c(void) { return 10.0 / (2 * l5_m()); }
static double l5_mark_re(void) { return l5_mode().re * 0.005; }
static double l5_mark_im(void) { return l5_mode().im * 0.005; }
static double l5_growth(void) { return growth0("spring", STIFF, "euler", 0.005); }
static double l5_growth_formula(void) { return hypot(1 + l5_mark_re(), l5_mark_im()); }
static double l6_region_omega(void) { return spectrum0("spring", "k=10000 c=0").largest; }
static double l6_mark(double dt) { return l6_region_omega() * dt; }
static double l6_mark_005(void) { return l6_mark(0.005); }
static double l6_mark_002(void) { return l6_mark(0.02); }
static double l6_mark_004(void) { return l6_mark(0.04); }
static double l6_dt_plus2(void) { return page_dt_after(L6, "RK4's region", SW_ACT_DT_DOUBLE, 2); }
static double l6_dt_plus3(void) { return page_dt_after(L6, "RK4's region", SW_ACT_DT_DOUBLE, 3); }
static double l6_inside_002(void) { return growth0("spring", "k=10000 c=0", "rk4", 0.02); }
static double l6_outside_004(void) { return growth0("spring", "k=10000 c=0", "rk4", 0.04); }
static double one_plus(void) { return 1 + SW_TRUTH_NEUTRAL; }
static double l7_region_swing(void) { return l7_slow() * 0.04; }
static double l7_region_stretch(void) { return l7_fast() * 0.04; }
static double l7_region_growth(void) { return growth0("stiff-spring", NULL, "implicit-euler", 0.04); }
/* backward Euler divides each mode by 1 - Δt·λ: its growth is the largest 1/|1 - Δt·λ| */
static double l7_region_formula(void)
{
    sw_spectrum sp = spectrum0("stiff-spring", NULL);
    double worst = 0;
    for (int k = 0; k < sp.n; k++)
        worst = fmax(worst, 1 / hypot(1 - 0.04 * sp.mode[k].re, 0.04 * sp.mode[k].im));
    return worst;
}
static double l7_dt_plus1(void) { return page_dt_after(L7, "Backward Euler's region", SW_ACT_DT_DOUBLE, 1); }
static double l8_verlet_bound(void) { return max_abs_drift("orbit", NULL, "verlet", 0.2, 1000); }
static double l8_rk4_100(void) { return -drift_at("orbit", NULL, "rk4", 0.2, 100); }

static double l2_dt_plus2(void) { return page_dt_after(L2, "Bigger steps, bigger errors", SW_ACT_DT_DOUBLE, 2); }
static double l5_dt_minus3(void) { return page_dt_after(L5, "Remedy 2: tiny time steps", SW_ACT_DT_HALVE, 3); }
static double l7_dt_plus3(void) { return page_dt_after(L7, "Stiff: a slow swing and a fast stretch", SW_ACT_DT_DOUBLE, 3); }
static double l8_dt_minus2(void) { return page_dt_after(L8, "RK4 leaks energy", SW_ACT_DT_HALVE, 2); }
static double l9_dt_plus3(void) { return page_dt_after(L9, "One step size does not fit all", SW_ACT_DT_DOUBLE, 3); }
/* RK4 on the parabola (no drag): the status line's error at t = 2. */
static double l4_parabola_error(void)
{
    sw_runner r;
    sw_app a;
    lesson_page(&r, &a, L4, "Gravity");
    steps_to(&a.sims[0], 2.0);
    double e = sw_app_error(&a, 0);
    page_free(&r, &a);
    return e;
}
/* Energy at t = 1 over its start, Euler at Δt = 0.00125 on the c = 10 spring. */
static double l5_grows_fourfold(void) { return 1 + drift_at("spring", STIFF, "euler", 0.00125, 1.0) / 100; }
static double l5_falls(void) { return drift_at("spring", STIFF, "euler", 0.000625, 1.0); }
/* How much the drift moved between t = 4 (after the second close pass) and two
 * orbits, as a fraction of it. */
static double l9_rk4_first(void) { return drift_at("orbit", ECC, "rk4", 0.05, 1.5); }
/* The time of RK4's second close pass: its nearest approach after t = 1. */
static double l9_rk4_second_pass(void)
{
    sw_sim s;
    sim_init(&s, "orbit", ECC, "rk4", 0.05);
    double nearest = INFINITY, when = NAN;
    while (s.t < 4) {
        sw_sim_step(&s);
        double r = hypot(s.sys.y[0], s.sys.y[1]);
        if (s.t > 1 && r < nearest) {
            nearest = r;
            when = s.t;
        }
    }
    sw_sim_free(&s);
    return when;
}
static double l9_constant(void)
{
    double late = drift_at("orbit", ECC, "rk4", 0.05, two_orbits());
    return fabs(late - drift_at("orbit", ECC, "rk4", 0.05, 4.0)) / late;
}
/* Symplectic Euler from rest on the undamped ω = 1 spring at ωΔt = 1: the
 * mean of M (the motion's energy over its start) over a long run. */
static double symplectic_mean_m(void)
{
    sw_sim s;
    sim_init(&s, "spring", "k=1 c=0 stretch=0.01", "symplectic-euler", 1.0);
    double y0[4], sum = 0;
    memcpy(y0, s.sys.y, sizeof y0);
    double m0 = sw_watch_measure(&s, y0);
    int n = 20000;
    for (int i = 0; i < n; i++) {
        sw_sim_step(&s);
        sum += sw_watch_measure(&s, y0) / m0;
    }
    sw_sim_free(&s);
    return sum / n;
}
static double symplectic_mean_formula(void) { return 1 / (1 - pow(1.0 / 2, 2)); }
/* The lowest x RK4 reaches on the default spring at Δt = 0.9 (ωΔt = 2.85,
 * inside the linear limit 2.938): below 0 is through the anchor. */
static double rk4_through_anchor(void)
{
    sw_sim s;
    sim_init(&s, "spring", NULL, "rk4", 0.9);
    double lowest = s.sys.y[0];
    for (int i = 0; i < 400 && !s.blown; i++) {
        sw_sim_step(&s);
        lowest = fmin(lowest, s.sys.y[0]);
    }
    sw_sim_free(&s);
    return lowest;
}
static double rk4_small_stretch(void) { return stability("spring", "stretch=0.2", "rk4").dt * spring_omega(); }
static double one(void) { return 1; }
static double four(void) { return 4; }
static double twenty(void) { return 20; }
static double bench_default_repeats(void)
{
    sw_bench_config c;
    sw_bench_config_default(&c);
    return c.repeats;
}
static double bench_quick_min(void)
{
    sw_bench_config c;
    sw_bench_config_quick(&c);
    return c.min_points;
}
static double bench_quick_max(void)
{
    sw_bench_config c;
    sw_bench_config_quick(&c);
    return c.max_points;
}
static double bench_quick_runs(void)
{
    sw_bench_config c;
    sw_bench_config_quick(&c);
    return c.repeats;
}
static double stab_agree(void) { return 100 * SW_STABILITY_AGREE; }
static double stab_shrink(void) { return 1 / SW_STABILITY_SHRINK; }
static double stab_longer(void) { return SW_STABILITY_LONGER; }
static double stab_longest(void) { return SW_STABILITY_LONGER * SW_STABILITY_LONGER; }
/* The drift the status line shows, against (E - E0)/(E0 - E_rest) worked
 * out here from the energies (the stiff pendulum after 100 steps). */
static double drift_definition(void)
{
    sw_sim s;
    sim_init(&s, "stiff-spring", NULL, "implicit-euler", 0.04);
    double e0 = sw_sim_energy(&s), rest = sw_truth_energy_floor(&s.sys);
    for (int i = 0; i < 100; i++)
        sw_sim_step(&s);
    double mine = 100 * (sw_sim_energy(&s) - e0) / (e0 - rest), shown = sw_sim_energy_drift(&s);
    sw_sim_free(&s);
    return fabs(mine - shown) / fabs(mine);
}
static double guide_dt_min(void) { return SW_DT_MIN; }
static double max_bytes(void) { return SW_LESSON_MAX_BYTES; }
static double max_line(void) { return SW_LESSON_MAX_LINE; }
static double max_title(void) { return SW_LESSON_MAX_TITLE; }
static double max_pages(void) { return SW_LESSON_MAX_PAGES; }
static double max_prose(void) { return SW_LESSON_MAX_PROSE; }
static double max_blocks(void) { return SW_LESSON_MAX_BLOCKS; }
static double max_goals(void) { return SW_LESSON_MAX_GOALS; }
static double max_answers(void) { return SW_LESSON_MAX_ANSWERS; }
static double max_compare(void) { return SW_LESSON_MAX_COMPARE; }
static double max_names(void) { return SW_LESSON_MAX_NAMES; }
static double max_files(void) { return SW_LESSON_MAX_FILES; }
/* The slack of ==, <= and >= in goals: the largest relative shortfall at
 * which "dt >= 0.2" still holds, by bisection on the goal itself. */
static double goal_slack(void)
{
    sw_lesson lesson;
    char err[SW_LESSON_ERRLEN];
    const char *text = "title: t\n--- p\n@scene spring\nText.\n@goal dt >= 0.2\n@hint h\n";
    ck_assert_msg(sw_lesson_parse("t", text, strlen(text), &lesson, err, sizeof err) == SW_OK, "%s", err);
    double lo = 0, hi = 1e-6;
    for (int i = 0; i < 200; i++) {
        double mid = 0.5 * (lo + hi);
        sw_lesson_obs obs;
        sw_lesson_obs_init(&obs);
        obs.dt = 0.2 * (1 - mid);
        if (sw_lesson_goal_met(&lesson.pages[0].goals[0], &obs))
            lo = mid;
        else
            hi = mid;
    }
    sw_lesson_free(&lesson);
    return lo;
}

/* ---- the table ----------------------------------------------------------- */

typedef enum claim_kind {
    ROUNDED,   /* the figure is the value rounded to its last written digit: within half a unit of it */
    ABS,       /* |computed - written| <= tol */
    REL,       /* |computed / written - 1| <= tol */
    EXACT,     /* a count or a constant: equal (to 1e-9 relative) */
    ATMOST,    /* "within", "below": computed <= written; tol > 0: and >= written·(1 - tol), a tight bound */
    ATLEAST,   /* "more than", "at least": computed >= written */
    MAGNITUDE  /* "near 1e-15": |log10(computed / written)| <= tol */
} claim_kind;

typedef struct claim {
    const char *file;       /* from the repository root */
    const char *snippet;    /* exact text, figure marked {...}; none: a formula claim */
    double (*compute)(void);
    claim_kind kind;
    double tol;
    const char *why;        /* why the tolerance is what it is */
    double (*formula)(void); /* a formula claim: the formula's value at the lesson's parameters */
} claim;


/* Common reasons. */
#define R_ROUND "written to its last digit"
#define R_COUNT "a count or a constant: exact"
#define R_ABOUT "\"about\" a whole number: within half of one"
#define R_RATIO "the page's goal accepts this much around the figure"
#define R_MATH "arithmetic the text does: to its last digit"

static const claim claims[] = {
    /* lesson 1 */
    { L1, "g(x) = ω(-y, x) with ω = {1} rad/s", l1_omega, EXACT, 0, R_COUNT, NULL },
    { L1, "one full turn takes 2π/ω ≈ {6.3} seconds", l1_turn, ROUNDED, 0, R_ROUND, NULL },
    { L1, "swings back and forth every {10} seconds", l1_gyre_swing, ABS, 1e-5, "the default ω = 0.628319 is 2π/10 to 6 digits", NULL },
    /* lesson 2 */
    { L2, "(Δt²/2)·x'': the local error is O(Δt{²})", l2_local_order, ABS, 0.1, "an order measured by halving: within 0.1", NULL },
    { L2, "Euler's global error is {first} order", l2_global_order, ABS, 0.1, "an order measured by halving: within 0.1", NULL },
    { L2, "multiplies the radius by √(1 + (ωΔt)²)", l2_factor, REL, 1e-12, "the growth per step from the one-step map is the formula to rounding", l2_factor_formula },
    { L2, "Δt = 0.1 that is a factor {1.005} per step", l2_factor, ROUNDED, 0, R_ROUND, NULL },
    { L2, "One turn takes {63} steps", l2_turn_steps, EXACT, 0, R_COUNT, NULL },
    { L2, "1.005⁶³ ≈ {1.37}", l2_power, ROUNDED, 0, R_MATH, NULL },
    { L2, "the radius grows by 1.005⁶³ ≈ {1.37}", l2_turn_growth, ROUNDED, 0, "the radius after 63 steps of the run, to the text's digits", NULL },
    { L2, "the radius grows by √1.16 ≈ {1.08} per step", l2_sqrt116, ROUNDED, 0, R_MATH, NULL },
    { L2, "At Δt = 0.4 the radius grows by √1.16 ≈ {1.08}", l2_factor04, ROUNDED, 0, R_ROUND, NULL },
    { L2, "({16} steps)", l2_turn_steps04, EXACT, 0, R_COUNT, NULL },
    { L2, "has more than {tripled} in size", l2_turn_growth04, ATLEAST, 0, "\"more than tripled\": at least 3", NULL },
    { L2, "(one turn, t = {6.28})", l2_report_time, ROUNDED, 0, R_ROUND, NULL },
    { L2, "Euler is order 1, so expect a ratio near {2}", l2_ratio1, ABS, 0.3, R_RATIO, NULL },
    { L2, "The ratio stays near 2 ({2.04}, then 2.02)", l2_ratio2, ROUNDED, 0, "the ratio the status line shows, to the text's digits", NULL },
    { L2, "The ratio stays near 2 (2.04, then {2.02})", l2_ratio3, ROUNDED, 0, "the ratio the status line shows, to the text's digits", NULL },
    { L2, "about {0.17} at Δt = 0.05", l2_err05, ROUNDED, 0, R_ROUND, NULL },
    { L2, "{0.08} at 0.025", l2_err025, ROUNDED, 0, R_ROUND, NULL },
    { L2, "{0.04} at 0.0125", l2_err0125, ROUNDED, 0, R_ROUND, NULL },
    { L2, "methods whose error falls as Δt{²}, or Δt⁴", l2_midpoint_order, ABS, 0.1, "an order measured by halving: within 0.1", NULL },
    { L2, "methods whose error falls as Δt², or Δt{⁴}", l2_rk4_order, ABS, 0.1, "an order measured by halving: within 0.1", NULL },
    { L2, "@hint Press + twice: 0.1, 0.2, {0.4}.", l2_dt_plus2, EXACT, 0, "the step two presses of + give", NULL },

    /* lesson 3 */
    { L3, "Euler's ball lands off the mark (by about {0.44} m here)", l3_miss, ROUNDED, 0, "the status line's error at t = 2, to the text's digits", NULL },
    { L3, "Euler's ball lands off the mark (by about {0.44} m here)", l3_miss_position, ROUNDED, 0, "the distance of the ball from the exact one at t = 2, to the text's digits", NULL },
    { L3, "Here k = {10} and m = 1", l3_k, EXACT, 0, R_COUNT, NULL },
    { L3, "Here k = 10 and m = {1}", l3_m, EXACT, 0, R_COUNT, NULL },
    { L3, "so ω = {3.16} rad/s", l3_omega, ROUNDED, 0, R_ROUND, NULL },
    { L3, "ωΔt = {0.063}: a factor", l3_omega_dt, ROUNDED, 0, R_ROUND, NULL },
    { L3, "a factor {1.004} per step", l3_energy_factor, ROUNDED, 0, "ρ² from the one-step map, to the text's digits", NULL },
    { L3, "multiplies the energy of this oscillation by 1 + (ωΔt)² every step", l3_energy_factor, REL, 1e-12, "ρ² of Euler's one-step map is 1 + (ωΔt)² to rounding", l3_formula },
    { L3, "per step, {50} steps per second", l3_steps_per_second, EXACT, 0, R_COUNT, NULL },
    { L3, "let it run about {two} seconds; the energy drift climbs past 50 %", l3_time_to_50, ABS, 0.25, "\"about two seconds\": within a quarter of a second", NULL },
    { L3, "for this chain of {10} beads in 2-D?", l3_beads, EXACT, 0, R_COUNT, NULL },
    { L3, "This chain has {10} beads", l3_beads, EXACT, 0, R_COUNT, NULL },
    { L3, "@answer c) {40} | Yes: 10 beads × (x, y, vx, vy).", l3_chain_dim, EXACT, 0, R_COUNT, NULL },
    { L3, "@answer b) {20} | That is the positions alone", l3_chain_positions, EXACT, 0, R_COUNT, NULL },
    { L3, "@answer b) {4}: position (x, y) and velocity (vx, vy)", l3_particle_dim, EXACT, 0, R_COUNT, NULL },
    { L3, "In 3-D, as in the lecture, it is {6}.", l3_3d, EXACT, 0, R_MATH, NULL },
    { L3, "By t = 10 Euler's energy is up {557} %", l3_phase_euler, ROUNDED, 0, R_ROUND, NULL },
    { L3, "backward Euler's down {86} %", l3_phase_be, ROUNDED, 0, R_ROUND, NULL },
    { L3, "only wobbles, within {3.3} %", l3_phase_se, ATMOST, 0.1, "a bound the run comes within 10 % of", NULL },
    /* lesson 4 */
    { L4, "restitution e (here {0.8})", l4_e, EXACT, 0, R_COUNT, NULL },
    { L4, "e = 1 is a perfect bounce", l4_perfect, ABS, 0.002, "a ball from 4 m with e = 1 rises back to 4 m (contact at step ends: 1e-3)", one },
    { L4, "e = {0} a dead stop", l4_dead, ABS, 0.002, "with e = 0 it does not rise again", NULL },
    { L4, "the speed is multiplied by {0.8}, the height", l4_e, EXACT, 0, R_COUNT, NULL },
    { L4, "@answer b) {2.56} m | Yes", l4_bounce_height, ABS, 0.005, "the first hop of a ball dropped from 4 m in the scene, at Δt = 1e-4 (contact is found at step ends: an error of order Δt·v ≈ 1e-3)", NULL },
    { L4, "the height by 0.8² = {0.64}", l4_e_squared, EXACT, 0, R_MATH, NULL },
    { L4, "@answer a) {3.2} m | That multiplies the height by e", l4_e_height, ABS, 1e-12, R_MATH, NULL },
    { L4, "here it gives about {2}. Any method", l4_ratio, ABS, 0.5, R_RATIO, NULL },
    { L4, "For a smooth motion RK4 would give {16}", l4_smooth_ratio, ABS, 2, "a ratio measured on the smooth projectile (drag on): the goals' tolerance for 16", NULL },
    { L4, "stepwise measures the error at t = {3} for both step sizes", l4_report_time, EXACT, 0, R_COUNT, NULL },
    { L4, "RK4 follows it to within {rounding} error", l4_parabola_error, ATMOST, 0, "the status line's error at t = 2 below 1e-12", NULL },
    /* lesson 5 */
    { L5, "Here k = {10} N/m, damping c = 0.5, mass 1 kg", l5_k, EXACT, 0, R_COUNT, NULL },
    { L5, "Here k = 10 N/m, damping c = {0.5}, mass 1 kg", l5_c, EXACT, 0, R_COUNT, NULL },
    { L5, "Here k = 10 N/m, damping c = 0.5, mass {1} kg", l5_m, EXACT, 0, R_COUNT, NULL },
    { L5, "the mass swings about {five} times in ten seconds", l5_swings, ABS, 0.5, R_ABOUT, NULL },
    { L5, "so it vibrates at ω = √(k/m) = {100} rad/s", l5_stiff_omega, ROUNDED, 0, R_ROUND, NULL },
    { L5, "Numbers: k = 10000, m = 1 so ω = {100}", l5_stiff_omega, ROUNDED, 0, R_ROUND, NULL },
    { L5, "Per step, Euler multiplies this spring's energy by about 1 - cΔt + kΔt²", l5_euler_energy_factor, REL, 1e-12, "ρ² of Euler's map, exactly the formula for m = 1", l5_arith },
    { L5, "that is 1 - 0.05 + 0.25 = {1.2}", l5_arith, ABS, 1e-12, R_MATH, NULL },
    { L5, "that is 1 - 0.05 + 0.25 = {1.2}: the damping", l5_euler_energy_factor, ROUNDED, 0, "ρ² of Euler's one-step map on the damped spring is exactly 1 - cΔt + kΔt² (m = 1)", NULL },
    { L5, "Press space; within {a} second the spring blows up", l5_blow, ATMOST, 0, "\"within a second\": before t = 1", NULL },
    { L5, "critically damped (c = 2√(km))", l5_critical, EXACT, 0, R_MATH, two_hundred },
    { L5, "both its modes now decay at rate {100} per second", l5_crit_rate, REL, 1e-6, "a double eigenvalue: its computed split is about √ε", NULL },
    { L5, "Euler multiplies each by |1 - 100Δt| = {0.5} per step", l5_crit_arith, EXACT, 0, R_MATH, NULL },
    { L5, "|1 - 100Δt| = {0.5} per step: the motion dies out", l5_crit_growth, REL, 1e-6, "ρ of the one-step map on a double eigenvalue (split about √ε)", NULL },
    { L5, "The energy still rises in the very first step, by {25} %", l5_crit_first_step, ROUNDED, 0, R_ROUND, NULL },
    { L5, "the mass relaxes at rate c/m = {5000} per second", l5_huge_rate, REL, 0.001, "the fast root (c + √(c² - 4km))/2m is c/m - k/c: 4998", NULL },
    { L5, "Euler needs Δt below {2/5000} for that", l5_huge_limit, REL, 0.001, "the limit 2/4998 from the one-step map against 2/5000", NULL },
    { L5, "a step {12.5} times smaller", l5_huge_smaller, ROUNDED, 0, R_ROUND, NULL },
    { L5, "that is Δt < c/k = {0.001}", l5_light_limit, REL, 1e-6, "Euler's limit from the one-step map on the damped spring is c/k", NULL },
    { L5, "that is Δt < c/k = {0.001}.", l5_light_arith, EXACT, 0, R_MATH, NULL },
    { L5, "@answer a) Any Δt below {0.001} | That was the limit with c = 10", l5_light_limit, REL, 1e-6, "as above", NULL },
    { L5, "@hint Press - three times: 0.0025, 0.00125, {0.000625}.", l5_dt_minus3, EXACT, 0, "the step three presses of - give", NULL },
    { L5, "@hint At Δt = 0.000625 the energy falls;", l5_falls, ATMOST, 0, "the drift at t = 1 is negative", zero },
    { L5, "at 0.00125 it still grows, to {four} times its start by t = 1", l5_grows_fourfold, ABS, 0.25, "four to the nearest quarter", NULL },
    { L5, "Switch to rk4 (press {5}, or i", key_rk4, EXACT, 0, "the key that picks the method", NULL },
    { L5, "@hint Press {5}, or i until the status line says rk4.", key_rk4, EXACT, 0, "the key that picks the method", NULL },
    { L5, "{1600} steps for one simulated second", l5_steps, EXACT, 0, R_COUNT, NULL },
    { L5, "{eight} times as many as at Δt = 0.005", l5_steps_ratio, EXACT, 0, R_COUNT, NULL },
    { L5, "its energy grows by 1 + (ωΔt)² every step", l5_undamped_factor, REL, 1e-12, "ρ² of Euler's map on the undamped spring at Δt = 0.000625", l5_undamped_formula },
    { L5, "With c = 0 the factor 1 + kΔt² is above 1 for every Δt", l5_undamped_limit, EXACT, 0, "no stable step: the limit in theory is 0", zero },
    { L5, "RK4 is stable on an oscillator while ωΔt < 2√2 ≈ {2.83}", rk4_wdt, ROUNDED, 0, R_ROUND, NULL },
    { L5, "while ωΔt < 2√2 ≈ {2.83}; here", two_root_two, ROUNDED, 0, R_MATH, NULL },
    { L5, "here ωΔt = {0.5}", l5_wdt, ROUNDED, 0, R_ROUND, NULL },
    { L5, "here λ = {-5} ± 99.9i", l5_lambda_re, ROUNDED, 0, R_ROUND, NULL },
    { L5, "here λ = -5 ± {99.9}i", l5_lambda_im, ROUNDED, 0, R_ROUND, NULL },
    { L5, "(decay rate c/2m = {5}, ω ≈ 100)", l5_half_c, EXACT, 0, R_MATH, NULL },
    { L5, "(decay rate c/2m = 5, ω ≈ {100})", l5_stiff_omega, ROUNDED, 0, R_ROUND, NULL },
    { L5, "Euler multiplies a mode by 1 + Δt·λ per step", l5_growth, REL, 1e-12, "ρ of Euler's one-step map is |1 + Δt·λ| to rounding", l5_growth_formula },
    { L5, "The marks are Δt·λ = {-0.025} ± 0.5i", l5_mark_re, ROUNDED, 0, R_ROUND, NULL },
    { L5, "The marks are Δt·λ = -0.025 ± {0.5}i", l5_mark_im, ROUNDED, 0, R_ROUND, NULL },
    { L5, "|1 + Δt·λ| = {1.095} per step", l5_growth, ROUNDED, 0, "the meter's growth per step, to the text's digits", NULL },
    { L5, "once Δt is below c/k = {0.001}", l5_light_limit, REL, 1e-6, "Euler's limit from the one-step map on the damped spring is c/k", NULL },
    /* lesson 6 */
    { L6, "divide the error by 2² = {4}. Measure it:", l6_ratio_mid, ABS, 0.5, R_RATIO, NULL },
    { L6, "divide the error by 2⁴ = {16}. Switch", l6_ratio_rk4, ABS, 2, R_RATIO, NULL },
    { L6, "  euler      0.0125   {503}    0.04", l6_steps_euler, EXACT, 0, R_COUNT, NULL },
    { L6, "  euler      0.0125   503    {0.04}", l6_err_euler, ROUNDED, 0, R_ROUND, NULL },
    { L6, "  midpoint   0.025    {252}    0.00065", l6_steps_mid, EXACT, 0, R_COUNT, NULL },
    { L6, "  midpoint   0.025    252    {0.00065}", l6_err_mid, ROUNDED, 0, R_ROUND, NULL },
    { L6, "  rk4        0.05     {126}    0.0000003", l6_steps_rk4, EXACT, 0, R_COUNT, NULL },
    { L6, "  rk4        0.05     126    {0.0000003}", l6_err_rk4, ROUNDED, 0, R_ROUND, NULL },
    { L6, "at ~{503} evaluations Euler", l6_evals_euler, EXACT, 0, R_COUNT, NULL },
    { L6, "Euler (Δt 0.0125) errs {0.040}", l6_err_euler, ROUNDED, 0, R_ROUND, NULL },
    { L6, "midpoint (0.025) {6.5e-4}", l6_err_mid, ROUNDED, 0, R_ROUND, NULL },
    { L6, "RK4 (0.05) {3.3e-7}", l6_err_rk4, ROUNDED, 0, R_ROUND, NULL },
    { L6, "about {500} evaluations of g for one turn", l6_evals_mid, REL, 0.02, "\"about 500\": the three runs take 503 and 504", NULL },
    { L6, "about {500} evaluations of g for one turn", l6_evals_rk4, REL, 0.02, "\"about 500\": the three runs take 503 and 504", NULL },
    { L6, "RK4 is about {100 000} times more accurate than Euler", l6_gain, REL, 0.5, "one significant figure: 50 000 to 150 000", NULL },
    { L6, "RK4 costs {four} evaluations per step, Euler one", l6_rk4_evals, EXACT, 0, R_COUNT, NULL },
    { L6, "RK4 costs four evaluations per step, Euler {one}", l6_euler_evals, EXACT, 0, R_COUNT, NULL },
    { L6, "Two evaluations of g per step instead of one", l6_mid_evals, EXACT, 0, R_COUNT, two },
    { L6, "@hint Press {5}, or i until the status line says rk4.", key_rk4, EXACT, 0, "the key that picks the method", NULL },
    { L6, "When does a {4}-evaluation step pay?", l6_rk4_evals, EXACT, 0, R_COUNT, NULL },
    { L6, "each halving of Δt gains {16}× for RK4", l6_rk4_gain, ABS, 2, "the goals' tolerance for 16", NULL },
    { L6, "gains 16× for RK4 against {2}× for Euler", l6_euler_gain, ABS, 0.3, "the goals' tolerance for 2", NULL },
    { L6, "oscillator it blows up once ωΔt > 2√2 ≈ {2.83}", rk4_wdt, ROUNDED, 0, R_ROUND, NULL },
    { L6, "@answer a) About {0.028} | Yes: 2.83 / 100.", l6_limit100, ROUNDED, 0, R_ROUND, NULL },
    { L6, "its edge there is at 2√2 ≈ {2.83}", rk4_wdt, ROUNDED, 0, R_ROUND, NULL },
    { L6, "This spring has ω = {100}", l6_region_omega, ROUNDED, 0, R_ROUND, NULL },
    { L6, "the marks Δt·λ sit at ±{0.5}i", l6_mark_005, ROUNDED, 0, R_ROUND, NULL },
    { L6, "at Δt = {0.02} the marks are at ±2i", l6_dt_plus2, EXACT, 0, "the step two presses of + give", NULL },
    { L6, "the marks are at ±{2}i, still inside", l6_mark_002, ROUNDED, 0, R_ROUND, NULL },
    { L6, "still inside; at", l6_inside_002, ATMOST, 0, "inside: RK4's growth at ωΔt = 2 is at most one", one_plus },
    { L6, "Δt = {0.04} they are at ±4i", l6_dt_plus3, EXACT, 0, "the step three presses of + give", NULL },
    { L6, "they are at ±{4}i, outside the region", l6_mark_004, ROUNDED, 0, R_ROUND, NULL },
    { L6, "outside the region, and the meter says GROWS", l6_outside_004, ATLEAST, 0, "outside: RK4's growth at ωΔt = 4 is above one", one_plus },
    { L6, "@hint Press + three times: 0.01, 0.02, {0.04}.", l6_dt_plus3, EXACT, 0, "the step three presses of + give", NULL },
    { L6, "ωΔt would be {28}", l6_twenty_eight, EXACT, 0, R_MATH, NULL },
    { L6, "over one turn (t = {2π})", l6_report_time, REL, 1e-12, R_COUNT, NULL },
    /* lesson 7 */
    { L7, "(k = {10000},", l7_k, EXACT, 0, R_COUNT, NULL },
    { L7, "ω = {100} rad/s). Measured", l7_fast, ROUNDED, 0, R_ROUND, NULL },
    { L7, "(about {3} rad/s)", l7_slow, ABS, 0.5, R_ABOUT, NULL },
    { L7, "fast stretch of the spring at ω = {100} rad/s", l7_fast, ROUNDED, 0, R_ROUND, NULL },
    { L7, "Verlet is stable while ωΔt < {2}", verlet_wdt, ROUNDED, 0, R_ROUND, NULL },
    { L7, "so the fast stretch limits Δt to {0.02}", l7_verlet_theory, ROUNDED, 0, "the limit in theory along the run, to the text's digits", NULL },
    { L7, "so the fast stretch limits Δt to {0.02}", l7_verlet_measured, ROUNDED, 0, "the limit measured by the stability lab, to the text's digits", NULL },
    { L7, "the swing alone would be fine with steps {ten} times longer", l7_swing_longer, ATLEAST, 0, "Verlet's limit on the swing's mode alone over its limit on the pendulum", NULL },
    { L7, "@hint Press + three times: 0.01, 0.02, {0.04}.", l7_dt_plus3, EXACT, 0, "the step three presses of + give", NULL },
    { L7, "at Δt = 0.04 Verlet blows up within {a} second", l7_verlet_blow, ATMOST, 0, "\"within a second\": before t = 1", NULL },
    { L7, "by t = 2.5 about {two thirds} of the swing's energy is gone", l7_be_fraction, ABS, 0.02, "\"about two thirds\": within two percentage points", NULL },
    { L7, "0.04 removes {66} % of the swing's energy by t = 2.5", l7_be_drift, ROUNDED, 0, R_ROUND, NULL },
    { L7, "the one-step linearised version {82} %", l7_lin_drift, ROUNDED, 0, R_ROUND, NULL },
    { L7, "one Newton step removes about {82} % of the swing's", l7_lin_drift, ROUNDED, 0, R_ROUND, NULL },
    { L7, "where backward Euler removed {66} %", l7_be_drift, ROUNDED, 0, R_ROUND, NULL },
    { L7, "lifts the energy from {-8.50} J to +38.4 J", l7_e0, ROUNDED, 0, R_ROUND, NULL },
    { L7, "lifts the energy from -8.50 J to {+38.4} J", l7_e1, ROUNDED, 0, R_ROUND, NULL },
    { L7, "gains energy ({-8.50} J to", l7_e0, ROUNDED, 0, R_ROUND, NULL },
    { L7, "({-8.50} J to +38.4 J) where", l7_e0, ROUNDED, 0, R_ROUND, NULL },
    { L7, "(-8.50 J to {+38.4} J) where backward Euler loses it", l7_e1, ROUNDED, 0, R_ROUND, NULL },
    { L7, "where backward Euler loses energy at any Δt here", l7_be_step, ATMOST, 0, "its first step at Δt = 1 loses energy (every Δt: tests/check_truth.c)", zero },
    { L7, "on a linear spring it shrinks every oscillation by 1/√(1 + (ωΔt)²) per step", l7_be_damping, REL, 1e-9, "ρ of backward Euler's map at ωΔt = 4", l7_be_damping_formula },
    { L7, "On a linear spring it is exactly backward Euler", l7_linear_same, ATMOST, 0, "to rounding: 1e-12 over 250 steps", rounding },
    { L7, "keeps the energy within {0.3} % at 0.04", l7_im_drift, ATMOST, 0.5, "a bound the run comes within half of", NULL },
    { L7, "starts to gain energy above Δt ≈ {0.19} (try", l7_im_limit, ROUNDED, 0, "the limit the stability lab measures, to the text's digits", NULL },
    { L7, "nonlinear spring above Δt ≈ {0.19} (stepwise", l7_im_limit, ROUNDED, 0, "the limit the stability lab measures, to the text's digits", NULL },
    { L7, "press {7} if you switched away.", key_be, EXACT, 0, "the key that picks the method", NULL },
    { L7, "linear-implicit-euler (press {8})", key_lbe, EXACT, 0, "the key that picks the method", NULL },
    { L7, "@hint The page chose implicit-midpoint; press {9} if you switched away.", key_im, EXACT, 0, "the key that picks the method", NULL },
    { L7, "A step divides each mode by 1 - Δt·λ", l7_region_growth, REL, 1e-9, "ρ of backward Euler's map is the largest 1/|1 - Δt·λ|", l7_region_formula },
    { L7, "(near ±{0.125}i at Δt = 0.04)", l7_region_swing, ROUNDED, 0, R_ROUND, NULL },
    { L7, "the stretch's (±{4}i, beyond", l7_region_stretch, ROUNDED, 0, R_ROUND, NULL },
    { L7, "@hint Press + once: {0.08}.", l7_dt_plus1, EXACT, 0, "the step one press of + gives", NULL },
    /* lesson 8 */
    { L8, "(eccentricity {0.5}; one orbit", l8_e, EXACT, 0, R_COUNT, NULL },
    { L8, "takes 2π ≈ {6.3} seconds", l8_period, ROUNDED, 0, "Kepler's period from the scene's energy", NULL },
    { L8, "(e = 0.5, period {2π})", l8_period, REL, 1e-12, "Kepler's period from the scene's energy", NULL },
    { L8, "loses {5} % of the energy by t ≈ 31", l8_rk4_31, ROUNDED, 0, R_ROUND, NULL },
    { L8, "loses 5 % of the energy by t ≈ {31}", l8_rk4_5, ROUNDED, 0, "the first time the drift passes -5 %, to the text's digits", NULL },
    { L8, "after about {five} orbits more than 5 % of the energy is gone", l8_rk4_5_orbits, ABS, 0.5, R_ABOUT, NULL },
    { L8, "and {35} % by t = 200", l8_rk4_200, ROUNDED, 0, R_ROUND, NULL },
    { L8, "stays within {0.7} % for 200 s", l8_verlet, ATMOST, 0.15, "a bound the run comes within 15 % of", NULL },
    { L8, "the angular momentum, stays near {1e-15}", l8_invariant, MAGNITUDE, 1, "\"near\": within a factor ten", NULL },
    { L8, "Euler at Δt 0.05 gains {60} % in its first close pass", l8_euler_1, ROUNDED, 0, "the drift at t = 1, after the pass, to the text's digits", NULL },
    { L8, "gains 60 % in its first close pass (within {one} second)", l8_euler_half, ATMOST, 0, "the drift passes 50 % before t = 1", NULL },
    { L8, "and {99} % by the second (t = 27)", l8_euler_27, ROUNDED, 0, R_ROUND, NULL },
    { L8, "within {half} a second, the energy jumps by more than half", l8_euler_half, ATMOST, 0, "the first time the drift passes 50 %", NULL },
    { L8, "within half a second, the energy jumps by more than {half}", l8_euler_1_fraction, ATLEAST, 0, "the drift after the pass, as a fraction", NULL },
    { L8, "Velocity Verlet costs {one} evaluation per step, RK4 four", l8_verlet_evals, EXACT, 0, R_COUNT, NULL },
    { L8, "Velocity Verlet costs one evaluation per step, RK4 {four}", l8_rk4_evals, EXACT, 0, R_COUNT, NULL },
    { L8, "So at Δt = {0.05} Verlet does the same work per second as RK4 at Δt = 0.2", l8_same_work, EXACT, 0, R_COUNT, NULL },
    { L8, "@hint Press - twice: 0.1, {0.05}.", l8_dt_minus2, EXACT, 0, "the step two presses of - give", NULL },
    { L8, "@hint Use verlet (press {6})", key_verlet, EXACT, 0, "the key that picks the method", NULL },
    { L8, "its energy wobbles within {12.3} % however", l8_verlet_bound, ATMOST, 0.05, "the largest wobble over 1000 s, a bound it comes within 5 % of", NULL },
    { L8, "by t = 100 its energy is down {15.5} %", l8_rk4_100, ROUNDED, 0, R_ROUND, NULL },
    { L8, "@hint Press {6}, or i until the status line says verlet.", key_verlet, EXACT, 0, "the key that picks the method", NULL },
    { L8, "@hint Press {1}, or I until the status line says euler.", key_euler, EXACT, 0, "the key that picks the method", NULL },
    /* lesson 9 */
    { L9, "whips past it {nineteen} times closer", l9_dist_ratio, REL, 1e-9, "apoapsis over periapsis of the true orbit", NULL },
    { L9, "nineteen times closer and {nineteen} times faster", l9_speed_ratio, REL, 1e-9, "the speeds at periapsis and apoapsis of the true orbit", NULL },
    { L9, "(1 + e)/(1 - e) = {19}", l9_arith, REL, 1e-12, R_MATH, NULL },
    { L9, "RK4 at fixed Δt 0.05 ({1008} evaluations)", l9_rk4_evals, EXACT, 0, R_COUNT, NULL },
    { L9, "(energy +{1250} %, then constant", l9_rk4_drift, REL, 0.004, "three significant figures", NULL },
    { L9, "(energy {-122} % by t = 1.5)", l9_rk4_first, ROUNDED, 0, R_ROUND, NULL },
    { L9, "the second, at t ≈ {2.9}, flings it away", l9_rk4_second_pass, ROUNDED, 0, "the time of the nearest approach after t = 1, to the text's digits", NULL },
    { L9, "at its second close pass (t ≈ {2.9}) RK4", l9_rk4_second_pass, ROUNDED, 0, "as above", NULL },
    { L9, "+1250 %, then {constant}: the planet has escaped", l9_constant, ABS, 0.001, "the drift moves less than 0.1 % of itself from t = 4 to two orbits", NULL },
    { L9, "@hint Press + three times: 0.1, 0.2, {0.4}.", l9_dt_plus3, EXACT, 0, "the step three presses of + give", NULL },
    { L9, "about {120} accepted, 50 rejected", l9_acc04, ABS, 10, "\"about 120\": within ten", NULL },
    { L9, "about 120 accepted, {50} rejected", l9_rej04, ABS, 5, "\"about 50\": within five", NULL },
    { L9, "{1027} evaluations, energy", l9_evals04, EXACT, 0, R_COUNT, NULL },
    { L9, "energy off by {0.002} % at worst", l9_drift04, ROUNDED, 0, "the largest |drift| over the run, to the text's digits", NULL },
    { L9, "largest step: {293} accepted, 28 rejected)", l9_acc005, EXACT, 0, R_COUNT, NULL },
    { L9, "largest step: 293 accepted, {28} rejected)", l9_rej005, EXACT, 0, R_COUNT, NULL },
    { L9, "rk45's energy is off by {a few thousandths} of a percent", l9_drift04, ABS, 0.004, "\"a few thousandths\": 0.001 to 0.009", NULL },
    { L9, "it needs about {1000} evaluations, as many as RK4 spent", l9_evals04, REL, 0.05, "\"about 1000\": within 5 %", NULL },
    { L9, "a 5th-order answer and a 4th-order one from the same {seven} stages", l9_rk45_stages, EXACT, 0, "the first step evaluates every stage", NULL },
    { L9, "({six} new evaluations: the", l9_rk45_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { L9, "takes each step twice at once: a {5}th-order answer", l9_rk45_order, EXACT, 0, "the method's order in the table", NULL },
    { L9, "@hint Press {0} (zero), or i until the status line says rk45.", key_rk45, EXACT, 0, "the key that picks the method", NULL },
    { L9, "The tolerance (rtol = {1e-6}) bounds each step's error", l9_sim_rtol, EXACT, 0, "the tolerance a sim starts with", NULL },
    { L9, "after two orbits the planet is off by about {0.034}", l9_rk45_error, ROUNDED, 0, "rk45 at largest step 0.4 (the page's), the error against Kepler at two orbits", NULL },
    { L9, "some {34 000} times rtol", l9_rk45_error_over_rtol, REL, 0.015, "two significant figures", NULL },
    { L9, "Ask for less per step and the run's error falls in proportion", l9_proportion, MAGNITUDE, 0.3, "error over rtol at rtol 1e-8 against at 1e-6: within a factor two", one },
    { L9, "dop853, {twelve} new evaluations per step", dop853_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { L9, "Dormand and Prince also paired an {8}th-order answer", ord_dop853, EXACT, 0, "the method's order in the table", NULL },
    { L9, "At this loose tolerance it costs about what rk45 does", l9_dop853_vs_rk45, ABS, 0.2, "dop853's evaluations over rk45's at rtol 1e-6, largest step 0.4: within 20 %", one },
    { L9, "two orbits cost dop853 {2690} evaluations", l9_tight_dop853_evals, EXACT, 0, "rtol 1e-10, atol 1e-13 (bench's 1e-3·rtol), largest step 0.4", NULL },
    { L9, "for an error of {9e-8}, and rk45", l9_tight_dop853_error, ROUNDED, 0, "as above, the error against Kepler", NULL },
    { L9, "and rk45 {4591} for 2e-6", l9_tight_rk45_evals, EXACT, 0, "as above", NULL },
    { L9, "and rk45 4591 for {2e-6}", l9_tight_rk45_error, ROUNDED, 0, "as above", NULL },
    { L9, "(press i once from rk45: it is the {11}th method)", l9_dop853_place, EXACT, 0, "dop853's place in the list", NULL },
    { L9, "(press i {once} from rk45", l9_dop853_after_rk45, EXACT, 0, "places from rk45 to dop853", NULL },
    /* lesson 10 */
    { L10, "A correct midpoint gives a ratio near {4}, RK4 near 16", l10_ratio_mid, ABS, 0.5, "the lessons' tolerance for 4", NULL },
    { L10, "A correct midpoint gives a ratio near 4, RK4 near {16}", l10_ratio_rk4, ABS, 2, "the lessons' tolerance for 16", NULL },
    { L10, "A first-order method shows {2.6}, then 2.3", l10_ratio_euler1, ROUNDED, 0, "the ratio the status line shows for euler, to the text's digits", NULL },
    { L10, "A first-order method shows 2.6, then {2.3}", l10_ratio_euler2, ROUNDED, 0, "as above, halving again", NULL },
    { L10, "until the ratio settles near {2}: over the", l10_ratio_euler5, ABS, 0.1, "the fifth halving, from Δt = 0.00125", NULL },
    { L10, "Euler's amplitude error grows like e^(ω²ΔtT/2) - 1", l10_ratio_euler1, REL, 0.01, "the ratio (e^x - 1)/(e^(x/2) - 1) at x = ω²ΔtT/2 = 1 against the measured one", l10_ratio_formula },
    { L10, "(it is {1} at Δt = 0.02)", l10_exponent, ABS, 1e-9, "ω²ΔtT/2 = 10·0.02·10/2, to rounding", NULL },
    { L10, "over the {10} s run", l10_duration, EXACT, 0, "the spring's report time", NULL },
    { L10, "what does an error ratio of {2} say about the order?", l2_ratio2, ABS, 0.3, "lesson 2's measurement, with the lessons' tolerance for 2", NULL },
    { L10, "midpoint and Heun agree to {rounding}", l10_spring_same, ATMOST, 0, "1e-12 over the report time", NULL },
    { L10, "Grade on the chain: on the one-dimensional spring", l10_chain_differ, ATLEAST, 0, "on the chain midpoint and Heun differ by more than check's tolerance", check_tolerance },
    /* README: what the tool claims, the integrator table */
    { README, "the ratio approaches 2^p once Δt is small enough", ord_rk4, ABS, 0.1, "rk4's order halving Δt from 0.04 on the spring: 4 within 0.1", four },
    { README, "| euler | explicit (forward) Euler | {1} | 1 |", ord_euler, ABS, 0.1, "the order measured halving Δt on the damped spring", NULL },
    { README, "| euler | explicit (forward) Euler | 1 | {1} |", ev_euler, EXACT, 0, "evaluations per step measured", NULL },
    { README, "| symplectic-euler | semi-implicit Euler: v then x | {1} | 1 |", ord_symplectic, ABS, 0.1, "as above", NULL },
    { README, "| symplectic-euler | semi-implicit Euler: v then x | 1 | {1} |", ev_symplectic, EXACT, 0, "as above", NULL },
    { README, "| midpoint | explicit midpoint (RK2) | {2} | 2 |", ord_midpoint, ABS, 0.1, "as above", NULL },
    { README, "| midpoint | explicit midpoint (RK2) | 2 | {2} |", ev_midpoint, EXACT, 0, "as above", NULL },
    { README, "| heun | Heun / explicit trapezoid (RK2) | {2} | 2 |", ord_heun, ABS, 0.1, "as above", NULL },
    { README, "| heun | Heun / explicit trapezoid (RK2) | 2 | {2} |", ev_heun, EXACT, 0, "as above", NULL },
    { README, "| rk4 | classical Runge–Kutta | {4} | 4 |", ord_rk4, ABS, 0.1, "as above (from Δt = 0.04: rounding stays below the error)", NULL },
    { README, "| rk4 | classical Runge–Kutta | 4 | {4} |", ev_rk4, EXACT, 0, "as above", NULL },
    { README, "| verlet | velocity Verlet (leapfrog) | {2} | 1", ord_verlet, ABS, 0.1, "as above", NULL },
    { README, "| verlet | velocity Verlet (leapfrog) | 2 | {1} (reuses the last acceleration) |", ev_verlet, EXACT, 0, "after the first step", NULL },
    { README, "| implicit-euler | backward Euler, Newton's method to rounding, direct solve | {1} |", ord_be, ABS, 0.1, "as above", NULL },
    { README, "direct solve | 1 | ≥ {1} + solves |", ev_be, ATLEAST, 0, "Newton iterates: at least one evaluation per step", NULL },
    { README, "(Baraff–Witkin's \"large steps\") | {1} | 1 + a linear solve |", ord_lbe, ABS, 0.1, "as above", NULL },
    { README, "(Baraff–Witkin's \"large steps\") | 1 | {1} + a linear solve |", ev_lbe, EXACT, 0, "one Newton step: one evaluation", NULL },
    { README, "| implicit-midpoint | implicit midpoint, Newton's method to rounding | {2} |", ord_im, ABS, 0.1, "as above", NULL },
    { README, "Newton's method to rounding | 2 | ≥ {2} + solves |", ev_im, ATLEAST, 0, "Newton iterates: at least two evaluations per step", NULL },
    { README, "| rk45 | Dormand–Prince 5(4), adaptive (rtol/atol) | {5} | 6", ord_rk45, EXACT, 0, "the method's order in the table", NULL },
    { README, "(rtol/atol) | 5 | {6} (reuses the last stage) |", l9_rk45_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { README, "| dop853 | Dormand–Prince 8(5,3) (Hairer), adaptive (rtol/atol) | {8} |", ord_dop853, EXACT, 0, "the method's order in the table", NULL },
    { README, "(Hairer), adaptive (rtol/atol) | 8 | {12} (reuses the last stage) |", dop853_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { INTEGRATORS, "\"Dormand-Prince 8(5,3), adaptive (Hairer)\", 8, {12},", dop853_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    { README, "rk45's error after two orbits is about {3·10⁴} times rtol", l9_rk45_error_over_rtol, ABS, 5000, "one significant figure", NULL },
    { README, "`1`–`9` and `{0}` pick one", key_rk45, EXACT, 0, "the key that picks the tenth method", NULL },
    { README, "the {ten} lessons in `lessons/`", lesson_count, EXACT, 0, R_COUNT, NULL },
    { README, "Euler's energy growth (1 + h²)^N", euler_energy_growth, REL, 1e-9, "Euler's energy on the ω = 1 spring after 50 steps of 0.1", euler_energy_formula },
    { README, "(ωh = {2} for symplectic Euler and Verlet", symplectic_wdt, ABS, 1e-6, "symplectic Euler's limit in theory (bisected to 1e-9)", NULL },
    { README, "(ωh = {2} for symplectic Euler and Verlet", verlet_wdt, ABS, 1e-6, "Verlet's limit in theory", NULL },
    { README, "(ωh = {2} for symplectic Euler and Verlet", verlet_measured_wdt, REL, 0.001, "Verlet's limit measured (bisection to 0.01 %)", NULL },
    { README, "symplectic Euler and Verlet, {2√2} for RK4", rk4_wdt, ABS, 1e-6, "RK4's limit in theory", NULL },
    { README, "symplectic Euler and Verlet, {2√2} for RK4", rk4_measured_wdt, REL, 0.001, "RK4's limit measured", NULL },
    { README, "their damped values: Euler {2}ζ", euler_damped_over_zeta, ABS, 1e-6, "Euler's damped limit over ζ on the default spring", NULL },
    { README, "RK4 {2.938} at ζ = 0.079 in theory", rk4_damped, ROUNDED, 0, R_ROUND, NULL },
    { README, "RK4 2.938 at ζ = {0.079} in theory", spring_zeta, ROUNDED, 0, "ζ = c/2√(km) of the default spring", NULL },
    { README, "on the default spring RK4 measures {2.815}", rk4_damped_measured, ROUNDED, 0, "the measured limit, ω·Δt to the text's digits", NULL },
    { README, "it throws the mass through its anchor", rk4_through_anchor, ATMOST, 0, "at Δt = 0.9 (ωΔt 2.85) the mass reaches x < 0", zero },
    { README, "with a smaller stretch it measures {2.938} too", rk4_small_stretch, ROUNDED, 0, "measured at stretch 0.2", NULL },
    { README, "stiff pendulum up to ω·Δt = {10⁴}", be_never_gains, ATLEAST, 0, "no step of 20 raised the energy at ω·Δt = 1, 10, ... 1e4", NULL },
    /* `stepwise list integrators` prints each method's order and evaluations
     * per step from the table in src/engine/integrators.c ("+solve" after an
     * implicit method's count: at least that many, and linear solves) */
    { INTEGRATORS, "\"explicit (forward) Euler\", {1}, 1,", ord_euler, ABS, 0.1, "the order measured halving Δt on the damped spring", NULL },
    { INTEGRATORS, "\"explicit (forward) Euler\", 1, {1},", ev_euler, EXACT, 0, "evaluations per step measured", NULL },
    { INTEGRATORS, "\"semi-implicit Euler\", {1}, 1,", ord_symplectic, ABS, 0.1, "as above", NULL },
    { INTEGRATORS, "\"semi-implicit Euler\", 1, {1},", ev_symplectic, EXACT, 0, "as above", NULL },
    { INTEGRATORS, "\"explicit midpoint (RK2)\", {2}, 2,", ord_midpoint, ABS, 0.1, "as above", NULL },
    { INTEGRATORS, "\"explicit midpoint (RK2)\", 2, {2},", ev_midpoint, EXACT, 0, "as above", NULL },
    { INTEGRATORS, "\"Heun / explicit trapezoid (RK2)\", {2}, 2,", ord_heun, ABS, 0.1, "as above", NULL },
    { INTEGRATORS, "\"Heun / explicit trapezoid (RK2)\", 2, {2},", ev_heun, EXACT, 0, "as above", NULL },
    { INTEGRATORS, "\"classical Runge-Kutta\", {4}, 4,", ord_rk4, ABS, 0.1, "as above", NULL },
    { INTEGRATORS, "\"classical Runge-Kutta\", 4, {4},", ev_rk4, EXACT, 0, "as above", NULL },
    { INTEGRATORS, "\"velocity Verlet (leapfrog)\", {2}, 1,", ord_verlet, ABS, 0.1, "as above", NULL },
    { INTEGRATORS, "\"velocity Verlet (leapfrog)\", 2, {1},", ev_verlet, EXACT, 0, "after the first step", NULL },
    { INTEGRATORS, "\"backward Euler (Newton to rounding, direct solve)\", {1}, 1,", ord_be, ABS, 0.1, "as above", NULL },
    { INTEGRATORS, "\"backward Euler (Newton to rounding, direct solve)\", 1, {1},", ev_be, ATLEAST, 0, "\"1+solve\": Newton iterates, at least one evaluation", NULL },
    { INTEGRATORS, "\"linearly implicit Euler (one Newton step)\", {1}, 1,", ord_lbe, ABS, 0.1, "as above", NULL },
    { INTEGRATORS, "\"linearly implicit Euler (one Newton step)\", 1, {1},", ev_lbe, EXACT, 0, "one Newton step: one evaluation", NULL },
    { INTEGRATORS, "\"implicit midpoint (Newton to rounding)\", {2}, 2,", ord_im, ABS, 0.1, "as above", NULL },
    { INTEGRATORS, "\"implicit midpoint (Newton to rounding)\", 2, {2},", ev_im, ATLEAST, 0, "\"2+solve\": Newton iterates, at least two evaluations", NULL },
    { INTEGRATORS, "\"Dormand-Prince 5(4), adaptive\", 5, {6},", l9_rk45_per_step, EXACT, 0, "evaluations per accepted step once under way", NULL },
    /* man page */
    { MAN, "Step size, in [{1e\\-9}, 1000]", dt_min, EXACT, 0, R_COUNT, NULL },
    { MAN, "Step size, in [1e\\-9, {1000}]", dt_max, EXACT, 0, R_COUNT, NULL },
    { MAN, "(defaults {1e\\-6} and 1e\\-9). The implicit", rtol_default, EXACT, 0, R_COUNT, NULL },
    { MAN, "(defaults 1e\\-6 and {1e\\-9}). The implicit", atol_default, EXACT, 0, R_COUNT, NULL },
    { MAN, "Comparison tolerances; defaults {1e\\-9} and 1e\\-9", check_rtol, EXACT, 0, R_COUNT, NULL },
    { MAN, "Comparison tolerances; defaults 1e\\-9 and {1e\\-9}", check_atol, EXACT, 0, R_COUNT, NULL },
    { MAN, "The small sweep the UI uses ({6}\\-8 step sizes, one run each)", bench_quick_min, EXACT, 0, R_COUNT, NULL },
    { MAN, "The small sweep the UI uses (6\\-{8} step sizes, one run each)", bench_quick_max, EXACT, 0, R_COUNT, NULL },
    { MAN, "The small sweep the UI uses (6\\-8 step sizes, {one} run each)", bench_quick_runs, EXACT, 0, R_COUNT, NULL },
    { MAN, "Timing repeats per point, 1..15 (default {3})", bench_default_repeats, EXACT, 0, R_COUNT, NULL },
    { MAN, "with a {ten\\-thousandfold} smaller copy of the motion", stab_shrink, REL, 1e-12, R_COUNT, NULL },
    { MAN, "Where the two differ by more than {2}% a line says why", stab_agree, REL, 1e-12, R_COUNT, NULL },
    /* docs/stability.md (its table: tests/e2e/test_stability_doc.sh) */
    { STAB, "It is taken at {16} times along the true solution", stab_samples, EXACT, 0, R_COUNT, NULL },
    { STAB, "\"none\" means the method grows already at |λ|·Δt = {0.01}", euler_grows_at_low, EXACT, 0, "the smallest |λ|·Δt probed, where Euler grows", NULL },
    { STAB, "\"unbounded\" that no mode grows at any Δt up to {1000}", be_unbounded_to, EXACT, 0, "backward Euler's theory runs to this Δt", NULL },
    { STAB, "over the horizon, {100} periods of the stiffest mode", horizon_periods, REL, 1e-12, "the horizon of a slow spring (ω = 0.1) in periods", NULL },
    { STAB, "and at least {20} report times", horizon_reports, REL, 1e-12, "the horizon of a stiff one in report times", NULL },
    { STAB, "report times: ρ^(T/Δt) > {1.01}", visible_growth, REL, 1e-9, "growth at which the meter calls it visible, bisected", NULL },
    { STAB, "when M passes {1000}, when", watch_bound, REL, 1e-6, "the level of M at which the watch says energy x1000, bisected", NULL },
    { STAB, "a twentieth of the run", watch_windows, EXACT, 0, R_COUNT, twenty },
    { STAB, "passes a level ({3} for a method that is not symplectic", raised_plain, EXACT, 0, R_COUNT, NULL },
    { STAB, "energy; {30} for a symplectic one", raised_symplectic, EXACT, 0, R_COUNT, NULL },
    { STAB, "{2} for an orbit, where M = 2 is the planet escaping", raised_orbit, EXACT, 0, R_COUNT, NULL },
    { STAB, "whose energy started from rest averages up to 1/(1 − (|λ|Δt/2)²)", symplectic_mean_m, REL, 1e-3, "symplectic Euler from rest at ωΔt = 1: mean M over 20000 steps", symplectic_mean_formula },
    { STAB, "same motion shrunk {ten-thousandfold} towards it", stab_shrink, REL, 1e-12, R_COUNT, NULL },
    { STAB, "Bisection between a stable and an unstable Δt runs to {0.01} %", stab_rel_tol, REL, 1e-12, R_COUNT, NULL },
    { STAB, "the step\nis probed again over {4} and then", stab_longer, EXACT, 0, "SW_STABILITY_LONGER; test_long_probes checks the horizon a result states", NULL },
    { STAB, "probed again over 4 and then {16} times the horizon", stab_longest, EXACT, 0, "two rounds of SW_STABILITY_LONGER", NULL },
    { STAB, "They agree within {2} % wherever", stab_agree, REL, 1e-12, R_COUNT, NULL },
    { STAB, "gains energy on the nonlinear stiff pendulum above Δt ≈ {0.19}", l7_im_limit, ROUNDED, 0, "the limit the stability lab measures", NULL },
    /* scenes: what `stepwise list` and `describe` print */
    { "src/scenes/flow_scenes.c", "every step multiplies the radius by sqrt(1 + (w dt)^2)", vortex_growth, REL, 1e-12, "ρ of Euler's map at Δt = 0.3", vortex_formula },
    { "src/scenes/spring_scenes.c", "explicit Euler gains energy every step: (1 + (w dt)^2) per step", spring_energy_growth, REL, 1e-12, "ρ² of Euler's map on the undamped spring at Δt = 0.05", spring_energy_formula },
    { "src/scenes/spring_scenes.c", "implicit midpoint gains energy on this nonlinear spring above dt {0.19}", l7_im_limit, ROUNDED, 0, "the limit the stability lab measures", NULL },
    { "src/scenes/orbit.c", "Kepler's exact ellipse, period 2 pi / sqrt(mu)", orbit_period_mu4, REL, 1e-12, "Kepler's period from the energy at mu = 4", orbit_period_formula },
    { "src/scenes/flow_scenes.c", "measured against a tight-tolerance {8}th-order", reference_order, EXACT, 0, "the order of the truth module's reference method", NULL },
    { "src/scenes/ball_scenes.c", "halve the step and the miss distance {halves}", projectile_ratio, ABS, 0.3, "the ratio halving Δt from 0.01: the lessons' tolerance for 2", NULL },
    { "src/scenes/ball_scenes.c", "error becomes O(dt)", bounce_order, ABS, 0.5, "the order lesson 4's page measures on the bounce", one },
    /* lessons/README.md, the authoring guide */
    { GUIDE, "| `@dt STEP` | the step size, in [{1e-9}, 1000] seconds |", guide_dt_min, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "| `@dt STEP` | the step size, in [1e-9, {1000}] seconds |", dt_max, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "`>=` forgive a relative difference of {1e-9}", goal_slack, REL, 1e-6, "the slack of a >= goal, bisected", NULL },
    { GUIDE, "(E - E0)/(E0 - E_rest) in percent", drift_definition, ATMOST, 0, "the drift the goals see against the definition worked out here (1e-12)", rounding },
    { GUIDE, "`0` the tenth, rk45 |", key_rk45, EXACT, 0, "the key that picks rk45", zero },
    { GUIDE, "| file size | {262144} bytes (256 KiB) |", max_bytes, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "| line length | {1000} bytes |", max_line, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "| lesson and page titles | {80} characters |", max_title, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "| pages per lesson | {64} |", max_pages, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "| prose per page | {6000} bytes |", max_prose, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "| paragraphs and verbatim blocks per page | {64} |", max_blocks, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "| goals per page | {8} |", max_goals, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "| answers per question | {6} |", max_answers, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "| methods in `@compare` | {2} |", max_compare, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "| names after `in` | {4} |", max_names, EXACT, 0, R_COUNT, NULL },
    { GUIDE, "| lesson files in one directory | {256} |", max_files, EXACT, 0, R_COUNT, NULL },
};

/* ---- reading the texts ------------------------------------------------- */

static int isspace_ascii(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

/* The file's text with every run of white space as one space; in a lesson,
 * a comment line's '#' (and the spaces after it) dropped, and with
 * prose_only its settings and goals too (questions, answers and hints stay).
 * Caller frees. */
static char *text_of_(const char *file, int prose_only)
{
    FILE *f = fopen(file, "rb");
    ck_assert_msg(f != NULL, "cannot open %s (run the tests from the repository root)", file);
    fseek(f, 0, SEEK_END);
    long len = ftell(f);
    rewind(f);
    char *raw = malloc((size_t)len + 1), *out = malloc((size_t)len + 2);
    ck_assert(raw && out && fread(raw, 1, (size_t)len, f) == (size_t)len);
    fclose(f);
    raw[len] = 0;
    int lesson = strstr(file, ".lesson") != NULL, line_start = 1;
    size_t n = 0;
    for (long i = 0; i < len; i++) {
        char c = raw[i];
        if (lesson && line_start) {
            long j = i;
            while (j < len && (raw[j] == ' ' || raw[j] == '\t'))
                j++;
            if (j < len && raw[j] == '#') {
                i = j;
                line_start = 0;
                continue;
            }
            /* settings and goals are what the page does, not what it says */
            if (prose_only && j < len && raw[j] == '@' && strncmp(raw + j, "@question", 9) != 0 &&
                strncmp(raw + j, "@answer", 7) != 0 && strncmp(raw + j, "@hint", 5) != 0) {
                while (i < len && raw[i] != '\n')
                    i++;
                continue;
            }
        }
        line_start = c == '\n';
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
            if (n > 0 && out[n - 1] != ' ')
                out[n++] = ' ';
        } else {
            out[n++] = c;
        }
    }
    out[n] = 0;
    free(raw);
    return out;
}

static char *text_of(const char *file) { return text_of_(file, 0); }

/* The snippet as it stands in the text (braces dropped, white space as in
 * text_of), and the figure between the braces ("" when none). */
static void split_snippet(const char *snippet, char *plain, size_t plen, char *figure, size_t flen)
{
    size_t n = 0, f = 0;
    int in = 0;
    figure[0] = 0;
    for (const char *c = snippet; *c && n + 1 < plen; c++) {
        if (*c == '{' || *c == '}') {
            in = *c == '{';
            continue;
        }
        if (isspace_ascii(*c)) {
            if (n > 0 && plain[n - 1] != ' ')
                plain[n++] = ' ';
        } else {
            plain[n++] = *c;
        }
        if (in && f + 1 < flen)
            figure[f++] = *c;
    }
    plain[n] = 0;
    figure[f] = 0;
}

/* Figures written in words, and what they stand for. */
static const struct { const char *word; double value; } words[] = {
    { "a", 1 }, { "one", 1 }, { "first", 1 }, { "second", 2 }, { "fourth", 4 }, { "two", 2 },
    { "half", 0.5 }, { "twothirds", 2.0 / 3.0 }, { "tripled", 3 }, { "five", 5 }, { "ten", 10 },
    { "adozen", 12 }, { "nineteen", 19 }, { "seven", 7 }, { "six", 6 }, { "four", 4 },
    { "eight", 8 }, { "ten-thousandfold", 1e4 }, { "halves", 2 }, { "rounding", 1e-12 },
    { "afewthousandths", 0.005 }, { "constant", 0 }, { "twelve", 12 }, { "once", 1 },
};

static const char *const superscripts[] = { "⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹" };

/* Superscript digits at *s as a number (advances *s); -1 when none. */
static int superscript(const char **s)
{
    int value = -1;
    for (int found = 1; found;) {
        found = 0;
        for (int d = 0; d < 10; d++) {
            size_t len = strlen(superscripts[d]);
            if (strncmp(*s, superscripts[d], len) == 0) {
                value = (value < 0 ? 0 : 10 * value) + d;
                *s += len;
                found = 1;
            }
        }
    }
    return value;
}

/* The figure as written: "1.37", "-8.50", "+38.4", "66 %", "100 000",
 * "1e\-9" (roff), "2√2", "√1.16", "10⁴", "²", or a word from the list.
 * Normalised text into norm (for the rounding rule). NaN when unreadable. */
static double parse_figure(const char *figure, char *norm, size_t nlen)
{
    size_t n = 0;
    for (const char *c = figure; *c && n + 1 < nlen;) {
        if (*c == ' ' || *c == '%') {
            c++;
        } else if (strncmp(c, "\xc2\xa0", 2) == 0) {
            c += 2; /* no-break space */
        } else if (strncmp(c, "\xe2\x80\x89", 3) == 0 || strncmp(c, "\xe2\x80\xaf", 3) == 0) {
            c += 3; /* thin spaces */
        } else if (strncmp(c, "\xe2\x88\x92", 3) == 0) {
            norm[n++] = '-'; /* U+2212 minus */
            c += 3;
        } else if (c[0] == '\\' && c[1] == '-') {
            norm[n++] = '-'; /* roff's minus */
            c += 2;
        } else {
            norm[n++] = *c++;
        }
    }
    norm[n] = 0;
    for (size_t i = 0; i < sizeof words / sizeof words[0]; i++)
        if (strcmp(norm, words[i].word) == 0)
            return words[i].value;
    const char *s = norm;
    int sup = superscript(&s);
    if (sup >= 0 && *s == 0)
        return sup;
    s = norm;
    char *end;
    double a = strtod(s, &end);
    if (end == s)
        a = 1;
    s = end;
    if (strncmp(s, "π", strlen("π")) == 0) {
        a *= 3.141592653589793;
        s += strlen("π");
    }
    if (*s == '/') {
        double b = strtod(s + 1, &end);
        if (end == s + 1 || b == 0)
            return NAN;
        a /= b;
        s = end;
    }
    if (strncmp(s, "√", strlen("√")) == 0) {
        s += strlen("√");
        double b = strtod(s, &end);
        if (end == s)
            return NAN;
        a *= sqrt(b);
        s = end;
    }
    if (strncmp(s, "·10", strlen("·10")) == 0) { /* 3·10⁴ */
        s += strlen("·10");
        sup = superscript(&s);
        if (sup < 0)
            return NAN;
        a *= pow(10, sup);
    }
    sup = superscript(&s);
    if (sup >= 0)
        a = pow(a, sup);
    return *s == 0 ? a : NAN;
}

/* Half a unit of the last digit written: "1.37" 0.005, "66" 0.5, "3.3e-7" 0.05e-7. */
static double half_unit(const char *norm)
{
    const char *dot = strchr(norm, '.'), *e = strpbrk(norm, "eE");
    int decimals = 0;
    if (dot)
        for (const char *c = dot + 1; *c >= '0' && *c <= '9'; c++)
            decimals++;
    int exponent = e ? atoi(e + 1) : 0;
    return 0.5 * pow(10, exponent - decimals);
}

static const char *kind_name(claim_kind k)
{
    static const char *const names[] = { "rounded", "abs", "rel", "exact", "at most", "at least", "magnitude" };
    return names[k];
}

/* Whether computed c holds the written figure w under the row's rule. */
static int holds(const claim *cl, double w, double c, const char *norm, double *tol_out)
{
    double tol = cl->tol;
    switch (cl->kind) {
    case ROUNDED:
        tol = half_unit(norm) * (1 + 1e-9);
        *tol_out = tol;
        return fabs(c - w) <= tol;
    case ABS:
        *tol_out = tol;
        return fabs(c - w) <= tol;
    case REL:
        *tol_out = tol * fabs(w);
        return fabs(c - w) <= tol * fabs(w);
    case EXACT:
        *tol_out = 1e-9 * fabs(w);
        return fabs(c - w) <= 1e-9 * fabs(w);
    case ATMOST:
        *tol_out = tol;
        return c <= w * (1 + 1e-12) && (tol <= 0 || c >= w * (1 - tol));
    case ATLEAST:
        *tol_out = tol;
        return c >= w * (1 - 1e-12) && (tol <= 0 || c <= w * (1 + tol));
    case MAGNITUDE:
        *tol_out = tol;
        return c > 0 && w > 0 && fabs(log10(c / w)) <= tol;
    }
    return 0;
}

static int print_values(void)
{
    const char *v = getenv("SW_CLAIMS_PRINT");
    return v && *v && strcmp(v, "0") != 0;
}

/* Rows whose computation bisects for a stability limit (a second or more
 * under valgrind each): SW_TEST_QUICK skips computing them. */
static int is_slow(double (*compute)(void))
{
    double (*const slow[])(void) = { l7_im_limit, l7_verlet_theory, l7_verlet_measured, verlet_measured_wdt,
                                     rk4_measured_wdt, rk4_damped_measured, rk4_small_stretch };
    for (size_t i = 0; i < sizeof slow / sizeof slow[0]; i++)
        if (slow[i] == compute)
            return 1;
    return 0;
}

/* Row i: the snippet is in its file, the figure parses, and the library's
 * value holds it. */
START_TEST(claim_holds)
{
    const claim *cl = &claims[_i];
    char plain[1024], figure[128], norm[128];
    split_snippet(cl->snippet, plain, sizeof plain, figure, sizeof figure);
    char *text = text_of(cl->file);
    int found = strstr(text, plain) != NULL;
    free(text);
    ck_assert_msg(found, "%s: the text no longer says \"%s\": update the row in tests/check_claims.c", cl->file,
                  plain);
    double w;
    if (figure[0]) {
        w = parse_figure(figure, norm, sizeof norm);
        ck_assert_msg(!isnan(w), "%s: cannot read the figure {%s} in \"%s\"", cl->file, figure, plain);
        ck_assert_msg(cl->formula == NULL, "row %d has both a figure and a formula", _i);
    } else {
        ck_assert_msg(cl->formula != NULL, "%s: \"%s\" marks no {figure} and names no formula", cl->file, plain);
        snprintf(norm, sizeof norm, "formula");
        w = cl->formula();
    }
    if (getenv("SW_TEST_QUICK") && is_slow(cl->compute))
        return; /* the text and its figure were checked; the bisection runs in the plain pass */
    clock_t start = clock();
    double c = cl->compute(), tol = 0, cpu = (double)(clock() - start) / CLOCKS_PER_SEC;
    int ok = holds(cl, w, c, norm, &tol);
    if (print_values() || !ok)
        fprintf(stderr, "%-4s %3d %s: \"%s\": written %.6g, computed %.6g (%s, tol %.3g; %.2f s)\n", ok ? "ok" : "FAIL",
                _i, cl->file, plain, w, c, kind_name(cl->kind), tol, cpu);
    ck_assert_msg(ok, "%s: \"%s\": the text says %.6g, the library gives %.6g (%s %.3g: %s)", cl->file, plain, w, c,
                  kind_name(cl->kind), tol, cl->why);
}
END_TEST

/* Texts that look like a quoted figure but are not one (the guard below
 * would otherwise ask for a row): a formula checked by the rows above at
 * the lesson's values, a setting the page makes, a size. */
static const struct { const char *file, *snippet; } not_figures[] = {
    { L2, "halving Δt divides the error by 2^p" },        /* the formula; the ratios have rows */
    { L5, "a Δt of 0.005 is far too long for that" },     /* the page's step; the limit has a row */
    { L5, "Look at Euler's factor 1 - cΔt + kΔt² with c = 0" }, /* the formula; its rows are above */
    { STAB, "which makes its map 3×3" },                   /* a matrix's size */
};

static const char *const guarded[] = { L1, L2, L3, L4, L5, L6, L7, L8, L9, L10, README, MAN, STAB };

/* Mark the first occurrence of snippet in text as covered. */
static void cover(const char *text, const char *snippet, unsigned char *covered)
{
    char plain[1024], figure[128];
    split_snippet(snippet, plain, sizeof plain, figure, sizeof figure);
    const char *at = strstr(text, plain);
    if (at)
        memset(covered + (at - text), 1, strlen(plain));
}

static int ends_with_word(const char *text, size_t end, const char *word)
{
    size_t n = strlen(word);
    if (end < n || strncmp(text + end - n, word, n) != 0)
        return 0;
    unsigned char before = end > n ? (unsigned char)text[end - n - 1] : ' ';
    return !((before >= 'a' && before <= 'z') || (before >= 'A' && before <= 'Z'));
}

/* A number at text[i] that reads like a quoted figure: after "≈", "about",
 * "near", "within", "factor", "by", "ratio" or "of", or before "%",
 * "times", "×" or "fold". */
static int figure_like(const char *text, size_t i, size_t *len)
{
    static const char *const before[] = { "≈", "about", "near", "within", "factor", "by", "ratio", "of" };
    static const char *const after[] = { "%", "times", "×", "fold", "-fold" };
    unsigned char prev = i > 0 ? (unsigned char)text[i - 1] : ' ';
    if (!(text[i] >= '0' && text[i] <= '9') || (prev >= '0' && prev <= '9') || prev == '.' || prev == '_' ||
        (prev >= 'a' && prev <= 'z') || (prev >= 'A' && prev <= 'Z'))
        return 0;
    size_t j = i;
    while ((text[j] >= '0' && text[j] <= '9') || (text[j] == '.' && text[j + 1] >= '0' && text[j + 1] <= '9'))
        j++;
    *len = j - i;
    size_t b = i;
    if (b > 0 && (text[b - 1] == '-' || text[b - 1] == '+'))
        b--;
    while (b > 0 && text[b - 1] == ' ')
        b--;
    for (size_t k = 0; k < sizeof before / sizeof before[0]; k++)
        if (ends_with_word(text, b, before[k]))
            return 1;
    while (text[j] == ' ')
        j++;
    for (size_t k = 0; k < sizeof after / sizeof after[0]; k++)
        if (strncmp(text + j, after[k], strlen(after[k])) == 0)
            return 1;
    return 0;
}

/* Every figure-like number in the guarded texts is in some row's snippet
 * (or named above as not a figure): a figure added without a row fails. */
START_TEST(every_figure_has_a_row)
{
    const char *file = guarded[_i];
    char *text = text_of_(file, 1);
    size_t len = strlen(text);
    if (strcmp(file, STAB) == 0 && strstr(text, "<!-- generated"))
        len = (size_t)(strstr(text, "<!-- generated") - text); /* the table has its own test */
    unsigned char *covered = calloc(len + 1, 1);
    for (size_t r = 0; r < sizeof claims / sizeof claims[0]; r++)
        if (strcmp(claims[r].file, file) == 0)
            cover(text, claims[r].snippet, covered);
    for (size_t r = 0; r < sizeof not_figures / sizeof not_figures[0]; r++)
        if (strcmp(not_figures[r].file, file) == 0)
            cover(text, not_figures[r].snippet, covered);
    int missing = 0;
    for (size_t i = 0; i < len; i++) {
        size_t n;
        if (figure_like(text, i, &n) && !covered[i]) {
            fprintf(stderr, "%s: no row for the figure in \"...%.*s...\"\n", file,
                    (int)(i + n + 20 < len ? n + 40 : len - (i > 20 ? i - 20 : 0)), text + (i > 20 ? i - 20 : 0));
            missing++;
        }
    }
    free(covered);
    free(text);
    ck_assert_msg(missing == 0, "%s: %d figure(s) with no row in tests/check_claims.c (listed on stderr)", file,
                  missing);
}
END_TEST

/* The parser reads figures as the texts write them. */
START_TEST(figures_parse)
{
    char norm[64];
    ck_assert_double_eq_tol(parse_figure("1.37", norm, sizeof norm), 1.37, 1e-15);
    ck_assert_double_eq_tol(half_unit(norm), 0.005, 1e-15);
    ck_assert_double_eq_tol(parse_figure("100 000", norm, sizeof norm), 1e5, 1e-9);
    ck_assert_double_eq_tol(parse_figure("+38.4", norm, sizeof norm), 38.4, 1e-12);
    ck_assert_double_eq_tol(half_unit(norm), 0.05, 1e-15);
    ck_assert_double_eq_tol(parse_figure("−8.50", norm, sizeof norm), -8.5, 1e-12);
    ck_assert_double_eq_tol(half_unit(norm), 0.005, 1e-15);
    ck_assert_double_eq_tol(parse_figure("66 %", norm, sizeof norm), 66, 1e-12);
    ck_assert_double_eq_tol(half_unit(norm), 0.5, 1e-15);
    ck_assert_double_eq_tol(parse_figure("1e\\-9", norm, sizeof norm), 1e-9, 1e-24);
    ck_assert_double_eq_tol(parse_figure("3.3e-7", norm, sizeof norm), 3.3e-7, 1e-20);
    ck_assert_double_eq_tol(half_unit(norm), 0.05e-7, 1e-20);
    ck_assert_double_eq_tol(parse_figure("2√2", norm, sizeof norm), 2 * sqrt(2), 1e-15);
    ck_assert_double_eq_tol(parse_figure("√1.16", norm, sizeof norm), sqrt(1.16), 1e-15);
    ck_assert_double_eq_tol(parse_figure("10⁴", norm, sizeof norm), 1e4, 1e-9);
    ck_assert_double_eq_tol(parse_figure("3·10⁴", norm, sizeof norm), 3e4, 1e-9);
    ck_assert_double_eq_tol(parse_figure("²", norm, sizeof norm), 2, 1e-15);
    ck_assert_double_eq_tol(parse_figure("two thirds", norm, sizeof norm), 2.0 / 3, 1e-15);
    ck_assert(isnan(parse_figure("1.3x", norm, sizeof norm)));
    /* a rule that cannot fail would pass this */
    claim c = { "", "", zero, ROUNDED, 0, "", NULL };
    double tol;
    parse_figure("1.37", norm, sizeof norm);
    ck_assert(holds(&c, 1.37, 1.374, norm, &tol));
    ck_assert(!holds(&c, 1.37, 1.376, norm, &tol));
    c.kind = ATMOST;
    c.tol = 0.2;
    ck_assert(holds(&c, 0.7, 0.65, norm, &tol));
    ck_assert(!holds(&c, 0.7, 0.71, norm, &tol));
    ck_assert(!holds(&c, 0.7, 0.5, norm, &tol));
}
END_TEST

/* Every row's snippet is unique to its place: a snippet found twice in its
 * file could survive the edit of the figure it was written for. */
START_TEST(snippets_unique)
{
    char plain[1024], figure[128];
    split_snippet(claims[_i].snippet, plain, sizeof plain, figure, sizeof figure);
    char *text = text_of(claims[_i].file);
    const char *first = strstr(text, plain);
    int twice = first && strstr(first + 1, plain) != NULL;
    free(text);
    ck_assert_msg(!twice, "%s: \"%s\" occurs more than once; make the snippet longer", claims[_i].file, plain);
}
END_TEST

Suite *make_claims_suite(void);
Suite *make_claims_suite(void)
{
    Suite *s = suite_create("claims");
    TCase *tc = tcase_create("claims");
    int n = (int)(sizeof claims / sizeof claims[0]);
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, figures_parse);
    tcase_add_loop_test(tc, snippets_unique, 0, n);
    tcase_add_loop_test(tc, claim_holds, 0, n);
    tcase_add_loop_test(tc, every_figure_has_a_row, 0, (int)(sizeof guarded / sizeof guarded[0]));
    suite_add_tcase(s, tc);
    return s;
}
