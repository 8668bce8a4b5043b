/* Watching a run for growth: the measured half of stability, shared by the
 * `stability` probes and the live meter. The quantity watched is the
 * energy of the motion, normalised to 1 at the start (sw_watch_measure), so
 * one set of thresholds serves every scene. */
#ifndef SW_SIM_WATCH_H
#define SW_SIM_WATCH_H

#include <stddef.h>

#include "stepwise/sim.h"

#define SW_WATCH_WINDOWS 20

typedef enum sw_watch_verdict {
    SW_WATCH_STEADY = 0,  /* no growth seen (bounded, or decaying) */
    SW_WATCH_BOUND = 1,   /* M rose past 1000: the motion gained a thousandfold energy */
    SW_WATCH_RAISED = 2,  /* M averaged above the raised level over a whole window, or above
                             that many times its lowest window: growth a nonlinearity capped
                             (see sw_watch_raised_level); a bound orbit: E >= 0 at any sample */
    SW_WATCH_TREND = 3    /* M's window peaks climbed window after window by more than
                             sampling an oscillation can make them (see sw_watch_sampling_floor in watch.c),
                             or the latest peak stands above the first by more than the first
                             varied */
} sw_watch_verdict;

typedef struct sw_watch {
    double window;        /* length of a window, in simulated time */
    double raised;        /* the level of SW_WATCH_RAISED */
    double rebound;       /* ... and the factor over the lowest window mean (0: none) */
    double low_mean;      /* the lowest window mean so far */
    double t0;            /* start of the current window */
    int windows;          /* complete windows so far */
    double first_max, first_min;   /* over the first window */
    double first_mean;    /* ... and its mean (NaN before it closes) */
    double escape;        /* a bound orbit: M at or above this (M = 2: E = 0) ... */
    double revolution;    /* ... for this long without a break is raised: the orbit's period at the
                             start (0: at any sample, as for an orbit whose period is unknown) */
    double unbound_since; /* the time M last rose to escape and has stayed there (NaN: it has not) */
    int relative;         /* 1: the raised level is `raised` times the first window's mean
                             when that is above 1 (a symplectic method's bounded swing) */
    double peak[SW_WATCH_WINDOWS]; /* peaks of the last complete windows, oldest first */
    double mean[SW_WATCH_WINDOWS]; /* and their means */
    int kept;             /* entries in peak/low */
    double cur_max, cur_min, cur_sum; /* the window in progress */
    long cur_n;
    double max_seen;
    double last;          /* the previous sample (NaN: none yet) */
    double step_max;      /* the largest |M_k - M_(k-1)| seen: how coarsely M is sampled */
    sw_watch_verdict verdict;      /* latched once not steady */
} sw_watch;

/* 1 when growth on sim s can be judged from M: no events at step
 * boundaries (contact and births split nearby runs), and an energy with a
 * floor or a well (an orbit), or a flow with a closed form (judged on |y|²;
 * a river's particles drift away from the origin, which is not growth);
 * else 0 with why filled. */
int sw_watch_judges(const sw_sim *s, char *why, size_t whylen);

/* M for a sim now: (E - E_floor) / (E(0) - E_floor) where the system has a
 * resting state, else 1 + (E - E(0)) / |E(0)|; for a flow without energy
 * |y|² / |y(0)|² (y0: the start). NaN when none applies. */
double sw_watch_measure(const sw_sim *s, const double *y0);

/* The level a window's mean M must pass to count as raised: 2 for a bound
 * state without a resting state (an orbit: M = 2 is E = 0, the planet
 * escaping); else 3 for a method that is not symplectic (a stable one only
 * loses energy, or gains a little of it), 30 for a symplectic one, and for
 * it 30 times the first window's mean where that is above 1 (its energy
 * swings about its start by a factor ω·dt sets, bounded all the same:
 * symplectic Euler's, started from rest, peaks at 1/(1 - |L|dt/2) and
 * averages 1/(1 - (|L|dt/2)²): 25 at 98% of its limit, 500 at 99.9%;
 * the first window, five periods of the stiffest mode at least, shows that
 * swing in full, and a bounded run's later windows average what it did). */
double sw_watch_raised_level(const sw_sim *s);

/* Start watching; window: simulated time per window (> 0); raised: see
 * sw_watch_raised_level, also the rebound factor: a window mean above
 * `raised` times the lowest before it (and above 1e-4, clear of rounding)
 * is raised too. Energy that sank (damping, or the truth) and comes back
 * is energy the method put in: no scene adds energy to its motion. */
void sw_watch_init(sw_watch *w, double window, double raised);
/* The same for sim s: its raised level (relative to the first window for a
 * symplectic method); for a bound state without a resting state (an orbit,
 * where M is not a fraction of the start's energy) no rebound test, and
 * escape where M >= 2 (E >= 0) holds for a whole revolution, the orbit's
 * period at the start (one body about a fixed centre: 2π·μ/(−2ε)^(3/2),
 * ε its energy per unit mass): a symplectic method's energy at a coarse
 * pericentre pass rises above 0 for a few steps and comes back, and the
 * orbit stays bound (symplectic Euler at e = 0.9, Δt = 0.01, 251 s:
 * largest radius 3.77); a planet that escapes stays unbound. With no
 * period known (many bodies), at any sample. */
void sw_watch_start(sw_watch *w, double window, const sw_sim *s);
/* 1 while an escape is being verified: M has been at or above the escape
 * level for less than a revolution. A run that ends then is run on until
 * the watch decides (at most a revolution more): the run itself shows
 * whether the orbit stays unbound. */
int sw_watch_pending(const sw_watch *w);
/* Feed a sample M at time t (t increasing); returns the verdict so far. */
sw_watch_verdict sw_watch_add(sw_watch *w, double t, double m);
/* Close the window in progress (the end of a run) and judge it too. */
sw_watch_verdict sw_watch_finish(sw_watch *w);
/* A few words for a verdict ("energy x1000", ...). */
const char *sw_watch_text(sw_watch_verdict v);

#endif
