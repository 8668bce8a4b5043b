/* The live app without a terminal: keys to actions through the one table,
 * what the status and meter tell the student (checked against theory), the
 * clock, compare, and frames composed for any terminal size. */
#include <check.h>
#include <complex.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stepwise/stepwise.h"
#include "app/app.h"
#include "canvas_help.h"
#include "render/screen.h"

static void app_with(sw_app *a, const char *scene, const char *method, double dt, const char *set)
{
    const sw_scene *sc = sw_scene_find(scene);
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    sw_scene_defaults(sc, p);
    char sets[128];
    snprintf(sets, sizeof sets, "%s", set ? set : "");
    for (char *kv = strtok(sets, " "); kv; kv = strtok(NULL, " ")) /* "k=1 c=0": one at a time */
        ck_assert_msg(sw_scene_set(sc, p, kv, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_msg(sw_app_init(a, sc, p, method ? sw_integrator_find(method) : NULL, dt, err, sizeof err) == SW_OK,
                  "%s", err);
}

/* Every key of every control in the one list reaches that control through
 * sw_key_lookup in its context, with its place among the control's keys. */
START_TEST(key_table_drives_lookup)
{
    int n;
    const sw_control *k = sw_controls(&n);
    ck_assert_int_eq(n, SW_ACT_COUNT - 1);
    ck_assert_int_gt(n, 20);
    for (int i = 0; i < n; i++) {
        ck_assert_int_eq(k[i].action, i + 1);
        ck_assert_ptr_eq(sw_control_of(k[i].action), &k[i]);
        ck_assert_msg(k[i].help_keys || i > 0, "first row needs a label");
        for (int j = 0; k[i].keys[j]; j++) {
            const sw_control *c;
            int arg;
            if (k[i].keys[j] == SW_KEY_NONE)
                continue;
            ck_assert(sw_key_lookup(k[i].keys[j], k[i].context, &c, &arg));
            ck_assert_int_eq(c->action, k[i].action);
            ck_assert_int_eq(arg, j + 1);
        }
    }
    const sw_control *c;
    int arg;
    ck_assert(!sw_key_lookup('n', SW_CTX_PLAY, &c, &arg)); /* lesson keys only in lessons */
    ck_assert(sw_key_lookup(SW_KEY_UP, SW_CTX_PLAY | SW_CTX_PANEL, &c, &arg));
    ck_assert_int_eq(c->action, SW_ACT_PANEL_UP);
    ck_assert(sw_key_lookup('7', SW_CTX_PLAY, &c, &arg));
    ck_assert_int_eq(c->action, SW_ACT_PICK_METHOD);
    ck_assert_int_eq(arg, 7);
    ck_assert_str_eq(sw_action_name(SW_ACT_DT_HALVE), "halve dt");
}
END_TEST

/* Switching integrators mid-run starts the run again at t = 0 from the
 * scene's first state (so err is this method's alone) and says so; locked
 * actions are refused. */
START_TEST(switch_keeps_state)
{
    sw_app a;
    app_with(&a, "spring", "euler", 0.01, NULL);
    double x0 = a.sims[0].sys.y[0];
    sw_app_advance(&a, 0.5, 100000);
    ck_assert(a.sims[0].t > 0 && a.sims[0].sys.y[0] != x0);
    ck_assert_int_eq(sw_app_key(&a, 'i', 0), 1);
    ck_assert_str_eq(a.sims[0].method->name, "symplectic-euler");
    ck_assert_double_eq(a.sims[0].t, 0);
    ck_assert_double_eq(a.sims[0].sys.y[0], x0);
    ck_assert_ptr_nonnull(strstr(a.message, "restarted at t = 0"));
    ck_assert_int_eq(sw_app_key(&a, '5', 0), 1);
    ck_assert_str_eq(a.sims[0].method->name, "rk4");
    sw_app_key(&a, 'I', 0);
    ck_assert_str_eq(a.sims[0].method->name, "heun");
    a.locked = SW_LOCK_INTEGRATOR;
    ck_assert_int_eq(sw_app_key(&a, 'i', 0), 0);
    ck_assert_str_eq(a.sims[0].method->name, "heun");
    ck_assert_ptr_nonnull(strstr(a.message, "locked"));
    sw_app_free(&a);
    /* a flow field skips the methods that need masses */
    app_with(&a, "vortex", "euler", 0.05, "n=10");
    sw_app_key(&a, 'i', 0);
    ck_assert_str_eq(a.sims[0].method->name, "midpoint");
    ck_assert_int_eq(sw_app_key(&a, '6', 0), 0);
    ck_assert_ptr_nonnull(strstr(a.message, "first-order"));
    sw_app_free(&a);
}
END_TEST

/* Halving dt reports the error ratio at the report time: about 2 for Euler
 * (global error O(dt)), 4 for midpoint, 16 for RK4 (±10%: the steps are in
 * each method's asymptotic range). */
START_TEST(halving_dt_measures_order)
{
    struct { const char *scene, *method; double dt, ratio; } cases[] = {
        { "vortex", "euler", 0.01, 2 }, { "vortex", "midpoint", 0.05, 4 }, { "spring", "rk4", 0.02, 16 },
    };
    for (int i = 0; i < 3; i++) {
        sw_app a;
        app_with(&a, cases[i].scene, cases[i].method, cases[i].dt, NULL);
        ck_assert_int_eq(sw_app_key(&a, '-', 0), 1);
        sw_app_dt_wait(&a); /* the vortex's runs go to a worker */
        ck_assert_double_eq(a.dt, cases[i].dt / 2);
        ck_assert_msg(fabs(a.error_ratio / cases[i].ratio - 1) < 0.1, "%s/%s: ratio %g, expected %g",
                      cases[i].scene, cases[i].method, a.error_ratio, cases[i].ratio);
        ck_assert_ptr_nonnull(strstr(a.message, "ratio"));
        sw_app_free(&a);
    }
}
END_TEST

/* The dt message measures with the run's own event mode (lesson 4 page 5):
 * the drag-free bounce under rk4 is first order with its contacts stepped
 * over (the error falls about 2-fold per halving, as for any first-order
 * error) and exact to rounding with them located, which the message says
 * instead of fitting an order to rounding. */
START_TEST(dt_message_uses_event_mode)
{
    sw_app a;
    app_with(&a, "bounce", "rk4", 0.01, NULL);
    sw_app_set_events(&a, SW_EVENTS_STEP);
    double stepped = sw_app_measure(&a, a.sims[0].method, 0.01);
    sw_app_set_events(&a, SW_EVENTS_LOCATE);
    double located = sw_app_measure(&a, a.sims[0].method, 0.01);
    ck_assert_msg(stepped > 1e-4 && located < 1e-12, "stepped over %g, located %g", stepped, located);
    ck_assert_int_eq(sw_app_key(&a, '-', 0), 1);
    ck_assert_msg(strstr(a.message, "at rounding level") && !strstr(a.message, "order ~"), "%s", a.message);
    sw_app_free(&a);
}
END_TEST

/* The meter's growth per step against theory: for Runge-Kutta methods the
 * stiffest mode λ = -γ + iω_d is multiplied by |R(hλ)| each step, R the
 * method's stability polynomial (1 + z; 1 + z + z²/2; Taylor to z⁴). */
START_TEST(meter_growth_matches_theory)
{
    const char *methods[] = { "euler", "midpoint", "heun", "rk4" };
    const char *sets[] = { "c=0.5", "c=0" };
    for (int s = 0; s < 2; s++)
        for (int m = 0; m < 4; m++) {
            sw_app a;
            app_with(&a, "spring", methods[m], 0.05, sets[s]);
            const sw_scene *sc = a.scene;
            double k = a.p[sw_scene_param_index(sc, "k")], mass = a.p[sw_scene_param_index(sc, "m")];
            double c = a.p[sw_scene_param_index(sc, "c")];
            sw_app_meter mt;
            ck_assert_int_eq(sw_app_stability(&a, &mt), 1);
            double growth = mt.growth, wdt = mt.stiff * a.dt;
            double g = c / (2 * mass), wd = sqrt(k / mass - g * g);
            double complex z = 0.05 * (-g + I * wd), r = 1 + z;
            if (m == 1 || m == 2)
                r += z * z / 2;
            if (m == 3)
                r += z * z / 2 + z * z * z / 6 + z * z * z * z / 24;
            ck_assert_msg(fabs(growth - cabs(r)) < 1e-9, "%s %s: growth %.12g, theory %.12g", methods[m], sets[s],
                          growth, cabs(r));
            ck_assert_double_eq_tol(wdt, sqrt(k / mass) * 0.05, 1e-15);
            sw_app_free(&a);
        }
}
END_TEST

/* The live watch judges only what the stability lab can measure: on the
 * river (no energy, no closed form) particles drift away from the origin,
 * |y|² grows, and that is the flow, not the method: no "growth" after a
 * long run. On the vortex under Euler (|y|² grows 1 + (ωΔt)² a step) the
 * same watch does say so. */
START_TEST(watch_only_where_judged)
{
    sw_app a;
    app_with(&a, "river", "rk4", 0.05, NULL);
    a.speed = 64;
    while (a.sims[0].t < 100)
        sw_app_advance(&a, 1.0, 100000);
    ck_assert_int_eq(a.watch.verdict, SW_WATCH_STEADY);
    sw_app_free(&a);
    app_with(&a, "vortex", "euler", 0.1, NULL);
    a.speed = 64;
    while (a.sims[0].t < 100 && a.watch.verdict == SW_WATCH_STEADY)
        sw_app_advance(&a, 1.0, 100000);
    ck_assert_int_ne(a.watch.verdict, SW_WATCH_STEADY);
    sw_app_free(&a);
}
END_TEST

/* The clock: one second of wall time at speed 1 is one simulated second in
 * whole steps; a step cap gives slow motion instead of falling behind forever. */
START_TEST(clock_and_slow_motion)
{
    sw_app a;
    app_with(&a, "orbit", "verlet", 0.01, NULL);
    for (int f = 0; f < 60; f++)
        sw_app_advance(&a, 1.0 / 60, 100000);
    ck_assert_int_eq(a.sims[0].steps, 100);
    ck_assert_double_eq_tol(a.sims[0].t, 1.0, 1e-12);
    ck_assert_double_eq(a.slowmo, 1.0);
    a.speed = 4;
    sw_app_advance(&a, 1.0, 100); /* asks for 400 steps, may take 100 */
    ck_assert_int_eq(a.sims[0].steps, 200);
    ck_assert_double_eq_tol(a.slowmo, 4.0, 1e-9);
    a.paused = 1;
    sw_app_advance(&a, 1.0, 100);
    ck_assert_int_eq(a.sims[0].steps, 200);
    sw_app_free(&a);
}
END_TEST

/* One rule for the run's state (issue 37): only space runs it; every key
 * that starts the run again at t = 0 (r, + and -, a method by i or by its
 * number, compare, a parameter from the panel) leaves it paused, so a page's "then
 * press space" always starts it; space pauses and runs; '.' pauses. The
 * meter line says which, PAUSED or running. */
START_TEST(one_rule_for_the_run)
{
    sw_app a;
    app_with(&a, "spring", "euler", 0.01, NULL);
    static const int keys[] = { 'r', '+', '-', 'i', '3', 'c', SW_KEY_RIGHT };
    for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++) {
        if (keys[k] == SW_KEY_RIGHT)
            sw_app_key(&a, 'p', 0); /* the panel: Right raises the parameter chosen */
        a.paused = 0;
        sw_app_advance(&a, 0.5, 100000);
        ck_assert_double_gt(a.sims[0].t, 0);
        sw_app_key(&a, keys[k], 0);
        ck_assert_msg(a.paused && a.sims[0].t == 0, "key %d: t = %g, %s", keys[k], a.sims[0].t,
                      a.paused ? "paused" : "running");
        sw_frame fr;
        char err[SW_ERRLEN];
        int clipped;
        ck_assert_int_eq(sw_frame_init(&fr, err, sizeof err), SW_OK);
        char *text = ct_compose(&fr, &a, NULL, 80, 24, &clipped);
        ck_assert_msg(strstr(text, "PAUSED") != NULL, "key %d: the screen does not say PAUSED:\n%s", keys[k], text);
        free(text);
        sw_frame_free(&fr);
        if (keys[k] == SW_KEY_RIGHT)
            sw_app_key(&a, SW_KEY_ESC, 0);
        sw_app_key(&a, ' ', 0);
        ck_assert(!a.paused);
    }
    sw_app_key(&a, ' ', 0);
    ck_assert(a.paused);
    sw_app_key(&a, ' ', 0);
    sw_app_key(&a, '.', 0);
    ck_assert(a.paused);
    sw_app_free(&a);
}
END_TEST

/* Compare runs three methods from the same state; a blow-up freezes only
 * the one that blew up. */
START_TEST(compare_race)
{
    sw_app a;
    app_with(&a, "spring", "euler", 0.3, "c=0");
    sw_app_key(&a, 'c', 0);
    sw_app_key(&a, ' ', 0); /* (compare restarts the runs paused) */
    ck_assert_int_eq(a.nsims, 3);
    ck_assert_str_ne(a.sims[1].method->name, "euler");
    ck_assert_str_ne(a.sims[2].method->name, "euler");
    ck_assert_str_ne(a.sims[1].method->name, a.sims[2].method->name);
    for (int f = 0; f < 600 && !a.sims[0].blown; f++)
        sw_app_advance(&a, 1.0, 100000);
    ck_assert_int_eq(a.sims[0].blown, 1); /* euler: energy x1.9 per step at w dt = 0.95 */
    ck_assert_int_eq(a.sims[1].blown, 0);
    char line[512];
    sw_app_status(&a, 0, line, sizeof line);
    ck_assert_ptr_nonnull(strstr(line, "BLOWN UP"));
    sw_app_key(&a, 'r', 0);
    ck_assert_int_eq(a.sims[0].blown, 0);
    ck_assert_double_eq(a.sims[0].t, 0);
    sw_app_free(&a);
}
END_TEST

/* Before the first step nothing has been integrated: the error reads 0,
 * not the truth's own rounding (lesson 9's orbit read "err 1e-34 m"). */
START_TEST(no_error_before_a_step)
{
    sw_app a;
    app_with(&a, "orbit", "rk4", 0.05, NULL);
    char line[512];
    sw_app_status(&a, 0, line, sizeof line);
    ck_assert_msg(strstr(line, "position error 0 m") != NULL, "%s", line);
    sw_app_free(&a);
}
END_TEST

/* A galaxy summed exactly (n = 100) shows its energy plainly; one whose
 * energy is the tree's (5000 stars, 5001 bodies) says it is approximate
 * and how far off the drift can be: the sim's bound, as the line prints
 * it. Its meter says why it has no spectrum (12.5e6 pairs, past the
 * 2^21 it multiplies live), and the app starts no job for it. */
START_TEST(approximate_energy_said)
{
    sw_app a;
    char line[512], bound[32];
    app_with(&a, "galaxy", "verlet", 0.01, NULL);
    sw_app_status(&a, 0, line, sizeof line);
    ck_assert_msg(strstr(line, "energy +0%") && !strstr(line, "≈"), "%s", line);
    sw_app_free(&a);
    app_with(&a, "galaxy", "verlet", 0.01, "n=5000 theta=0.5");
    ck_assert_int_eq(sw_sim_step(&a.sims[0]), 0);
    double e = sw_sim_energy_drift_error(&a.sims[0]);
    ck_assert(e > 0);
    snprintf(bound, sizeof bound, "±%.2g%%", e);
    sw_app_status(&a, 0, line, sizeof line);
    ck_assert_msg(strstr(line, "energy ≈") && strstr(line, bound), "%s (bound %s)", line, bound);
    ck_assert_int_eq(sw_app_meter_out_of_reach(&a), 5001L * 5000 / 2);
    sw_field f[8];
    int warn, n = sw_app_meter_fields(&a, f, 8, &warn);
    ck_assert_int_eq(n, 1);
    ck_assert_msg(strstr(f[0].full, "not measured") && strstr(f[0].full, "1.3e+07 pairs"), "%s", f[0].full);
    sw_app_meter_refresh(&a);
    ck_assert(!sw_app_meter_pending(&a));
    sw_app_free(&a);
}
END_TEST

/* The graph series stays bounded however long the run. */
START_TEST(graph_bounded)
{
    sw_app a;
    app_with(&a, "orbit", "rk4", 0.05, NULL);
    a.graph = 1;
    for (int f = 0; f < 20000; f++)
        sw_app_advance(&a, 1.0 / 60, 10);
    ck_assert_int_le(a.series[0].len, SW_APP_GRAPH);
    ck_assert_int_gt(a.series[0].len, SW_APP_GRAPH / 4);
    ck_assert_double_gt(a.series[0].t[a.series[0].len - 1], 300.0);
    sw_app_free(&a);
}
END_TEST

static char *compose_text(sw_app *a, int cols, int rows)
{
    sw_frame f;
    sw_screen scr;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_frame_init(&f, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_screen_init(&scr, cols, rows, err, sizeof err), SW_OK);
    sw_frame_push_trails(&f, a);
    sw_frame_compose(&f, a, NULL, &scr);
    size_t cap = (size_t)cols * (size_t)rows * 4 + (size_t)rows + 1;
    char *text = malloc(cap);
    ck_assert_uint_gt(sw_screen_to_text(&scr, text, cap), 0);
    sw_screen_free(&scr);
    sw_frame_free(&f);
    return text;
}

/* Frames: the status names method and dt; a tiny terminal gets a message;
 * a blown-up state (NaN, inf) reaches the picture and the banner safely. */
/* An adaptive method's status line at 80 columns keeps what lesson 9
 * compares: its evaluations and its accepted and rejected steps (a
 * newcomer could not check the pages' evaluation counts when evals was
 * the first field dropped). */
START_TEST(adaptive_status_keeps_evals)
{
    sw_app a;
    app_with(&a, "orbit", "rk45", 0.4, NULL);
    for (int f = 0; f < 20; f++)
        sw_app_advance(&a, 0.1, 1000);
    char *t = compose_text(&a, 80, 24);
    ck_assert_msg(strstr(t, "evals ") && strstr(t, "acc ") && strstr(t, " rej "), "%s", t);
    free(t);
    sw_app_free(&a);
}
END_TEST

START_TEST(frames_compose)
{
    sw_app a;
    app_with(&a, "spring", "rk4", 0.02, NULL);
    char *t = compose_text(&a, 80, 24);
    ck_assert_ptr_nonnull(strstr(t, "spring  rk4  dt=0.02  t=0.000"));
    /* The scene pane is the 20 rows above the status block (one sim: 4
     * rows), which holds the legend's letters; its last row is the
     * picture's legend ("o rk4  # anchor  - spring"): look for the anchor
     * and the mass in the 19 above it only. */
    int anchor = 0, mass = 0;
    const char *line = t;
    for (int row = 0; row < 19 && line; row++) {
        const char *nl = strchr(line, '\n');
        size_t len = nl ? (size_t)(nl - line) : strlen(line);
        anchor += memchr(line, '#', len) != NULL;
        mass += memchr(line, 'o', len) != NULL;
        line = nl ? nl + 1 : NULL;
    }
    ck_assert_int_eq(anchor, 1);
    ck_assert_int_eq(mass, 1);
    free(t);
    t = compose_text(&a, 40, 10);
    ck_assert_ptr_nonnull(strstr(t, "terminal too small: 40x10"));
    free(t);
    a.help = 1;
    t = compose_text(&a, 100, 40);
    ck_assert_ptr_nonnull(strstr(t, "halve dt"));
    free(t);
    sw_app_free(&a);

    app_with(&a, "chain", "euler", 0.2, NULL);
    a.trails = a.ghost = a.graph = 1;
    sw_app_key(&a, 'c', 0);
    sw_app_key(&a, ' ', 0); /* (compare restarts the runs paused) */
    for (int f = 0; f < 200 && !a.sims[0].blown; f++)
        sw_app_advance(&a, 1.0, 1000);
    ck_assert(a.sims[0].blown);
    a.sims[1].sys.y[0] = NAN; /* non-finite values must reach the canvas harmlessly */
    a.sims[1].sys.y[1] = INFINITY;
    sw_sim_state_changed(&a.sims[1]);
    a.braille = 1;
    t = compose_text(&a, 120, 40);
    ck_assert_ptr_nonnull(strstr(t, "BLOWN UP at step"));
    free(t);
    sw_app_free(&a);
}
END_TEST


/* The meter's word never contradicts the number beside it: the word is
 * decided from rho and the digits follow (values just above and below 1
 * print with more digits; within SW_TRUTH_NEUTRAL of 1 it reads neutral). */
START_TEST(meter_word_agrees_with_number)
{
    static const struct { double rho; int grows, slow; const char *word; int sign; } cases[] = {
        { 1 + 4e-7, 1, 0, "grows", 1 },            /* visible over a long horizon, 1.000000 at 6 digits */
        { 1 + 4e-9, 0, 1, "grows slowly", 1 },
        { 1 - 3e-8, 0, 0, "decays", -1 },
        { 1 - 3e-10, 0, -1, "decays slowly", -1 }, /* too little to see: said, and the digits still below 1 */
        { 0.996995, 0, 0, "decays", -1 },
        { 1.0, 0, 0, "neutral", 0 },
        { 1 + 1e-13, 0, 0, "neutral", 0 },         /* within SW_TRUTH_NEUTRAL */
        { 1.5, 1, 0, "grows", 1 },
        { 2.573751923687954, 0, 0, "grows", 1 },   /* the fastest mode's factor, from rho alone: six digits */
        { 1 + 1e-9, 0, 0, "grows", 1 },            /* from rho alone, beyond SW_TRUTH_NEUTRAL */
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char num[40];
        const char *w = sw_app_growth_text(cases[i].rho, cases[i].grows, cases[i].slow, num, sizeof num);
        ck_assert_str_eq(w, cases[i].word);
        ck_assert_msg(strncmp(num, "×", strlen("×")) == 0, "%s", num);
        double shown = strtod(num + strlen("×"), NULL);
        int sign = shown > 1 ? 1 : shown < 1 ? -1 : 0;
        ck_assert_msg(sign == cases[i].sign, "rho %.17g printed %s beside '%s'", cases[i].rho, num, w);
        ck_assert_int_ge((int)strlen(num), (int)strlen("×1.000000"));
        /* a factor 1e-6 or more from 1 needs no more than the six digits */
        if (fabs(cases[i].rho - 1) >= 1e-6)
            ck_assert_msg(strlen(num) == strlen("×1.000000"), "rho %.17g printed %s", cases[i].rho, num);
    }
}
END_TEST

static int fields_have(const sw_field *f, int n, const char *what)
{
    for (int i = 0; i < n; i++)
        if (strstr(f[i].full, what))
            return 1;
    return 0;
}

/* The meter on an undamped spring (ω = 1) under Verlet, whose limit in ω·Δt
 * is 2 and which is neutral below it (its map has |eigenvalues| = 1 there):
 * just below the limit it reads neutral, just above it grows; the labels
 * say stiffness·dt of limit. With damping the limit shown is the damped
 * one and RK4's undamped 2√2 (its stability interval on the imaginary
 * axis, Hairer & Wanner IV.2) is said beside it. */
START_TEST(meter_words_at_the_limit)
{
    sw_field f[8];
    int warn, n;
    sw_app a;
    app_with(&a, "spring", "verlet", 1.99, "k=1 c=0");
    n = sw_app_meter_fields(&a, f, 8, &warn);
    ck_assert(fields_have(f, n, "stiffness·dt 1.99 of limit 2"));
    ck_assert_msg(fields_have(f, n, "per step: neutral"), "%s", f[n - 1].full);
    ck_assert(!fields_have(f, n, "undamped"));
    sw_app_free(&a);
    app_with(&a, "spring", "verlet", 2.01, "k=1 c=0");
    n = sw_app_meter_fields(&a, f, 8, &warn);
    ck_assert_msg(fields_have(f, n, "per step: GROWS"), "%s", f[n - 1].full);
    ck_assert(warn);
    sw_app_free(&a);
    app_with(&a, "spring", "rk4", 0.4, "k=1 c=0.1");
    n = sw_app_meter_fields(&a, f, 8, &warn);
    ck_assert(fields_have(f, n, "per step: decays") && !fields_have(f, n, "decays slowly"));
    char want[64];
    snprintf(want, sizeof want, "%.3g undamped", 2 * sqrt(2.0));
    ck_assert_msg(fields_have(f, n, want), "no '%s' in %s / %s", want, f[0].full, f[1].full);
    sw_app_free(&a);
    /* RK4 on the vortex at its default dt = 0.05: it decays by (ωΔt)^6/144
     * a step (|R(iy)|² = 1 - y^6/72 + y^8/576 for RK4), about 1e-10, far
     * under 1% over the horizon: "decays slowly", not "decays" */
    app_with(&a, "vortex", "rk4", 0.05, NULL);
    n = sw_app_meter_fields(&a, f, 8, &warn);
    ck_assert_msg(fields_have(f, n, "decays slowly"), "%s", f[n - 1].full);
    sw_app_free(&a);
}
END_TEST

/* err is the largest position error in metres against the truth at this
 * time (m: velocities, m/s), computed here from sw_truth_state directly;
 * a dt change mid-run starts the run again, so err starts again from 0. */
START_TEST(err_is_position_in_metres_and_restarts)
{
    sw_app a;
    app_with(&a, "spring", "euler", 0.02, NULL);
    sw_app_advance(&a, 1.0, 100000);
    const sw_sim *s = &a.sims[0];
    double truth[64], pos = 0, vel = 0;
    int half = s->sys.ode->dim / 2;
    ck_assert_int_le(s->sys.ode->dim, 64);
    ck_assert_int_eq(sw_truth_state(a.scene, a.p, s->t, truth), 0);
    for (int k = 0; k < half; k++) {
        pos = fmax(pos, fabs(s->sys.y[k] - truth[k]));
        vel = fmax(vel, fabs(s->sys.y[half + k] - truth[half + k]));
    }
    ck_assert(pos > 0 && vel > 0 && pos != vel);
    /* the truth here is the closed form: the same to rounding */
    ck_assert_double_eq_tol(sw_app_error(&a, 0), pos, 1e-12 * fmax(1, pos));
    sw_field f[SW_STATUS_FIELDS];
    int n = sw_app_status_fields(&a, 0, f, SW_STATUS_FIELDS);
    ck_assert(fields_have(f, n, "position error") && fields_have(f, n, " m"));
    ck_assert_int_eq(sw_app_key(&a, 'm', 0), 1);
    ck_assert_double_eq_tol(sw_app_error(&a, 0), vel, 1e-12 * fmax(1, vel));
    n = sw_app_status_fields(&a, 0, f, SW_STATUS_FIELDS);
    ck_assert(fields_have(f, n, "velocity error") && fields_have(f, n, " m/s"));
    sw_app_key(&a, 'm', 0);
    ck_assert_int_eq(sw_app_key(&a, '-', 0), 1);
    ck_assert_double_eq(a.sims[0].t, 0);
    ck_assert_double_eq(sw_app_error(&a, 0), 0);
    ck_assert_ptr_nonnull(strstr(a.message, "position error"));
    ck_assert_ptr_nonnull(strstr(a.message, "restarted at t = 0"));
    sw_app_free(&a);
    /* an adaptive method's dt only caps its steps: no order is read from it */
    app_with(&a, "spring", "rk45", 0.1, NULL);
    ck_assert_int_eq(sw_app_key(&a, '+', 0), 1);
    ck_assert_msg(strstr(a.message, "the tolerances set the error, not dt"), "%s", a.message);
    ck_assert(isnan(a.error_ratio));
    sw_app_free(&a);
}
END_TEST

/* w measures on a worker: the key returns at once, the runs step on while
 * it measures, and the report is taken when it is done; a new scene while
 * it measures stops it (nothing leaks: the sanitizer and valgrind passes). */
START_TEST(workprec_sweep_beside_the_picture)
{
    sw_app a;
    app_with(&a, "chain", "rk4", 0.01, NULL);
    ck_assert_int_eq(sw_app_key(&a, 'w', 0), 1);
    ck_assert_int_eq(a.workprec, 1);
    ck_assert(a.sweep != NULL || a.bench != NULL);
    double t0 = a.sims[0].t;
    sw_app_advance(&a, 0.05, 1000);
    ck_assert_double_gt(a.sims[0].t, t0); /* stepping does not wait for it */
    sw_app_sweep_wait(&a);
    ck_assert_ptr_null(a.sweep);
    ck_assert_ptr_nonnull(a.bench);
    ck_assert_ptr_nonnull(strstr(a.message, "work-precision: error against derivative evaluations"));
    sw_app_free(&a);
    app_with(&a, "chain", "rk4", 0.01, NULL);
    ck_assert_int_eq(sw_app_key(&a, 'w', 0), 1);
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_app_set_scene(&a, sw_scene_find("spring"), NULL, err, sizeof err), SW_OK);
    ck_assert_ptr_null(a.sweep);
    ck_assert_ptr_null(a.bench);
    ck_assert_int_eq(a.workprec, 0);
    sw_app_free(&a);
}
END_TEST

