/* Stability limits measured, not quoted: the largest step at which a method
 * keeps a scene from blowing up or growing, found by bisection on sw_sim
 * runs. Growth is judged on a measure M of the state (the scene's energy, or
 * ½|y|² for a flow without one) and on the distance D between the sim and a
 * twin started 1e-7 ahead along its path: the linearised dynamics, which
 * stability theory is about, act on D whatever the state's amplitude. */
#ifndef SW_LAB_STABILITY_H
#define SW_LAB_STABILITY_H

#include <stddef.h>

#include "stepwise/sim.h"

typedef enum sw_stab_kind {
    SW_STAB_LIMIT = 0,    /* stable at dt, unstable at dt_unstable: the limit lies between */
    SW_STAB_NONE = 1,     /* unstable even at the smallest step probed */
    SW_STAB_UNBOUNDED = 2 /* stable even at the largest step probed */
} sw_stab_kind;

/* A probe cuts its run into this many windows and takes M's peak in each. */
#define SW_STAB_WINDOWS 20

/* A probe's verdict. */
enum {
    SW_PROBE_STABLE = 0,
    SW_PROBE_BLOWN = 1,  /* the sim or its twin blew up (non-finite, runaway, failed solve) */
    SW_PROBE_BOUND = 2,  /* M rose above its start by more than (bound - 1)·|M0| */
    SW_PROBE_TWIN = 3,   /* D² rose above twin_bound times its start */
    SW_PROBE_TREND = 4,  /* M grew: window peaks climbed steadily, or the last tenth's peak
                            beat the first tenth's by more than the first tenth varied */
    SW_PROBE_DECAYED = 5 /* stable: D² fell below 1e-24 of its start, the run stopped early */
};

typedef struct sw_stability_config {
    double periods;  /* simulated time per probe, in periods 2π/ω (report times when ω is unknown) */
    double reports;  /* but at least this many report times */
    long min_steps;  /* but at least this many steps */
    long max_steps;  /* and at most this many */
    double bound;    /* see SW_PROBE_BOUND */
    double twin_bound; /* see SW_PROBE_TWIN */
    int rises;       /* TREND when at least this many of the 19 window-to-window peak
                        changes are rises (and the peaks rose by > 1e-12·|M0| in all) */
    double jump;     /* TREND when last_max - first_max > jump·first_range + 1e-9·|M0| */
    double low;      /* smallest ω·Δt probed (Δt = low·(scene dt) when ω is unknown) */
    double high;     /* largest ω·Δt probed (capped at SW_DT_MAX) */
    double rel_tol;  /* bisection stops once dt_unstable / dt - 1 < rel_tol */
} sw_stability_config;

/* One run at one step size and what it showed. */
typedef struct sw_stability_probe {
    double dt;
    long steps;        /* steps taken (fewer than planned when it failed early) */
    int verdict;       /* SW_PROBE_* */
    double m0;         /* M at the start */
    double first_max, first_range; /* M over the first tenth of the run (2 windows) */
    double last_max;   /* M's peak over the last tenth */
    int rises;         /* window-to-window rises of M's peak, out of SW_STAB_WINDOWS - 1 */
    char reason[SW_ERRLEN]; /* SW_PROBE_BLOWN: the sim's blow-up reason */
} sw_stability_probe;

typedef struct sw_stability_result {
    const sw_integrator *method;
    sw_stab_kind kind;
    double dt;          /* LIMIT: largest stable step found; NONE: the smallest probed;
                           UNBOUNDED: the largest probed */
    double dt_unstable; /* LIMIT: smallest unstable step found; NaN otherwise */
    double omega;       /* the scene's stiffest frequency; NaN when unknown */
    double theory;      /* method->stability: largest ω·Δt on x'' = -ω²x (0 none, INFINITY unbounded) */
    int probes;
    long steps;         /* summed over all probes */
    sw_stability_probe fail; /* the failing probe nearest the limit (NONE: the one at dt) */
} sw_stability_result;

/* 100 periods, 10 report times and at least 400 steps per probe, bound 1e4,
 * twin bound 1e8, 16 rises, jump 1, ω·Δt from 0.01 to 1000, bisection to 1e-4. */
void sw_stability_config_default(sw_stability_config *c);

/* 1 when growth can be judged on scene sc: it defines an energy or knows its
 * stiffest frequency (a flow, judged on ½|y|²), and it has no events at step
 * boundaries (contact splits nearby runs); else 0 with why filled. */
int sw_stability_applicable(const sw_scene *sc, char *why, size_t whylen);

/* Run sc (parameters p, NULL: defaults) under m at step dt for the probe's
 * simulated time and judge it. 0 or a status (init failure) with err filled. */
int sw_stability_probe_run(const sw_scene *sc, const double *p, const sw_integrator *m, double dt,
                           const sw_stability_config *c, sw_stability_probe *out, char *err,
                           size_t errlen);

/* Find m's largest stable step on sc by bisection between a stable and an
 * unstable step. 0, or SW_EINVAL (an adaptive method, a method that cannot
 * step the scene, or a scene where growth cannot be judged) with err filled. */
int sw_stability_find(const sw_scene *sc, const double *p, const sw_integrator *m,
                      const sw_stability_config *c, sw_stability_result *out, char *err,
                      size_t errlen);

#endif
