/* The implicit and Rosenbrock methods as the lecture writes them (see
 * reference_implicit.h): plain loops over the whole state, in the order the
 * formulas read. The production steps (implicit.c, rosenbrock.c) take the
 * same floating-point operations in the same order, four lanes wide or
 * fused into one pass a stage; a test holds them to these bits. Where the
 * production form takes a sum in four partial sums (Newton's |G|₂), this
 * form keeps the same four sums, written out, so that both take the same
 * decisions. */
#include "engine/reference_implicit.h"

#include <math.h>
#include <string.h>

#include "engine/implicit.h"
#include "engine/ode_fast.h"
#include "engine/rosenbrock.h"
#include "stepwise/base.h"

/* ---- Newton's method -------------------------------------------------- */

/* |v|∞, NaN when any component is. */
static double norm_inf(int n, const double *v)
{
    double m = 0;
    int nan = 0;
    for (int i = 0; i < n; i++) {
        double a = fabs(v[i]);
        if (a != a)
            nan = 1;
        else if (a > m)
            m = a;
    }
    return nan ? NAN : m;
}

/* |v|₂ from its sum of squares, component i added to partial sum i mod 4
 * (the last n mod 4 components to sum 0), the sums added (s0 + s2) +
 * (s1 + s3); scaled by the largest component where the square would
 * overflow or underflow. */
static double norm2(int n, const double *v)
{
    double part[4] = { 0, 0, 0, 0 };
    int whole = n - n % 4;
    for (int i = 0; i < whole; i++)
        part[i % 4] += v[i] * v[i];
    for (int i = whole; i < n; i++)
        part[0] += v[i] * v[i];
    double sq = (part[0] + part[2]) + (part[1] + part[3]);
    return sq > 1e-280 && sq < 1e280 ? sqrt(sq) : swi_norm2_scaled(n, v);
}

/* Newton on G(Δ) = Δ - σh·f(t + θσh, y0 + θΔ) = 0 from Δ = d (θ = 1:
 * backward Euler, y1 = y0 + Δ; θ = ½: the implicit midpoint rule):
 *     solve (I - θσh·J) δ = -G(Δ),  then  Δ = Δ + λ·δ,
 * λ halved until |G|₂ falls (a line search: far from the solution a full
 * step can overshoot). Stop when the correction λ|δ|∞ is at rounding
 * level, 1e-12·|y0 + Δ|∞ (swi_newton_next, implicit.c, says exactly when).
 * With keep_j, simplified Newton: J taken once, at the first iterate, and
 * kept while each iteration shrinks |G| eightfold (each solve with the
 * same J reuses its factors); a slower or stalled iteration takes J afresh.
 * A kept J converges linearly, at the rate q of successive corrections,
 * so its tolerance is an eighth, on the correction or on the error q/(1 - q)
 * times it that is left. Without keep_j, J afresh at every iterate.
 * Vectors: 1 (the iterate), 2 (-G), 3 (δ), 4 (with keep_j: where J was
 * taken). */