/* A run at its scene's default step follows the default when the
 * parameters change (water's step follows n); a step the student chose
 * stays. The expected steps are sw_scene_dt's, whose own test
 * (check_water) holds them under the stability limit. */
START_TEST(default_step_follows_the_parameters)
{
    const sw_scene *sc = sw_scene_find("water");
    sw_app a;
    app_with(&a, "water", "symplectic-euler", 0, NULL);
    ck_assert_double_eq(a.dt, sw_scene_dt(sc, a.p));
    ck_assert_double_eq(sw_scene_dt(sc, NULL), a.dt); /* NULL: the defaults */
    double p[SW_MAX_PARAMS];
    memcpy(p, a.p, sizeof p);
    int n = sw_scene_param_index(sc, "n");
    ck_assert_int_ge(n, 0);
    p[n] = 10000;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_app_set_scene(&a, sc, p, err, sizeof err), SW_OK);
    ck_assert_double_eq(a.dt, sw_scene_dt(sc, p));
    ck_assert_double_lt(a.dt, sc->dt);
    a.dt = 1e-4; /* the student's own step */
    p[n] = 2000;
    ck_assert_int_eq(sw_app_set_scene(&a, sc, p, err, sizeof err), SW_OK);
    ck_assert_double_eq(a.dt, 1e-4);
    sw_app_free(&a);
}
END_TEST

