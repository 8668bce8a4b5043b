/* The explicit adaptive methods as the lecture writes them (see
 * reference_adaptive.h). Read a method from its entry at the bottom of the
 * file: its trial (one line a stage, each a row of its tableau; the new
 * state; the error estimate), then the controller every method here
 * shares, adaptive_step — accept the
 * trial when its error norm is at most 1, else try again with a smaller
 * step; either way propose the next step from the error. The production
 * steps take the same floating-point operations in the same order, cut
 * into slices, vectorised, with the runaway test folded in; a test holds
 * them to these bits. */
#include "engine/reference_adaptive.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "engine/dop853_tableau.h"
#include "engine/regularise.h"
#include "engine/rk45_tableau.h"
#include "engine/rkn12_tableau.h"
#include "engine/rkn_tableau.h"
#include "engine/stepper.h"
#include "engine/vern_tableau.h"
#include "stepwise/base.h"

#define X(name, p, q) static const double RKN_##name = (double)(p) / (q);
SW_RKN_TABLEAU(X)
#undef X

enum { K = SW_REF_STAGES + 2 }; /* k[1] .. k[K - 1] */

/* A row of weights w[1], w[2], ... (the ones not named are 0). */
#define ROW(...) ((const double[K]){ __VA_ARGS__ })

int sw_ref_adaptive_init(sw_ref_adaptive *r, int dim)
{
    *r = (sw_ref_adaptive){ .dim = dim, .rtol = SW_RTOL_DEFAULT, .atol = SW_ATOL_DEFAULT };
    double *v = calloc((size_t)(K + 1) * (size_t)dim, sizeof *v);
    if (!v)
        return SW_ENOMEM;
    for (int j = 1; j < K; j++)
        r->k[j] = v + (size_t)(j - 1) * (size_t)dim;
    r->vectors = v;
    r->yt = v + (size_t)(K - 1) * (size_t)dim;
    r->y0 = v + (size_t)K * (size_t)dim;
    return SW_OK;
}

/* dop853-lc's run: dop853's lecture form stepping in Levi-Civita's
 * variables, seen by the change of variables (regularise.c) as a stepper. */
struct sw_ref_lc {
    sw_lc lc;
    sw_stepper st;        /* its method lc_row, its memory in `in` */
    sw_ref_adaptive in;   /* dop853's lecture form on the regularised state */
    sw_lc_left left;      /* where the last step left the particle, and w there */
};

void sw_ref_adaptive_free(sw_ref_adaptive *r)
{
    free(r->vectors);
    if (r->lc) {
        sw_ref_adaptive_free(&r->lc->in);
        free(r->lc);
    }
    *r = (sw_ref_adaptive){ 0 };
}

/* Σ_j w[j]·k[j][c] over the stages j that have a weight, in stage order:
 * the tableau's sum written out term by term. It starts from -0.0, which
 * added to any x gives x (also for x = ±0), as no start at all would. */
static double weighted(const double w[K], double *const k[K], int c)
{
    double sum = -0.0;
    for (int j = 1; j < K; j++)
        if (w[j] != 0)
            sum += w[j] * k[j][c];
    return sum;
}

/* Stage i of an explicit Runge-Kutta method at time t_i:
 * Y = y + h·Σ_j a_ij k_j, k_i = f(t_i, Y). */
static void rk_stage(sw_ref_adaptive *r, sw_ode *ode, double t_i, const double *y, double h, const double a[K],
                     int i)
{
    for (int c = 0; c < ode->dim; c++)
        r->yt[c] = y[c] + h * weighted(a, r->k, c);
    sw_ode_eval(ode, t_i, r->yt, r->k[i]);
}

/* Stage i of a Runge-Kutta-Nyström method on y = [x | v] (d each), a_j
 * the second half of k_j: X = x + c_i·h·v + h²·Σ_j A_ij a_j, a_i = f(t +
 * c_i·h, [X | v]) (the acceleration reads positions only; v is there
 * because the derivative takes a whole state). */
