/* The particle derivative for small systems — the orbit's one body under a
 * central field, a chain of a few beads — as straight loops over the
 * compiled springs and particles, one function per combination of the
 * kinds present, picked once when the forces are compiled: no blocks, no
 * padding, no flags tested per call. Invariant: the same operations in the
 * same order as particles_deriv.c's passes (spring forces, each particle's
 * sum over its list, the central field, gravity, drag, 1/m), so the same
 * bits; tests/check_derivative.c compares the two on every scene. */
#include "engine/particles_small.h"

#include <math.h>

#include "engine/clones.h"
#include "engine/spring1.h"

/* Spring j's force on its particle a from d = x_a - x_b and dv = v_a - v_b,
 * as block_forces computes it (particles_deriv.c): engine/spring1.h. */
SW_INLINE void spring_force(const struct sw_particles_model *m, int j, double dx, double dy, double dvx,
                            double dvy, int damped, double *fx, double *fy)
{
    sw_spring_force(m->k[j], m->c[j], m->rest[j], dx, dy, dvx, dvy, damped, fx, fy);
}

/* dydt = (v, f/m) with f = Σ ±(spring forces) + central + m·g - k·v, for
 * the kinds given (constant arguments: each combination its own loops). */
SW_INLINE void small_eval(const sw_particles *p, const double *restrict y, double *restrict dydt, int one,
                          int springs, int damped, int central, int gravity, int drag)
{
    const struct sw_particles_model *m = p->model;
    int n = one ? 1 : p->n;
    const double *x = y, *v = y + 2 * n;
    double *force = m->force;
    if (springs && !one) {
        for (int j = 0; j < m->npair; j++) {
            int a = m->a[j], b = m->b[j];
            spring_force(m, j, x[a] - x[b], x[a + 1] - x[b + 1], damped ? v[a] - v[b] : 0.0,
                         damped ? v[a + 1] - v[b + 1] : 0.0, damped, &force[2 * j], &force[2 * j + 1]);
        }
        for (int j = m->npair; j < m->npair + m->nanchor; j++) {
            int a = m->a[j];
            spring_force(m, j, x[a] - m->ax[j], x[a + 1] - m->ay[j], damped ? v[a] : 0.0,
                         damped ? v[a + 1] : 0.0, damped, &force[2 * j], &force[2 * j + 1]);
        }
    }
    const sw_force *c = &p->forces[central ? m->extra[0] : 0];
    const double *restrict mass = p->mass, *restrict inv = p->inv_mass;
    double cx = c->cx, cy = c->cy, mu = c->mu, gx = m->gx, gy = m->gy, kd = m->kdrag;
    for (int i = 0; i < n; i++) {
        double fx = 0.0, fy = 0.0;
        for (int e = springs ? m->first[i] : 0; springs && !one && e < m->first[i + 1]; e++) {
            fx += m->sign[e] * force[m->spring[e]];
            fy += m->sign[e] * force[m->spring[e] + 1];
        }
        /* One particle: each spring of its list computed where it is summed,
         * the force kept in registers (no store to m->force and load back on
         * the way from the state to the derivative); the same operations in
         * the same order (a spring listed twice is computed twice, the same
         * bits). */
        for (int e = springs ? m->first[0] : 0; springs && one && e < m->first[1]; e++) {
            int j = m->spring[e] / 2, a = m->a[j];
            double sx, sy;
            if (j < m->npair) {
                int b = m->b[j];
                spring_force(m, j, x[a] - x[b], x[a + 1] - x[b + 1], damped ? v[a] - v[b] : 0.0,
                             damped ? v[a + 1] - v[b + 1] : 0.0, damped, &sx, &sy);
            } else {
                spring_force(m, j, x[a] - m->ax[j], x[a + 1] - m->ay[j], damped ? v[a] : 0.0,
                             damped ? v[a + 1] : 0.0, damped, &sx, &sy);
            }
            fx += m->sign[e] * sx;
            fy += m->sign[e] * sy;
        }
        if (central) {
            double cfx, cfy;
            sw_central_force(cx, cy, mu, mass[i], x[2 * i], x[2 * i + 1], &cfx, &cfy);
            fx += cfx;
            fy += cfy;
        }
        if (gravity) {
            fx += mass[i] * gx;
            fy += mass[i] * gy;
        }
        if (drag) {
            fx -= kd * v[2 * i];
            fy -= kd * v[2 * i + 1];
        }
        dydt[2 * i] = v[2 * i];
        dydt[2 * i + 1] = v[2 * i + 1];
        dydt[2 * n + 2 * i] = fx * inv[i];
        dydt[2 * n + 2 * i + 1] = fy * inv[i];
    }
}

