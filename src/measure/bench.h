/* Work–precision sweeps: error at a scene's report time against what it cost
 * (derivative evaluations, wall time), for each integrator over a geometric
 * sweep of step sizes; the observed order fitted from the sweep; the cheapest
 * method per error level; and the plot as ASCII text, CSV or SVG. Every run
 * is an sw_sim advanced with sw_sim_run_until, as in the UI and the recorder. */
#ifndef SW_MEASURE_BENCH_H
#define SW_MEASURE_BENCH_H

#include <stdatomic.h>
#include <stddef.h>
#include <stdio.h>

#include "sim/truth.h"
#include "stepwise/sim.h"

#define SW_BENCH_MAX_POINTS 16
#define SW_BENCH_MAX_METHODS 24
/* An order is fitted from at least this many points above the floor: two
 * points give a slope whatever the error does between them. */
#define SW_BENCH_MIN_FIT 3
/* ... and a slope below this is no order: the error does not fall with the step. */
#define SW_BENCH_MIN_ORDER 0.1
/* A fitted point's error is at least this many times the series' floor (the
 * larger of the assumed round-off and the plateau the run itself reached):
 * round-off of at most a tenth moves ln error by at most ln 1.1 = 0.095. */
#define SW_BENCH_MARGIN 10.0
/* A point is on the round-off plateau when no finer point's error falls
 * below this fraction of its own: asymptotic points always have finer ones
 * well below them (a halving takes even a first-order error to 0.5). */
#define SW_BENCH_STALL 0.75
/* The fitted points span at least this factor in step: between neighbours
 * whose steps differ by a few per cent (an adaptive method whose step count
 * hardly changes) a local slope is noise. */
#define SW_BENCH_MIN_SPAN 2.0
/* The local slopes between neighbouring fitted points agree within this
 * band: max - min <= SW_BENCH_BAND_ABS + SW_BENCH_BAND_REL·order. */
#define SW_BENCH_BAND_ABS 0.15
#define SW_BENCH_BAND_REL 0.03
/* A plateau within this factor of the assumed floor (SW_BENCH_SAMPLES runs'
 * round-off, scale·(1e-13 + 4e-16·steps)) is round-off amplified by the
 * dynamics (the orbit at e = 0.97 amplifies it about 340 times); above it,
 * the error stops falling for another reason and is not called round-off. */
#define SW_BENCH_ROUNDOFF 1e3
/* bench fits no error from this fraction of the state up: coarser errors
 * are seldom asymptotic, and a table of orders should not depend on luck. */
#define SW_BENCH_CEILING 1e-2

/* A run's error is the largest over the truth module's sample times
 * (sw_truth_sample_time): one report time may be special, the run is not. */
#define SW_BENCH_SAMPLES SW_TRUTH_SAMPLES

/* Where the true state at the report time comes from. */
enum { SW_BENCH_EXACT = 1, SW_BENCH_REFERENCE = 2 };

/* Why a series has no order (sw_bench_series.no_order). */
enum {
    SW_BENCH_ORDER_OK = 0,       /* an order was fitted */
    SW_BENCH_ORDER_FEW = 1,      /* fewer than SW_BENCH_MIN_FIT clean points, no plateau reached */
    SW_BENCH_ORDER_FLAT = 2,     /* the error does not fall with the step (slope < SW_BENCH_MIN_ORDER) */
    SW_BENCH_ORDER_PAST = 3,     /* the error stopped falling (a plateau) or reached round-off before a clean fit */
    SW_BENCH_ORDER_STEPS = 4,    /* the steps do not shrink as the tolerance tightens: the error is not read against them */
    SW_BENCH_ORDER_MONOTONE = 5, /* the finest clean errors do not fall steadily */
    SW_BENCH_ORDER_SLOPES = 6,   /* the local slopes at the finest clean steps disagree: not yet in the asymptotic range */
    SW_BENCH_ORDER_ABOVE = 7     /* the slope is above the method's order by more than SW_BENCH_ABOVE */
};