static void rkn_stage(sw_ref_adaptive *r, sw_ode *ode, double t, const double *y, double h, double c_i,
                      const double a[K], int i)
{
    int d = ode->dim / 2;
    for (int c = 0; c < d; c++) {
        r->yt[c] = y[c] + c_i * h * y[d + c] + h * h * weighted(a, r->k, d + c);
        r->yt[d + c] = y[d + c];
    }
    sw_ode_eval(ode, t + c_i * h, r->yt, r->k[i]);
}

/* The larger of |y0| and |y1|, the scale sk = atol + rtol·max(|y0|, |y1|)
 * of an error. */
static double scale(const sw_ref_adaptive *r, double y0, double y1)
{
    double a0 = fabs(y0), a1 = fabs(y1);
    return r->atol + r->rtol * (a1 > a0 ? a1 : a0);
}

/* Squares added into four sums by i mod 4, then the four pairwise: how
 * dop853, rkn and rkn12 add their error terms (four chains side by side
 * are four lanes of one vector in the production loops). */
static double by4(const double part[4]) { return (part[0] + part[1]) + (part[2] + part[3]); }

/* Half of an RKN trial's new state on y = [x | v] (d each), y0 kept:
 * the positions (half 0) x1 = x + h·v + h²·Σ b_i a_i with the error
 * h²·Σ e_i a_i, or the velocities (half 1) v1 = v + h·Σ b_i a_i with the
 * error h·Σ e_i a_i. Each error over its scale sk, squared, into sq by
 * index mod 4. The scale's max(|y0|, |y1|) takes |y0| where one is NaN,
 * or with nan_new |y1| (rkn12.c's way). Positions first: they read the
 * old v. */
static void rkn_half(sw_ref_adaptive *r, double *y, double h, int half, int d, const double b[K],
                     const double e[K], int nan_new, double sq[4])
{
    for (int i = half * d; i < (half + 1) * d; i++) {
        double y0 = y[i], a = weighted(b, r->k, d + i % d), err = weighted(e, r->k, d + i % d);
        r->y0[i] = y0;
        if (half == 0) {
            y[i] = y0 + h * y[d + i] + h * h * a;
            err = h * h * err;
        } else {
            y[i] = y0 + h * a;
            err = h * err;
        }
        double m0 = fabs(y0), m1 = fabs(y[i]);
        double m = nan_new ? (m0 > m1 ? m0 : m1) : (m1 > m0 ? m1 : m0);
        double q = err / (r->atol + r->rtol * m);
        sq[i % 4] += q * q;
    }
}

/* A trial step of size h from (t, y): y0 = y kept, y replaced by the new
 * state, k[next] the derivative there; returns the error norm. */
typedef double trial_fn(sw_ref_adaptive *r, sw_ode *ode, double t, double *y, double h);

/* Dormand-Prince 5(4): six stages, y1 = y + h·Σ b_i k_i (5th order); the
 * error h·Σ e_i k_i against the embedded 4th-order solution uses k7 =
 * f(t + h, y1), the next step's k1 (first same as last). Norm: the RMS of
 * error/sk. */
static double rk45_trial(sw_ref_adaptive *r, sw_ode *ode, double t, double *y, double h)
{
    rk_stage(r, ode, t + C2 * h, y, h, ROW([1] = A21), 2);
    rk_stage(r, ode, t + C3 * h, y, h, ROW([1] = A31, A32), 3);
    rk_stage(r, ode, t + C4 * h, y, h, ROW([1] = A41, A42, A43), 4);
    rk_stage(r, ode, t + C5 * h, y, h, ROW([1] = A51, A52, A53, A54), 5);
    rk_stage(r, ode, t + h, y, h, ROW([1] = A61, A62, A63, A64, A65), 6);
    const double *b = ROW([1] = B1, 0, B3, B4, B5, B6), *e = ROW([1] = E1, 0, E3, E4, E5, E6, E7);
    for (int i = 0; i < ode->dim; i++) {
        r->y0[i] = y[i];
        y[i] = y[i] + h * weighted(b, r->k, i);
    }
    sw_ode_eval(ode, t + h, y, r->k[7]);
    double sum = 0;
    for (int i = 0; i < ode->dim; i++) {
        double q = h * weighted(e, r->k, i) / scale(r, r->y0[i], y[i]);
        sum += q * q;
    }
    return sqrt(sum / ode->dim);
}

