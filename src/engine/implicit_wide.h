/* Private to the engine: Newton's passes over the state (implicit_wide.c),
 * four lanes wide. Each is the plain loop of reference_implicit.c bit for
 * bit; the norms only steer Newton's decisions, never its iterates. */
#ifndef SW_ENGINE_IMPLICIT_WIDE_H
#define SW_ENGINE_IMPLICIT_WIDE_H

/* |v|₂: the sum of squares in four partial sums (component i into sum
 * i mod 4, the tail into sum 0), added (s0 + s2) + (s1 + s3); where that
 * sum would overflow or lose digits, swi_norm2_scaled. */
double swi_norm2(int n, const double *v);
/* |v|₂ scaled by the largest component (one serial sum of (v_i/m)²). */
double swi_norm2_scaled(int n, const double *v);
/* g = h·g - (d + λ·δ) (the residual -G at the trial iterate); returns |g|₂
 * as swi_norm2 takes it. */
double swi_residual(int n, double *g, double h, const double *d, double lambda, const double *delta);
/* d += λ·δ; returns |δ|∞ (NaN when any component is) and sets *size =
 * |y + d|∞ (NaN components skipped). */
double swi_advance(int n, double *d, double lambda, const double *delta, const double *y, double *size);

#endif
