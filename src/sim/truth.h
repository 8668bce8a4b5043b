/* The truth module: every question about accuracy and stability is answered
 * here, once, with one set of reference tolerances. The true state (the
 * scene's closed form where it holds for these parameters, else a tight
 * reference run), the error norm, the energy of the motion, whether a
 * method can run a scene, and linear stability: the eigenvalues of the
 * scene's linearisation, each method's growth per step on them computed
 * from its own one-step map (plugins included), and the largest stable Δt.
 * The meter, `stability`, `bench`, the ghost and the lessons all ask it. */
#ifndef SW_SIM_TRUTH_H
#define SW_SIM_TRUTH_H

#include <stddef.h>

#include "stepwise/sim.h"

/* The reference run: the most accurate built-in adaptive method at these
 * tolerances (rtol, atol = 1e-14 against states of order one). */
#define SW_TRUTH_RTOL 1e-12
#define SW_TRUTH_ATOL 1e-14

/* Work budgets, in state components × derivative evaluations (about 2.5e8
 * of them a second here for particles, 5e7 for the gyre's trigonometry):
 * what a key press may spend measuring (about half a second), what a live
 * reference run may spend per simulated second, and what a report
 * (`stability`, the `w` plot) may spend before it starts. Work above a
 * budget is refused up front with the estimate in the message. */
#define SW_WORK_KEY 1e8
/* The reference's cost is measured by a pilot of 20 steps unless those
 * would cost more than this (a thousand key presses): then it is estimated
 * at the scene's step, without running anything. */
#define SW_TRUTH_PILOT_MAX 1e11
#define SW_WORK_LIVE_PER_S 5e7
#define SW_WORK_REPORT 1e10

/* ---- the true state ------------------------------------------------------ */

/* The method of the reference runs: the most accurate built-in adaptive one. */
const sw_integrator *sw_truth_reference_method(void);

typedef enum sw_truth_source {
    SW_TRUTH_NONE = 0,      /* neither a closed form nor a trustworthy reference */
    SW_TRUTH_EXACT = 1,     /* the scene's closed form */
    SW_TRUTH_REFERENCE = 2  /* a tight-tolerance reference run */
} sw_truth_source;

/* Where the truth for a built system comes from; why (may be NULL) gets
 * the reason when it is not the closed form ("the mass swings through its
 * anchor ..."), or "" for EXACT. */
sw_truth_source sw_truth_source_of(const sw_system *sys, char *why, size_t whylen);

/* The true state along one run, advanced on demand. */
typedef struct sw_truth {
    sw_truth_source source;
    sw_system sys;        /* a private copy of the scene (exact() reads its parameters) */
    sw_sim ref;           /* the reference run (REFERENCE) */
    int have_ref, failed;
    long max_evals;       /* the reference run's evaluations at most (0: no bound); past them
                           * sw_truth_at fails, why saying so (a caller's budget: set it before
                           * the first sw_truth_at) */
    double frame;         /* the reference run's frame (its largest step): the scene's dt, or
                           * longer when only far-apart times will be asked for (set it
                           * before the first sw_truth_at) */
    double *y;            /* the state at time t (sys.ode->dim doubles) */
    double t;             /* NaN: none computed yet */
    double ref_rate;      /* the reference's evaluations per simulated second over its first
                             steps (0: not yet measured); a run that spends SW_TRUTH_CRAWL times
                             what that rate predicts, plus SW_TRUTH_CRAWL_SLACK, is stopped */
    char why[SW_ERRLEN];  /* see sw_truth_source_of */
} sw_truth;

/* A reference run that costs this many times what its first steps
 * predicted is crawling (balls at rest on the floor: a contact located
 * every step) and is stopped: the truth ends there (sw_truth_at: NULL,
 * `why` says so) instead of running on for minutes (issue 38:
 * `stability bounce --set drag=0.5` never returned). */
#define SW_TRUTH_CRAWL 50.0
#define SW_TRUTH_CRAWL_SLACK 1e5 /* evaluations: short runs are never stopped */

/* Prepare the truth for scene sc with parameters p (NULL: defaults).
 * 0, or a status with err filled (the scene does not build, no memory). */
int sw_truth_init(sw_truth *tr, const sw_scene *sc, const double *p, char *err, size_t errlen);
void sw_truth_free(sw_truth *tr);
/* What one derivative evaluation of sys costs in the budgets' unit, state
 * components (dim, or more where a force joins every pair of particles),
 * and in *solve what one implicit solve costs (engine/particles_solve.h). */
double sw_truth_eval_work(const sw_system *sys, double *solve);
/* What one step of m on sys costs in the same unit: its nominal evaluations
 * × an evaluation's work; an implicit method 4 times that (Newton's
 * iterations) and 3 solves beyond what an evaluation costs. An estimate for
 * budgets, not a count. */
