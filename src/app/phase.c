/* The phase view's coordinates: for a chosen particle, one generalised
 * coordinate q and its rate dq/dt computed from the state (x, v), so the
 * picture is the state itself, not a sketch: a spring's stretch, a
 * pendulum's angle, an orbit's radius, or plain x or y. A flow has no
 * velocities: its phase space is the plane, so its "phase point" is (x, y). */
#include "app/app.h"

#include <math.h>
#include <stddef.h>

/* The first spring from particle i to a fixed anchor: 1 with it, else 0. */
static int anchor_spring(const sw_system *sys, int i, sw_spring *out)
{
    const sw_particles *p = &sys->particles;
    int count = sw_particles_spring_count(p);
    for (int j = 0; j < count; j++) {
        sw_particles_spring(p, j, out);
        if (out->a == i && out->b < 0)
            return 1;
    }
    return 0;
}

int sw_phase_available(const sw_system *sys, int i, sw_phase_coord c)
{
    if (i < 0 || i >= sys->n)
        return 0;
    if (sys->kind == SW_SYS_FLOW)
        return c == SW_PHASE_PLANE;
    sw_spring sp;
    double cx, cy, mu;
    switch (c) {
    case SW_PHASE_STRETCH:
    case SW_PHASE_ANGLE:
        return anchor_spring(sys, i, &sp);
    case SW_PHASE_RADIUS:
        return sw_particles_central(&sys->particles, &cx, &cy, &mu);
    case SW_PHASE_X:
    case SW_PHASE_Y:
        return 1;
    default:
        return 0;
    }
}

int sw_phase_point(const sw_system *sys, const double *y, int i, sw_phase_coord c, double *q, double *v)
{
    if (!sw_phase_available(sys, i, c))
        return 0;
    if (sys->kind == SW_SYS_FLOW) {
        *q = y[2 * i];
        *v = y[2 * i + 1];
        return isfinite(*q) && isfinite(*v);
    }
    int n = sys->n;
    double x = y[2 * i], yy = y[2 * i + 1], vx = y[2 * n + 2 * i], vy = y[2 * n + 2 * i + 1];
    sw_spring sp;
    double cx = 0, cy = 0, mu, dx, dy, r;
    switch (c) {
    case SW_PHASE_STRETCH:
    case SW_PHASE_ANGLE:
        anchor_spring(sys, i, &sp);
        dx = x - sp.ax;
        dy = yy - sp.ay;
        r = hypot(dx, dy);
        if (c == SW_PHASE_STRETCH) {
            /* d|d|/dt = d·v/|d| */
            *q = r - sp.rest;
            *v = r > 0 ? (dx * vx + dy * vy) / r : 0;
        } else {
            /* from straight down: θ = atan2(dx, -dy), θ' = (d × v)/|d|² */
            *q = atan2(dx, -dy);
            *v = r > 0 ? (-dy * vx + dx * vy) / (r * r) : 0;
        }
        break;
    case SW_PHASE_RADIUS:
        sw_particles_central(&sys->particles, &cx, &cy, &mu);
        dx = x - cx;
        dy = yy - cy;
        r = hypot(dx, dy);
        *q = r;
        *v = r > 0 ? (dx * vx + dy * vy) / r : 0;
        break;
    case SW_PHASE_X:
        *q = x;
        *v = vx;
        break;
    default:
        *q = yy;
        *v = vy;
        break;
    }
    return isfinite(*q) && isfinite(*v);
}

static int has_gravity(const sw_particles *p)
{
    for (int k = 0; k < p->nforces; k++)
        if (p->forces[k].kind == SW_FORCE_GRAVITY && (p->forces[k].gx != 0 || p->forces[k].gy != 0))
            return 1;
    return 0;
}

void sw_phase_default(const sw_system *sys, int *i, sw_phase_coord *c)
{
    *i = 0;
    if (sys->kind == SW_SYS_FLOW) {
        *c = SW_PHASE_PLANE;
        return;
    }
    sw_spring sp;
    double cx, cy, mu;
    const sw_particles *p = &sys->particles;
    if (sw_particles_central(p, &cx, &cy, &mu))
        *c = SW_PHASE_RADIUS;
    else if (sys->n == 1 && anchor_spring(sys, 0, &sp))
        /* under gravity a mass on a spring swings (a pendulum: its angle);
         * without, it only stretches */
        *c = has_gravity(p) ? SW_PHASE_ANGLE : SW_PHASE_STRETCH;
    else if (sys->n > 1 && sw_particles_spring_count(p) > 0) {
        *i = (sys->n - 1) / 2; /* the middle bead, moving across the chain */
        *c = SW_PHASE_Y;
    } else
        *c = SW_PHASE_Y;
}

void sw_phase_names(sw_phase_coord c, const char **q, const char **q_unit, const char **v, const char **v_unit)
{
    static const char *const names[SW_PHASE_NCOORDS][4] = {
        [SW_PHASE_STRETCH] = { "stretch", "m", "its rate", "m/s" },
        [SW_PHASE_ANGLE] = { "angle", "rad", "its rate", "rad/s" },
        [SW_PHASE_RADIUS] = { "radius", "m", "its rate", "m/s" },
        [SW_PHASE_X] = { "x", "m", "vx", "m/s" },
        [SW_PHASE_Y] = { "y", "m", "vy", "m/s" },
        [SW_PHASE_PLANE] = { "x", "m", "y", "m" },
    };
    int k = c >= 0 && c < SW_PHASE_NCOORDS ? (int)c : SW_PHASE_Y;
    *q = names[k][0];
    *q_unit = names[k][1];
    *v = names[k][2];
    *v_unit = names[k][3];
}

void sw_phase_cycle(const sw_system *sys, int *i, sw_phase_coord *c, int dir)
{
    if (dir == 1 || dir == -1) {
        for (int k = 1; k <= SW_PHASE_NCOORDS; k++) {
            sw_phase_coord next = (sw_phase_coord)((((int)*c + dir * k) % SW_PHASE_NCOORDS + SW_PHASE_NCOORDS) %
                                                   SW_PHASE_NCOORDS);
            if (sw_phase_available(sys, *i, next)) {
                *c = next;
                return;
            }
        }
        return;
    }
    int step = dir > 0 ? 1 : -1, n = sys->n;
    for (int k = 1; k <= n; k++) {
        int j = ((*i + step * k) % n + n) % n;
        if (sw_phase_available(sys, j, *c)) {
            *i = j;
            return;
        }
    }
}
