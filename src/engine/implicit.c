/* The implicit methods — backward Euler and the implicit midpoint rule by
 * Newton's method, and the linearly implicit Euler step — and the linear
 * solve they share: a system's own solve, or a dense finite-difference
 * fallback for small systems. */
#include "engine/stepper.h"

#include <math.h>
#include <string.h>

#include "engine/clones.h"
#include "engine/linalg.h"
#include "stepwise/base.h"

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
static double norm2_scaled(int n, const double *v)
{
    double m = sw_norm_inf(n, v), s = 0;
    if (!(m > 0) || !isfinite(m))
        return m;
    for (int i = 0; i < n; i++)
        s += (v[i] / m) * (v[i] / m);
    return m * sqrt(s);
}

static SW_CLONES double sum_squares(int n, const double *v)
{
    v4d sum = { 0, 0, 0, 0 };
    int i = 0;
    for (; i + 4 <= n; i += 4) {
        v4d vi;
        memcpy(&vi, v + i, sizeof vi);
        sum += vi * vi;
    }
    double s0 = sum[0], s1 = sum[1], s2 = sum[2], s3 = sum[3];
    for (; i < n; i++)
        s0 += v[i] * v[i];
    return (s0 + s2) + (s1 + s3);
}

static double norm2_of(int n, const double *v, double sq)
{
    return sq > 1e-280 && sq < 1e280 ? sqrt(sq) : norm2_scaled(n, v);
}

static double norm2(int n, const double *v) { return norm2_of(n, v, sum_squares(n, v)); }

/* g = h·g - (d + λ·δ) (the residual -G at the trial iterate) and |g|₂ as
 * norm2 takes it, in one pass. */
static SW_CLONES double residual(int n, double *g, double h, const double *d, double lambda, const double *delta)
{
    v4d sum = { 0, 0, 0, 0 };
    int i = 0;
    for (; i + 4 <= n; i += 4) {
        v4d gi, di, dl;
        memcpy(&gi, g + i, sizeof gi);
        memcpy(&di, d + i, sizeof di);
        memcpy(&dl, delta + i, sizeof dl);
        gi = h * gi - (di + lambda * dl);
        memcpy(g + i, &gi, sizeof gi);
        sum += gi * gi;
    }
    double s0 = sum[0], s1 = sum[1], s2 = sum[2], s3 = sum[3];
    for (; i < n; i++) {
        g[i] = h * g[i] - (d[i] + lambda * delta[i]);
        s0 += g[i] * g[i];
    }
    return norm2_of(n, g, (s0 + s2) + (s1 + s3));
}

/* d += λ·δ; returns |δ|∞ (NaN when any component is, as sw_norm_inf) and
 * sets *size = |y + d|∞ (NaN components skipped, as fmax skips them). The
 * maxima four lanes wide, without branches: a maximum is the same whatever
 * the order it is taken in. */