/* DOP853: twelve stages, y1 = y + h·Σ b_i k_i (8th order). Hairer's
 * error: the 5th-order estimate e5 = Σ er_i k_i and the 3rd-order one
 * e3 = Σ b_i k_i - (bhh1 k1 + bhh9 k9 + bhh12 k12), each over sk, give
 * err = |h|·S5 / √(n·(S5 + 0.01·S3)), S5 and S3 the sums of their
 * squares: e5, damped where e3 says e5 is unreliably small. k13 =
 * f(t + h, y1) is the next step's k1. */
static double dop853_trial(sw_ref_adaptive *r, sw_ode *ode, double t, double *y, double h)
{
    double *const *k = r->k;
    rk_stage(r, ode, t + DP8_C2 * h, y, h, ROW([1] = DP8_A2_1), 2);
    rk_stage(r, ode, t + DP8_C3 * h, y, h, ROW([1] = DP8_A3_1, DP8_A3_2), 3);
    rk_stage(r, ode, t + DP8_C4 * h, y, h, ROW([1] = DP8_A4_1, [3] = DP8_A4_3), 4);
    rk_stage(r, ode, t + DP8_C5 * h, y, h, ROW([1] = DP8_A5_1, [3] = DP8_A5_3, DP8_A5_4), 5);
    rk_stage(r, ode, t + DP8_C6 * h, y, h, ROW([1] = DP8_A6_1, [4] = DP8_A6_4, DP8_A6_5), 6);
    rk_stage(r, ode, t + DP8_C7 * h, y, h, ROW([1] = DP8_A7_1, [4] = DP8_A7_4, DP8_A7_5, DP8_A7_6), 7);
    rk_stage(r, ode, t + DP8_C8 * h, y, h,
             ROW([1] = DP8_A8_1, [4] = DP8_A8_4, DP8_A8_5, DP8_A8_6, DP8_A8_7), 8);
    rk_stage(r, ode, t + DP8_C9 * h, y, h,
             ROW([1] = DP8_A9_1, [4] = DP8_A9_4, DP8_A9_5, DP8_A9_6, DP8_A9_7, DP8_A9_8), 9);
    rk_stage(r, ode, t + DP8_C10 * h, y, h,
             ROW([1] = DP8_A10_1, [4] = DP8_A10_4, DP8_A10_5, DP8_A10_6, DP8_A10_7, DP8_A10_8, DP8_A10_9), 10);
    rk_stage(r, ode, t + DP8_C11 * h, y, h,
             ROW([1] = DP8_A11_1, [4] = DP8_A11_4, DP8_A11_5, DP8_A11_6, DP8_A11_7, DP8_A11_8, DP8_A11_9,
                 DP8_A11_10), 11);
    rk_stage(r, ode, t + h, y, h,
             ROW([1] = DP8_A12_1, [4] = DP8_A12_4, DP8_A12_5, DP8_A12_6, DP8_A12_7, DP8_A12_8, DP8_A12_9,
                 DP8_A12_10, DP8_A12_11), 12);
    const double *b = ROW([1] = DP8_B1, [6] = DP8_B6, DP8_B7, DP8_B8, DP8_B9, DP8_B10, DP8_B11, DP8_B12);
    const double *er = ROW([1] = DP8_ER1, [6] = DP8_ER6, DP8_ER7, DP8_ER8, DP8_ER9, DP8_ER10, DP8_ER11, DP8_ER12);
    double sq5[4] = { 0 }, sq3[4] = { 0 };
    for (int i = 0; i < ode->dim; i++) {
        double bk = weighted(b, k, i);
        r->y0[i] = y[i];
        y[i] = y[i] + h * bk;
        double per_sk = 1.0 / scale(r, r->y0[i], y[i]);
        double e3 = (bk - DP8_BHH1 * k[1][i] - DP8_BHH9 * k[9][i] - DP8_BHH12 * k[12][i]) * per_sk;
        double e5 = weighted(er, k, i) * per_sk;
        sq5[i % 4] += e5 * e5;
        sq3[i % 4] += e3 * e3;
    }
    sw_ode_eval(ode, t + h, y, k[13]);
    double err5 = by4(sq5), err3 = by4(sq3), deno = err5 + 0.01 * err3;
    return fabs(h) * err5 * sqrt(1.0 / (ode->dim * (deno > 0 ? deno : 1.0)));
}