/* A key press spends at most a->work_key state evaluations: below what the
 * gyre's reference costs (its particles × DP8's steps to the report time,
 * about 2.4e6), the work-precision key and the Δt measurement both say so
 * with the budget and leave nothing half-built. */
START_TEST(key_press_keeps_to_its_budget)
{
    sw_app a;
    app_with(&a, "gyre", "rk4", 0.05, NULL);
    a.work_key = 1e6;
    ck_assert_int_eq(sw_app_key(&a, 'w', 0), 0);
    ck_assert_int_eq(a.workprec, 0);
    ck_assert_ptr_null(a.bench);
    ck_assert_msg(strstr(a.message, "no work-precision plot") && strstr(a.message, "over the 4e+06"), "%s", a.message);
    ck_assert_int_eq(sw_app_key(&a, '-', 0), 1);
    ck_assert_msg(strstr(a.message, "over the 1e+06 a key press may spend"), "%s", a.message);
    ck_assert(isnan(a.error_ratio));
    sw_app_free(&a);
}
END_TEST

/* The keys that may work for a key press's budget name what they do, for
 * the screen to show before it: the work-precision key while no sweep is
 * kept, the Δt keys while their runs stay on the picture's thread, u when
 * there is a stop time; never a quick key, nor one whose work goes to a
 * worker (the picture runs on: nothing to wait for). */