static int newton(sw_stepper *s, sw_ode *ode, double t, const double *y0, double h, double theta, double *d,
                  int max_iter, int keep_j)
{
    int n = ode->dim, fresh = 1;
    double *yk = SW_WORK(s, 1), *g = SW_WORK(s, 2), *delta = SW_WORK(s, 3), *yj = SW_WORK(s, 4);
    double te = t + theta * h, c = theta * h, lambda = 1.0, last_step = INFINITY, size = 0;
    /* -G at the start: h·f(y0 + θΔ) - Δ */
    for (int i = 0; i < n; i++)
        yk[i] = y0[i] + theta * d[i];
    sw_ode_eval(ode, te, yk, g);
    for (int i = 0; i < n; i++)
        g[i] = h * g[i] - d[i];
    double gnorm = norm2(n, g);
    for (int iter = 0; iter < max_iter; iter++) {
        if (!isfinite(gnorm)) {
            s->why = "Newton's method met a non-finite residual";
            return -1;
        }
        if (gnorm == 0)
            return 0;
        if (keep_j && fresh)
            memcpy(yj, yk, (size_t)n * sizeof *yj); /* J at this iterate, kept */
        /* (I - θσh·J) δ = -G, J at the kept point or at this iterate */
        if (sw_ode_solve(s, ode, te, keep_j ? yj : yk, c, g, delta) != 0) {
            s->why = "the linear system of a Newton step is singular";
            return -1;
        }
        s->newton_iters++;
        lambda = fmin(1.0, 4.0 * lambda);
        /* a kept J's full correction that leaves Δ settled (the rule
         * below, judged before G is evaluated again): Δ = Δ + δ, done */
        if (keep_j && !fresh && lambda == 1.0 && swi_newton_settled(norm_inf(n, delta), size, last_step)) {
            for (int i = 0; i < n; i++)
                d[i] = d[i] + 1.0 * delta[i];
            return 0;
        }
        /* the line search: from four times the last λ (at most 1), halved
         * until |G| falls by the Armijo margin */
        double gnew = INFINITY;
        for (int tries = 0; tries < 30; tries++) {
            for (int i = 0; i < n; i++)
                yk[i] = y0[i] + theta * (d[i] + lambda * delta[i]);
            sw_ode_eval(ode, te, yk, g);
            for (int i = 0; i < n; i++)
                g[i] = h * g[i] - (d[i] + lambda * delta[i]);
            gnew = norm2(n, g);
            if (gnew <= (1.0 - 1e-4 * lambda) * gnorm || gnew == 0)
                break;
            lambda *= 0.5;
        }
        /* Δ = Δ + λδ; |δ|∞ and |y0 + Δ|∞ for the stopping rule */
        double dmax = norm_inf(n, delta);
        size = 0;
        for (int i = 0; i < n; i++) {
            d[i] = d[i] + lambda * delta[i];
            double b = fabs(y0[i] + d[i]);
            if (b > size)
                size = b;
        }
        /* stop at rounding level, or take J afresh, or go on (implicit.c:
         * the rule is one for both forms) */
        int next = swi_newton_next(lambda * dmax, size, gnew, gnorm, lambda, keep_j, &fresh,
                                   &last_step, &s->why);
        if (next <= 0)
            return next;
        gnorm = gnew;
    }
    s->why = "Newton's method did not converge (a smaller dt helps)";
    return -1;
}

/* Newton from d, J afresh at every iterate, for the continuation. */
static int newton_far(sw_stepper *s, sw_ode *ode, double t, const double *y0, double h, double theta, double *d)
{
    return newton(s, ode, t, y0, h, theta, d, 12, 0);
}

/* y1 = y0 + Δ with Δ from Newton, starting at Δ = 0. Where that fails (a
 * step turning a nonlinear force through a large angle), continuation
 * (implicit.c, one for both forms): the equation for σ·h, σ rising from 0
 * to 1, each solution the start of the next. */
static int implicit_step(sw_stepper *s, sw_ode *ode, double *t, double *y, double h, double theta)
{
    int n = ode->dim;
    double *d = SW_WORK(s, 0);
    for (int i = 0; i < n; i++)
        d[i] = 0.0;
    if (newton(s, ode, *t, y, h, theta, d, 40, 1) != 0 &&
        swi_newton_continuation(s, ode, *t, y, h, theta, newton_far, s->why) != 0)
        return SW_EDIVERGED;
    for (int i = 0; i < n; i++)
        y[i] = y[i] + d[i];
    *t += h;
    s->why = NULL;
    return 0;
}

/* Backward Euler: y1 = y0 + h·f(t1, y1). */
int sw_refi_implicit_euler(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    return implicit_step(s, ode, t, y, h, 1.0);
}

/* Implicit midpoint: y1 = y0 + h·f(t + h/2, (y0 + y1)/2). */
int sw_refi_implicit_midpoint(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    return implicit_step(s, ode, t, y, h, 0.5);
}

/* Linearly implicit Euler (Baraff and Witkin's "large steps"): one Newton
 * step of backward Euler from y0, f and J both at (t1, y0):
 *     (I - h·J) Δy = h·f(t1, y0),   y1 = y0 + Δy. */
int sw_refi_linear_implicit_euler(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    int n = ode->dim;
    double *r = SW_WORK(s, 0), *dy = SW_WORK(s, 1);
    sw_ode_eval(ode, *t + h, y, r);
    for (int i = 0; i < n; i++)
        r[i] = r[i] * h;
    if (sw_ode_solve(s, ode, *t + h, y, h, r, dy) != 0) {
        s->why = "the linear system of the step is singular";
        return SW_EDIVERGED;
    }
    for (int i = 0; i < n; i++)
        y[i] = y[i] + dy[i];
    *t += h;
    return 0;
}

/* ---- RODAS4 ----------------------------------------------------------- */

/* One trial of size h: six stages, each solving with the same matrix,
 *     (I - γh·J) k_i = γh·[f(t + α_i h, y0 + Σ_j a_ij k_j) + Σ_j (c_ij/h) k_j + d_i h f_t],
 * J and f_t at (t, y0), j < i; then y1 = (the last stage's point) + k_6
 * (stiffly accurate) and k_6 the error estimate, normed as rk45's. The
 * controller (adaptive.c) gives k_1's f(t, y0) in slot s->fsal and takes
 * the old y from slot S_SAVED on a rejection. No runaway test. */
