/* Private to the engine: one spring's force as one inline function, so that
 * the small particle derivative (particles_small.c) and a method stepping a
 * lone particle on a lone anchored spring with no call (rkn12.c and rkn.c,
 * through sw_ode_fast's spring1) compute it with the same operations in the
 * same order: the same bits, as central.h does for the central field. */
#ifndef SW_ENGINE_SPRING1_H
#define SW_ENGINE_SPRING1_H

#include <math.h>

#include "engine/clones.h"

/* A spring of stiffness k, damping c and rest length rest on its end a,
 * from d = x_a - x_b and dv = v_a - v_b, as block_forces computes it
 * (particles_deriv.c): |d| from the squares, d = 0 divided by 1 (a force
 * ±0), and where |d|² < 1e-290 or NaN from hypot, no force where that is
 * not positive. */
SW_INLINE void sw_spring_force(double k, double c, double rest, double dx, double dy, double dvx, double dvy,
                               int damped, double *fx, double *fy)
{
    /* q = l + (l == 0) as a choice, not an addition: the same value (l + 0
     * is l, a -0 compares equal to 0 and gives 1, a NaN stays), one
     * addition fewer between the root and the division */
    double l2 = dx * dx + dy * dy, l = sqrt(l2), q = l == 0 ? 1.0 : l;
    double ux = dx / q, uy = dy / q;
    double mag = k * (l - rest);
    if (damped)
        mag += c * (dvx * ux + dvy * uy);
    if (!(l2 >= 1e-290)) {
        l = hypot(dx, dy);
        if (!(l > 0)) {
            *fx = *fy = 0.0;
            return;
        }
        ux = dx / l, uy = dy / l;
        mag = k * (l - rest) + (damped ? c * (dvx * ux + dvy * uy) : 0.0);
    }
    *fx = -mag * ux;
    *fy = -mag * uy;
}

/* One particle on one undamped spring to the anchor (ax, ay), perhaps under
 * gravity, and no other force (the stiff-spring pendulum): the numbers its
 * acceleration needs, as the system stores them. */
typedef struct sw_spring1 {
    double ax, ay, k, rest;
    double mgx, mgy; /* mass·g, as the small derivative forms it */
    double inv;      /* 1/mass */
    int gravity;
} sw_spring1;

/* The lone particle's acceleration at (x, y): the small derivative's, whose
 * force sum starts at 0.0 and adds the spring's force times its sign (+1
 * for the particle at the spring's free end: the product is the force, bit
 * for bit), then gravity, and is then times 1/m. */
SW_INLINE void sw_spring1_accel(const sw_spring1 *s, double x, double y, double *ax, double *ay)
{
    double sx, sy;
    sw_spring_force(s->k, 0.0, s->rest, x - s->ax, y - s->ay, 0.0, 0.0, 0, &sx, &sy);
    double fx = 0.0 + sx, fy = 0.0 + sy;
    if (s->gravity) {
        fx += s->mgx;
        fy += s->mgy;
    }
    *ax = fx * s->inv;
    *ay = fy * s->inv;
}

#endif