START_TEST(slow_keys_say_so_first)
{
    sw_app a;
    app_with(&a, "spring", "rk4", 0.05, NULL);
    ck_assert_ptr_null(sw_app_key_notice(&a, 'w', 0)); /* measured on a worker: no wait to announce */
    ck_assert_ptr_nonnull(sw_app_key_notice(&a, '-', 0));
    ck_assert_ptr_nonnull(sw_app_key_notice(&a, '+', 0));
    a.work_inline = 0; /* every Δt measurement on the worker */
    ck_assert_ptr_null(sw_app_key_notice(&a, '-', 0));
    a.work_inline = SW_APP_WORK_INLINE;
    ck_assert_ptr_null(sw_app_key_notice(&a, 'u', 0));
    ck_assert_ptr_null(sw_app_key_notice(&a, 'g', 0));
    ck_assert_ptr_null(sw_app_key_notice(&a, 'n', 0)); /* a lesson's key, outside a lesson */
    sw_app_set_until(&a, 2);
    ck_assert_ptr_nonnull(sw_app_key_notice(&a, 'u', 0));
    ck_assert_int_eq(sw_app_key(&a, 'w', 0), 1);
    sw_app_sweep_wait(&a);
    ck_assert_ptr_nonnull(a.bench);
    ck_assert_ptr_null(sw_app_key_notice(&a, 'w', 0)); /* the kept sweep: at once */
    sw_app_free(&a);
}
END_TEST

