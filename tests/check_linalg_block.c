/* The block Thomas solve of a chain's band (engine/linalg_block.h): on
 * block-tridiagonal matrices of 2x2 blocks it solves what Gaussian
 * elimination with partial pivoting on the dense matrix solves, and it
 * refuses, leaving the band as it was, where no pivoting is unsafe. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "engine/linalg.h"
#include "engine/linalg_block.h"

enum { NBMAX = 12, NMAX = 2 * NBMAX, KL = 3, LD = 3 * KL + 1 };

/* Entry (i, j) of a block-tridiagonal test matrix, kind:
 * 0 diagonally dominant, non-symmetric (a small step: M ahead);
 * 1 symmetric positive definite and stiff (M + 1e6·a stretched chain's
 *   stiffness: the Schur complements' conditions reach ~1e5);
 * 2 non-symmetric, not dominant (a damped stiff chain: c·Fv and its
 *   turning term);
 * 3 kind 1 again, for a right-hand side along the springs (test below).
 * Outside the blocks (i, i), (i, i ± 1) zero. */
static double entry(int kind, int i, int j)
{
    int bi = i / 2, bj = j / 2, d = bi - bj;
    if (kind == 3)
        kind = 1;
    if (d < -1 || d > 1)
        return 0.0;
    double wiggle = sin(1.3 * i + 0.7 * j + kind);
    if (kind == 0)
        return (i == j ? 6.0 : 0.0) + wiggle;
    /* springs of stiffness 1e6 from each bead to the next (and the ends
     * to anchors), spring s (beads s and s + 1) along a unit n_s turning
     * by 0.4 a spring: its stiffness block k·(n_s·n_sᵀ + 1e-4·I) on the
     * two diagonal blocks, minus it beside them; plus M = I */
    int r = i % 2, c = j % 2;
    double k = 0;
    for (int sp = (d == 0 ? bi - 1 : (bi < bj ? bi : bj)); sp <= (d == 0 ? bi : (bi < bj ? bi : bj)); sp++) {
        double th = 0.4 * sp, n0 = cos(th), n1 = sin(th);
        double dir = (r == 0 ? n0 : n1) * (c == 0 ? n0 : n1) + (r == c ? 1e-4 : 0.0);
        k += 1e6 * (d == 0 ? 1.0 : -1.0) * dir;
    }
    k += i == j ? 1.0 : 0.0;
    if (kind == 2)
        k += 3e4 * wiggle * (d == 0 ? 1.0 : 0.5);
    return k;
}

/* ‖A·x - b‖_∞ / (‖A‖_∞·‖x‖_∞ + ‖b‖_∞): the normwise backward error. */
static double backward_error(int n, const double *a, const double *x, const double *b)
{
    double res = 0, an = 0, xn = 0, bn = 0;
    for (int i = 0; i < n; i++) {
        double s = -b[i], row = 0;
        for (int j = 0; j < n; j++) {
            s += a[i * n + j] * x[j];
            row += fabs(a[i * n + j]);
        }
        res = fmax(res, fabs(s));
        an = fmax(an, row);
        xn = fmax(xn, fabs(x[i]));
        bn = fmax(bn, fabs(b[i]));
    }
    return res / (an * xn + bn);
}

/* Every size from 1 to NBMAX blocks, the four kinds: the factors are
 * accepted, the band is left untouched, and the solution's backward error
 * is at rounding: at most 8·n·ε (a backward stable solve's bound for
 * these sizes; the Schur complements do not grow here). On the stiff SPD
 * kind the Schur complements' 2x2 conditions reach 1e4 along directions
 * turning with the chain: there Cramer's rule (an explicit inverse)
 * misses this bound when b lies along the springs (kind 3). On the
 * dominant kind, whose condition is below 10, the solution also agrees
 * with the dense elimination's to 1e-13 of its size. */