/* RKN6(4) on y = [x | v] (d each): stages 2 to 5; stage 6 is the new
 * position x1 = x + h·v + h²·Σ bx_i a_i (row 6 of A is bx, c6 = 1), so a6
 * = f(t + h, x1) is the next step's a1; then v1 = v + h·Σ bv_i a_i. The
 * errors h²·Σ ex_i a_i and h·Σ ev_i a_i, ex = bx - b̂x and ev = bv - b̂v
 * against the embedded 4th-order solution; norm: the RMS of error/sk,
 * the squares added by4 over [x | v]. */
static double rkn_trial(sw_ref_adaptive *r, sw_ode *ode, double t, double *y, double h)
{
    int d = ode->dim / 2;
    rkn_stage(r, ode, t, y, h, RKN_C2, ROW([1] = RKN_A21), 2);
    rkn_stage(r, ode, t, y, h, RKN_C3, ROW([1] = RKN_A31, RKN_A32), 3);
    rkn_stage(r, ode, t, y, h, RKN_C4, ROW([1] = RKN_A41, RKN_A42, RKN_A43), 4);
    rkn_stage(r, ode, t, y, h, RKN_C5, ROW([1] = RKN_A51, RKN_A52, RKN_A53, RKN_A54), 5);
    const double *bx = ROW([1] = RKN_BX1, RKN_BX2, RKN_BX3, RKN_BX4, RKN_BX5);
    const double *bv = ROW([1] = RKN_BV1, RKN_BV2, RKN_BV3, RKN_BV4, RKN_BV5, RKN_BV6);
    const double *ex = ROW([1] = RKN_BX1 - RKN_HX1, RKN_BX2 - RKN_HX2, RKN_BX3 - RKN_HX3, RKN_BX4 - RKN_HX4,
                           RKN_BX5 - RKN_HX5);
    const double *ev = ROW([1] = RKN_BV1 - RKN_HV1, RKN_BV2 - RKN_HV2, RKN_BV3 - RKN_HV3, RKN_BV4 - RKN_HV4,
                           RKN_BV5 - RKN_HV5);
    double sq[4] = { 0 };
    rkn_half(r, y, h, 0, d, bx, ex, 0, sq);
    sw_ode_eval(ode, t + h, y, r->k[6]); /* at [x1 | v0]: a6 */
    rkn_half(r, y, h, 1, d, bv, ev, 0, sq);
    return sqrt(by4(sq) / ode->dim);
}

/* RKN12(10): the same shape with 17 stages (the tableau's macros give
 * each stage's row), not first same as last: the new state's derivative
 * is evaluated at the end, into k18. */
static double rkn12_trial(sw_ref_adaptive *r, sw_ode *ode, double t, double *y, double h)
{
    int d = ode->dim / 2;
#define W(j, w) [j] = (w),
#define STAGE(i, c, terms) rkn_stage(r, ode, t, y, h, (c), ROW(terms), (i));
    SW_RKN12_STAGES(STAGE, W, W)
#undef STAGE
    const double *bx = ROW(SW_RKN12_BX(W, W)), *bv = ROW(SW_RKN12_BV(W, W));
    const double *ex = ROW(SW_RKN12_EX(W, W)), *ev = ROW(SW_RKN12_EV(W, W));
#undef W
    double sq[4] = { 0 };
    rkn_half(r, y, h, 0, d, bx, ex, 1, sq);
    rkn_half(r, y, h, 1, d, bv, ev, 1, sq);
    sw_ode_eval(ode, t + h, y, r->k[18]);
    return sqrt(by4(sq) / ode->dim);
}

/* Verner's pairs, vern_tableau.h's numbers (indices from 0, its k_j in
 * k[j + 1]): Σ_j w_j k_j over S stages with each group of stages whose
 * nodes nearly coincide summed about one of them, m = M[j]: w_j (k_j -
 * k_m), and the group's sum times k_m, in stage order. */