static SW_CLONES double advance(int n, double *d, double lambda, const double *delta, const double *y,
                                double *size)
{
    v4d m4 = { 0, 0, 0, 0 }, s4 = { 0, 0, 0, 0 };
    v4i nan4 = { 0, 0, 0, 0 };
    int i = 0;
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

/* Newton's method from Δ = d on G(Δ) = Δ - σh·f(t + θσh, y0 + θΔ) = 0, the
 * equation of backward Euler (θ = 1, y1 = y0 + Δ) and of the implicit
 * midpoint rule (θ = ½) over the step σh. Each iteration solves
 * (I - θσh·J)·δ = -G; farther away a backtracking line search on |G|₂
 * keeps every step a descent step (the Newton direction is one for the
 * Euclidean norm of the residual). Converged when the correction is at
 * rounding level, |δ| <= 1e-12·|y0 + Δ|, or when no descent is left and
 * |δ| <= 1e-9·|y0 + Δ| (rounding in G decides it).
 * With yj (a vector to keep it in), simplified Newton: J is taken at the
 * first iterate and its factorisation kept (the solve reuses it for the
 * same state and c) while the iteration contracts |G| by SIMPLIFIED_RATE
 * or better; a slower or stalled iteration takes J afresh at the current
 * iterate, and only a stall with a fresh J fails. With a kept J the
 * tolerance is an eighth of the above, on the correction or on the error
 * the rate of convergence predicts is left. The iterates are Newton's own
 * where J does not change (linear systems: the same bits).
 * Without yj, J afresh at every iterate (quadratic convergence: the
 * continuation below, where the start is far from the solution).
 * Returns 0 with d the solution, or -1 with s->why set. With from_zero
 * the start is Δ = 0, d cleared in the first pass over it (no pass of its
 * own). Vectors 1..3 (and yj): with yj the iterates alternate between
 * vector 1 and yj, so the point J was taken at stays where it was written
 * and is never copied. */
#define SIMPLIFIED_RATE 0.125

static int newton(sw_stepper *s, sw_ode *ode, double t, const double *y, double h, double theta,
                  double *d, int from_zero, int max_iter, double *yj)
{
    int n = ode->dim, fresh = 1;
    double *ym = SW_WORK(s, 1), *g = SW_WORK(s, 2), *delta = SW_WORK(s, 3);
    double te = t + theta * h, c = theta * h, lambda = 1.0, last_step = INFINITY;
    const double *at = ym; /* where J is taken */
    if (from_zero)
        for (int i = 0; i < n; i++) {
            d[i] = 0.0;
            ym[i] = y[i] + theta * d[i];
        }
    else
        for (int i = 0; i < n; i++)
            ym[i] = y[i] + theta * d[i];
    sw_ode_eval(ode, te, ym, g);
    for (int i = 0; i < n; i++)
        g[i] = h * g[i] - d[i]; /* -G */
    double gnorm = norm2(n, g);
    for (int iter = 0; iter < max_iter; iter++) {
        if (!isfinite(gnorm)) {
            s->why = "Newton's method met a non-finite residual";
            return -1;
        }
        if (gnorm == 0)
            return 0; /* Δ solves G = 0 exactly */
        if (!yj) {
            at = ym;
        } else if (fresh) {
            /* J at this iterate, kept in its vector; the next iterates
             * go to the other one */
            at = ym;
            ym = ym == yj ? SW_WORK(s, 1) : yj;
        }
        if (sw_ode_solve(s, ode, te, at, c, g, delta) != 0) {
            s->why = "the linear system of a Newton step is singular";
            return -1;
        }
        s->newton_iters++;
        /* Backtrack until |G| drops (Armijo, halving λ), starting from four
         * times the last accepted λ: a full step where Newton converges,
         * few wasted evaluations where a curved valley needs short ones. */
        double gnew = INFINITY;
        lambda = fmin(1.0, 4.0 * lambda);
        for (int ls = 0; ls < 30; ls++) {
            for (int i = 0; i < n; i++)
                ym[i] = y[i] + theta * (d[i] + lambda * delta[i]);
            sw_ode_eval(ode, te, ym, g);
            gnew = residual(n, g, h, d, lambda, delta);
            if (gnew <= (1.0 - 1e-4 * lambda) * gnorm || gnew == 0)
                break;
            lambda *= 0.5;
        }
        /* step = λ·|δ|∞, d += λδ and size = |y + d|∞, in one pass */
        double size, dmax = advance(n, d, lambda, delta, y, &size);
        double step = lambda * dmax;
        int kept = yj && !fresh;
        /* With a kept J the iteration converges linearly, at the rate θ of
         * successive corrections, and the error left after a correction is
         * about θ/(1 - θ) times it, not its square: that estimate (Hairer
         * and Wanner's stopping rule) must be at 1/8 of the tolerance. */
        double tol = kept ? 1e-12 * SIMPLIFIED_RATE : 1e-12;
        if (step <= tol * size || gnew == 0)
            return 0;
        double rate = step / last_step;
        last_step = step;
        if (kept && lambda == 1.0 && rate < SIMPLIFIED_RATE && rate / (1 - rate) * step <= tol * size)
            return 0;
        int stalled = !(gnew < gnorm) || lambda < 1.0 / 1024;
        if (stalled && !kept) {
            if (step <= 1e-9 * size)
                return 0;
            s->why = "Newton's method stalled: no solution of the implicit equation was found "
                     "near the last state (a smaller dt helps)";
            return -1;
        }
        /* a kept J that no longer contracts fast: take it afresh */
        fresh = yj && (stalled || lambda < 1.0 || gnew > SIMPLIFIED_RATE * gnorm);
        gnorm = gnew;
    }
    s->why = "Newton's method did not converge (a smaller dt helps)";
    return -1;
}

/* One implicit step (θ = 1 backward Euler, θ = ½ implicit midpoint). Newton
 * from Δ = 0 converges in a few iterations unless the step turns the motion
 * through a large angle of a nonlinear force (a stiff pendulum at ω·Δt =
 * 100). Then the step is solved by continuation: the equation for σ·h, σ
 * rising from 0 to 1, each solution the start of the next (predicted by the
 * secant through the last two), σ's increment doubled after a solve and
 * quartered after a failed one. That finds the solution connected to y0,
 * the one backward Euler means where the equation has several; it fails,
 * with a message, only when that branch folds back. Vectors 0..5. */
static int implicit_step(sw_stepper *s, sw_ode *ode, double *t, double *y, double h, double theta)
{
    int n = ode->dim;
    double *d = SW_WORK(s, 0), *done = SW_WORK(s, 4), *prev = SW_WORK(s, 5);
    if (newton(s, ode, *t, y, h, theta, d, 1, 40, SW_WORK(s, 4)) != 0) {
        const char *why = s->why;
        double sigma = 0, sigma_prev = 0, dsigma = 0.125;
        memset(done, 0, (size_t)n * sizeof *done);
        memset(prev, 0, (size_t)n * sizeof *prev);
        for (int tries = 0; sigma < 1; tries++) {
            if (tries == 400 || dsigma < 1e-7) {
                s->why = why;
                return SW_EDIVERGED;
            }
            /* predict by the secant through the last two solutions */
            double next = fmin(1.0, sigma + dsigma);
            double w = sigma > sigma_prev ? (next - sigma) / (sigma - sigma_prev) : 0.0;
            for (int i = 0; i < n; i++)
                d[i] = done[i] + w * (done[i] - prev[i]);
            if (newton(s, ode, *t, y, next * h, theta, d, 0, 12, NULL) == 0) {
                sigma_prev = sigma;
                sigma = next;
                memcpy(prev, done, (size_t)n * sizeof *d);
                memcpy(done, d, (size_t)n * sizeof *d);
                dsigma *= 2;
            } else {
                dsigma *= 0.25;
            }
        }
    }
    sw_axpy(n, y, y, 1.0, d);
    *t += h;
    s->why = NULL;
    return 0;
}

/* Backward Euler: y1 = y0 + h·f(t1, y1), solved to rounding. */
int sw_step_implicit_euler(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    return implicit_step(s, ode, t, y, h, 1.0);
}

/* Implicit midpoint: y1 = y0 + h·f(t + h/2, (y0 + y1)/2), Newton as above. */
int sw_step_implicit_midpoint(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    return implicit_step(s, ode, t, y, h, 0.5);
}

/* Linearly implicit Euler (Baraff & Witkin's "large steps"): one Newton step
 * of backward Euler, G(Δ) = Δ - h·f(t1, y0 + Δ) = 0, from Δ = 0, so f and J
 * both at (t1, y0), t1 = t0 + h: (I - h·J(t1, y0))·Δy = h·f(t1, y0). The
 * same as backward Euler when f is linear in y; on a nonlinear system it can
 * gain energy where backward Euler cannot, which is what a lesson shows.
 * (f and J were once taken at different times, t0 and t1: on a field that
 * changes with time, the gyre, that is no Newton step of anything.) */
int sw_step_linear_implicit_euler(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    double *r = SW_WORK(s, 0), *dy = SW_WORK(s, 1);
    sw_ode_eval(ode, *t + h, y, r);
    for (int i = 0; i < ode->dim; i++)
        r[i] *= h;
    if (sw_ode_solve(s, ode, *t + h, y, h, r, dy) != 0) {
        s->why = "the linear system of the step is singular";
        return SW_EDIVERGED;
    }
    sw_axpy(ode->dim, y, y, 1.0, dy);
    *t += h;
    return 0;
}

/* Dense fallback: J by forward differences, one column per evaluation, then
 * (I - c·J) z = r by Gaussian elimination with partial pivoting, the
 * factors kept: a second solve at the same t, y (contents) and c reuses
 * them. s->dense holds the factors (n²), then three n-vectors that serve as
 * f(y), y + ε and f(y + ε) while J is formed and afterwards as the key:
 * c and t, y, and the row interchanges + 1 (0: no factors kept). A system
 * of one component keeps none (no room for the key). A stepper serves one
 * system, so the key need not name it. */
static int dense_solve(sw_stepper *s, sw_ode *ode, double t, const double *y, double c,
                       const double *r, double *z)
{
    int n = ode->dim, perm[SW_DENSE_MAX];
    double *a = s->dense, *f0 = a + (size_t)n * n, *yp = f0 + n, *f1 = yp + n;
    int kept = n >= 2 && f1[0] >= 1 && f0[0] == c && f0[1] == t &&
               memcmp(yp, y, (size_t)n * sizeof *y) == 0;
    if (kept) {
        for (int i = 0; i < n; i++)
            perm[i] = (int)f1[i] - 1;
    } else {
        f1[0] = 0;
        sw_ode_eval(ode, t, y, f0);
        memcpy(yp, y, (size_t)n * sizeof *yp);
        for (int j = 0; j < n; j++) {
            double eps = 1e-7 * fmax(1.0, fabs(y[j]));
            yp[j] = y[j] + eps;
            sw_ode_eval(ode, t, yp, f1);
            yp[j] = y[j];
            for (int i = 0; i < n; i++)
                a[i * n + j] = (i == j) - c * (f1[i] - f0[i]) / eps;
        }
        if (sw_dense_factor(n, a, perm) != 0) {
            f1[0] = 0;
            return SW_EDIVERGED;
        }
        if (n >= 2) {
            f0[0] = c;
            f0[1] = t;
            for (int i = 0; i < n; i++)
                f1[i] = perm[i] + 1;
        }
    }
    memcpy(z, r, (size_t)n * sizeof *z);
    sw_dense_lu_solve(n, a, perm, z);
    return SW_OK;
}

int sw_ode_solve(sw_stepper *s, sw_ode *ode, double t, const double *y, double c,
                 const double *r, double *z)
{
    ode->solves++;
    if (ode->solve)
        return ode->solve(ode->ctx, t, y, c, r, z);
    return dense_solve(s, ode, t, y, c, r, z);
}
