/* The engine's Nyström methods (rkn, rkn12) in the tests' hands, for
 * tests/check_rkn.c and tests/check_rkn12.c. A method is named as
 * 'stepwise list integrators' names it. */
#ifndef SW_TESTS_NYSTROM_RUN_H
#define SW_TESTS_NYSTROM_RUN_H

#include "nystrom.h"
#include "stepwise/particles.h"

/* Accelerations in long double, for nys_steps (nystrom.h): the oscillator
 * x'' = -x and Kepler's x'' = -x/|x|³. */
void nys_oscillator(const long double x[2], long double a[2]);
void nys_kepler(const long double x[2], long double a[2]);

/* Kepler's ellipse (a = 1, μ = 1, eccentricity e, from perihelion) and the
 * oscillator x = (cos t, 0) at t: (x, v) into out. */
void nys_kepler_exact(double e, double t, double out[4]);
void nys_oscillator_exact(double t, double out[4]);

/* max_i |a_i - b_i| over a state of 4; the least-squares slope of log e
 * against log h over n points. */
double nys_max_err(const double *a, const long double *b);
double nys_slope(const double *h, const double *e, int n);

/* One particle of mass 1: on a zero-rest-length spring k = 1 (c = damping)
 * to the origin from (1, 0) at rest, or (kepler_orbit) about a central
 * body μ = 1 from perihelion of the ellipse of eccentricity e. */
void nys_particle(sw_particles *p, int kepler_orbit, double e, double c);

/* n steps of h exactly (every trial accepted) on that particle, c = 0:
 * the state into y, the evaluations into *evals. */
void nys_fixed(const char *method, int kepler_orbit, double e, double h, long n, double y[4], long *evals);

/* The largest state error at T after n fixed steps from the start above
 * (oscillator, or orbit at eccentricity e) against the closed form: of the
 * engine's method, or of the weights wx, wv with the tableau's stages
 * stepped in long double (an embedded solution the engine only uses for
 * its error estimate). */
double nys_engine_error(const char *method, int kepler_orbit, double e, double T, long n);
double nys_tableau_error(const nys_tableau *tb, const long double *wx, const long double *wv, int kepler_orbit,
                         double e, double T, long n);

/* The engine's method is its tableau (ck_assert): 40 fixed steps of h[0]
 * on the oscillator and of h[1] on the orbit at e = 0.5 end within tol of
 * the tableau's weights bx, bv stepped in long double, and take
 * 1 + per_step evaluations a step. */
void nys_engine_is_tableau(const char *method, const nys_tableau *tb, const long double *bx, const long double *bv,
                           const double h[2], int per_step, double tol);

/* The method's one-particle entry and its general one end on the same
 * bits (ck_assert). */
void nys_one_particle_same_bits(const char *method);

/* 300 steps of method on the one particle p under control at rtol = atol =
 * 1e-10 (ck_assert that each succeeds), through p's own solver view, or
 * (inline_path 0) through a copy of it without the inline paths (central1,
 * spring1): the state into y, the accepted and rejected steps and the
 * evaluations into counts. */
void nys_controlled_300(const char *method, sw_particles *p, int inline_path, double y[4], long counts[3]);

/* One particle on one anchored spring, with gravity and without: the
 * method's entry that computes the spring inline (sw_ode_fast's spring1)
 * ends on the same bits, steps, rejections and evaluations as through the
 * derivative, 300 steps under control at 1e-10 (ck_assert); and a second
 * spring, damping, a second particle or a resting floor takes the inline
 * spring away. */
void nys_spring_inline_same_bits(const char *method);

/* The method under error control at rtol = atol = tol over [0, T]: the
 * error against the closed form at T, the evaluations, and (steps not
 * NULL) the smallest and largest accepted step with the radius of each. */
double nys_controlled(const char *method, int kepler_orbit, double e, double T, double tol, long *evals,
                      double steps[4]);

/* Tolerance proportionality (ck_assert): at tol = tol0, tol0/100, ..., four
 * tolerances, on the oscillator over t = 30 and the orbit at e = 0.5 over
 * one period, the error at the end is below 100 × tol and each 100×
 * tighter tolerance cuts it by 20 .. 1000×. */
void nys_tolerance_proportional(const char *method, double tol0);

/* Damping, drag and a flow field refused with a one-line message naming
 * why and what to use; undamped springs and k = 0 drag accepted
 * (ck_assert). */
void nys_refuses_velocity_forces(const char *method);

#endif