/* An order-p method's error is C·h^p + O(h^(p+1)) with C nonzero on almost
 * every problem, so a slope steadily above p says the h^p term is not yet
 * the largest at the steps swept (rodas4 reads 4.95 on the orbit at
 * e = 0.9 on fixed steps down to 3.6e-7, where its h^5 term still leads),
 * or vanishes on this problem: either way not the order. bench's series
 * (whose method's order is known) print no order when the slope exceeds
 * the order by more than this; a slope below it is printed (order lost to
 * events stepped over, or to stiffness, is what a student should see). */
#define SW_BENCH_ABOVE 0.3

/* Why a series' sweep ended. */
enum {
    SW_BENCH_STOP_ENOUGH = 0,   /* min_points swept and fit_points in the fit range */
    SW_BENCH_STOP_FLOOR = 1,    /* the error reached round-off / the reference's accuracy */
    SW_BENCH_STOP_BUDGET = 2,   /* the next run would exceed max_work */
    SW_BENCH_STOP_MAX = 3,      /* max_points swept */
    SW_BENCH_STOP_DT_MIN = 4    /* the next step would be below SW_DT_MIN */
};

typedef struct sw_bench_point {
    double dt;        /* the sim's step (adaptive methods: the largest step allowed) */
    double rtol;      /* adaptive methods: the tolerance (atol = rtol·1e-3); 0 otherwise */
    double h;         /* step used for the fit: dt, or report time / accepted steps */
    double error;     /* largest |y - y_true| over all components and the sample times; NaN if blown */
    double floor;     /* below this the error is round-off or reference noise */
    long evals;       /* derivative evaluations (sw_sim_evals) */
    long solves;      /* linear solves (implicit methods) */
    long steps;
    double seconds;   /* wall time of sw_sim_run_until, median over `repeats` runs */
    int repeats;
    int blown;        /* the sim blew up before the report time */
    double blow_time;
    int in_fit;       /* 1 when this point entered the order fit */
} sw_bench_point;

typedef struct sw_bench_series {
    const sw_integrator *method;
    int npoints;
    sw_bench_point points[SW_BENCH_MAX_POINTS]; /* the runs as a user makes them (adaptive: controlled,
                                                    one per tolerance): the work-precision plot's */
    /* Adaptive methods: the same formula on fixed steps (error control off,
     * SW_TOL_NONE), the points the order is fitted from. An order is the
     * exponent p in error = C·h^p for a constant step h; a controlled run's
     * error against its mean step T/N is not that: it divides how fast the
     * error falls with the tolerance by how fast the steps grow, and the
     * first is not yet proportional at any tolerance above round-off (the
     * controller holds the embedded estimate at rtol, the run carries the
     * higher-order solution), so the slope read above p (rk45 5.34 on the
     * orbits, rkn 6.66 on the stiff spring: docs/performance.md). */
    int nfixed;
    sw_bench_point fixed[SW_BENCH_MAX_POINTS];
    double order;     /* least-squares slope of ln error against ln h (sw_bench_order_points), > 0;
                         NaN when none (no_order says why) */
    int nfit;         /* points in the fit: 0, or SW_BENCH_MIN_FIT and more */
    int no_order;     /* SW_BENCH_ORDER_*: why order is NaN */
    int ncandidates;  /* clean points: between SW_BENCH_MARGIN × floor and 1e-2 of the state, before the plateau */
    double slope_min, slope_max; /* local slopes between neighbouring fit points (no order: between the
                                    finest clean points, NaN when fewer than 2) */
    int asymptotic;   /* 1 when an order was fitted (its local slopes agree) */
    double floor;     /* the series' floor: the largest point floor, or the plateau's largest error */
    int plateau;      /* index of the first point on the round-off plateau, -1 when none was reached */
    char why[160];    /* no order: why, in a few words ("" when there is an order) */
    int stop;         /* SW_BENCH_STOP_* */
} sw_bench_series;

