/* The implicit methods — backward Euler and the implicit midpoint rule by
 * Newton's method, and the linearly implicit Euler step — and the linear
 * solve they share: a system's own solve, or a dense finite-difference
 * fallback for small systems. Newton's passes over the state run in
 * implicit_wide.c (four lanes, fused); the same steps in plain loops, as
 * the lecture writes them, are in reference_implicit.c, and
 * tests/check_reference_implicit.c holds these to their bits. */
#include "engine/implicit.h"

#include <math.h>
#include <string.h>

#include "engine/linalg.h"
#include "engine/ode_fast.h"
#include "stepwise/base.h"

/* Newton's stopping rule (implicit.h): converged, failed, or go on with a
 * kept or a fresh J. SIMPLIFIED_RATE: the contraction a kept J must keep. */
#define SIMPLIFIED_RATE 0.125

int swi_newton_settled(double step, double size, double last_step)
{
    double tol = 1e-12 * SIMPLIFIED_RATE, rate = step / last_step;
    return step <= tol * size || (rate > 0 && rate < SIMPLIFIED_RATE && rate / (1 - rate) * step <= tol * size);
}

int swi_newton_next(double step, double size, double gnew, double gnorm, double lambda, int keep_j, int *fresh,
                    double *last_step, const char **why)
{
    int kept = keep_j && !*fresh;
    /* With a kept J the iteration converges linearly, at the rate θ of
     * successive corrections, and the error left after a correction is
     * about θ/(1 - θ) times it, not its square: that estimate (Hairer
     * and Wanner's stopping rule) must be at 1/8 of the tolerance. */
    double tol = kept ? 1e-12 * SIMPLIFIED_RATE : 1e-12;
    if (step <= tol * size || gnew == 0)
        return 0;
    double rate = step / *last_step; /* 0 after the first correction: no rate yet */
    *last_step = step;
    if (kept && lambda == 1.0 && rate > 0 && rate < SIMPLIFIED_RATE && rate / (1 - rate) * step <= tol * size)
        return 0;
    int stalled = !(gnew < gnorm) || lambda < 1.0 / 1024;
    if (stalled && !kept) {
        if (step <= 1e-9 * size)
            return 0;
        *why = "Newton's method stalled: no solution of the implicit equation was found "
               "near the last state (a smaller dt helps)";
        return -1;
    }
    /* a kept J that no longer contracts fast: take it afresh */
    *fresh = keep_j && (stalled || lambda < 1.0 || gnew > SIMPLIFIED_RATE * gnorm);
    return 1;
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
 * the rate of convergence predicts is left; a correction that meets that
 * before it is taken (swi_newton_settled: the rate from it and the last
 * one) is taken with no evaluation after it, which only the descent test
 * read. The iterates are Newton's own
 * where J does not change (linear systems: the same bits).
 * Without yj, J afresh at every iterate (quadratic convergence: the
 * continuation below, where the start is far from the solution).
 * Returns 0 with d the solution, or -1 with s->why set. With from_zero
 * the start is Δ = 0, d cleared in the first pass over it (no pass of its
 * own). Vectors 1..3 (and yj): with yj the iterates alternate between
 * vector 1 and yj, so the point J was taken at stays where it was written
 * and is never copied. */
static int newton(sw_stepper *s, sw_ode *ode, double t, const double *y, double h, double theta,
                  double *d, int from_zero, int max_iter, double *yj)
{
    int n = ode->dim, fresh = 1;
    double *ym = SW_WORK(s, 1), *g = SW_WORK(s, 2), *delta = SW_WORK(s, 3);
    double te = t + theta * h, c = theta * h, lambda = 1.0, last_step = INFINITY, size = 0;
    const double *at = ym; /* where J is taken */
    swi_start(n, ym, y, theta, d, from_zero); /* ym = y + θ·d, d = 0 first with from_zero */
    sw_ode_eval(ode, te, ym, g);
    double gnorm = swi_minus_g(n, g, h, d); /* g = h·g - d: -G, and |g|₂ */
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
        /* a kept J's point is where the last solve was (same); a fresh
         * one's factors are asked for again only as that (new) */
        int (*solve)(sw_stepper *, sw_ode *, double, const double *, double, const double *, double *) =
            !yj ? sw_ode_solve : fresh ? sw_ode_solve_new : sw_ode_solve_same;
        if (solve(s, ode, te, at, c, g, delta) != 0) {
            s->why = "the linear system of a Newton step is singular";
            return -1;
        }
        s->newton_iters++;
        lambda = fmin(1.0, 4.0 * lambda);
        /* a kept J's full correction that leaves the iterate settled needs
         * no evaluation after it */
        if (yj && !fresh && lambda == 1.0 && swi_newton_settled(swi_norm_inf(n, delta), size, last_step)) {
            swi_take(n, d, delta); /* d = d + 1·δ, swi_advance's operations; its norms unread */
            return 0;
        }
        /* Backtrack until |G| drops (Armijo, halving λ), starting from four
         * times the last accepted λ: a full step where Newton converges,
         * few wasted evaluations where a curved valley needs short ones. */
        double gnew = INFINITY;
        for (int ls = 0; ls < 30; ls++) {
            swi_trial_point(n, ym, y, theta, d, lambda, delta); /* ym = y + θ·(d + λ·δ) */
            sw_ode_eval(ode, te, ym, g);
            gnew = swi_residual(n, g, h, d, lambda, delta);
            if (gnew <= (1.0 - 1e-4 * lambda) * gnorm || gnew == 0)
                break;
            lambda *= 0.5;
        }
        /* step = λ·|δ|∞, d += λδ and size = |y + d|∞, in one pass */
        double dmax = swi_advance(n, d, lambda, delta, y, &size);
        double step = lambda * dmax;
        int next = swi_newton_next(step, size, gnew, gnorm, lambda, yj != NULL, &fresh, &last_step, &s->why);
        if (next <= 0)
            return next;
        gnorm = gnew;
    }
    s->why = "Newton's method did not converge (a smaller dt helps)";
    return -1;
}

