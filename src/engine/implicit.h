/* Private to the engine: what the implicit methods' production form
 * (implicit.c) and lecture form (reference_implicit.c) share — Newton's
 * stopping rule and its continuation, which decide but compute no iterate
 * (implicit.c) — and Newton's passes over the state four lanes wide
 * (implicit_wide.c), each the plain loop of reference_implicit.c bit for
 * bit; the norms only steer Newton's decisions, never its iterates. */
#ifndef SW_ENGINE_IMPLICIT_H
#define SW_ENGINE_IMPLICIT_H

#include "engine/stepper.h"

/* Newton's stopping rule for the implicit methods (implicit.c), one for the
 * production and the lecture form: after an iteration with correction step
 * = λ·|δ|∞ at size = |y0 + Δ|∞ and |G|₂ gone from gnorm to gnew, 0
 * converged, -1 failed (*why set), 1 go on (*fresh: take J afresh;
 * *last_step the last correction, INFINITY at the start). */
int swi_newton_next(double step, double size, double gnew, double gnorm, double lambda, int keep_j, int *fresh,
                    double *last_step, const char **why);
/* Newton from Δ = d on the implicit equation over the step h (implicit.c),
 * J afresh at every iterate, at most 12 iterations: 0, d the solution. */
typedef int swi_newton_fn(sw_stepper *s, sw_ode *ode, double t, const double *y, double h, double theta,
                          double *d);
/* The continuation in σ·h, σ from 0 to 1, that solves the implicit step
 * where Newton from Δ = 0 failed with `why` (implicit.c), each equation by
 * `solve`: 0 with Δ in work vector 0, or SW_EDIVERGED with s->why = why. */
int swi_newton_continuation(sw_stepper *s, sw_ode *ode, double t, const double *y, double h, double theta,
                            swi_newton_fn *solve, const char *why);
/* Whether a kept J's full correction of |δ|∞ = step, after one of
 * last_step (INFINITY: none yet), with |y0 + Δ|∞ = size before it, leaves
 * Δ within the kept J's tolerance by swi_newton_next's rule: then the
 * correction is taken without evaluating G after it (both forms). */
int swi_newton_settled(double step, double size, double last_step);
/* |v|∞, NaN when any component is. */
double swi_norm_inf(int n, const double *v);
/* |v|₂ scaled by the largest component (one serial sum of (v_i/m)²). */
double swi_norm2_scaled(int n, const double *v);
/* g = h·g - (d + λ·δ) (the residual -G at the trial iterate); returns |g|₂:
 * the sum of squares in four partial sums (component i into sum i mod 4,
 * the tail into sum 0), added (s0 + s2) + (s1 + s3); where that sum would
 * overflow or lose digits, swi_norm2_scaled. */
double swi_residual(int n, double *g, double h, const double *d, double lambda, const double *delta);
/* d += λ·δ; returns |δ|∞ (NaN when any component is) and sets *size =
 * |y + d|∞ (NaN components skipped). */
double swi_advance(int n, double *d, double lambda, const double *delta, const double *y, double *size);

/* Newton's plain passes, in the loops' own order (AVX2 clones, the same
 * bits): ym = y + θ·(d + λ·δ), the iterate tried; with from_zero d = 0
 * first and ym = y + θ·d; g = h·g - d (-G), returning |g|₂ as
 * swi_residual takes it; y = y + 1·d, the step taken (sw_axpy's operations). */
void swi_trial_point(int n, double *ym, const double *y, double theta, const double *d, double lambda,
                     const double *delta);
void swi_start(int n, double *ym, const double *y, double theta, double *d, int from_zero);
double swi_minus_g(int n, double *g, double h, const double *d);
void swi_take(int n, double *y, const double *d);
/* v = v·h (v[i] *= h). */
void swi_scale(int n, double *v, double h);

#endif
