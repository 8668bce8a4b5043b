/* Flow fields written per point, and the steps fused with them. A scene
 * writes its field once, as two small functions — PREP(params, t), the
 * coefficients for time t (a struct COEF), and POINT(&coef, x, y, &vx, &vy),
 * the velocity at one point — and SW_POINT_FIELD(NAME, COEF, PREP, POINT)
 * makes from them:
 *   NAME_field   the field over n points (sw_field_fn), for every method;
 *   NAME_euler,  Euler's and RK4's steps with each point's stages in
 *   NAME_rk4     registers (sw_point_step_fn): no derivative vectors
 *                written and read back;
 *   NAME_point   the sw_point_field of the three, for sw_flow_fuse.
 * The fused steps do exactly the generic methods' arithmetic (explicit.c:
 * the same operations in the same order, the runaway test alike), so a run
 * gives the same bits either way (tests/check_pointwise.c). Private to the
 * engine and the scenes. */
#ifndef SW_ENGINE_POINTWISE_H
#define SW_ENGINE_POINTWISE_H

#include "engine/clones.h"
#include "engine/stepper.h"
#include "stepwise/flow.h"

/* The runaway test over x[2lo, 2hi), just written: a flat pass over
 * components that stay in cache (a block of SW_POINT_BLOCK points), so
 * the update loop keeps each point's pair together and the test never
 * separates the components. */
#define SW_POINT_BLOCK 256

static inline __attribute__((always_inline)) unsigned long long sw_point_beyond(const double *restrict x, int lo,
                                                                               int hi, unsigned long long add)
{
    unsigned long long over = 0;
#pragma GCC unroll 4
    for (int j = 2 * lo; j < 2 * hi; j++)
        over |= sw_beyond_bits(x[j], add);
    return over;
}

#define SW_POINT_FIELD(NAME, COEF, PREP, POINT)                                                           \
    SW_CLONES static void NAME##_field(const void *params, double t, int n, const double *x, double *v)  \
    {                                                                                                     \
        const COEF c = PREP(params, t);                                                                   \
        for (int i = 0; i < n; i++)                                                                       \
            POINT(&c, x[2 * i], x[2 * i + 1], &v[2 * i], &v[2 * i + 1]);                                  \
    }                                                                                                     \
    SW_CLONES static unsigned NAME##_euler(const void *params, double t, int n, double *restrict x,       \
                                           double h, unsigned elim)                                       \
    {                                                                                                     \
        const COEF c = PREP(params, t);                                                                   \
        unsigned long long over = 0, add = sw_beyond_add(elim);                                           \
        for (int lo = 0; lo < n; lo += SW_POINT_BLOCK) {                                                  \
            int hi = lo + SW_POINT_BLOCK < n ? lo + SW_POINT_BLOCK : n;                                   \
            for (int i = lo; i < hi; i++) {                                                               \
                double px = x[2 * i], py = x[2 * i + 1], vx, vy;                                          \
                POINT(&c, px, py, &vx, &vy);                                                              \
                x[2 * i] = px + h * vx;                                                                   \
                x[2 * i + 1] = py + h * vy;                                                               \
            }                                                                                             \
            over |= sw_point_beyond(x, lo, hi, add);                                                      \
        }                                                                                                 \
        return sw_beyond_any(over);                                                                       \
    }                                                                                                     \
    SW_CLONES static unsigned NAME##_rk4(const void *params, double t, int n, double *restrict x,         \
                                         double h, unsigned elim)                                         \
    {                                                                                                     \
        const COEF c1 = PREP(params, t), c2 = PREP(params, t + 0.5 * h), c4 = PREP(params, t + h);        \
        unsigned long long over = 0, add = sw_beyond_add(elim);                                           \
        for (int lo = 0; lo < n; lo += SW_POINT_BLOCK) {                                                  \
            int hi = lo + SW_POINT_BLOCK < n ? lo + SW_POINT_BLOCK : n;                                   \
            for (int i = lo; i < hi; i++) {                                                               \
            double px = x[2 * i], py = x[2 * i + 1], k1x, k1y, k2x, k2y, k3x, k3y, k4x, k4y;              \
            POINT(&c1, px, py, &k1x, &k1y);                                                               \
            POINT(&c2, px + 0.5 * h * k1x, py + 0.5 * h * k1y, &k2x, &k2y);                               \
            POINT(&c2, px + 0.5 * h * k2x, py + 0.5 * h * k2y, &k3x, &k3y);                               \
            POINT(&c4, px + h * k3x, py + h * k3y, &k4x, &k4y);                                           \
            x[2 * i] = px + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);                                \
            x[2 * i + 1] = py + h / 6.0 * (k1y + 2.0 * k2y + 2.0 * k3y + k4y);                            \
            }                                                                                             \
            over |= sw_point_beyond(x, lo, hi, add);                                                      \
        }                                                                                                 \
        return sw_beyond_any(over);                                                                       \
    }                                                                                                     \
    static const sw_point_field NAME##_point = { NAME##_field, NAME##_euler, NAME##_rk4 }

#endif
