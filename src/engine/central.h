/* Private to the engine: a central field's pull on one particle as one
 * inline function, so that the central kind's add (force_fields.c), the
 * small particle derivative (particles_small.c) and a method stepping a
 * lone particle in a lone field with no call (rkn12.c, through
 * sw_ode_fast's central1) compute it with the same operations in the same
 * order: the same bits. */
#ifndef SW_ENGINE_CENTRAL_H
#define SW_ENGINE_CENTRAL_H

#include <math.h>

#include "engine/clones.h"

/* A central field of parameter mu at (cx, cy) and the one particle in it:
 * its mass and 1/mass as the system stores them. */
typedef struct sw_central1 {
    double cx, cy, mu, mass, inv;
} sw_central1;

/* The force -mu·m/r³·d on a particle of mass m at (x, y), d its offset from
 * the centre. */
SW_INLINE void sw_central_force(double cx, double cy, double mu, double m, double x, double y, double *fx,
                                double *fy)
{
    double dx = x - cx, dy = y - cy;
    double r2 = dx * dx + dy * dy;
    double s = -mu * m / (r2 * sqrt(r2));
    *fx = s * dx;
    *fy = s * dy;
}

/* The acceleration of the lone particle in the lone field: the small
 * derivative's, whose force sum starts at 0.0 and is then times 1/m. With
 * canon (a constant; only where sw_central1_canon(c)) the subtraction of a
 * +0 centre and the product by 1/m = 1 are left out: x - (+0) is x and
 * f·1 is f, bit for bit, so the numbers are the same. */
SW_INLINE void sw_central1_accel(const sw_central1 *c, int canon, double x, double y, double *ax, double *ay)
{
    double fx, fy;
    sw_central_force(canon ? 0.0 : c->cx, canon ? 0.0 : c->cy, c->mu, c->mass, x, y, &fx, &fy);
    *ax = canon ? 0.0 + fx : (0.0 + fx) * c->inv;
    *ay = canon ? 0.0 + fy : (0.0 + fy) * c->inv;
}

/* The centre at (+0, +0) and 1/m = 1 (the orbit scene). */
static inline int sw_central1_canon(const sw_central1 *c)
{
    return c->cx == 0 && !signbit(c->cx) && c->cy == 0 && !signbit(c->cy) && c->inv == 1.0;
}

#endif
