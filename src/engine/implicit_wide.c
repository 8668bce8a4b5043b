/* Newton's passes over the state for the implicit methods (implicit.c),
 * four lanes wide and fused: each gives the bits of the plain loops in
 * reference_implicit.c (lane k holds the components i ≡ k (mod 4), the
 * partial sums the plain loops keep; a maximum is the same in any order). */
#include "engine/implicit.h"

#include <math.h>
#include <string.h>

#include "engine/clones.h"
#include "engine/linalg.h"
#include "engine/stepper.h"

/* Four doubles side by side: lane k of a sum holds the chain of additions
 * of the components i ≡ k (mod 4), the scalar code's four partial sums;
 * lane-wise IEEE operations, so the bits do not depend on the width. */
typedef double v4d __attribute__((vector_size(4 * sizeof(double))));
typedef long long v4i __attribute__((vector_size(4 * sizeof(long long))));

/* (no functions that take or return one: without AVX that changes the ABI) */
static const v4i MAGNITUDE = { 0x7FFFFFFFFFFFFFFFLL, 0x7FFFFFFFFFFFFFFFLL, 0x7FFFFFFFFFFFFFFFLL,
                               0x7FFFFFFFFFFFFFFFLL }; /* & clears the sign: fabs */

/* Euclidean norm: the sum of squares in four interleaved partial sums (the
 * serial sum's chain of additions was the cost; the norm only steers
 * Newton's decisions, never its iterates) where it neither overflows nor
 * loses digits to underflow (one pass, no division), else scaled by the
 * largest component. */
double swi_norm2_scaled(int n, const double *v)
{
    double m = sw_norm_inf(n, v), s = 0;
    if (!(m > 0) || !isfinite(m))
        return m;
    for (int i = 0; i < n; i++)
        s += (v[i] / m) * (v[i] / m);
    return m * sqrt(s);
}

static double norm2_of(int n, const double *v, double sq)
{
    return sq > 1e-280 && sq < 1e280 ? sqrt(sq) : swi_norm2_scaled(n, v);
}

/* g = h·g - (d + λ·δ) (the residual -G at the trial iterate), or with no δ
 * g = h·g - d, and |g|₂ as norm2 takes it, in one pass. */
SW_INLINE double residual(int n, double *g, double h, const double *d, double lambda, const double *delta)
{
    v4d sum = { 0, 0, 0, 0 };
    int i = 0;
#pragma GCC unroll 2
    for (; i + 4 <= n; i += 4) {
        v4d gi, di, dl;
        memcpy(&gi, g + i, sizeof gi);
        memcpy(&di, d + i, sizeof di);
        if (delta) {
            memcpy(&dl, delta + i, sizeof dl);
            gi = h * gi - (di + lambda * dl);
        } else {
            gi = h * gi - di;
        }
        memcpy(g + i, &gi, sizeof gi);
        sum += gi * gi;
    }
    double s0 = sum[0], s1 = sum[1], s2 = sum[2], s3 = sum[3];
    for (; i < n; i++) {
        g[i] = delta ? h * g[i] - (d[i] + lambda * delta[i]) : h * g[i] - d[i];
        s0 += g[i] * g[i];
    }
    return norm2_of(n, g, (s0 + s2) + (s1 + s3));
}

SW_CLONES double swi_residual(int n, double *g, double h, const double *d, double lambda, const double *delta)
{
    return residual(n, g, h, d, lambda, delta);
}

SW_CLONES double swi_minus_g(int n, double *g, double h, const double *d)
{
    return residual(n, g, h, d, 0.0, NULL);
}

/* d += λ·δ; returns |δ|∞ (NaN when any component is, as sw_norm_inf) and
 * sets *size = |y + d|∞ (NaN components skipped, as fmax skips them). The
 * maxima four lanes wide, without branches: a maximum is the same whatever
 * the order it is taken in. */