START_TEST(block_solve_solves)
{
    for (int kind = 0; kind < 4; kind++)
        for (int nb = 1; nb <= NBMAX; nb++) {
            int n = 2 * nb;
            double band[LD * NMAX], before[LD * NMAX], f[SW_BLOCK_DOUBLES(NBMAX)];
            double dense[NMAX * NMAX], lu[NMAX * NMAX], b[NMAX], x[NMAX], xd[NMAX];
            int piv[NMAX];
            sw_band bd;
            sw_band_init(&bd, n, KL, KL, band, piv);
            for (int i = 0; i < n; i++) {
                for (int j = 0; j < n; j++) {
                    dense[i * n + j] = entry(kind, i, j);
                    if (abs(i - j) <= KL)
                        sw_band_add(&bd, i, j, dense[i * n + j]);
                }
                /* kind 3: each bead pushed along its springs, the stiff
                 * direction, so that x is as small as b / ‖A‖ */
                double th = 0.4 * (i / 2 - 0.5);
                b[i] = x[i] = xd[i] = kind == 3 ? (i % 2 == 0 ? cos(th) : sin(th)) : cos(0.9 * i + kind);
            }
            memcpy(before, band, sizeof(double) * LD * n);
            memcpy(lu, dense, sizeof(double) * n * n);
            ck_assert_int_eq(sw_dense_solve(n, lu, xd), 0);
            ck_assert_msg(sw_block_factor(&bd, f) == 0, "kind %d, %d blocks: refused", kind, nb);
            ck_assert_mem_eq(band, before, sizeof(double) * LD * n);
            sw_block_solve(&bd, f, x);
            double be = backward_error(n, dense, x, b);
            ck_assert_msg(be <= 8 * n * DBL_EPSILON, "kind %d, %d blocks: backward error %g", kind, nb, be);
            if (kind == 0) {
                double diff = 0, size = 0;
                for (int i = 0; i < n; i++) {
                    diff = fmax(diff, fabs(x[i] - xd[i]));
                    size = fmax(size, fabs(xd[i]));
                }
                ck_assert_msg(diff <= 1e-13 * size, "%d blocks: %g from the dense solution", nb, diff);
            }
        }
}
END_TEST

/* Where elimination needs a row interchange the blocks do not make, the
 * factorisation refuses and leaves the band as it was (the caller then
 * factors it with pivoting): a first block singular to 1e-9 beside order-1
 * neighbours and a first block of 1e-4·I (well conditioned itself): both
 * make the next Schur complement grow 1e4-fold and more, past 16.
 * The band's own LU solves both (the matrices are far from singular). */
START_TEST(block_factor_refuses_without_pivots)
{
    for (int which = 0; which < 2; which++) {
        enum { NB = 4, N = 2 * NB };
        double band[LD * N], before[LD * N], f[SW_BLOCK_DOUBLES(NB)];
        int piv[N];
        sw_band bd;
        sw_band_init(&bd, N, KL, KL, band, piv);
        for (int i = 0; i < N; i++)
            for (int j = 0; j < N; j++) {
                double v = entry(0, i, j);
                if (i < 2 && j < 2)
                    v = which == 0 ? (i == 1 && j == 1 ? 1.0 + 1e-9 : 1.0) : (i == j ? 1e-4 : 0.0);
                if (v != 0)
                    sw_band_add(&bd, i, j, v);
            }
        memcpy(before, band, sizeof band);
        ck_assert_int_eq(sw_block_factor(&bd, f), -1);
        ck_assert_mem_eq(band, before, sizeof band);
        ck_assert_int_eq(sw_band_factor(&bd), 0);
    }
}
END_TEST

/* Not a chain's band (kl = 2): refused, whatever the entries. */
START_TEST(block_factor_wants_a_chain_band)
{
    enum { N = 6, K = 2, L = 3 * K + 1 };
    double band[L * N], f[SW_BLOCK_DOUBLES(N / 2)];
    int piv[N];
    sw_band bd;
    sw_band_init(&bd, N, K, K, band, piv);
    for (int i = 0; i < N; i++)
        sw_band_add(&bd, i, i, 1.0);
    ck_assert_int_eq(sw_block_factor(&bd, f), -1);
}
END_TEST

Suite *make_linalg_block_suite(void);
Suite *make_linalg_block_suite(void)
{
    Suite *s = suite_create("linalg_block");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, block_solve_solves);
    tcase_add_test(tc, block_factor_refuses_without_pivots);
    tcase_add_test(tc, block_factor_wants_a_chain_band);
    suite_add_tcase(s, tc);
    return s;
}