double sw_truth_step_work(const sw_system *sys, const sw_integrator *m);
/* What a reference run to t_end would cost, in state components times
 * derivative evaluations (sw_truth_eval_work × evaluations): measured on a pilot of up to
 * 20 accepted steps and extrapolated by their mean step. 0 for a closed
 * form, INFINITY when the pilot fails. Callers refuse work above a budget
 * with this number in the message. */
double sw_truth_reference_cost(sw_truth *tr, double t_end);

/* The true state at time t >= 0, or NULL when there is none (source NONE,
 * or the reference run failed). A reference run steps forward to t and is
 * restarted when t goes back; the pointer is valid until the next call. */
const double *sw_truth_at(sw_truth *tr, double t);
/* The true state at time t into out, from a fresh truth (one call, one
 * run); 0, or -1 when there is none. */
int sw_truth_state(const sw_scene *sc, const double *p, double t, double *out);

/* A run's error, as `bench` and the dt-change message measure it: the
 * largest over SW_TRUTH_SAMPLES times evenly spread to the report time T,
 * T·j/SW_TRUTH_SAMPLES for j = 1..SW_TRUTH_SAMPLES. One report time can be
 * special (a whole number of periods, where symplectic Euler's first-order
 * error cancels and it reads as second order); the run as a whole is not. */
#define SW_TRUTH_SAMPLES 16
/* The j-th sample time of a run to T (j = SW_TRUTH_SAMPLES: T itself). */
double sw_truth_sample_time(double T, int j);
/* The first sample a run at fixed step dt stops at: 1, or SW_TRUTH_SAMPLES
 * (T alone) when dt is above half the samples' spacing, where stopping at
 * every sample would shorten the step asked for. Adaptive runs: pass 0. */
int sw_truth_first_sample(double T, double dt);

/* The error norm: max over every state component (positions, and for
 * particles velocities) of |y_i - truth_i|. NaN when any is NaN. */
double sw_truth_error(int dim, const double *y, const double *truth);

/* Whether method m can run scene sc at all, without building it (kind of
 * system, second-order methods on flows, adaptive methods where a fixed
 * step is needed is the caller's business); 1, or 0 with why filled. */
int sw_truth_method_applies(const sw_scene *sc, const sw_integrator *m, char *why, size_t whylen);

/* ---- linear stability ---------------------------------------------------- */

#define SW_TRUTH_MODES 48

/* A mode of the linearisation: eigenvalue λ and its partner μ, the other
 * root of the mode's own equation (x'' = (λ+μ)x' - λμ·x for a particle
 * system; for a flow, or a complex λ, μ is λ's conjugate). */
typedef struct sw_mode {
    double re, im;        /* λ */
    double pre, pim;      /* μ */
} sw_mode;

typedef struct sw_spectrum {
    int order;            /* 1 flow, 2 particles */
    int n;                /* modes kept, stiffest first */
    sw_mode mode[SW_TRUTH_MODES];
    int growing;          /* physically growing modes (Re λ > 0) left out */
    int free;             /* free modes (λ = μ = 0: a spring at its rest length swung sideways, a
                             uniform flow) left out: every consistent method maps them by 1 */
    int complete;         /* 1: every eigenvalue; 0: the stiffest mode only */
    double largest;       /* largest |λ| over the modes kept */
} sw_spectrum;

/* The spectrum of ∂f/∂y for system sys at state y and time t: all of it for
 * flows (2x2 blocks per point) and for particle systems up to 32 particles
 * (dense QR), the stiffest mode by power iteration above that. Modes that
 * grow physically (an orbit's tidal stretching, a compressed spring's
 * buckling) are counted in `growing` and left out: their growth is the
 * physics, not the method. 0, or -1 when the eigenvalues do not converge. */
int sw_truth_spectrum(sw_system *sys, double t, const double *y, sw_spectrum *out);

/* The growth per step of method m at step h: the spectral radius of the
 * method's own one-step map on each mode's test system (the map includes
 * what the method carries between steps, so Verlet's reused acceleration
 * makes it 3x3), the largest over the spectrum; NaN for adaptive methods
 * or when the step fails. *worst (may be NULL) gets its mode. */
double sw_truth_growth_all(const sw_integrator *m, const sw_spectrum *sp, double h, int *worst);

/* ρ within this of 1 is neutral: rounding in the eigenvalues of a small
 * one-step map is about 1e-15. */
#define SW_TRUTH_NEUTRAL 1e-12

/* The horizon a growth is judged over: 100 periods 2π/|λ| of the stiffest
 * mode, and at least 20 report times (the stability probes run this long). */
double sw_truth_horizon(const sw_scene *sc, double stiffest);
/* Whether growth ρ per step of dt shows over the horizon: the mode grows by
 * more than 1% (ρ^(T/dt) > 1.01). Slower growth is real but no run shows it. */
int sw_truth_growth_visible(double rho, double dt, double horizon);

