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
 * gives the same bits either way (tests/check_pointwise.c). They take the
 * points two at a time and test the pair just written as one vector, so
 * the compiler keeps each pair in one vector from load to test (a separate
 * test pass, or a test per component, cost Euler on the vortex half again
 * its update). Private to the engine and the scenes. */
#ifndef SW_ENGINE_POINTWISE_H
#define SW_ENGINE_POINTWISE_H

#include <string.h>

#include "engine/clones.h"
#include "engine/stepper.h"
#include "stepwise/flow.h"

/* The runaway test (stepper.h) of two points just written at x[0..3], as
 * a running maximum per component slot: each component's exponent field
 * alone (the double 2^e, +0, or +inf for inf and NaN: never NaN, so the
 * maximum is exact) kept if larger. Two vector operations per pair, on
 * values still in registers, where a separate test pass or a test per
 * component cost Euler on the vortex half again its update. */
SW_INLINE double sw_point_exponent(double v)
{
    unsigned long long bits;
    memcpy(&bits, &v, sizeof bits);
    bits &= SW_EXPONENT_BITS;
    memcpy(&v, &bits, sizeof v);
    return v;
}

SW_INLINE void sw_point_beyond2(double top[4], const double *x)
{
    for (int e = 0; e < 4; e++) {
        double a = sw_point_exponent(x[e]);
        top[e] = a > top[e] ? a : top[e];
    }
}

/* Whether any component was beyond elim: the slots' largest, and an odd
 * last point's components. */
static inline unsigned sw_point_beyond_end(const double top[4], const double *x, int odd, unsigned elim)
{
    unsigned long long add = sw_beyond_add(elim);
    unsigned long long over = sw_beyond_bits(top[0], add) | sw_beyond_bits(top[1], add) |
                              sw_beyond_bits(top[2], add) | sw_beyond_bits(top[3], add);
    if (odd)
        over |= sw_beyond_bits(x[0], add) | sw_beyond_bits(x[1], add);
    return sw_beyond_any(over);
}

/* The field alone: all a student plugin's host is built with (-DSW_FIELD_ONLY),
 * so that no built-in method's code, fused or not, is in its memory. */
#define SW_POINT_FIELD_ONLY(NAME, COEF, PREP, POINT)                                                     \
    SW_CLONES static void NAME##_field(const void *params, double t, int n, const double *x, double *v) \
    {                                                                                                 \
        const COEF c = PREP(params, t);                                                               \
        for (int i = 0; i < n; i++)                                                                   \
            POINT(&c, x[2 * i], x[2 * i + 1], &v[2 * i], &v[2 * i + 1]);                              \
    }

#ifdef SW_FIELD_ONLY
#define SW_POINT_FIELD(NAME, COEF, PREP, POINT)                                                       \
    SW_POINT_FIELD_ONLY(NAME, COEF, PREP, POINT)                                                      \
    static const sw_point_field NAME##_point = { NAME##_field, NULL, NULL }
#else
#define SW_POINT_FIELD(NAME, COEF, PREP, POINT)                                                       \
    SW_POINT_FIELD_ONLY(NAME, COEF, PREP, POINT)                                                      \
    /* one point's Euler step, and its RK4 step (c1, c2, c4: at t, t + h/2, t + h) */                 \
    SW_INLINE void NAME##_euler1(const COEF *c, double *x, int j, double h)                           \
    {                                                                                                 \
        double px = x[j], py = x[j + 1], vx, vy;                                                      \
        POINT(c, px, py, &vx, &vy);                                                                   \
        x[j] = px + h * vx;                                                                           \
        x[j + 1] = py + h * vy;                                                                       \
    }                                                                                                 \
    SW_INLINE void NAME##_rk41(const COEF *c1, const COEF *c2, const COEF *c4, double *x, int j,      \
                               double h)                                                              \
    {                                                                                                 \
        double px = x[j], py = x[j + 1], k1x, k1y, k2x, k2y, k3x, k3y, k4x, k4y;                      \
        POINT(c1, px, py, &k1x, &k1y);                                                                \
        POINT(c2, px + 0.5 * h * k1x, py + 0.5 * h * k1y, &k2x, &k2y);                                \
        POINT(c2, px + 0.5 * h * k2x, py + 0.5 * h * k2y, &k3x, &k3y);                                \
        POINT(c4, px + h * k3x, py + h * k3y, &k4x, &k4y);                                            \
        x[j] = px + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);                                    \
        x[j + 1] = py + h / 6.0 * (k1y + 2.0 * k2y + 2.0 * k3y + k4y);                                \
    }                                                                                                 \
    /* the steps over n points, two at a time (then an odd last one) */                               \
    SW_CLONES static unsigned NAME##_euler(const void *params, double t, int n, double *restrict x,   \
                                           double h, unsigned elim)                                   \
    {                                                                                                 \
        const COEF c = PREP(params, t);                                                               \
        double top[4] = { 0.0, 0.0, 0.0, 0.0 };                                                       \
        int i = 0;                                                                                    \
        for (; i + 2 <= n; i += 2) {                                                                  \
            for (int e = 0; e < 2; e++)                                                               \
                NAME##_euler1(&c, x, 2 * (i + e), h);                                                 \
            sw_point_beyond2(top, x + 2 * i);                                                         \
        }                                                                                             \
        if (i < n)                                                                                    \
            NAME##_euler1(&c, x, 2 * i, h);                                                           \
        return sw_point_beyond_end(top, x + 2 * i, i < n, elim);                                      \
    }                                                                                                 \
    SW_CLONES static unsigned NAME##_rk4(const void *params, double t, int n, double *restrict x,     \
                                         double h, unsigned elim)                                     \
    {                                                                                                 \
        const COEF c1 = PREP(params, t), c2 = PREP(params, t + 0.5 * h), c4 = PREP(params, t + h);    \
        double top[4] = { 0.0, 0.0, 0.0, 0.0 };                                                       \
        int i = 0;                                                                                    \
        for (; i + 2 <= n; i += 2) {                                                                  \
            for (int e = 0; e < 2; e++)                                                               \
                NAME##_rk41(&c1, &c2, &c4, x, 2 * (i + e), h);                                        \
            sw_point_beyond2(top, x + 2 * i);                                                         \
        }                                                                                             \
        if (i < n)                                                                                    \
            NAME##_rk41(&c1, &c2, &c4, x, 2 * i, h);                                                  \
        return sw_point_beyond_end(top, x + 2 * i, i < n, elim);                                      \
    }                                                                                                 \
    static const sw_point_field NAME##_point = { NAME##_field, NAME##_euler, NAME##_rk4 }
#endif

#endif
