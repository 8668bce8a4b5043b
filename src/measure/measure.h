/* What a method does, measured rather than claimed: its order of accuracy
 * and its stability limit on the undamped spring, where the exact solution
 * and the theory (x'' = -ω²x) are known. Used to put a plugin's measured
 * figures beside the ones it claims (check, try). */
#ifndef SW_MEASURE_MEASURE_H
#define SW_MEASURE_MEASURE_H

#include <stddef.h>

#include "measure/bench.h"
#include "stepwise/sim.h"

/* The measuring problem: spring with c = 0 (k 10, m 1: ω = √10), to t = 2. */
#define SW_MEASURE_T 2.0
/* The sweep: from ω·dt = 0.51 (where an eighth-order error is still well
 * above round-off) down to dt = 0.16/2^11 = 7.8e-5 (where a first-order
 * one is below 1e-2 of the state for three halvings); stopped once four
 * points carry an order. */
#define SW_MEASURE_DT0 0.16
#define SW_MEASURE_POINTS 12
#define SW_MEASURE_SETTLED 4
/* A probe's samples: its first point's run, the whole graded run where
 * four points over it fit the budget below, else at most this many steps
 * of the graded dt. */
#define SW_MEASURE_PROBE_STEPS 64
/* ... and a probe's work (sw_measure_step_work × steps, the run at the
 * graded dt to the graded run's end included) at most SW_MEASURE_FREE, or
 * SW_MEASURE_GRADED times the graded run's own where that is more: what
 * the sweep costs the student's CPU time is bounded by what the graded run
 * cost it (a first-order method on the 3-mass chain: 3.1e6 in all). */
#define SW_MEASURE_FREE 2.5e7
#define SW_MEASURE_GRADED 1.0
/* ... and the reference run a probe's errors are measured against (a
 * scene without a closed form) at most this much work, the grader's own
 * (a tight run on a tree galaxy of 20 000 stars took 44 min). */
#define SW_MEASURE_REF_WORK 2.5e9
/* The graded dt's point off the fit still stands when its local slope to
 * the fit is within this of the order (the order point's own margin). */
#define SW_MEASURE_GRADED_SLOPE 0.5

/* Order: the largest error against the exact solution over the sample
 * times to SW_MEASURE_T (sw_truth_sample_time) for dt = SW_MEASURE_DT0
 * halved up to SW_MEASURE_POINTS - 1 times, until SW_MEASURE_SETTLED
 * points carry an order or the error reaches round-off; *order is the
 * order rule's (sw_bench_order_rule). *fit (NULL: not wanted) gets the
 * points and the fit. 0, or SW_EINVAL with err saying why: a run failed,
 * the plugin failed, or "no order: " and the rule's reason. */
int sw_measure_order(const sw_integrator *m, double *order, sw_bench_series *fit, char *err, size_t errlen);

/* The run a plugin is graded on, as its order's probe (docs/grading.md,
 * "What a measured figure stands on"): the same scene, parameters and
 * start, the sweep's first step the graded dt. */
typedef struct sw_measure_probe {
    const sw_scene *scene;
    const double *p;
    double dt;               /* the graded dt: the sweep's first point */
    double stop_at;          /* the graded run's sw_sim_step_until argument (0: whole steps) */
    long graded_steps;       /* the steps the graded run took */
    const double *graded_y;  /* its last state (NULL: not compared) */
    int *whole;              /* out, or NULL: 1 when the sweep spanned the whole graded run and
                              * its first point repeated it; else the order stands on a part */
    long *span;              /* out, or NULL: the steps of dt each point's runs span, from the
                              * start (the horizon, once halved to its error ceiling) */
} sw_measure_probe;

/* The order on a probe (NULL: the spring, as sw_measure_order): dt, dt/2,
 * ... each run sampled 16 times over the first steps of dt of the graded
 * run (all of them where four points fit the budget, else at most
 * SW_MEASURE_PROBE_STEPS; halved, down to one, while the error at dt is
 * at or over SW_BENCH_CEILING of the state), the error against the scene's
 * exact solution or the truth module's reference run. Point 0 runs the
 * graded run again to its end and must land on graded_y bit for bit, and
 * the order stands only when the fit includes point 0: a plugin that
 * tells the measuring runs from its graded run (by its dt, its system,
 * its start or its run count) gets no order, never one its graded run
 * does not show. */
int sw_measure_order_on(const sw_integrator *m, const sw_measure_probe *pr, double *order, sw_bench_series *fit,
                        char *err, size_t errlen);
/* A step of m on sys in the budgets' unit: sw_truth_eval_work times its
 * evaluations (as m says, 1 to 16). A graded run whose steps × this is
 * over SW_MEASURE_FREE is not run again: give its probe no graded_y. */
double sw_measure_step_work(const sw_system *sys, const sw_integrator *m);

/* Stability limit ω·dt on the same spring, from sw_stability_find. *kind
 * is its sw_stab_kind. 0, or a status with err filled. */
int sw_measure_stability(const sw_integrator *m, double *omega_dt, int *kind, char *err,
                         size_t errlen);
/* The same for a built-in method measured as a plugin is: without
 * SW_SYMPLECTIC, which a plugin never has and which makes the stability
 * watch laxer (sim/watch.c), so that a plugin and its method compare like
 * for like (an honest symplectic Euler: 1.61 both, where the flag gives
 * the method 1.91). */
int sw_measure_stability_as_plugin(const sw_integrator *m, double *omega_dt, int *kind, char *err,
                                   size_t errlen);

/* Whether m's stability limit on the spring is ref's (measured as a
 * plugin, as sw_measure_stability_as_plugin) within rel of it, decided
 * in at most two runs of m whatever the precision of the limit's own
 * bisection: m holds at (1 - rel) × ref's limit and not at (1 + rel) ×
 * it, over the horizon that set ref's (ref with none: m does not hold at
 * ref's smallest step; unbounded: m holds at ref's largest). The
 * stability point's decision (grade/verdict.c). */
typedef struct sw_stability_match {
    int kind;             /* ref's sw_stab_kind */
    double limit;         /* ref's ω·dt: 0 none, ∞ unbounded */
    double inside, outside; /* the ω·dt where m ran (NaN: not run) */
    int held_inside, held_outside; /* 1 m held there, 0 did not, -1 not run */
    int match;            /* 1: m's limit is ref's within rel */
    long steps;           /* m's steps in all, a failing run's to where it failed */
    int budget;           /* the status: m ran out of its CPU time (SIGXCPU) */
} sw_stability_match;
/* Whether measuring runs that spent `spent` s of CPU on `steps` steps went
 * at the pace of a graded run that took graded_cpu s for graded_steps
 * (or at most SW_MEASURE_PACE_SLACK times slower a step): a plugin slow
 * everywhere, whose measurement the grader's budget cut short; else it
 * was slower only where it was measured, which it can tell apart. */
#define SW_MEASURE_PACE_SLACK 4.0
int sw_measure_pace_holds(double graded_cpu, long graded_steps, double spent, long steps);
/* 0, or a status with err filled (m failed: the plugin's words). */
int sw_measure_stability_match(const sw_integrator *m, const sw_integrator *ref, double rel,
                               sw_stability_match *out, char *err, size_t errlen);

#endif
