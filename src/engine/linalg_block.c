/* The block Thomas algorithm on a band whose entries lie in 2x2 blocks on
 * the diagonal and its neighbours (a chain's velocity system): for block
 * rows i = 0, 1, ... the Schur complement S_i = D_i - W_i·U_(i-1), with
 * W_i = L_i·S_(i-1)^-1 (S_0 = D_0), each S_i factored as a 2x2 LU with
 * partial pivoting inside the block; then W's forward pass and the S's
 * backward one. A 2x2 block is two columns of two doubles, side by side in
 * the band's layout (engine/linalg.h: entry (r, c) at top + r - c + c·ld),
 * so each column is one two-lane vector here.
 *
 * No row leaves its block row, so the elimination is stable where the
 * Schur complements do not grow: where the matrix is block diagonally
 * dominant (M ahead of c·Fv + c²·Fx: small steps or soft springs) and
 * where it is symmetric positive definite (undamped springs, all
 * stretched: -Fx is then positive semidefinite, and S_i <= D_i). A
 * compressed spring (its transverse stiffness negative) or damping that
 * turns with the spring (Fx not symmetric) can make them grow:
 * sw_block_factor then refuses, and the caller factors the band with
 * partial pivoting. Each S_i's own factors are backward stable whatever
 * its condition (elimination with partial pivoting on 2x2); an explicit
 * inverse (Cramer's rule) is not: tried first, its solutions' backward
 * error reached 3000 times the band's on stiff chains. */
#include "engine/linalg_block.h"

/* A chain's band: ld = 2·kl + ku + 1 = 10, so block row i's diagonal
 * block starts at top + 20·i (column 0; column 1 at + 9), its lower
 * neighbour (i, i - 1) 18 before it and its upper (i, i + 1) 18 after. */
#define LD 10
#define ROW (2 * LD)
#define COL1 (LD - 1)
#define NEXT (2 * LD - 2)
#define PER SW_BLOCK_PER
_Static_assert(SW_BSWAP < PER, "block factors' length");

/* z = S^-1·t by S's factors f. */
static inline v2d block_apply(const double *f, v2d t)
{
    if (f[SW_BSWAP] != 0)
        t = (v2d){ t[1], t[0] };
    double t0 = t[0], t1 = t[1];
    double x1 = (t1 - f[SW_BELL] * t0) * f[SW_BR22];
    return (v2d){ (t0 - f[SW_BU12] * x1) * f[SW_BR11], x1 };
}

int sw_block_factor(const sw_band *b, double *f)
{
    int nb = b->n / 2;
    if (b->kl != 3 || b->ku != 3 || b->n % 2 != 0 || b->ld != LD)
        return -1;
    const double *e = b->a + b->kl + b->ku; /* block row i's diagonal block */
    int bad = 0;
    const double *prev = NULL;
    for (int i = 0; i < nb; i++, e += ROW, f += PER) {
        v2d s0 = load2(e), s1 = load2(e + COL1), l0 = s0, l1 = s0, u0 = s0, u1 = s0;
        if (i > 0) {
            l0 = load2(e - NEXT);
            l1 = load2(e - NEXT + COL1);
            u0 = load2(e - 2);
            u1 = load2(e - 2 + COL1);
        }
        bad |= sw_block_row(f, prev, s0, s1, l0, l1, u0, u1);
        prev = f;
    }
    return bad ? -1 : 0;
}

SW_CLONES void sw_block_solve(const sw_band *b, const double *f, double *x)
{
    int nb = b->n / 2;
    if (nb == 0)
        return;
    v2d prev = load2(x);
#pragma GCC unroll 2
    for (int i = 1; i < nb; i++) { /* y_i = x_i - W_i·y_(i-1) */
        const double *fi = f + PER * i;
        prev = load2(x + 2 * i) - (load2(fi + SW_BW0) * prev[0] + load2(fi + SW_BW1) * prev[1]);
        store2(x + 2 * i, prev);
    }
    /* x_i = S_i^-1·(y_i - U_i·x_(i+1)), the last row without U */
    const double *e = b->a + b->kl + b->ku + (size_t)ROW * (size_t)(nb - 1);
    v2d next = block_apply(f + PER * (nb - 1), prev);
    store2(x + 2 * (nb - 1), next);
#pragma GCC unroll 2
    for (int i = nb - 2; i >= 0; i--) {
        e -= ROW;
        v2d yi = load2(x + 2 * i) - (load2(e + NEXT) * next[0] + load2(e + NEXT + COL1) * next[1]);
        next = block_apply(f + PER * i, yi);
        store2(x + 2 * i, next);
    }
}