typedef struct sw_bench_config {
    int min_points;    /* sweep at least this many step sizes (unless stopped by floor or budget) */
    int max_points;    /* and at most this many (<= SW_BENCH_MAX_POINTS) */
    int fit_points;    /* after min_points, stop once this many points are in the fit range */
    double fine;       /* ... and the finest error is below fine·scale (0: any), or settled
                          points agree: an order read where the error is still large can be a
                          lower-order term's cancellation (symplectic Euler's first-order term,
                          small on a chain started at rest, is overtaken by its second-order one
                          above dt ≈ 1.6e-3, over three halvings) */
    int settled;       /* ... or this many points fit, asymptotic (0: fine alone decides) */
    int repeats;       /* timing repeats per point; the median is kept */
    double repeat_below; /* repeat only runs faster than this many seconds */
    double max_work;   /* skip runs above this many (evaluations + solver iterations) × dimension */
    const atomic_int *stop; /* NULL, or set by another thread: the sweep ends at its next sample
                               time with SW_EINVAL, "stopped" (the UI's sweep on a worker) */
    int no_fixed;      /* 1: adaptive methods sweep their controlled runs only, and have no order
                          (the UI's plot, which shows no order); 0: their fixed steps too */
} sw_bench_config;

/* One scene's sweep: the truth at the report time and one series per method. */
typedef struct sw_bench_report {
    const sw_scene *scene;
    double p[SW_MAX_PARAMS];
    double t_report;
    int dim;
    int source;        /* SW_BENCH_EXACT or SW_BENCH_REFERENCE */
    double *samples;   /* the true state at the sample times (SW_BENCH_SAMPLES × dim doubles), owned */
    const double *truth; /* ... the last of them: the state at t_report */
    double ref_error;  /* reference: |rtol 1e-12 run - rtol 1e-11 run| over the samples, an upper estimate of its error */
    long ref_evals;    /* evaluations the reference runs took */
    const atomic_int *stop; /* as sw_bench_config's, for the reference runs */
    double scale;      /* max(1, max |truth| over the samples): errors are judged against this */
    double omega;      /* largest |λ| of the linearisation at the start, NaN when unknown */
    sw_spectrum spectrum; /* the linearisation's modes at the start (n = 0: none) */
    int nseries;
    sw_bench_series series[SW_BENCH_MAX_METHODS];
    sw_events_mode events; /* how the sweep's runs meet events (set after init; default step) */
} sw_bench_report;

/* The `stepwise bench` sweep: 8 to 16 step sizes, 3 repeats (default run < 30 s). */
void sw_bench_config_default(sw_bench_config *c);
/* A small sweep for the UI (`w`): 6 to 8 step sizes, one run each, under a second. */
void sw_bench_config_quick(sw_bench_config *c);

/* 1 when scene sc with parameters p (NULL: defaults) has an exact solution or
 * a trustworthy reference (sw_truth_reference_method); 0 with the reason in why otherwise. */
int sw_bench_measurable(const sw_scene *sc, const double *p, char *why, size_t whylen);

/* Prepare r for sc with parameters p (NULL: defaults): the true state at the
 * report time from the exact solution or, failing that, a tight run of the reference method
 * (rtol 1e-12, atol 1e-14) computed once here. 0, SW_EINVAL (no reference),
 * SW_ENOMEM or SW_EDIVERGED (the reference run failed). r is freed on failure. */
int sw_bench_init(sw_bench_report *r, const sw_scene *sc, const double *p, char *err, size_t errlen);
void sw_bench_free(sw_bench_report *r);

/* Sweep method m and append its series to r, with its fitted order. 0, or
 * SW_EINVAL when m cannot step this scene (err says why) or r is full. */
int sw_bench_sweep(sw_bench_report *r, const sw_integrator *m, const sw_bench_config *c,
                   char *err, size_t errlen);

/* Sweep every method in methods (NULL: every registered one) that can step
 * the scene; the others are left out silently. 0 or a status. */
int sw_bench_sweep_all(sw_bench_report *r, const sw_integrator *const *methods, int nmethods,
                       const sw_bench_config *c, char *err, size_t errlen);

/* 1 when sw_bench_scene_quick's estimate is within budget; else 0 with err
 * saying why (as sw_bench_scene_quick would refuse). ref_cost: the truth's
 * sw_truth_reference_cost to the scene's duration when the caller has it
 * (the app: no second pilot run on a key press), NAN to work it out. */
int sw_bench_quick_affordable(const sw_scene *sc, const double *p, double ref_cost, double budget, char *err,
                              size_t errlen);
/* For the UI: init + sweep_all with the quick config, within budget state
 * evaluations in all (refused with SW_EINVAL, err saying why, when the
 * reference alone would spend a quarter of it). r must be freed with
 * sw_bench_free when this returns 0. stop: see sw_bench_config. */