/* The parameter panel's Left and Right walk one ladder (1-2-5 per decade)
 * both ways and reach every damping the lessons set (c = 0.5, 10, 200,
 * 5000) from the default and from each other; Left from the ladder's
 * floor gives 0 and Right from 0 the floor (issue 37: Left halved 200 to
 * 100 to 0, Right from 0 gave 100, so 10 and 0.5 were out of reach). */
START_TEST(panel_reaches_lesson_values)
{
    sw_app a;
    app_with(&a, "spring", NULL, 0.01, "c=200");
    const sw_scene *sc = a.scene;
    int ci = -1;
    for (int i = 0; i < sc->nparams; i++)
        if (strcmp(sc->params[i].name, "c") == 0)
            ci = i;
    ck_assert_int_ge(ci, 0);
    sw_app_apply(&a, SW_ACT_PANEL, 0);
    a.param_sel = ci;
    static const double down[] = { 100, 50, 20, 10, 5, 2, 1, 0.5 };
    for (size_t k = 0; k < sizeof down / sizeof down[0]; k++) {
        sw_app_apply(&a, SW_ACT_PANEL_DEC, 0);
        ck_assert_msg(a.p[ci] == down[k], "Left %zu: c = %g, not %g", k + 1, a.p[ci], down[k]);
    }
    static const double up[] = { 1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000 };
    for (size_t k = 0; k < sizeof up / sizeof up[0]; k++) {
        sw_app_apply(&a, SW_ACT_PANEL_INC, 0);
        ck_assert_msg(a.p[ci] == up[k], "Right %zu: c = %g, not %g", k + 1, a.p[ci], up[k]);
    }
    /* down to the floor (a millionth of the range: 0.1), then 0, and back */
    while (a.p[ci] > 0.1)
        sw_app_apply(&a, SW_ACT_PANEL_DEC, 0);
    ck_assert_double_eq(a.p[ci], 0.1);
    sw_app_apply(&a, SW_ACT_PANEL_DEC, 0);
    ck_assert_double_eq(a.p[ci], 0);
    sw_app_apply(&a, SW_ACT_PANEL_INC, 0);
    ck_assert_double_eq(a.p[ci], 0.1);
    sw_app_free(&a);
}
END_TEST