/* The largest step h <= h_max such that every step up to it keeps the growth
 * of every mode at most 1 + SW_TRUTH_NEUTRAL: 0 when the method grows
 * already at |λ|·h = 0.01 (Euler and RK2 on an undamped oscillator grow at
 * every step), h_max (and *unbounded = 1) when no step up to h_max grows. */
double sw_truth_limit(const sw_integrator *m, const sw_spectrum *sp, double h_max, int *unbounded);

/* A workspace for asking again and again (the live meter): with it the
 * calls below allocate nothing once it has grown to the system and met the
 * method. NULL when out of memory. */
typedef struct sw_truth_work sw_truth_work;
sw_truth_work *sw_truth_work_new(void);
void sw_truth_work_free(sw_truth_work *w);
int sw_truth_spectrum_with(sw_truth_work *w, sw_system *sys, double t, const double *y, sw_spectrum *out);
double sw_truth_growth_with(sw_truth_work *w, const sw_integrator *m, const sw_spectrum *sp, double h,
                            int *worst);
double sw_truth_limit_with(sw_truth_work *w, const sw_integrator *m, const sw_spectrum *sp, double h_max,
                           int *unbounded);

/* The live meter's spectrum a slice at a time. A large coupled particle
 * system's stiffest mode is found by power iteration, one product with the
 * Jacobian per pass, up to a few hundred passes: too slow for one frame at
 * n = 1e5. A job runs those passes a given number at a time; run whole
 * from a cold start it gives exactly what sw_truth_spectrum_with gives. A
 * job started again on the same system starts warm, from the last vector
 * (the state moved a little: a few passes do). The Jacobian's blocks are
 * assembled in sys by the first pass: nothing else may assemble them in
 * that system until the job is done (start it again if something did). */
typedef struct sw_spectrum_job {
    int active;           /* started and not yet done */
    int stage, it, n2;    /* where it is: main or shifted iteration, pass, 2n */
    int assembled;        /* the blocks in sys are at the job's state */
    int sliced;           /* assembling the blocks takes a call of its own */
    int growing;          /* a physically growing mode was the largest */
    int warm_ok;          /* v holds the last job's vector for this system */
    double t;             /* time of the state the job started at (the caller's) */
    double lam, lam_main, shift;
    double *v, *w;        /* into buf */
    double *buf;          /* 2 · 2n doubles, owned */
    size_t cap;
    /* particles no force joins (each one's own blocks, particle by particle) */
    const double *own;    /* the blocks at the job's state, in sys's solver; NULL: not yet */
    int next, central;    /* the next particle to take; a central field (every particle asked) */
    double last[8];       /* the last particle's blocks per unit mass (a particle like it adds nothing) */
    sw_spectrum part;     /* the modes so far */
} sw_spectrum_job;

/* 1 when sys's spectrum takes more than `slice` state components × passes:
 * power iteration on a large coupled system, or the modes of many free
 * particles (a fluid's, each particle's own blocks; one costs about 512
 * components). Then the meter runs it as a job. */
int sw_truth_spectrum_sliced(const sw_system *sys, long slice);
/* Start (or restart) job j on sys, for the state at time t: 0, or -1 out of memory. */
int sw_spectrum_job_start(sw_spectrum_job *j, const sw_system *sys, double t);
/* Up to `passes` more passes at state y (the state the job started at; it
 * is read by the first call only, which assembles the Jacobian's blocks);
 * for free particles, the modes of up to passes · 2n / 512 of them. 1 when done, with out filled; 0 when
 * there is more to do; -1 when it failed (or was not started). */
int sw_spectrum_job_run(sw_spectrum_job *j, sw_system *sys, const double *y, long passes, sw_spectrum *out);
void sw_spectrum_job_free(sw_spectrum_job *j);

/* The same over a run, from spectra taken at `samples` times in [0, t_end]
 * along the true solution (or, with no truth, at the start alone): the
 * smallest limit and the time whose linearisation sets it, the largest |λ|
 * seen, and, when h > 0, the largest growth per step at step h, where, and
 * the growth accumulated along the run.
 * 0 with *out set, or -1 with err filled. */
typedef struct sw_truth_along {
    double limit;         /* dt; NaN when the method fails on its test systems */
    int unbounded;        /* no sample limits the step up to h_max */
    double t_limit;       /* the sample that sets the limit */
    double stiffest;      /* largest |λ| seen; 0 when nothing moves */
    double growth;        /* at h: the largest growth per step over the samples (NaN: h = 0) */
    double growth_lambda; /* |λ| of the mode that grows most */
    double t_growth;      /* the sample where it does */
    double growth_total;  /* at h: the growth accumulated over [0, t_end], each sample's growth per
                             step held over its share of the run */
    double ref_work;      /* the reference run behind the samples: evaluations × sw_truth_eval_work
                             (the same whether this call ran it or found it done) */
} sw_truth_along;
int sw_truth_along_run(const sw_scene *sc, const double *p, const sw_integrator *m, double t_end, int samples,
                       double h_max, double h, sw_truth_along *out, char *err, size_t errlen);

#endif