int sw_bench_scene_quick(sw_bench_report *r, const sw_scene *sc, const double *p, double budget,
                         const atomic_int *stop, char *err, size_t errlen);

/* Refit a series (marks in_fit, sets order, nfit, no_order, why, floor,
 * plateau, the local slopes and asymptotic). An order stands only on points
 * that can carry one:
 *  - the plateau: the first point no finer point falls below
 *    SW_BENCH_STALL of, and every point after it, is past the asymptotic
 *    range; its largest error is the run's own floor (round-off amplified by
 *    the dynamics, or the reference's accuracy), never guessed;
 *  - clean points: not blown, before the plateau, error between
 *    SW_BENCH_MARGIN × the larger of the point's floor and the plateau's
 *    and 1e-2·scale;
 *  - the fit: the longest contiguous run of clean points that ends at the
 *    finest one (the asymptotic range is at the fine end), at least
 *    SW_BENCH_MIN_FIT of them, error and step strictly falling, the steps
 *    spanning SW_BENCH_MIN_SPAN, the local slopes within the band;
 *    then the least-squares slope of ln error against ln h.
 * Returns the order, or NaN with no_order and why saying which rule failed;
 * never <= 0. */
double sw_bench_fit(const sw_bench_report *r, sw_bench_series *s);

/* The points s's order is fitted from (and in_fit marks): the fixed-step
 * runs for an adaptive method, the points otherwise; their count in *n. */
const sw_bench_point *sw_bench_order_points(const sw_bench_series *s, int *n);

/* Round-off's share of an error after `steps` steps on a state of size
 * scale: scale·(1e-13 + 4e-16·steps) (it grows at most about linearly
 * with the steps). The floor each point of a sweep is judged against. */
double sw_bench_roundoff(double scale, long steps);

/* The order rule of sw_bench_fit for any measured sequence, the one rule
 * every printed order passes (check's measured order, the Δt-halving
 * message, the `w` plot): n points (at most SW_BENCH_MAX_POINTS, coarse to
 * fine) with step h[i], error error[i] (NaN or infinite: the run blew up)
 * after steps[i] steps (its floor: sw_bench_roundoff), on a state of size
 * scale; errors from ceiling·scale up are not fitted (bench and check:
 * SW_BENCH_CEILING; the Δt message, which says when the error is too large a
 * share of the motion, more). Fills *s (method NULL) as sw_bench_fit does and returns the order, or NaN with s->why
 * saying which rule failed. */
double sw_bench_order_rule(const double *h, const double *error, const long *steps, int n, double scale,
                           double ceiling, sw_bench_series *s);

/* The cheapest measured point with error <= level: by wall time, or by
 * evaluations when by_evals. Returns the series index and sets *point, or -1. */
int sw_bench_cheapest(const sw_bench_report *r, double level, int by_evals, int *point);

/* The character that marks method m in plots: its 1-based position in the
 * integrator list ('1'..'9', then 'a'..'z'). */
char sw_bench_marker(const sw_integrator *m);

enum { SW_BENCH_X_TIME = 0, SW_BENCH_X_EVALS = 1 };

/* Why series s has no order, in a few words for "no order: ..." ("" when it has one): s->why. */
const char *sw_bench_no_order_text(const sw_bench_series *s);

/* Render error against wall time (SW_BENCH_X_TIME) or evaluations on log–log
 * axes: `height` rows of exactly `width` characters, each ended by '\n', then
 * a NUL, so buf must hold (width + 1) * height + 1 bytes. Row 0 is a title,
 * the last rows a legend (marker = method). 0, or SW_EINVAL when width < 40
 * or height < 10. */
int sw_bench_plot(const sw_bench_report *r, int xaxis, char *buf, int width, int height);

/* The points of every report as CSV, numbers in %.17g. 0 or SW_EIO. */
int sw_bench_write_csv(FILE *out, const sw_bench_report *const *reports, int nreports,
                       char *err, size_t errlen);
/* The work–precision plots as one SVG document: a row per report, two log–log
 * panels (error against time, against evaluations), each with an x and a y
 * axis group and one series group (a polyline and its points) per method. */
int sw_bench_write_svg(FILE *out, const sw_bench_report *const *reports, int nreports,
                       char *err, size_t errlen);

#endif