static void lecture_trial(sw_stepper *s, sw_ode *ode, double t, double *y, double h, int lo, int hi,
                          unsigned elim, sw_trial_sums *sums)
{
    (void)lo, (void)hi, (void)elim;
    int n = ode->dim;
    const double *f0 = SW_WORK(s, s->fsal);
    double *yt = SW_WORK(s, S_YT), *rhs = SW_WORK(s, S_RHS), *ft = SW_WORK(s, S_FT);
    double *f1 = SW_WORK(s, s->fsal ? 0 : S_F1), gh = SW_RODAS_GAMMA * h;
    s->why = NULL;
    memcpy(SW_WORK(s, S_SAVED), y, (size_t)n * sizeof *y);
    /* f_t by a difference, or, where the system says f ignores t and f(t,
     * y0) is finite, 0 without an evaluation (Hairer's RODAS has the same
     * switch for autonomous systems): (f - f)/δ would be +0 there */
    int autonomous = sw_ode_autonomous(ode), timed = 0;
    for (int i = 0; i < n && autonomous; i++)
        autonomous = isfinite(f0[i]);
    if (autonomous)
        for (int i = 0; i < n; i++)
            ft[i] = 0.0;
    else
        timed = swr_time_derivative(ode, t, y, f0, ft);
    for (int st = 0; st < SW_RODAS_STAGES; st++) {
        double *k = SW_WORK(s, S_K1 + st);
        const double *f = f0;
        if (st > 0) {
            /* the stage's point y0 + Σ a_ij k_j, and f there (into k_i's
             * vector, which the solve then overwrites with k_i) */
            for (int i = 0; i < n; i++)
                yt[i] = y[i];
            for (int j = 0; j < st; j++)
                for (int i = 0; i < n; i++)
                    yt[i] = yt[i] + SW_RODAS_A[st][j] * SW_WORK(s, S_K1 + j)[i];
            sw_ode_eval(ode, t + SW_RODAS_ALPHA[st] * h, yt, k);
            f = k;
        }
        /* the right-hand side γh·(f + d_i h f_t + Σ (c_ij/h) k_j); d_i h is
         * 0 for an autonomous system (adding +0 still turns -0 into +0) */
        double dh = timed ? SW_RODAS_D[st] * h : 0.0;
        for (int i = 0; i < n; i++)
            rhs[i] = f[i] + dh * ft[i];
        for (int j = 0; j < st; j++) {
            double c_over_h = SW_RODAS_C[st][j] / h;
            for (int i = 0; i < n; i++)
                rhs[i] = rhs[i] + c_over_h * SW_WORK(s, S_K1 + j)[i];
        }
        for (int i = 0; i < n; i++)
            rhs[i] = gh * rhs[i];
        if (sw_ode_solve(s, ode, t, y, gh, rhs, k) != 0) {
            s->why = "the linear system of a Rosenbrock stage is singular";
            sums->err = NAN;
            return;
        }
    }
    const double *k6 = SW_WORK(s, S_K6);
    double sum = 0;
    for (int i = 0; i < n; i++) {
        double y1 = yt[i] + k6[i], a0 = fabs(y[i]), a1 = fabs(y1);
        double q = k6[i] / (s->atol + s->rtol * (a1 > a0 ? a1 : a0));
        sum += q * q;
        y[i] = y1;
    }
    sw_ode_eval(ode, t + h, y, f1);
    sums->err = sum;
}

/* One accepted RODAS4 step of at most h_max: the lecture's trial under
 * the production controller (the same settings: adaptive.c is shared). */
int sw_refi_rodas4(sw_stepper *s, sw_ode *ode, double *t, double *y, double h_max)
{
    sw_adaptive lecture = swr_rodas4;
    lecture.trial = lecture_trial;
    return sw_adaptive_step(&lecture, s, ode, t, y, h_max);
}

sw_step_fn *sw_refi_of(sw_step_fn *step)
{
    if (step == sw_step_implicit_euler)
        return sw_refi_implicit_euler;
    if (step == sw_step_implicit_midpoint)
        return sw_refi_implicit_midpoint;
    if (step == sw_step_linear_implicit_euler)
        return sw_refi_linear_implicit_euler;
    if (step == sw_step_rodas4)
        return sw_refi_rodas4;
    return NULL;
}