Suite *make_app_suite(void);
/* A plugin's label is its author's text: the message that names it on
 * switching shows a right-to-left override, an isolate and a zero-width
 * space escaped (util/escape.h), never raw, so it cannot show "RK4
 * password" backwards or hide a word on the student's screen. */
START_TEST(method_label_escaped)
{
    sw_app a;
    app_with(&a, "spring", "euler", 0.01, NULL);
    sw_integrator odd = *sw_integrator_find("euler");
    odd.label = "RK4 \u202Edrowssap\u202C \u2066x\u2069 zero\u200Bwidth";
    ck_assert_int_eq(sw_app_set_method(&a, &odd), SW_OK);
    ck_assert_msg(strstr(a.message, "(RK4 \\xe2\\x80\\xaedrowssap\\xe2\\x80\\xac \\xe2\\x81\\xa6x"
                                    "\\xe2\\x81\\xa9 zero\\xe2\\x80\\x8bwidth)"), "%s", a.message);
    for (const char *p = a.message; *p; p++)
        ck_assert_msg((unsigned char)*p < 0x80, "a raw byte 0x%02x in '%s'", (unsigned char)*p, a.message);
    char *t = compose_text(&a, 120, 30);
    ck_assert_ptr_nonnull(strstr(t, "\\xe2\\x80\\xae"));
    ck_assert_ptr_null(strstr(t, "\u202E"));
    free(t);
    ck_assert_int_eq(sw_app_set_method(&a, sw_integrator_find("euler")), SW_OK);
    sw_app_free(&a);
}
END_TEST

