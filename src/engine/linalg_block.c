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

#include <float.h>
#include <math.h>
#include <string.h>

typedef double v2d __attribute__((vector_size(2 * sizeof(double))));

/* Largest growth of a Schur complement over its diagonal block accepted,
 * in squared Frobenius norms (‖S_i‖ <= 16·‖D_i‖), and smallest second
 * pivot of a 2x2 block against its first (below: singular to working
 * precision). */
#define GROWTH2_MAX 0x1p8
#define PIVOT_MIN 0x1p-52

/* A chain's band: ld = 2·kl + ku + 1 = 10, so block row i's diagonal
 * block starts at top + 20·i (column 0; column 1 at + 9), its lower
 * neighbour (i, i - 1) 18 before it and its upper (i, i + 1) 18 after. */
#define LD 10
#define ROW (2 * LD)
#define COL1 (LD - 1)
#define NEXT (2 * LD - 2)

static inline v2d load(const double *p)
{
    v2d v;
    memcpy(&v, p, sizeof v);
    return v;
}

static inline void store(double *p, v2d v)
{
    memcpy(p, &v, sizeof v);
}

/* Block row i's factors, SW_BLOCK_DOUBLES / nb doubles: W_i by columns
 * (0-3), then S_i = Pᵀ·[1 0; l 1]·[u11 u12; 0 u22] by its reciprocal
 * pivots, u12, l and whether P swaps the rows (4-8). */
enum { W0 = 0, W1 = 2, R11 = 4, U12 = 5, R22 = 6, ELL = 7, SWAP = 8, PER = 10 };
_Static_assert(PER == SW_BLOCK_PER, "block factors' length");

/* ‖S‖²_F for S by its columns. */
static inline double norm2(v2d s0, v2d s1)
{
    v2d q = s0 * s0 + s1 * s1;
    return q[0] + q[1];
}

/* z = S^-1·t by S's factors f. */
static inline v2d block_apply(const double *f, v2d t)
{
    double t0 = t[0], t1 = t[1];
    if (f[SWAP] != 0) {
        t0 = t[1];
        t1 = t[0];
    }
    double x1 = (t1 - f[ELL] * t0) * f[R22];
    return (v2d){ (t0 - f[U12] * x1) * f[R11], x1 };
}

int sw_block_factor(const sw_band *b, double *f)
{
    int nb = b->n / 2;
    if (b->kl != 3 || b->ku != 3 || b->n % 2 != 0 || b->ld != LD)
        return -1;
    const double *e = b->a + b->kl + b->ku; /* block row i's diagonal block */
    int bad = 0;
    const double *prev = f;
    for (int i = 0; i < nb; i++, e += ROW, f += PER) {
        v2d s0 = load(e), s1 = load(e + COL1), w0 = { 0, 0 }, w1 = { 0, 0 };
        if (i > 0) {
            v2d l0 = load(e - NEXT), l1 = load(e - NEXT + COL1), u0 = load(e - 2), u1 = load(e - 2 + COL1);
            /* W = L·S^-1 by rows (the two lanes): z·U = row of L, then
             * ·[1 0; -l 1], then P's swap of the columns */
            v2d z0 = l0 * prev[R11];
            v2d z1 = (l1 - z0 * prev[U12]) * prev[R22];
            z0 = z0 - z1 * prev[ELL];
            w0 = prev[SWAP] != 0 ? z1 : z0;
            w1 = prev[SWAP] != 0 ? z0 : z1;
            double dn = norm2(s0, s1);
            s0 = s0 - (w0 * u0[0] + w1 * u0[1]); /* S = D - W·U */
            s1 = s1 - (w0 * u1[0] + w1 * u1[1]);
            bad |= !(norm2(s0, s1) <= GROWTH2_MAX * dn);
        }
        /* S finite (its squared norm is): then so are its factors, |l| <= 1 */
        bad |= !(norm2(s0, s1) <= DBL_MAX);
        /* S's LU with the larger of its first column's entries as pivot */
        double a = s0[0], c = s0[1], bb = s1[0], d = s1[1];
        int swap = fabs(c) > fabs(a);
        if (swap) {
            double t = a;
            a = c;
            c = t;
            t = bb;
            bb = d;
            d = t;
        }
        double l = c / a, u22 = d - l * bb;
        bad |= !(fabs(u22) > PIVOT_MIN * fabs(a)); /* false too where a = 0: l is NaN */
        store(f + W0, w0);
        store(f + W1, w1);
        f[R11] = 1.0 / a;
        f[U12] = bb;
        f[R22] = 1.0 / u22;
        f[ELL] = l;
        f[SWAP] = swap;
        prev = f;
    }
    return bad ? -1 : 0;
}

void sw_block_solve(const sw_band *b, const double *f, double *x)
{
    int nb = b->n / 2;
    if (nb == 0)
        return;
    v2d prev = load(x);
    for (int i = 1; i < nb; i++) { /* y_i = x_i - W_i·y_(i-1) */
        const double *fi = f + PER * i;
        prev = load(x + 2 * i) - (load(fi + W0) * prev[0] + load(fi + W1) * prev[1]);
        store(x + 2 * i, prev);
    }
    /* x_i = S_i^-1·(y_i - U_i·x_(i+1)), the last row without U */
    const double *e = b->a + b->kl + b->ku + (size_t)ROW * (size_t)(nb - 1);
    v2d next = block_apply(f + PER * (nb - 1), prev);
    store(x + 2 * (nb - 1), next);
    for (int i = nb - 2; i >= 0; i--) {
        e -= ROW;
        v2d yi = load(x + 2 * i) - (load(e + NEXT) * next[0] + load(e + NEXT + COL1) * next[1]);
        next = block_apply(f + PER * i, yi);
        store(x + 2 * i, next);
    }
}
