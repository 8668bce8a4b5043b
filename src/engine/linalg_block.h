/* Private to the engine: a block-tridiagonal solve with 2x2 blocks (the
 * block Thomas algorithm), for a chain's velocity system, read from the
 * band it was written into (engine/linalg.h's layout, kl = ku = 3). It
 * pivots only inside a 2x2 block; it refuses (and the caller factors the
 * band with its row interchanges instead) where that is not safe. Nothing
 * here allocates. */
#ifndef SW_ENGINE_LINALG_BLOCK_H
#define SW_ENGINE_LINALG_BLOCK_H

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

#endif
