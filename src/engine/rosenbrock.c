/* RODAS4, Hairer & Wanner's L-stable Rosenbrock method of order 4 with an
 * embedded order-3 estimate, under the shared step-size controller
 * (adaptive.c). The stages' arithmetic runs in rosenbrock_wide.c (one
 * unrolled pass a stage); the trial in plain loops, as the lecture writes
 * it, is in reference_implicit.c, held to these bits by
 * tests/check_reference_implicit.c. Linearly implicit: one Jacobian per step, and every stage
 * solves with the same matrix (I - γh·J(t0, y0)) through sw_ode_solve with
 * the same (t0, y0, γh), so a solve that keeps its factorisation factors
 * once per step. Invariant: y0 is left untouched until a trial has every
 * stage, so a failed solve costs only the trial. */
#include "engine/rosenbrock.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "engine/ode_fast.h"
#include "engine/rodas_tableau.h"
#include "stepwise/base.h"

int swr_time_derivative(sw_ode *ode, double t, const double *y, const double *f0, double *ft)
{
    int n = ode->dim, any = 0;
    double delta = sqrt(DBL_EPSILON * fmax(1e-5, fabs(t)));
    sw_ode_eval(ode, t + delta, y, ft);
    for (int i = 0; i < n; i++) {
        ft[i] = (ft[i] - f0[i]) / delta;
        any |= ft[i] != 0;
    }
    return any;
}

/* A trial step of size h over the whole state (the solve couples it, so the
 * controller never slices it): stage i solves, scaled by γh,
 *     (I - γh·J) k_i = γh·[f(t + α_i h, y0 + Σ a_ij k_j) + Σ (c_ij/h) k_j + d_i h f_t],
 * y1 = y0 + Σ m_i k_i; error estimate k_6, normed as rk45's. A failed solve
 * makes the sums NaN (the controller shrinks the step) and leaves y0.
 * Each stage is two passes over the state (its point, then its right-hand
 * side, stage_combine) around its evaluation, which lands in k_i's own
 * vector until the solve overwrites it with k_i: nothing is cleared or
 * copied between stages. */
static void rodas_trial(sw_stepper *s, sw_ode *ode, double t, double *y, double h, int lo, int hi,
                        unsigned elim, sw_trial_sums *sums)
{
    (void)lo, (void)hi;
    int n = ode->dim;
    const double *f0 = SW_WORK(s, s->fsal), *k[SW_RODAS_STAGES];
    double *yt = SW_WORK(s, S_YT), *rhs = SW_WORK(s, S_RHS), *ft = SW_WORK(s, S_FT);
    double *saved = SW_WORK(s, S_SAVED), *f1 = SW_WORK(s, s->fsal ? 0 : S_F1);
    double gh = SW_RODAS_GAMMA * h;
    s->why = NULL;
    /* the controller's copy of y0 (restored on a rejection) is taken in
     * the second stage's point pass, which reads y0 anyway */
    /* ∂f/∂t by its difference, unless the system says f ignores t and f0
     * is finite: then (f - f0)/δ is +0 in every component, not evaluated,
     * and the stages add +0 for its term (with_ft 2), the same bits */
    int known_zero = sw_ode_autonomous(ode) && swr_all_finite(n, f0);
    int timed = known_zero ? 0 : swr_time_derivative(ode, t, y, f0, ft);
    for (int st = 0; st < SW_RODAS_STAGES; st++)
        k[st] = SW_WORK(s, S_K1 + st);
    for (int st = 0; st < SW_RODAS_STAGES; st++) {
        double *kst = SW_WORK(s, S_K1 + st), c_over_h[SW_RODAS_STAGES];
        const double *f = f0;
        if (st > 0) {
            if (st == 1)
                swr_stage_point_keep(n, yt, saved, y, SW_RODAS_A[1][0], k[0]);
            else
                swr_stage_combine(n, st, 0, yt, y, 0.0, NULL, 0.0, SW_RODAS_A[st], k);
            sw_ode_eval(ode, t + SW_RODAS_ALPHA[st] * h, yt, kst);
            f = kst;
        }
        for (int j = 0; j < st; j++)
            c_over_h[j] = SW_RODAS_C[st][j] / h;
        /* d_i h f_t is 0·f_t = +0 where f does not depend on t: adding it
         * still turns a -0 into +0, as the lecture form did */
        double dh = timed ? SW_RODAS_D[st] * h : 0.0;
        swr_stage_combine(n, st, known_zero ? 2 : 1, rhs, f, dh, ft, gh, c_over_h, k);
        /* stages after the first: at y0, as the first was (its factors
         * asked for again only so) */
        if ((st > 0 ? sw_ode_solve_same : sw_ode_solve_new)(s, ode, t, y, gh, rhs, kst) != 0) {
            s->why = "the linear system of a Rosenbrock stage is singular";
            sums->err = NAN;
            if (st == 0) /* before the copy: the controller restores y0 from it */
                memcpy(saved, y, (size_t)n * sizeof *y);
            return;
        }
    }
    /* Stiffly accurate: y1 = (the last stage's point) + k_6; k_6 the error. */
    const double *k6 = SW_WORK(s, S_K6);
    unsigned long long over = 0, add = sw_beyond_add(elim);
    double sum = 0;
    for (int i = 0; i < n; i++) {
        double y1 = yt[i] + k6[i], a0 = fabs(y[i]), a1 = fabs(y1);
        double q = k6[i] / (s->atol + s->rtol * (a1 > a0 ? a1 : a0));
        sum += q * q;
        y[i] = y1;
        over |= sw_beyond_bits(y1, add);
    }
    sw_ode_eval(ode, t + h, y, f1);
    sums->err = sum;
    sums->beyond |= sw_beyond_any(over);
}

/* Hairer's RODAS: h_new/h = 0.9·err^(-1/4) within [1/5, 6], no growth right
 * after a rejection. The trial counts its own evaluations (a failed solve
 * stops it early). */
const sw_adaptive swr_rodas4 = {
    .trial = rodas_trial,
    .evals = 0,
    .coupled = 1,
    .fsal_other = S_F1,
    .saved = S_SAVED,
    .expo = 0.25,
    .safety = 0.9,
    .fac_min = 0.2,
    .fac_max = 6.0,
    .hold = 1,
};

_Static_assert(ROSENBROCK_VECTORS == 12, "rodas4 needs 12 work vectors (integrators.c)");

/* One accepted RODAS4 step of at most h_max. */
int sw_step_rodas4(sw_stepper *s, sw_ode *ode, double *t, double *y, double h_max)
{
    return sw_adaptive_step(&swr_rodas4, s, ode, t, y, h_max);
}
