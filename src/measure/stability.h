/* Stability limits, in theory and measured, side by side. Theory: the
 * largest Δt at which the method's one-step map does not grow on any mode
 * of the scene's linearisation, at the start and along the true solution
 * (src/sim/truth.h). Measurement: bisection on sw_sim runs, each watched
 * for growth of the energy of its motion (src/sim/watch.h). Where the two
 * disagree the result says why. */
#ifndef SW_MEASURE_STABILITY_H
#define SW_MEASURE_STABILITY_H

#include <stddef.h>

#include "sim/watch.h"
#include "stepwise/sim.h"

/* A measured limit is reported rounded down to this many significant
 * digits, and that step is run again from the scene's start to verify it. */
#define SW_STABILITY_DIGITS 5
/* Theory and measurement agree when they differ by at most this fraction. */
#define SW_STABILITY_AGREE 0.02
/* Where a scene has a resting state, every probe also runs the motion shrunk
 * by this factor towards it, so no nonlinearity can cap a growing mode. */
#define SW_STABILITY_SHRINK 1e-4
/* Where the measured limit lies above the theory's, it is probed again over
 * this many times the probe's time, twice (16x in all), and searched again
 * below where a longer run grows. */
#define SW_STABILITY_LONGER 4.0

typedef enum sw_stab_kind {
    SW_STAB_LIMIT = 0,    /* stable at dt, unstable at dt_unstable: the limit lies between */
    SW_STAB_NONE = 1,     /* unstable even at the smallest step probed */
    SW_STAB_UNBOUNDED = 2 /* stable even at the largest step probed */
} sw_stab_kind;

/* A probe's verdict: stable, decayed (stable, stopped early), blown, or
 * one of the watch's growth verdicts. */
enum {
    SW_PROBE_STABLE = 0,
    SW_PROBE_BLOWN = 1,   /* non-finite, runaway, or a failed implicit solve */
    SW_PROBE_BOUND = 2,   /* SW_WATCH_BOUND */
    SW_PROBE_RAISED = 3,  /* SW_WATCH_RAISED */
    SW_PROBE_TREND = 4,   /* SW_WATCH_TREND */
    SW_PROBE_DECAYED = 5  /* the motion's energy fell below 1e-20 of its start: stable */
};

typedef struct sw_stability_config {
    double periods;  /* simulated time per probe, in periods 2π/|λ|max (report times when none) */
    double reports;  /* but at least this many report times */
    long min_steps;  /* but at least this many steps */
    long max_steps;  /* and at most this many */
    double low;      /* smallest |λ|·Δt probed (Δt = low·(scene dt) when |λ| = 0) */
    double high;     /* largest |λ|·Δt probed (capped at SW_DT_MAX) */
    double rel_tol;  /* bisection stops once dt_unstable / dt - 1 < rel_tol */
    double horizon;  /* > 0: simulated time per probe, instead of periods and reports */
    int samples;     /* spectra along the true solution for the theory */
} sw_stability_config;

/* One run at one step size and what it showed. */
typedef struct sw_stability_probe {
    double dt;
    long steps;        /* steps taken (fewer than planned when it failed early) */
    double work;       /* evaluations × sw_truth_eval_work + solver iterations × a solve's */
    int verdict;       /* SW_PROBE_* */
    double m_max;      /* largest M seen */
    int small;         /* the verdict is the small-amplitude copy's (see stability.c) */
    char reason[SW_ERRLEN]; /* SW_PROBE_BLOWN: the sim's blow-up reason */
} sw_stability_probe;

typedef struct sw_stability_result {
    const sw_integrator *method;
    sw_stab_kind kind;
    double dt;          /* LIMIT: largest stable step found; NONE: the smallest probed;
                           UNBOUNDED: the largest probed */
    double dt_unstable; /* LIMIT: smallest unstable step found; NaN otherwise */
    double stiff;       /* largest |λ| of the linearisation along the run; 0 when none */
    double theory;      /* the limit in theory (dt): 0 none */
    int theory_unbounded; /* ... no limit up to SW_DT_MAX */
    double horizon;     /* simulated time of the probes that set dt (longer where confirmed) */
    int probes;
    long steps;         /* summed over all probes */
    double work;        /* the probes' and the theory's reference run's, in SW_WORK_REPORT's units:
                           what the budget bounds (tests/check_stability_budget.c) */
    sw_stability_probe fail; /* the failing probe nearest the limit (NONE: the one at dt) */
    int measured;       /* 0: theory only (the scene's growth cannot be measured: why says so) */
    int agree;          /* theory and measurement within 2% (or both none / both unbounded) */
    char why[2 * SW_ERRLEN]; /* when they do not agree, or nothing was measured: why */
} sw_stability_result;

/* A probe verdict in a few words ("blew up", "energy grew", ...). */
const char *sw_stability_verdict_text(int verdict);

/* 100 periods, 20 report times and 400 steps per probe at least, 4e6 at
 * most; |λ|·Δt from 0.01 to 1000; bisection to 1e-4; 16 spectra. */
void sw_stability_config_default(sw_stability_config *c);

/* 1 when growth can be measured on scene sc with parameters p (NULL:
 * defaults): no events at step boundaries (contact splits nearby runs), and
 * an energy with a floor or a well (an orbit), or a flow with a closed form
 * (judged on |y|²); else 0 with why filled. */
int sw_stability_measurable(const sw_scene *sc, const double *p, char *why, size_t whylen);

/* Run sc (parameters p, NULL: defaults) under m at step dt for the probe's
 * simulated time and judge it. 0 or a status (init failure) with err filled. */
int sw_stability_probe_run(const sw_scene *sc, const double *p, const sw_integrator *m, double dt,
                           const sw_stability_config *c, sw_stability_probe *out, char *err,
                           size_t errlen);

/* What sw_stability_find would cost for each of methods[0..n), summed, in
 * state components × derivative evaluations (see SW_WORK_REPORT): per
 * method the reference run for the theory, the probe at the smallest step
 * (with its small copy) and about 25 probes near the limit; the parts that
 * depend only on the scene (its stiffness, the reference run's pilot)
 * worked out once. Adaptive methods are left out (no limit to find). An
 * estimate, for refusing before starting; each (NULL: not wanted) gets the
 * n terms, 0 for a method left out. */
double sw_stability_cost_sum(const sw_scene *sc, const double *p, const sw_integrator *const *methods, int n,
                             const sw_stability_config *c, double *each);

/* Theory and measurement of m's largest stable step on sc (theory alone
 * where growth cannot be measured). 0, or SW_EINVAL (an adaptive method, a
 * method that cannot step the scene) with err filled. */
int sw_stability_find(const sw_scene *sc, const double *p, const sw_integrator *m,
                      const sw_stability_config *c, sw_stability_result *out, char *err,
                      size_t errlen);

#endif