static double grouped(int S, const double *w, const unsigned char *m, double *const k[K], int c)
{
    double sum = -0.0;
    for (int j = 0; j < S; j++)
        if (w[j] != 0)
            sum += m[j] == j ? w[j] * k[j + 1][c] : w[j] * (k[j + 1][c] - k[m[j] + 1][c]);
    return sum;
}

/* A Verner pair of S stages (its tables, A and its groups M row by row
 * with stride S): S - 1 stages after k1, y1 = y + h·Σ b_i k_i, the error
 * h·Σ e_i k_i against the embedded solution; its norm the RMS of
 * error/sk, the squares added by4. Not FSAL: k[S + 1] = f(t + h, y1) is
 * evaluated after, the next step's k1. */
static double vern_trial(int S, const double *C, const double *A, const unsigned char *AM, const double *B,
                         const unsigned char *BM, const double *E, const unsigned char *EM, sw_ref_adaptive *r,
                         sw_ode *ode, double t, double *y, double h)
{
    for (int i = 1; i < S; i++) {
        for (int c = 0; c < ode->dim; c++)
            r->yt[c] = y[c] + h * grouped(S, A + i * S, AM + i * S, r->k, c);
        sw_ode_eval(ode, t + C[i] * h, r->yt, r->k[i + 1]);
    }
    double sq[4] = { 0 };
    for (int i = 0; i < ode->dim; i++) {
        r->y0[i] = y[i];
        y[i] = y[i] + h * grouped(S, B, BM, r->k, i);
        double q = h * grouped(S, E, EM, r->k, i) / scale(r, r->y0[i], y[i]);
        sq[i % 4] += q * q;
    }
    sw_ode_eval(ode, t + h, y, r->k[S + 1]);
    return sqrt(by4(sq) / ode->dim);
}

static double vern8_trial(sw_ref_adaptive *r, sw_ode *ode, double t, double *y, double h)
{
    return vern_trial(13, V8_C, &V8_A[0][0], &V8_A_M[0][0], V8_B, V8_B_M, V8_E, V8_E_M, r, ode, t, y, h);
}

static double vern9_trial(sw_ref_adaptive *r, sw_ode *ode, double t, double *y, double h)
{
    return vern_trial(16, V9_C, &V9_A[0][0], &V9_A_M[0][0], V9_B, V9_B_M, V9_E, V9_E_M, r, ode, t, y, h);
}

/* Hairer's first step (HINIT) for a method of this order: h with
 * h^order·max(‖f‖, ‖f'‖) ≈ 0.01 in the norm of the tolerances, f' from an
 * explicit Euler step of the probe size h0 = 0.01·‖y‖/‖f‖; at most 100·h0
 * and h_max. One evaluation. */
static double first_step(sw_ref_adaptive *r, sw_ode *ode, double t, const double *y, double order, double h_max)
{
    int n = ode->dim;
    const double *f0 = r->k[1];
    double *y1 = r->yt, *f1 = r->y0, norm_f = 0, norm_y = 0;
    for (int i = 0; i < n; i++) {
        double sk = r->atol + r->rtol * fabs(y[i]);
        norm_f += (f0[i] / sk) * (f0[i] / sk);
        norm_y += (y[i] / sk) * (y[i] / sk);
    }
    double h = norm_f <= 1e-10 || norm_y <= 1e-10 ? 1e-6 : sqrt(norm_y / norm_f) * 0.01;
    h = fmin(h, h_max);
    for (int i = 0; i < n; i++)
        y1[i] = y[i] + h * f0[i];
    sw_ode_eval(ode, t + h, y1, f1);
    double norm_df = 0;
    for (int i = 0; i < n; i++) {
        double sk = r->atol + r->rtol * fabs(y[i]), q = (f1[i] - f0[i]) / sk;
        norm_df += q * q;
    }
    double f_prime = sqrt(norm_df) / h, size = fmax(fabs(f_prime), sqrt(norm_f));
    double h1 = size <= 1e-15 ? fmax(1e-6, h * 1e-3) : pow(0.01 / size, 1.0 / order);
    h = fmin(fmin(100 * h, h1), h_max);
    return h > 0 ? h : h_max; /* NaN (a non-finite f): h_max */
}

