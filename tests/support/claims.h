/* The claims test (tests/check_claims.c) in parts: what every part shares.
 * The rows live beside the measurements only they use (claims_lessons_a.c:
 * lessons 1-5; claims_lessons_b.c: lessons 6-10; claims_docs.c: the README,
 * the man page, docs/stability.md, the guide, the scenes' strings); runs,
 * pages and measurements more than one part uses are in claims_runs.c and
 * claims_shared.c; claims_events.c: event location's figures in
 * docs/performance.md and lesson 4; claims_methods.c: yoshida4's and the
 * Barnes-Hut tree's figures in docs/performance.md and docs/scenes.md;
 * claims_stiff.c: rodas4's. */
#ifndef SW_TEST_CLAIMS_H
#define SW_TEST_CLAIMS_H

#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "app/app.h"
#include "app/runner.h"
#include "lesson/lesson.h"
#include "measure/bench.h"
#include "grade/check.h"
#include "measure/stability.h"
#include "render/region.h"
#include "sim/truth.h"
#include "sim/watch.h"
#include "stepwise/stepwise.h"

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
#define L11 "lessons/11-fire-and-water.lesson"
#define GUIDE "lessons/README.md"
#define README "README.md"
#define MAN "docs/stepwise.1"
#define STAB "docs/stability.md"
#define INTEGRATORS "src/engine/integrators.c"
#define TWO_PI 6.283185307179586
#define STIFF "k=10000 c=10"
#define ECC "e=0.9"

typedef struct rk45_run { double accepted, rejected, evals, drift; } rk45_run;

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

/* The rows, in tables (one per part). */
extern const claim sw_claims_a[], sw_claims_b[], sw_claims_d[], sw_claims_e[], sw_claims_m[];
extern const size_t sw_claims_a_n, sw_claims_b_n, sw_claims_d_n, sw_claims_e_n, sw_claims_m_n;
/* claims_stages.c: the stage view's page in lesson 6 */
extern const claim sw_claims_s[];
extern const size_t sw_claims_s_n;
/* claims_rkn.c: the Runge-Kutta-Nystrom pair's figures (README, guide, table, lesson 9). */
extern const claim sw_claims_r[];
extern const size_t sw_claims_r_n;
/* claims_stiff.c: the stiff method rodas4's figures (lesson 9, performance, README). */
extern const claim sw_claims_k[];
extern const size_t sw_claims_k_n;
extern const claim sw_claims_o[]; /* claims_bench.c: the order rule in docs/performance.md */
extern const size_t sw_claims_o_n;

/* claims_lesson11.c: lesson 11's figures (fire, explosion, water). */
extern const claim sw_claims_l[];
extern const size_t sw_claims_l_n;
/* claims_fire.c: the fire scene's stability figures (docs/scenes.md). */
extern const claim sw_claims_f[];
extern const size_t sw_claims_f_n;
/* claims_rewind.c: how far back the rewind keys go (README, man page, architecture). */
extern const claim sw_claims_w[];
extern const size_t sw_claims_w_n;

/* Runs, pages and measurements (claims_runs.c). */
const sw_scene *cl_scene_p(const char *name, const char *sets, double *p);
double cl_param(const char *scene, const char *name);
const sw_integrator *cl_method(const char *name);
void cl_sim_init(sw_sim *s, const char *scene, const char *sets, const char *m, double dt);
void cl_steps_to(sw_sim *s, double T);
double cl_drift_at(const char *scene, const char *sets, const char *m, double dt, double T);
/* The drift at exactly t = T (the last step cut to land there: a page's @until T). */
double cl_drift_until(const char *scene, const char *sets, const char *m, double dt, double T);
double cl_time_drift_passes(const char *scene, const char *sets, const char *m, double dt, double level,
                                double T);
double cl_max_abs_drift(const char *scene, const char *sets, const char *m, double dt, double T);
double cl_blow_time(const char *scene, const char *sets, const char *m, double dt, double T);
sw_spectrum cl_spectrum0(const char *scene, const char *sets);
double cl_growth0(const char *scene, const char *sets, const char *m, double dt);
double cl_limit0(const char *scene, const char *sets, const char *m);
sw_stability_result cl_stability(const char *scene, const char *sets, const char *m);
void cl_lesson_page(sw_runner *r, sw_app *a, const char *file, const char *title);
void cl_page_free(sw_runner *r, sw_app *a);
void cl_act(sw_app *a, sw_action action, int arg);
double cl_page_ratio(const char *file, const char *title, const char *integrator, int k);
double cl_page_shown_ratio(const char *file, const char *title, const char *integrator, int k);
double cl_page_error(const char *file, const char *title, const char *m, double dt);
double cl_key_of(const char *name);
/* 1 when key picks the place-th method (1-based), name, in play. */
double cl_key_picks(int key, int place, const char *name);
double cl_page_dt_after(const char *file, const char *title, sw_action action, int k);
double cl_evals_per_step(const char *scene, const char *sets, const char *m, double dt, int n);
double cl_order_by_halving(const char *scene, const char *sets, const char *m, double dt);
double cl_vortex_radius_growth(const char *m, double dt, double T);
long cl_steps_for(const char *scene, const char *sets, const char *m, double dt, double T);

/* Measurements the parts share (claims_shared.c). */
double cl_l2_ratio2(void);
double cl_l4_ratio(void);
double cl_l5_k(void);
double cl_l5_c(void);
double cl_l5_m(void);
double cl_rk4_wdt(void);
double cl_verlet_wdt(void);
double cl_l7_verlet_theory(void);
double cl_l7_verlet_measured(void);
double cl_zero(void);
double cl_rounding(void);
double cl_l7_im_limit(void);
double cl_orbit_period(const char *sets);
double cl_two_orbits(void);
double cl_adaptive_per_step(const char *m);
double cl_l9_rk45_per_step(void);
double cl_dop853_per_step(void);
double cl_ord_dop853(void);
void cl_l9_adaptive(const char *m, double rtol, double atol, double *evals, double *error);
double cl_l9_rk45_error(void);
double cl_l9_rk45_error_over_rtol(void);
double cl_verlet_measured_wdt(void);
double cl_rk4_measured_wdt(void);
double cl_spring_omega(void);
double cl_rk4_damped_measured(void);
double cl_key_rk4(void);
double cl_key_rk45(void);
double cl_rk4_small_stretch(void);
/* claims_bench.c: rodas4 on the gyre (a sweep of seconds: the quick tier skips it) */
double cl_gyre_first_error(void);
double cl_gyre_slope_min(void);
double cl_gyre_slope_max(void);
/* Water's slow rows (claims_fire.c): Euler's measured limit, the dam break
 * against Martin & Moyce, the big dam's blow-up. */
double cl_water_euler_1s(void);
double cl_water_euler_8s(void);
double cl_dam_worst(void);
double cl_dam_ahead_least(void);
double cl_dam_ahead_most(void);
double cl_dam_behind_least(void);
double cl_dam_behind_most(void);
double cl_dam_default_nu(void);
double cl_big_dam_blowup(void);
double cl_big_dam_builds(void);
double cl_big_dam_build_every(void);
double cl_one(void);

#endif
