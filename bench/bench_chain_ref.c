/* The chain's reference in long double, for the peer comparison's stiff
 * chains (bench_peer.c). A double-precision run at tolerance 1e-13 ends
 * about 1e-9 from the truth on the chain at k = 1e6 (a local tolerance
 * adds up over 1e4-1e5 steps, and rounding with it), so it cannot judge a
 * method at 1e-9. This one is independent of the engine: the derivative is
 * written here from docs/scenes.md's equations (springs, then gravity;
 * f = -[k(|d| - rest) + c (v_a - v_b)·d/|d|] d/|d| on bead a, -f on b),
 * and the classical RK4 steps it in long double (x87: a 64-bit
 * significand, rounding 5.4e-20) at N and 2N steps, N doubled until the
 * two agree: the difference over 15 estimates the finer run's error
 * (Richardson, order 4), and the ratio of successive differences, 16 in
 * the asymptotic range, is checked before it is believed. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "bench_common.h"

typedef long double real;

typedef struct chain {
    int n;
    real k, m, c, rest, g;
} chain;

/* One spring between a (bead) and b (bead, or the anchor (bx, by) at rest
 * when b < 0): its force added to a and, negated, to b. */
static void spring(const chain *ch, const real *y, real *f, int a, int b, real bx, real by)
{
    const real *x = y, *v = y + 2 * ch->n;
    real xb = b < 0 ? bx : x[2 * b], yb = b < 0 ? by : x[2 * b + 1];
    real vxb = b < 0 ? 0 : v[2 * b], vyb = b < 0 ? 0 : v[2 * b + 1];
    real dx = x[2 * a] - xb, dy = x[2 * a + 1] - yb, len = sqrtl(dx * dx + dy * dy);
    if (len == 0)
        return;
    real inv = 1 / len, ux = dx * inv, uy = dy * inv;
    real s = -(ch->k * (len - ch->rest) + ch->c * ((v[2 * a] - vxb) * ux + (v[2 * a + 1] - vyb) * uy));
    f[2 * a] += s * ux, f[2 * a + 1] += s * uy;
    if (b >= 0)
        f[2 * b] -= s * ux, f[2 * b + 1] -= s * uy;
}

/* dy = (v, f/m), f of the n + 1 springs in order, then gravity. */
static void deriv(const chain *ch, const real *y, real *dy, real *f)
{
    int n = ch->n;
    memset(f, 0, (size_t)2 * n * sizeof *f);
    spring(ch, y, f, 0, -1, 0, 0);
    for (int j = 1; j < n; j++)
        spring(ch, y, f, j, j - 1, 0, 0);
    spring(ch, y, f, n - 1, -1, (n + 1) * ch->rest, 0);
    for (int i = 0; i < 2 * n; i++) {
        dy[i] = y[2 * n + i];
        dy[2 * n + i] = (f[i] + (i % 2 ? -ch->m * ch->g : 0)) / ch->m;
    }
}

/* N RK4 steps from y0 over [0, T] into y; work holds 6 state-long vectors. */
static void rk4(const chain *ch, const double *y0, real T, long steps, real *y, real *work)
{
    int dim = 4 * ch->n;
    real *k1 = work, *k2 = k1 + dim, *k3 = k2 + dim, *k4 = k3 + dim, *yt = k4 + dim, *f = yt + dim;
    real h = T / steps;
    for (int i = 0; i < dim; i++)
        y[i] = y0[i];
    for (long s = 0; s < steps; s++) {
        deriv(ch, y, k1, f);
        for (int i = 0; i < dim; i++)
            yt[i] = y[i] + h / 2 * k1[i];
        deriv(ch, yt, k2, f);
        for (int i = 0; i < dim; i++)
            yt[i] = y[i] + h / 2 * k2[i];
        deriv(ch, yt, k3, f);
        for (int i = 0; i < dim; i++)
            yt[i] = y[i] + h * k3[i];
        deriv(ch, yt, k4, f);
        for (int i = 0; i < dim; i++)
            y[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    }
}

/* The largest |a_i - b_i|; infinite where a difference is not finite (a
 * run blown up at too few steps: fmaxl alone would pass over its NaNs, and
 * two runs all NaN would "agree" to 0). */
static real max_diff(int dim, const real *a, const real *b)
{
    real d = 0;
    for (int i = 0; i < dim; i++) {
        real x = fabsl(a[i] - b[i]);
        if (!(x <= LDBL_MAX))
            return INFINITY;
        d = fmaxl(d, x);
    }
    return d;
}

int bench_chain_reference(const double *par, const double *y0, double T, double goal, double *ref,
                          double *estimate, long *steps)
{
    chain ch = { (int)par[0], par[1], par[2], par[3], par[4], par[5] };
    int dim = 4 * ch.n, rc = -1;
    real *buf = malloc((size_t)9 * dim * sizeof *buf);
    if (!buf)
        return -1;
    real *coarse = buf, *fine = coarse + dim, *work = fine + dim;
    real last = INFINITY;
    long n = 1L << 12;
    rk4(&ch, y0, T, n, coarse, work);
    for (; n <= 1L << 24; n *= 2) {
        rk4(&ch, y0, T, 2 * n, fine, work);
        real diff = max_diff(dim, coarse, fine);
        /* in the asymptotic range each halving of h divides the
         * difference by 16 (more than 12 is taken as there) */
        if (diff / 15 <= goal && last / diff > 12) {
            for (int i = 0; i < dim; i++)
                ref[i] = (double)fine[i];
            *estimate = (double)(diff / 15);
            *steps = 2 * n;
            rc = 0;
            break;
        }
        last = diff;
        real *t = coarse;
        coarse = fine, fine = t;
    }
    free(buf);
    return rc;
}
