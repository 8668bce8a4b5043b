/* Private to the engine: what the one-particle entries of the Nyström pairs
 * (rkn.c, rkn12.c) share — 2-lane vectors, and a trial's end: the error
 * norm's squares, the runaway test, the old state saved and the new one
 * written, as their general bodies do them (the same bits). */
#ifndef SW_ENGINE_NYSTROM2_H
#define SW_ENGINE_NYSTROM2_H

#include <math.h>
#include <string.h>

#include "engine/adaptive.h"
#include "engine/clones.h"
#include "engine/lanes.h"

/* From [x | v] to [x1 | v1] with error estimates ex, ev: RMS of e_i / (atol
 * + rtol·max(|y0_i|, |y1_i|)), the squares in the order [x | v] added by
 * i mod 4; the max as the general body writes it (new_first: m1 > m0 ? m1
 * : m0, rkn's; else m0 > m1 ? m0 : m1, rkn12's: the same but for NaNs).
 * The old state into saved, the new one into y. */
SW_INLINE void sw_nys2_finish(v2d x, v2d v, v2d x1, v2d v1, v2d ex, v2d ev, double atol,
                              double rtol, unsigned elim, int new_first, double *y, double *saved,
                              sw_trial_sums *sums)
{
    unsigned long long over = 0, add = sw_beyond_add(elim);
    double q[4];
    for (int i = 0; i < 2; i++) {
        double m0 = fabs(x[i]), m1 = fabs(x1[i]), n0 = fabs(v[i]), n1 = fabs(v1[i]);
        double mx = new_first ? (m1 > m0 ? m1 : m0) : (m0 > m1 ? m0 : m1);
        double mv = new_first ? (n1 > n0 ? n1 : n0) : (n0 > n1 ? n0 : n1);
        double rx = ex[i] / (atol + rtol * mx), rv = ev[i] / (atol + rtol * mv);
        q[i] = rx * rx;
        q[2 + i] = rv * rv;
        over |= sw_beyond_bits(x1[i], add) | sw_beyond_bits(v1[i], add);
    }
    memcpy(saved, &x, sizeof x);
    memcpy(saved + 2, &v, sizeof v);
    memcpy(y, &x1, sizeof x1);
    memcpy(y + 2, &v1, sizeof v1);
    sums->err = sw_add_by4(sums->part[0], q, 4);
    sums->beyond |= sw_beyond_any(over);
}

#endif