/* A method's trial and its controller's constants. */
typedef struct control {
    trial_fn *trial;
    int next;      /* the stage whose derivative is at the new state: the next k1 */
    double expo;   /* 1/(q+1), q the embedded order: error ∝ h^(q+1) */
    double safety, fac_min, fac_max; /* h_new = h·clamp(safety·err^-expo, fac_min, fac_max) */
    int hold;        /* after a rejection the accepted step does not grow */
    int guess_first; /* the first step from first_step, else h_max */
    int predict;     /* Gustafsson: growth also limited by the error's trend */
} control;

/* One accepted step: trials until the error norm err is at most 1. A
 * rejected trial restores y and shrinks h by the factor its err proposes
 * (a tenth when the trial is not finite); an accepted one moves t and
 * proposes the next step. */
static int adaptive_step(const control *m, sw_ref_adaptive *r, sw_ode *ode, double *t, double *y, double h_max)
{
    if (!r->have_k1)
        sw_ode_eval(ode, *t, y, r->k[1]);
    r->have_k1 = 1;
    double h = r->h_next > 0 && r->h_next < h_max ? r->h_next : h_max;
    if (m->guess_first && !(r->h_next > 0))
        h = first_step(r, ode, *t, y, 1.0 / m->expo, h_max);
    int rejected = 0;
    for (int tries = 0; tries < 200; tries++) {
        double err = m->trial(r, ode, *t, y, h);
        double grow = err > 0 ? m->safety * pow(err, -m->expo) : m->fac_max;
        if (err <= 1.0) {
            double *k1 = r->k[1];
            r->k[1] = r->k[m->next];
            r->k[m->next] = k1;
            *t += h;
            if (m->predict && r->err_last > 0) /* err ≈ C·h^(q+1), C from the last two steps */
                grow = fmin(grow, m->safety * (h / r->h_last) * pow(r->err_last / (err * err), m->expo));
            r->h_last = h;
            r->err_last = m->predict ? fmax(0.01, err) : 0;
            r->h_next = h * fmin(m->fac_max, fmax(m->fac_min, grow));
            if (m->hold && rejected && r->h_next > h)
                r->h_next = h;
            r->accepted++;
            return SW_OK;
        }
        memcpy(y, r->y0, (size_t)ode->dim * sizeof *y);
        r->rejected++;
        rejected = 1;
        if (err != err) { /* not finite: a tenth */
            h *= 0.1;
            continue;
        }
        h *= fmax(m->fac_min, grow);
        if (h < 1e-14 * fmax(1.0, fabs(*t)))
            break;
    }
    return SW_EDIVERGED;
}

int sw_ref_rk45(sw_ref_adaptive *r, sw_ode *ode, double *t, double *y, double h_max)
{
    static const control dp5 = { .trial = rk45_trial, .next = 7, .expo = 0.2, .safety = 0.9, .fac_min = 0.2,
                                 .fac_max = 5.0 };
    return adaptive_step(&dp5, r, ode, t, y, h_max);
}

int sw_ref_dop853(sw_ref_adaptive *r, sw_ode *ode, double *t, double *y, double h_max)
{
    static const control dp8 = { .trial = dop853_trial, .next = 13, .expo = 1.0 / 8, .safety = 0.9,
                                 .fac_min = 1.0 / 3, .fac_max = 6.0, .hold = 1, .guess_first = 1 };
    return adaptive_step(&dp8, r, ode, t, y, h_max);
}

int sw_ref_rkn(sw_ref_adaptive *r, sw_ode *ode, double *t, double *y, double h_max)
{
    static const control rkn64 = { .trial = rkn_trial, .next = 6, .expo = 0.2, .safety = 0.9, .fac_min = 0.2,
                                   .fac_max = 5.0 };
    return adaptive_step(&rkn64, r, ode, t, y, h_max);
}

int sw_ref_rkn12(sw_ref_adaptive *r, sw_ode *ode, double *t, double *y, double h_max)
{
    static const control rkn1210 = { .trial = rkn12_trial, .next = 18, .expo = 1.0 / 11, .safety = 0.9,
                                     .fac_min = 1.0 / 3, .fac_max = 6.0, .hold = 1, .guess_first = 1,
                                     .predict = 1 };
    return adaptive_step(&rkn1210, r, ode, t, y, h_max);
}