SW_CLONES double swi_advance(int n, double *d, double lambda, const double *delta, const double *y,
                                double *size)
{
    v4d m4 = { 0, 0, 0, 0 }, s4 = { 0, 0, 0, 0 };
    v4i nan4 = { 0, 0, 0, 0 };
    int i = 0;
#pragma GCC unroll 2
    for (; i + 4 <= n; i += 4) {
        v4d dl, di, yi;
        memcpy(&dl, delta + i, sizeof dl);
        memcpy(&di, d + i, sizeof di);
        memcpy(&yi, y + i, sizeof yi);
        v4d a = (v4d)((v4i)dl & MAGNITUDE);
        nan4 |= a != a;
        v4i take = a > m4; /* m4 = a > m4 ? a : m4, lane by lane */
        m4 = (v4d)(((v4i)a & take) | ((v4i)m4 & ~take));
        di = di + lambda * dl;
        memcpy(d + i, &di, sizeof di);
        v4d b = (v4d)((v4i)(yi + di) & MAGNITUDE);
        take = b > s4;
        s4 = (v4d)(((v4i)b & take) | ((v4i)s4 & ~take));
    }
    double m = 0, sz = 0;
    int nan = (nan4[0] | nan4[1] | nan4[2] | nan4[3]) != 0;
    for (int k = 0; k < 4; k++) {
        m = m4[k] > m ? m4[k] : m;
        sz = s4[k] > sz ? s4[k] : sz;
    }
    for (; i < n; i++) {
        double a = fabs(delta[i]);
        nan |= a != a;
        m = a > m ? a : m;
        d[i] = d[i] + lambda * delta[i];
        double b = fabs(y[i] + d[i]);
        sz = b > sz ? b : sz;
    }
    *size = sz;
    return nan ? NAN : m;
}

/* |v|∞, NaN when any component is (as sw_norm_inf), four lanes wide
 * without branches, as swi_advance takes it. */
SW_CLONES double swi_norm_inf(int n, const double *v)
{
    v4d m4 = { 0, 0, 0, 0 };
    v4i nan4 = { 0, 0, 0, 0 };
    int i = 0;
#pragma GCC unroll 2
    for (; i + 4 <= n; i += 4) {
        v4d a;
        memcpy(&a, v + i, sizeof a);
        a = (v4d)((v4i)a & MAGNITUDE);
        nan4 |= a != a;
        v4i take = a > m4;
        m4 = (v4d)(((v4i)a & take) | ((v4i)m4 & ~take));
    }
    double m = 0;
    int nan = (nan4[0] | nan4[1] | nan4[2] | nan4[3]) != 0;
    for (int k = 0; k < 4; k++)
        m = m4[k] > m ? m4[k] : m;
    for (; i < n; i++) {
        double a = fabs(v[i]);
        nan |= a != a;
        m = a > m ? a : m;
    }
    return nan ? NAN : m;
}

SW_CLONES void swi_trial_point(int n, double *restrict ym, const double *restrict y, double theta,
                               const double *restrict d, double lambda, const double *restrict delta)
{
#pragma GCC unroll 2
    for (int i = 0; i < n; i++)
        ym[i] = y[i] + theta * (d[i] + lambda * delta[i]);
}

SW_CLONES SW_ONE_PASS void swi_start(int n, double *restrict ym, const double *restrict y, double theta, double *restrict d,
                         int from_zero)
{
    if (from_zero)
#pragma GCC unroll 2
        for (int i = 0; i < n; i++) {
            d[i] = 0.0;
            ym[i] = y[i] + theta * d[i];
        }
    else
        for (int i = 0; i < n; i++)
            ym[i] = y[i] + theta * d[i];
}

SW_CLONES void swi_take(int n, double *restrict y, const double *restrict d)
{
#pragma GCC unroll 2
    for (int i = 0; i < n; i++)
        y[i] = y[i] + 1.0 * d[i];
}

SW_CLONES void swi_scale(int n, double *v, double h)
{
    for (int i = 0; i < n; i++)
        v[i] *= h;
}
