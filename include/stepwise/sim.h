/* A running simulation: a built scene, an integrator and its workspace, the
 * clock, counters, and blow-up detection. The TUI, the recorder, the checker
 * and the benchmarks all advance a sim the same way, so a trace recorded in
 * one equals a trace recorded in another, bit for bit. */
#ifndef STEPWISE_SIM_H
#define STEPWISE_SIM_H

#include <stddef.h>
#include "stepwise/base.h"
#include "stepwise/integrator.h"
#include "stepwise/scene.h"

/* How a sim meets its scene's events (stepwise/scene.h): at the end of the
 * step that crossed them (today's handling, first order), or located inside
 * the step, which is cut there, jumped and completed (the method's order). */
typedef enum sw_events_mode { SW_EVENTS_STEP = 0, SW_EVENTS_LOCATE = 1 } sw_events_mode;

typedef struct sw_sim {
    sw_system sys;
    sw_stepper *stepper;   /* the method's running state, owned (opaque) */
    const sw_integrator *method;
    double rtol, atol;     /* error control of adaptive methods, Newton's of implicit ones */
    double dt;             /* fixed step (rk45: initial and largest step) */
    double t;
    long steps;
    double energy0;        /* energy at t = 0 (NaN when the scene has none) */
    struct sw_sim_derived *derived; /* quantities worked out on first use (private) */
    double runaway;        /* a state component beyond this counts as a blow-up */
    int blown;             /* 1 once the state went non-finite or ran away */
    long blow_step;
    double blow_time;
    char blow_reason[SW_ERRLEN];
    sw_events_mode events; /* SW_EVENTS_STEP unless sw_sim_set_events says otherwise */
    struct sw_sim_events *ev; /* location workspace (private), NULL in step mode */
} sw_sim;

/* Limits on the step that every front end accepts. */
#define SW_DT_MIN 1e-9
#define SW_DT_MAX 1e3

/* Build scene sc (p NULL: defaults) under method m with step dt; 0 or a status. */
int sw_sim_init(sw_sim *s, const sw_scene *sc, const double *p, const sw_integrator *m,
                double dt, char *err, size_t errlen);
void sw_sim_free(sw_sim *s);
/* Change the method and keep the state and time; 0 or SW_EINVAL. */
int sw_sim_set_method(sw_sim *s, const sw_integrator *m, char *err, size_t errlen);
/* Meet events by mode from now on (kept across method changes and resets);
 * 0, or SW_ENOMEM with err filled (the location workspace). */
int sw_sim_set_events(sw_sim *s, sw_events_mode mode, char *err, size_t errlen);
/* Events located so far (0 in step mode), and the time of the last one
 * (NaN when none). */
long sw_sim_events_located(const sw_sim *s);
double sw_sim_events_last_time(const sw_sim *s);
/* "step" or "locate". */
const char *sw_events_mode_name(sw_events_mode mode);
/* Parse "step" or "locate"; 0, or SW_EINVAL with err naming what is allowed. */
int sw_events_mode_parse(const char *text, sw_events_mode *out, char *err, size_t errlen);

/* Set the tolerances (kept across method changes and resets). */
void sw_sim_set_tolerances(sw_sim *s, double rtol, double atol);
/* Accepted and rejected steps of an adaptive method so far (0 for the others). */
void sw_sim_step_counts(const sw_sim *s, long *accepted, long *rejected);
/* Change the step size; dt must lie in [SW_DT_MIN, SW_DT_MAX]. */
int sw_sim_set_dt(sw_sim *s, double dt, char *err, size_t errlen);
/* Start again from state y (ode->dim doubles) at the current time: caches
 * forgotten, E(0) taken anew from y. */
void sw_sim_set_state(sw_sim *s, const double *y);
/* Back to the initial state at t = 0 with counters cleared. */
int sw_sim_reset(sw_sim *s, char *err, size_t errlen);
/* One step (rk45: one accepted step, never past t_stop when t_stop > t).
 * Returns 0, or 1 when the sim has blown up (now or before). */
int sw_sim_step_until(sw_sim *s, double t_stop);
int sw_sim_step(sw_sim *s);
/* Step until t >= t_end (landing on it exactly) or a blow-up; 0 or 1. */
int sw_sim_run_until(sw_sim *s, double t_end);
/* Derivative evaluations so far. */
long sw_sim_evals(const sw_sim *s);
/* Whether a blow-up's reason (blow_reason, and the copies checks and
 * probes keep) is a plugin's step that refused (SW_PLUGIN_REFUSED): a run
 * that stopped, not one that diverged. */
int sw_sim_refused(const char *reason);
/* Energy now; NaN when the scene defines none. */
double sw_sim_energy(const sw_sim *s);
/* A bound on |sw_sim_energy - the exact energy|: 0 where the scene sums
 * it exactly, else its own bound (a large galaxy's tree). */
double sw_sim_energy_error(const sw_sim *s);
/* The energy scale drifts are measured against: the energy of the motion
 * at the start, E(0) - E_floor, where the system has a resting state of
 * least energy (a spring, a pendulum, a chain), else |E(0)| (an orbit's
 * binding energy, a projectile's launch energy). NaN when undefined. */
double sw_sim_energy_scale(const sw_sim *s);
/* The least energy of the system as built (its resting state): the scene's
 * own floor, else for particles with springs and no central body the energy
 * of the static equilibrium reached from the start (worked out once); NaN
 * when there is none (a potential unbounded below: an orbit, free flight). */
double sw_sim_energy_floor(const sw_sim *s);
/* The resting state reached from the start of a particle system (backward
 * Euler with the longest step dissipates every motion; its fixed point has
 * f(y) = 0: at rest where the forces balance) into out (dim doubles, may be
 * NULL), its energy into *energy (may be NULL). 0, or -1 when there is none
 * (a flow, no energy, contact, or the run does not settle). */
int sw_sim_resting_state(const sw_system *sys, double *out, double *energy);
/* 1 when the scale is the energy of the motion, 0 when it is |E(0)|. */
int sw_sim_energy_scale_is_motion(const sw_sim *s);
/* The energy's drift (E - E(0)) / scale, in percent; NaN when undefined. */
double sw_sim_energy_drift(const sw_sim *s);
/* A bound on |the drift shown - the exact drift|, in percent: the bounds
 * on E and E(0) over the scale; 0 when both are exact. */
double sw_sim_energy_drift_error(const sw_sim *s);
/* Largest absolute state error against the exact solution; NaN if none. */
double sw_sim_exact_error(const sw_sim *s, double *scratch);
/* The scene's invariant drift now (0 on exact paths); NaN when none. Worked
 * out once per state and kept until the state changes (bit for bit what a
 * fresh computation gives). */
double sw_sim_drift(const sw_sim *s);
/* Forget what was worked out from the state (the drift). Every sw_sim_
 * function that changes the state, the time or the system does it; call it
 * after writing s->sys.y, s->sys.extra or s->t directly. */
void sw_sim_state_changed(sw_sim *s);
/* Whether particle i is to be drawn now. */
int sw_sim_alive(const sw_sim *s, int i);

#endif
