/* Levi-Civita regularisation of one body about one centre (issue 26): the
 * close pass of an eccentric orbit, taken in a clock that slows down there.
 *
 * One particle (state [x | v], dim 4) moves under a central field
 * -mu·d/|d|³, d = x - c, and whatever else its system adds (P, the rest of
 * its acceleration). In complex numbers d = u², and in the fictitious time
 * s with dt = r ds (r = |d| = |u|²) the motion is
 *
 *     u'' = (h/2)·u + (r/2)·conj(u)·P,   h' = r·(v · P),   t' = r,
 *
 * with h = |v|²/2 - mu/r the Kepler energy and v = 2u'/conj(u). Without P
 * it is a harmonic oscillator (h < 0 is constant): the 1/r² singularity and
 * the steps it forces at the pericentre are gone, and a method steps in s
 * at about the same size all around the orbit (Stiefel & Scheifele, *Linear
 * and Regular Celestial Mechanics*, 1971, ch. 1-2; the planar case is
 * Levi-Civita's, 1920). The regularised state is w = [u, u', h, t]
 * (dim 6), an ordinary first-order system for any of the engine's methods.
 *
 * Where the particle is alone in its field (sw_ode_central1) P is 0 and the
 * particle's own derivative is never called; otherwise it is, once per
 * evaluation, and P is its acceleration less the field's. */
#ifndef SW_ENGINE_REGULARISE_H
#define SW_ENGINE_REGULARISE_H

#include <stddef.h>

#include "engine/lanes.h"
#include "engine/stepper.h"
#include "stepwise/ode.h"

enum { SW_LC_DIM = 6 };

/* f = dw/ds alone in the field (P = 0): the oscillator u'' = (h/2)·u and
 * the clock t' = |u|², each pair of f written by one 16-byte store, as
 * the steppers' small entries read them (dop853's six-component one loads
 * 16 bytes at a time: a load that one store wrote is forwarded from it,
 * one that two 8-byte stores wrote waits for the cache). Lane-wise IEEE
 * operations: the bits of the scalar ones. Inline, so that a step can
 * take it into its stages (dop853.c); the regularised system's derivative
 * is sw_lc_deriv_alone, the same. */
static inline void sw_lc_alone(const double *w, double *f)
{
    v2d half_h = { 0.5 * w[4], 0.5 * w[4] };
    v2d acc = half_h * load2(w), clock = { 0.0, w[0] * w[0] + w[1] * w[1] };
    store2(f, load2(w + 2));
    store2(f + 2, acc);
    store2(f + 4, clock);
}

/* The regularised system's derivative alone in the field; a step that
 * finds it as ode->deriv may call sw_lc_alone instead. */
sw_deriv_fn sw_lc_deriv_alone;

typedef struct sw_lc {
    sw_ode ode;        /* the regularised system, in s; ode.ctx is this struct */
    sw_ode *base;      /* the particle's own system, [x | v] -> [v | a] */
    double cx, cy, mu; /* the centre and the field's acceleration parameter */
    int alone;         /* the field is the particle's only force: P = 0 */
    double yb[4], fb[4]; /* scratch: the particle's state and derivative */
    const char *why;     /* why the last sw_lc_step failed (static text) */
} sw_lc;

/* The regularised system of base, a one-particle system ([x | v], dim 4,
 * order 2) in a central field of parameter mu at (cx, cy), mu > 0 (the
 * field's acceleration, already divided by the mass). SW_OK, or SW_EINVAL
 * with err naming what does not fit. */
int sw_lc_init(sw_lc *lc, sw_ode *base, double cx, double cy, double mu, char *err, size_t errlen);

/* One-particle systems alone in one field: the same from the field the
 * system declares. SW_OK, or SW_EINVAL with err. */
int sw_lc_init_central(sw_lc *lc, sw_ode *base, char *err, size_t errlen);

/* [x | v] at time t into w, and back. The particle must not be at the
 * centre (r > 0); sw_lc_from returns SW_EINVAL there, else SW_OK. Of the
 * two square roots of d it takes the one with re(u) >= 0. */
int sw_lc_from(const sw_lc *lc, double t, const double *y, double *w);
void sw_lc_to(const sw_lc *lc, const double *w, double *y);

/* A run in the variables, from step to step, alone in the field. They
 * carry what the particle's state does not: the energy h, the flow's
 * constant, which taken back from [x | v] would take up each step's error
 * in u and u' (a drift of the period); and a method's first-same-as-last
 * derivative is f at w, a function of w alone (sw_lc_alone: no clock, no
 * parameter). So a step that starts where the last one left the
 * particle, bit for bit, goes on from w; any other (a rewind, a state set
 * from outside, a changed field, a new run, a perturbed system) starts
 * from the particle. */
typedef struct sw_lc_left {
    double w[SW_LC_DIM]; /* the regularised state the steps advance */
    int valid;           /* the key below is where w left the particle: */
    const sw_ode *base;  /* the system, */
    double cx, cy, mu;   /* its field, */
    double t, y[4];      /* the time and the state, bit for bit */
} sw_lc_left;

/* left->w for a step from (t, y) in lc: 1, w as the last step left it,
 * where lc is alone in its field and the key is lc's system and field
 * and (t, y) bit for bit; else 0,
 * w = sw_lc_from's, or SW_EINVAL where that fails. Either way the key is
 * then cleared until sw_lc_leave. */
int sw_lc_resume(sw_lc_left *left, const sw_lc *lc, double t, const double *y);

/* The step in lc ended at left->w: the particle's state into y
 * (sw_lc_to), and the key set to it and to w's clock. */
void sw_lc_leave(sw_lc_left *left, const sw_lc *lc, double *y);

/* One step of s, an adaptive method made for lc->ode (its rtol and atol
 * set), from w (its clock at t = w[5]) of at most dt in t: the step the
 * error control takes, or, where that would pass t + dt, the one that
 * ends there, found by Newton's method on its length (t' = r) and the
 * clock set to t + dt within 4 ulps (1e-9 where Newton's method stalls,
 * at a collision). SW_OK, or SW_EDIVERGED when a step fails or the clock
 * stops advancing, with lc->why saying which. */
int sw_lc_step(sw_lc *lc, sw_stepper *s, double *w, double dt);

/* Steps of sw_lc_step until the clock reaches t_end; the particle's state
 * there into y. SW_OK, or SW_EDIVERGED. */
int sw_lc_run_until(sw_lc *lc, sw_stepper *s, double *w, double t_end, double *y);

#endif