/* One function per combination: one particle (O), springs (S), damped (D),
 * central (C), gravity (G), drag (K); the table below is indexed by those. */
#define SMALL(O, S, D, C, G, K)                                                                    \
    static void small_##O##S##D##C##G##K(const sw_particles *p, const double *y, double *dydt)      \
    {                                                                                              \
        small_eval(p, y, dydt, O, S, D, C, G, K);                                                  \
    }
#define SMALL_GK(O, S, D, C)                                                                       \
    SMALL(O, S, D, C, 0, 0) SMALL(O, S, D, C, 0, 1) SMALL(O, S, D, C, 1, 0) SMALL(O, S, D, C, 1, 1)
#define SMALL_ALL(O) SMALL_GK(O, 0, 0, 0) SMALL_GK(O, 0, 0, 1) SMALL_GK(O, 1, 0, 0) SMALL_GK(O, 1, 0, 1) \
    SMALL_GK(O, 1, 1, 0) SMALL_GK(O, 1, 1, 1)
SMALL_ALL(0)
SMALL_ALL(1)
#define ROW(O, S, D, C) small_##O##S##D##C##00, small_##O##S##D##C##01, small_##O##S##D##C##10, small_##O##S##D##C##11
#define TABLE(O)                                                                                   \
    { { { ROW(O, 0, 0, 0) }, { ROW(O, 0, 0, 1) } }, { { ROW(O, 1, 0, 0) }, { ROW(O, 1, 0, 1) } },  \
      { { ROW(O, 1, 1, 0) }, { ROW(O, 1, 1, 1) } } }

/* [one particle][springs · 2 + damped][central][gravity · 2 + drag] */
static swp_small_fn *const small_table[2][3][2][4] = { TABLE(0), TABLE(1) };

int swp_small_central1(const sw_particles *p, sw_central1 *c)
{
    const struct sw_particles_model *m = p->model;
    if (m->small != small_100100)
        return 0;
    const sw_force *f = &p->forces[m->extra[0]];
    *c = (sw_central1){ .cx = f->cx, .cy = f->cy, .mu = f->mu, .mass = p->mass[0], .inv = p->inv_mass[0] };
    return 1;
}

swp_small_fn *swp_small_pick(const sw_particles *p)
{
    const struct sw_particles_model *m = p->model;
    int total = m->npair + m->nanchor;
    int central = m->nextra == 1 && p->forces[m->extra[0]].kind == SW_FORCE_CENTRAL;
    if (p->n > SWP_SMALL_PARTICLES || total > SWP_SMALL_SPRINGS || (m->nextra > 0 && !central))
        return NULL;
    int kinds = total > 0 ? 1 + m->damped : 0;
    return small_table[p->n == 1][kinds][central][m->gravity * 2 + m->drag];
}

int swp_small_spring1(const sw_particles *p, sw_spring1 *s)
{
    const struct sw_particles_model *m = p->model;
    if ((m->small != small_110000 && m->small != small_110010) || m->first[1] - m->first[0] != 1)
        return 0;
    int j = m->spring[m->first[0]] / 2;
    if (j < m->npair || m->sign[m->first[0]] != 1.0)
        return 0;
    *s = (sw_spring1){ .ax = m->ax[j], .ay = m->ay[j], .k = m->k[j], .rest = m->rest[j], .inv = p->inv_mass[0],
                       .gravity = m->gravity, .mgx = p->mass[0] * m->gx, .mgy = p->mass[0] * m->gy };
    return 1;
}
