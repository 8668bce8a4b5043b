/* The block Thomas algorithm on a band whose entries lie in 2x2 blocks on
 * the diagonal and its neighbours (a chain's velocity system): for block
 * rows i = 0, 1, ... the Schur complement S_i = D_i - W_i·U_(i-1), with
 * W_i = L_i·S_(i-1)^-1 (S_0 = D_0); then W's forward pass and S^-1's
 * backward one. A 2x2 block is two columns of two doubles, side by side in
 * the band's layout (engine/linalg.h: entry (r, c) at top + r - c + c·ld),
 * so each column is one two-lane vector here.
 *
 * Without pivoting this is stable where the Schur complements stay well
 * conditioned and the multipliers small: where the matrix is block
 * diagonally dominant (M ahead of c·Fv + c²·Fx: small steps or soft
 * springs) and where it is symmetric positive definite (undamped springs,
 * all stretched: -Fx is then positive semidefinite, and the Schur
 * complements of a positive definite matrix are positive definite with
 * |W| bounded by their conditioning). A compressed spring (its
 * transverse stiffness negative) or damping that turns with the spring
 * (Fx not symmetric) can break both: sw_block_factor then refuses, and the
 * caller factors the band with partial pivoting. */
#include "engine/linalg_block.h"

#include <math.h>
#include <string.h>

typedef double v2d __attribute__((vector_size(2 * sizeof(double))));
typedef long long v2i __attribute__((vector_size(2 * sizeof(long long))));

/* Largest 2x2 condition (‖S‖²_F / |det S|) and multiplier row sum
 * (‖W‖_∞) accepted. */
#define COND_MAX 0x1p20
#define GROWTH_MAX 0x1p10

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

/* |w0| + |w1| lane by lane: the rows' absolute sums of W (w0, w1 its
 * columns). */
static inline v2d row_sums(v2d w0, v2d w1)
{
    const v2i mask = { 0x7fffffffffffffffLL, 0x7fffffffffffffffLL };
    return (v2d)((v2i)w0 & mask) + (v2d)((v2i)w1 & mask);
}

int sw_block_factor(const sw_band *b, double *f)
{
    int nb = b->n / 2;
    if (b->kl != 3 || b->ku != 3 || b->n % 2 != 0 || b->ld != LD)
        return -1;
    const double *e = b->a + b->kl + b->ku; /* block row i's diagonal block */
    const v2d limit = { GROWTH_MAX, GROWTH_MAX };
    v2i grown = { 0, 0 }; /* a lane set where some W's row sum passed the limit (or is NaN) */
    int bad = 0;
    v2d p0 = { 0, 0 }, p1 = { 0, 0 }; /* S_(i-1)^-1 by columns */
    for (int i = 0; i < nb; i++, e += ROW, f += 8) {
        v2d s0 = load(e), s1 = load(e + COL1), w0 = { 0, 0 }, w1 = { 0, 0 };
        if (i > 0) {
            v2d l0 = load(e - NEXT), l1 = load(e - NEXT + COL1), u0 = load(e - 2), u1 = load(e - 2 + COL1);
            w0 = l0 * p0[0] + l1 * p0[1]; /* W = L·S^-1, by columns */
            w1 = l0 * p1[0] + l1 * p1[1];
            grown |= ~(row_sums(w0, w1) <= limit);
            s0 = s0 - (w0 * u0[0] + w1 * u0[1]); /* S = D - W·U */
            s1 = s1 - (w0 * u1[0] + w1 * u1[1]);
        }
        double a = s0[0], c = s0[1], bb = s1[0], d = s1[1];
        double det = a * d - bb * c, norm = a * a + bb * bb + c * c + d * d;
        /* norm finite: every entry, and det (|det| <= norm / 2), finite */
        bad |= !(det != 0 && fabs(det) * COND_MAX >= norm && norm <= 0x1.fffffffffffffp1023);
        double r = 1.0 / det;
        p0 = (v2d){ d * r, -c * r }; /* S^-1, by columns */
        p1 = (v2d){ -bb * r, a * r };
        store(f, p0);
        store(f + 2, p1);
        store(f + 4, w0);
        store(f + 6, w1);
    }
    return bad || grown[0] || grown[1] ? -1 : 0;
}

void sw_block_solve(const sw_band *b, const double *f, double *x)
{
    int nb = b->n / 2;
    if (nb == 0)
        return;
    v2d prev = load(x);
    for (int i = 1; i < nb; i++) { /* y_i = x_i - W_i·y_(i-1) */
        const double *fi = f + 8 * i;
        prev = load(x + 2 * i) - (load(fi + 4) * prev[0] + load(fi + 6) * prev[1]);
        store(x + 2 * i, prev);
    }
    /* x_i = S_i^-1·(y_i - U_i·x_(i+1)), the last row without U */
    const double *e = b->a + b->kl + b->ku + (size_t)ROW * (size_t)(nb - 1);
    v2d next = load(f + 8 * (nb - 1)) * prev[0] + load(f + 8 * (nb - 1) + 2) * prev[1];
    store(x + 2 * (nb - 1), next);
    for (int i = nb - 2; i >= 0; i--) {
        e -= ROW;
        const double *fi = f + 8 * i;
        v2d yi = load(x + 2 * i) - (load(e + NEXT) * next[0] + load(e + NEXT + COL1) * next[1]);
        next = load(fi) * yi[0] + load(fi + 2) * yi[1];
        store(x + 2 * i, next);
    }
}