Suite *make_app_suite(void)
{
    Suite *s = suite_create("app");
    TCase *tc = tcase_create("model");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, key_table_drives_lookup);
    tcase_add_test(tc, one_rule_for_the_run);
    tcase_add_test(tc, switch_keeps_state);
    tcase_add_test(tc, method_label_escaped);
    tcase_add_test(tc, meter_word_agrees_with_number);
    tcase_add_test(tc, meter_words_at_the_limit);
    tcase_add_test(tc, err_is_position_in_metres_and_restarts);
    tcase_add_test(tc, halving_dt_measures_order);
    tcase_add_test(tc, dt_message_uses_event_mode);
    tcase_add_test(tc, meter_growth_matches_theory);
    tcase_add_test(tc, watch_only_where_judged);
    tcase_add_test(tc, clock_and_slow_motion);
    tcase_add_test(tc, compare_race);
    tcase_add_test(tc, no_error_before_a_step);
    tcase_add_test(tc, approximate_energy_said);
    tcase_add_test(tc, graph_bounded);
    tcase_add_test(tc, frames_compose);
    tcase_add_test(tc, adaptive_status_keeps_evals);
    tcase_add_test(tc, key_press_keeps_to_its_budget);
    tcase_add_test(tc, workprec_sweep_beside_the_picture);
    tcase_add_test(tc, default_step_follows_the_parameters);
    tcase_add_test(tc, slow_keys_say_so_first);
    tcase_add_test(tc, panel_reaches_lesson_values);
    suite_add_tcase(s, tc);
    return s;
}