/* Continuation (implicit.h), after Newton from Δ = 0 failed with `why`:
 * the equation for σ·h, σ rising from 0 to 1, each solution the start of
 * the next (predicted by the secant through the last two), σ's increment
 * doubled after a solve and quartered after a failed one. That finds the
 * solution connected to y0, the one backward Euler means where the
 * equation has several; it fails, with a message, only when that branch
 * folds back. Vectors 0 (Δ), 4 and 5. */
int swi_newton_continuation(sw_stepper *s, sw_ode *ode, double t, const double *y, double h, double theta,
                            swi_newton_fn *solve, const char *why)
{
    int n = ode->dim;
    double *d = SW_WORK(s, 0), *done = SW_WORK(s, 4), *prev = SW_WORK(s, 5);
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
        if (solve(s, ode, t, y, next * h, theta, d) == 0) {
            sigma_prev = sigma;
            sigma = next;
            memcpy(prev, done, (size_t)n * sizeof *d);
            memcpy(done, d, (size_t)n * sizeof *d);
            dsigma *= 2;
        } else {
            dsigma *= 0.25;
        }
    }
    return 0;
}

/* Newton from d with J afresh at every iterate, for the continuation. */
static int newton_far(sw_stepper *s, sw_ode *ode, double t, const double *y, double h, double theta, double *d)
{
    return newton(s, ode, t, y, h, theta, d, 0, 12, NULL);
}

/* One implicit step (θ = 1 backward Euler, θ = ½ implicit midpoint). Newton
 * from Δ = 0 converges in a few iterations unless the step turns the motion
 * through a large angle of a nonlinear force (a stiff pendulum at ω·Δt =
 * 100); then continuation. Vectors 0..5. */
static int implicit_step(sw_stepper *s, sw_ode *ode, double *t, double *y, double h, double theta)
{
    double *d = SW_WORK(s, 0);
    if (newton(s, ode, *t, y, h, theta, d, 1, 40, SW_WORK(s, 4)) != 0 &&
        swi_newton_continuation(s, ode, *t, y, h, theta, newton_far, s->why) != 0)
        return SW_EDIVERGED;
    swi_take(ode->dim, y, d); /* y = y + 1·d, sw_axpy's operations */
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
    swi_scale(ode->dim, r, h); /* r = h·f */
    if (sw_ode_solve_new(s, ode, *t + h, y, h, r, dy) != 0) { /* not solved at y again */
        s->why = "the linear system of the step is singular";
        return SW_EDIVERGED;
    }
    swi_take(ode->dim, y, dy);
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

/* Through the fast path's hook where the system has one, else ode->solve. */
static int solve_by(sw_stepper *s, sw_ode *ode, sw_solve_fn *fn, double t, const double *y, double c,
                    const double *r, double *z)
{
    if (!fn)
        return sw_ode_solve(s, ode, t, y, c, r, z);
    ode->solves++;
    return fn(ode->ctx, t, y, c, r, z);
}

int sw_ode_solve_same(sw_stepper *s, sw_ode *ode, double t, const double *y, double c,
                      const double *r, double *z)
{
    return solve_by(s, ode, ode->fast ? ode->fast->solve_same : NULL, t, y, c, r, z);
}

int sw_ode_solve_new(sw_stepper *s, sw_ode *ode, double t, const double *y, double c,
                     const double *r, double *z)
{
    return solve_by(s, ode, ode->fast ? ode->fast->solve_new : NULL, t, y, c, r, z);
}
