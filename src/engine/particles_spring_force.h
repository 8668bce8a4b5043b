/* Private to the particle derivative and the chain's fused rk4
 * (particles_deriv.c, particles_chain.c): the spring forces of a block
 * of springs from their differences, one loop without indices that the
 * compiler vectorises. Both paths inline this one function, so a spring's
 * force is the same operations in the same order (the same bits) wherever
 * it is computed. */
#ifndef SW_ENGINE_PARTICLES_SPRING_FORCE_H
#define SW_ENGINE_PARTICLES_SPRING_FORCE_H

#include <math.h>
#include <string.h>

#include "engine/clones.h"
#include "engine/lanes.h"

/* The sign bit set when l2 (a sum of squares: +0 or more, or NaN) is below
 * 1e-290 or NaN, i.e. when !(l2 >= 1e-290), from its bits alone: below, its
 * bits minus those of 1e-290 wrap around; a NaN with the sign clear
 * carries into the sign bit when 2^52 - 1 is added; one with it set has it
 * set. Integer operations, so the loop that ORs these vectorises. */
static inline unsigned long long small_or_nan(double l2)
{
    const double tiny = 1e-290;
    unsigned long long b, t;
    memcpy(&b, &l2, sizeof b);
    memcpy(&t, &tiny, sizeof t);
    return b | (b - t) | (b + 0x000FFFFFFFFFFFFFULL);
}

/* Spring forces of a block from its differences d (and dv), as (x, y) pairs:
 *   f_a = -[k(|d| - rest) + c·(v_a - v_b)·d̂] d̂,  d̂ = d/|d|,
 * |d| = √(dx² + dy²), or hypot(dx, dy) where dx² + dy² < 1e-290 (there the
 * squares lose their digits or vanish). Where |d| = 0 the direction is
 * undefined and the plain loop adds no force; here d = 0 is divided by 1
 * instead (l + (l == 0), a select without a branch, so the loop
 * vectorises) and the force is ±0, which leaves a sum as it is: the sums
 * start at +0, and a sum that starts at +0 is never -0. The hypot cases are
 * found after the loop (their squares were kept in len2) and redone; the
 * loop flags whether there are any with integer operations on l2's bits,
 * which vectorise (see small_or_nan), so the usual block is not scanned. */
SW_INLINE void block_forces(int len, const double *restrict k, const double *restrict c, const double *restrict rest,
                            const double *restrict d, const double *restrict dv, double *restrict force,
                            double *restrict len2, int damped)
{
    unsigned long long flag = 0;
    int len4 = (len + 3) & ~3; /* whole vectors: the padding is computed and never read */
    for (int j = 0; j < len4; j++) {
        double dx = d[2 * j], dy = d[2 * j + 1];
        double l2 = dx * dx + dy * dy, l = sqrt(l2), q = l + (l == 0);
        double ux = dx / q, uy = dy / q;
        double mag = k[j] * (l - rest[j]);
        if (damped)
            mag += c[j] * (dv[2 * j] * ux + dv[2 * j + 1] * uy);
        len2[j] = l2;
        flag |= small_or_nan(l2);
        force[2 * j] = -mag * ux;
        force[2 * j + 1] = -mag * uy;
    }
    for (int j = 0; flag >> 63 && j < len; j++) {
        if (len2[j] >= 1e-290)
            continue;
        double dx = d[2 * j], dy = d[2 * j + 1], l = hypot(dx, dy);
        if (!(l > 0)) {
            force[2 * j] = force[2 * j + 1] = 0.0;
            continue;
        }
        double ux = dx / l, uy = dy / l;
        double mag = k[j] * (l - rest[j]) + (damped ? c[j] * (dv[2 * j] * ux + dv[2 * j + 1] * uy) : 0.0);
        force[2 * j] = -mag * ux;
        force[2 * j + 1] = -mag * uy;
    }
}

#endif
