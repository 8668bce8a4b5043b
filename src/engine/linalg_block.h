/* Private to the engine: a block-tridiagonal solve with 2x2 blocks (the
 * block Thomas algorithm), for a chain's velocity system, read from the
 * band it was written into (engine/linalg.h's layout, kl = ku = 3). It
 * pivots nowhere; it refuses (and the caller factors the band with its
 * row interchanges instead) where that is not safe. Nothing here
 * allocates. */
#ifndef SW_ENGINE_LINALG_BLOCK_H
#define SW_ENGINE_LINALG_BLOCK_H

#include "engine/linalg.h"

/* Doubles the factors of a band of b->n = 2·nb rows need: 8 a block row. */
#define SW_BLOCK_DOUBLES(nb) ((size_t)8 * (size_t)(nb))

/* Factor the band b, whose entries lie in 2x2 blocks on the diagonal and
 * its two neighbours only (a chain's: kl = ku = 3, b->n even, the (i,
 * i ± 2) blocks zero), into f without touching b: block row i keeps
 * S_i^-1 (the inverse of its Schur complement, by columns) and
 * W_i = L_i·S_(i-1)^-1. 0, or -1 when a Schur complement is not safely
 * invertible (its 2x2 condition, ‖S‖²_F/|det S|, above 2^20, or not
 * finite) or a multiplier W grows past 2^10 (element growth unchecked by
 * pivoting): then f is of no use and the band is untouched. */
int sw_block_factor(const sw_band *b, double *f);
/* Solve with those factors and b's upper blocks, x (b->n long) becoming
 * the solution. */
void sw_block_solve(const sw_band *b, const double *f, double *x);

#endif
