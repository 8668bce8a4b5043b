/* What the engine benchmark's sections share: a monotonic clock, medians
 * and spreads of repeated timings, and the peer comparison's entry point. */
#ifndef SW_BENCH_COMMON_H
#define SW_BENCH_COMMON_H

#include <stdlib.h>
#include <time.h>

#include "stepwise/particles.h"

#define MAX_REPEATS 15

static inline double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The calling thread's CPU time in seconds: what a run costs on a loaded
 * machine, where the monotonic clock also counts other programs' turns. */
static inline double thread_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static inline int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Median of v[0..n) (sorts v in place). */
static inline double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* The undamped chain as the scene builds it, for the hand-fused baselines
 * (bench_base.c): n beads, stiffness k, rest length, 1/m, the right
 * anchor's x, and room for the n + 1 spring forces (2(n + 1) doubles). */
typedef struct bench_chain {
    int n;
    double k, rest, inv_m, right_x;
    double *f;
} bench_chain;

/* The vortex's seeds, as the scene places them (2n doubles). */
void base_vortex_seed(double *y, int n);
/* Hand-fused steps: `steps` steps of h on y in place (bench_base.c). */
void base_vortex_euler(double *y, int n, double w, double h, long steps);
void base_vortex_rk4(double *y, int n, double w, double h, long steps);
void base_chain_euler(bench_chain *ch, double *y, double h, long steps);
/* work: 8n doubles */
void base_chain_rk4(bench_chain *ch, double *y, double *work, double h, long steps);

typedef struct bench_peer_opts {
    int repeats;        /* paired timed runs (at least 5 for the table) */
    int chain_n, vortex_n;
    int quick;          /* error 1e-6 only, fewer searches */
    const char *only;   /* NULL, or the one scene to compare (orbit, chain, vortex) */
    int stiff;          /* the stiff set instead (issue 41): rodas4 among stepwise's methods */
} bench_peer_opts;

/* The chain's state at T from y0 (bench_chain_ref.c), independent of the
 * engine: RK4 in long double, steps doubled until the error estimate
 * (Richardson) is at most goal. par: n, k, m, c, rest, g. 0, or -1. */
int bench_chain_reference(const double *par, const double *y0, double T, double goal, double *ref,
                          double *estimate, long *steps);

/* The peer comparison (bench_peer.c): stepwise's cheapest method against
 * GSL's cheapest stepper at equal error, or a note when GSL is absent. */
void bench_peer(const bench_peer_opts *o);

struct sw_ode;
struct sw_integrator;
/* Method m (NULL: GSL's rk8pd) on the orbit's Levi-Civita equations,
 * landed on T by dop853-lc's own landing (bench_lc.c; GSL builds only):
 * from the one-body system ode's state y0 at 0 to T at rtol = atol = tol,
 * the state at T into y; 0, or -1 when the run failed. */
int bench_lc_run(const struct sw_integrator *m, struct sw_ode *ode, const double *y0, double T, double tol,
                 double *y, double *seconds, long *evals);
/* For callgrind: `runs` runs of the orbit at e = 0.9 to its report time at
 * tol, by "dop853-lc" or "rk8pd-lc", or their set-up alone ("setup")
 * (bench_lc.c); 0, or 1. */
int bench_lc_probe(const char *who, double tol, long runs);

/* For counting instructions (bench/instructions.sh): build SCENE at SET
 * ("e=0.9") and call its derivative `calls` times at the start, as the
 * methods call it (the small path where it applies) or through the
 * generic passes; 0, or 1 when the scene or setting is not a particle
 * system's. */
int bench_deriv_probe(const char *scene, const char *set, long calls, int generic);

/* Barnes-Hut against the direct sum at n = 1e3, 1e4, 1e5 (quick: the first
 * two): time per evaluation, force error, fitted exponents (bench_tree.c). */
void bench_tree(int repeats, int quick);
/* EVALS evaluations of the tree on bench_tree's disc of N bodies at THETA
 * (the arguments as typed), for callgrind: the difference between two
 * counts is what the evaluations cost. 0; 1 when the disc cannot be
 * built; 2, with a one-line message, for arguments out of range. */
int bench_tree_probe(const char *n, const char *theta, const char *evals);
/* Median seconds per evaluation of p's derivative over `repeats` runs of at
 * least `least` seconds each; *allocs: allocations during the timed runs. */
double bench_time_eval(sw_particles *p, double *dydt, int repeats, double least, long *allocs);
/* Least-squares slope of log t against log n over the points with t > 0. */
double bench_fit(const double *n, const double *t, int m);
/* The water scene's derivative (SPH, its neighbours from a cell list) at
 * n = 1e3, 1e4, 1e5 (quick: the first two): seconds per evaluation and the
 * exponent of n fitted (bench_water.c). */
void bench_water(int repeats, int quick);

/* Methods for x'' = f(x) at equal error: rkn, yoshida4 against dop853,
 * rk45, verlet on the undamped chain and the orbit (quick: 1e-3 only)
 * (bench_rkn.c). */
void bench_rkn(int repeats, int quick);
/* The implicit methods against rk4 on the chain of chain_n beads: ns per
 * particle-step and the paired ratio to rk4, about `target` seconds a
 * timed repeat (bench_implicit.c). */
void bench_implicit(int repeats, int chain_n, double target);
/* rodas4 against CVODE's BDF on stiff problems at equal error, or rodas4
 * alone when CVODE is absent (bench_stiff.c). */
void bench_stiff(int repeats, int quick);
/* Frame cost (bench_frame.c): the plain rasteriser per scene (vortex at
 * vortex_n first), and the heavy views through the app layer (quick: at
 * n = 1e4 instead of 1e5). */
void bench_frame_cost(int vortex_n, double target);
void bench_heavy_views(int quick);
/* Keys that could stall the picture: the longest frame from each key on (bench_keys.c). */
void bench_key_gaps(int repeats, int quick);
/* One heavy view alone, for a profiler or paired timings (bench_frame.c;
 * `bench_engine --frame-view`). */
void bench_heavy_one(const char *scene, const char *set, int n, int compare, int ghost, int lanes, int trails, double seconds,
                     double dt);

/* The largest |a[i] - b[i]| over n, a NaN difference taken as the largest
 * (bench_base.c): the error measure of the peer, rkn and stiff tables. */
double bench_max_diff(int n, const double *a, const double *b);

#endif