int sw_ref_vern8(sw_ref_adaptive *r, sw_ode *ode, double *t, double *y, double h_max)
{
    static const control v87 = { .trial = vern8_trial, .next = 14, .expo = 1.0 / 8, .safety = 0.9,
                                 .fac_min = 1.0 / 3, .fac_max = 6.0, .hold = 1, .guess_first = 1 };
    return adaptive_step(&v87, r, ode, t, y, h_max);
}

int sw_ref_vern9(sw_ref_adaptive *r, sw_ode *ode, double *t, double *y, double h_max)
{
    static const control v98 = { .trial = vern9_trial, .next = 17, .expo = 1.0 / 9, .safety = 0.9,
                                 .fac_min = 1.0 / 3, .fac_max = 6.0, .hold = 1, .guess_first = 1 };
    return adaptive_step(&v98, r, ode, t, y, h_max);
}

/* dop853's lecture form as the change of variables calls a method: its
 * memory kept in the stepper's fields (have_cache, h_next, the counts). */
static int lc_inner_step(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    sw_ref_adaptive *in = s->inner;
    in->have_k1 = s->have_cache;
    in->h_next = s->h_next;
    in->rtol = s->rtol;
    in->atol = s->atol;
    int rc = sw_ref_dop853(in, ode, t, y, h);
    s->have_cache = in->have_k1;
    s->h_next = in->h_next;
    s->rejected = in->rejected;
    return rc;
}

static const sw_integrator lc_row = { .name = "dop853 (lecture form, regularised)", .step = lc_inner_step,
                                      .flags = SW_EXPLICIT | SW_ADAPTIVE };

/* dop853-lc: [x | v] at t to w = [u, u', energy, t], one step of dop853
 * in the fictitious time s landed on at most t + h_max (sw_lc_step), and
 * back. Each step from the particle's state alone, as dop853_lc.c. */
int sw_ref_dop853_lc(sw_ref_adaptive *r, sw_ode *ode, double *t, double *y, double h_max)
{
    char err[SW_ERRLEN];
    if (!r->lc) {
        r->lc = calloc(1, sizeof *r->lc);
        if (!r->lc || sw_ref_adaptive_init(&r->lc->in, SW_LC_DIM) != SW_OK)
            return SW_ENOMEM;
    }
    struct sw_ref_lc *lc = r->lc;
    double *w = lc->left.w;
    if (sw_lc_init_central(&lc->lc, ode, err, sizeof err) != SW_OK)
        return SW_EINVAL;
    int resumed = sw_lc_resume(&lc->left, &lc->lc, *t, y);
    if (resumed < 0)
        return SW_EDIVERGED;
    lc->st = (sw_stepper){ .method = &lc_row, .dim = SW_LC_DIM, .inner = &lc->in, .rtol = r->rtol,
                           .atol = r->atol, .h_next = r->h_next, .rejected = lc->in.rejected,
                           .have_cache = resumed };
    long rejected = lc->in.rejected;
    int rc = sw_lc_step(&lc->lc, &lc->st, w, h_max);
    ode->evals += lc->lc.ode.evals;
    r->rejected += lc->in.rejected - rejected;
    if (rc != SW_OK)
        return rc;
    r->accepted++;
    r->h_next = lc->st.h_next;
    r->h_last = w[5] - *t;
    *t = w[5];
    sw_lc_leave(&lc->left, &lc->lc, y);
    return SW_OK;
}

sw_ref_adaptive_fn *sw_ref_adaptive_of(sw_step_fn *step)
{
    static const struct {
        sw_step_fn *step;
        sw_ref_adaptive_fn *ref;
    } pairs[] = {
        { sw_step_rk45, sw_ref_rk45 }, { sw_step_dop853, sw_ref_dop853 }, { sw_step_rkn, sw_ref_rkn },
        { sw_step_rkn12, sw_ref_rkn12 }, { sw_step_dop853_lc, sw_ref_dop853_lc }, { sw_step_vern8, sw_ref_vern8 },
        { sw_step_vern9, sw_ref_vern9 },
    };
    for (size_t i = 0; i < sizeof pairs / sizeof pairs[0]; i++)
        if (pairs[i].step == step)
            return pairs[i].ref;
    return NULL;
}
