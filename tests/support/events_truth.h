/* Event location's independent truths and order measurements, shared by
 * tests/check_events.c and the claims rows (claims_events.c). */
#ifndef SW_TEST_EVENTS_TRUTH_H
#define SW_TEST_EVENTS_TRUTH_H

#include "stepwise/stepwise.h"

/* Uniform motion between walls lo and hi, speed times -e at each: the
 * state at t; the hit times into hit[] (up to *nhit; both may be NULL). */
void ev_walls_at(double x, double v, double lo, double hi, double e, double t, double *xo, double *vo,
                 double *hit, int *nhit);
/* Free flight under g above a floor at 0, leaving at e times the landing
 * speed: the state at t; the landing times into land[] (up to *nland). */
void ev_floor_at(double y, double v, double g, double e, double t, double *yo, double *vo, double *land,
                 int *nland);
/* The undamped spring through its anchor from (x, v), piecewise harmonic
 * about ±rest: the state at t; the crossing times into cross[]. */
void ev_spring_closed(double k, double m, double rest, double x, double v, double t, double *xo, double *vo,
                      double *cross, int *ncross);
/* A sim of scene (p NULL: defaults) under method with step dt and mode. */
void ev_sim_of(sw_sim *s, const char *scene, const double *p, const char *method, double dt,
               sw_events_mode mode);
/* Largest state error at T against truth. */
double ev_run_error(const char *scene, const double *p, const char *method, double dt, sw_events_mode mode,
                    double T, const double *truth);
/* Mean log2 error ratio over dt, dt/2, dt/4 (errors into errs[3]). */
double ev_observed_order(const char *scene, const double *p, const char *method, double dt,
                         sw_events_mode mode, double T, const double *truth, double *errs);
/* Least-squares slope of log2 error against log2 dt over dt = 0.01 / 2^j, j < 6, stepped over. */
double ev_step_order(const char *scene, const double *p, const char *method, double T, const double *truth);
/* The bounce's state at T (p: n, g, e, drag): closed form without drag,
 * else dop853 at rtol 1e-13 with events located. */
void ev_bounce_truth(const double *p, double T, double *truth);
/* The spring's state at T (p: k, m, c = 0, rest, stretch, g = 0). */
void ev_spring_truth(const double *p, double T, double *truth);

#endif
