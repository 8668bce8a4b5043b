/* Hot bodies (fire, explosion): a temperature beside x and v. Of 2m
 * particles, body i < m keeps its temperature above ambient θ_i in the
 * velocity of its heat slot m + i, so y = [x | v] stays the solver's split
 * and every method steps θ as it steps a velocity under drag:
 *   body:  m x'' = m g + m·buoy·θ ŷ - m·k·x'       (buoyancy, drag)
 *   slot:  θ' = -cool·θ,  r' = 0                   (Newton's cooling; r = 1 alive)
 * The slot's position (∫θ dt, age) is what x' = v makes of it. The coupling
 * is one way (θ moves the body, the body never θ): the Jacobian is block
 * triangular, its eigenvalues those of each particle's own blocks, which is
 * all the descriptor gives (-k on a body, -cool on a slot). */
#include "engine/forces.h"

#include <stdio.h>

static long heat_pairs(const sw_particles *p, const sw_force *fo, int *reach)
{
    (void)p, (void)fo;
    *reach = 0;
    return 0;
}

static void heat_add(const sw_particles *p, const sw_force *fo, const double *x, const double *v, double *f)
{
    (void)x;
    int m = p->n / 2;
    for (int i = 0; i < m; i++) {
        double mass = p->mass[i], theta = v[2 * (m + i)];
        f[2 * i] += mass * (fo->gx - fo->k * v[2 * i]);
        f[2 * i + 1] += mass * (fo->gy + fo->buoy * theta - fo->k * v[2 * i + 1]);
        f[2 * (m + i)] -= p->mass[m + i] * fo->cool * theta;
    }
}

static void heat_blocks(const sw_particles *p, const sw_force *fo, const double *x, const double *v,
                        swp_blocks *out)
{
    (void)x, (void)v;
    int m = p->n / 2;
    for (int i = 0; i < m; i++) {
        out->diag[8 * i + 4] -= p->mass[i] * fo->k;
        out->diag[8 * i + 7] -= p->mass[i] * fo->k;
        out->diag[8 * (m + i) + 4] -= p->mass[m + i] * fo->cool;
    }
}

static void heat_values(const sw_force *fo, char *buf, size_t len)
{
    snprintf(buf, len, "g = (%g, %g), buoy = %g, k = %g, cool = %g", fo->gx, fo->gy, fo->buoy, fo->k, fo->cool);
}

static int heat_uses_velocity(const sw_force *fo) { return fo->k != 0 || fo->cool != 0 || fo->buoy != 0; }

const swp_force_type swp_heat = {
    .name = "heat",
    .formula = "f = m g + m buoy theta y^ - m k v; theta' = -cool theta (theta = T - T_ambient)",
    .values = heat_values,
    .add = heat_add,
    .pairs = heat_pairs,
    .blocks = heat_blocks,
    .uses_velocity = heat_uses_velocity,
};
