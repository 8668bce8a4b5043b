/* Private to the engine: a block-tridiagonal solve with 2x2 blocks (the
 * block Thomas algorithm), for a chain's velocity system, read from the
 * band it was written into (engine/linalg.h's layout, kl = ku = 3). It
 * pivots only inside a 2x2 block; it refuses (and the caller factors the
 * band with its row interchanges instead) where that is not safe. Nothing
 * here allocates. */
#ifndef SW_ENGINE_LINALG_BLOCK_H
#define SW_ENGINE_LINALG_BLOCK_H

#include <float.h>
#include <math.h>

#include "engine/clones.h"
#include "engine/lanes.h"
#include "engine/linalg.h"

/* Doubles the factors of a band of b->n = 2·nb rows need. */
#define SW_BLOCK_PER 10
#define SW_BLOCK_DOUBLES(nb) ((size_t)SW_BLOCK_PER * (size_t)(nb))

/* Factor the band b, whose entries lie in 2x2 blocks on the diagonal and
 * its two neighbours only (a chain's: kl = ku = 3, ld = 10, b->n even, the
 * (i, i ± 2) blocks zero), into f without touching b: block row i keeps
 * W_i = L_i·S_(i-1)^-1 and the pivoted LU of its Schur complement S_i.
 * 0, or -1 when a Schur complement grows (‖S_i‖_F > 16·‖D_i‖_F), is not
 * finite, or is singular to working precision (its second pivot below
 * 2^-52 of its first): then f is of no use and the band is untouched. */
int sw_block_factor(const sw_band *b, double *f);
/* Solve with those factors and b's upper blocks, x (b->n long) becoming
 * the solution. */
void sw_block_solve(const sw_band *b, const double *f, double *x);

/* Block row i's factors, SW_BLOCK_PER doubles: W_i by columns (0-3), then
 * S_i = Pᵀ·[1 0; l 1]·[u11 u12; 0 u22] by its reciprocal pivots, u12, l
 * and whether P swaps the rows (4-8). */
enum { SW_BW0 = 0, SW_BW1 = 2, SW_BR11 = 4, SW_BU12 = 5, SW_BR22 = 6, SW_BELL = 7, SW_BSWAP = 8 };

/* Largest growth of a Schur complement over its diagonal block accepted,
 * in squared Frobenius norms (‖S_i‖ <= 16·‖D_i‖), and smallest second
 * pivot of a 2x2 block against its first (below: singular to working
 * precision). */
#define SW_BLOCK_GROWTH2_MAX 0x1p8
#define SW_BLOCK_PIVOT_MIN 0x1p-52

/* ‖S‖²_F for S by its columns. */
SW_INLINE double sw_block_norm2(v2d s0, v2d s1)
{
    v2d q = s0 * s0 + s1 * s1;
    return q[0] + q[1];
}

/* One block row of sw_block_factor, into f: its diagonal block D (s0, s1,
 * by columns) and, past the first row (prev, the last row's factors, not
 * NULL), its lower neighbour L (l0, l1) and the upper block above it U
 * (u0, u1). Nonzero where the row refuses (sw_block_factor's -1). The one
 * copy of the row's arithmetic: the band's factorisation and a chain's
 * fused one (particles_solve.c) give the same bits by it. */
SW_INLINE int sw_block_row(double *f, const double *prev, v2d s0, v2d s1, v2d l0, v2d l1, v2d u0, v2d u1)
{
    int bad = 0;
    v2d w0 = { 0, 0 }, w1 = { 0, 0 };
    if (prev) {
        /* W = L·S^-1 by rows (the two lanes): z·U = row of L, then
         * ·[1 0; -l 1], then P's swap of the columns */
        v2d z0 = l0 * prev[SW_BR11];
        v2d z1 = (l1 - z0 * prev[SW_BU12]) * prev[SW_BR22];
        z0 = z0 - z1 * prev[SW_BELL];
        w0 = prev[SW_BSWAP] != 0 ? z1 : z0;
        w1 = prev[SW_BSWAP] != 0 ? z0 : z1;
        double dn = sw_block_norm2(s0, s1);
        s0 = s0 - (w0 * u0[0] + w1 * u0[1]); /* S = D - W·U */
        s1 = s1 - (w0 * u1[0] + w1 * u1[1]);
        bad |= !(sw_block_norm2(s0, s1) <= SW_BLOCK_GROWTH2_MAX * dn);
    }
    /* S finite (its squared norm is): then so are its factors, |l| <= 1 */
    bad |= !(sw_block_norm2(s0, s1) <= DBL_MAX);
    /* S's LU with the larger of its first column's entries as pivot */
    int swap = fabs(s0[1]) > fabs(s0[0]);
    if (swap) { /* the rows exchanged */
        s0 = (v2d){ s0[1], s0[0] };
        s1 = (v2d){ s1[1], s1[0] };
    }
    double a = s0[0], c = s0[1], bb = s1[0], d = s1[1];
    double l = c / a, u22 = d - l * bb;
    bad |= !(fabs(u22) > SW_BLOCK_PIVOT_MIN * fabs(a)); /* false too where a = 0: l is NaN */
    store2(f + SW_BW0, w0);
    store2(f + SW_BW1, w1);
    f[SW_BR11] = 1.0 / a;
    f[SW_BU12] = bb;
    f[SW_BR22] = 1.0 / u22;
    f[SW_BELL] = l;
    f[SW_BSWAP] = swap;
    return bad;
}

#endif
