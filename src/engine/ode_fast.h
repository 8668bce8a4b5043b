/* Private to the engine and the layers above it: what a system can offer
 * the built-in explicit methods beyond the lecture's solver view (sw_ode),
 * for speed only (and one fact about it: whether its acceleration ignores
 * velocities). Every fast path gives the generic method's numbers bit for
 * bit; a system without them (particles, a plugin's view) runs the generic
 * loops. */
#ifndef SW_ENGINE_ODE_FAST_H
#define SW_ENGINE_ODE_FAST_H

#include "engine/central.h"
#include "engine/spring1.h"
#include "stepwise/ode.h"

/* For pointwise systems, where each point's derivative depends only on that
 * point (flow fields): dydt[0..len) from the slice y[0..len) alone. Lets
 * explicit methods step the state block by block in cache. */
typedef void sw_deriv_part_fn(void *ctx, double t, int len, const double *y, double *dydt);

/* A step of a fixed explicit method that a system takes itself, point by
 * point with each point's stages in registers, with exactly the arithmetic
 * of the generic method (so the same bits): y advanced from t by h in
 * place. Returns non-zero when a new component's exponent field is at or
 * beyond elim (the runaway test, 0x800: never). Flow fields written per
 * point offer Euler's and RK4's (engine/pointwise.h). */
typedef unsigned sw_fused_step_fn(void *ctx, double t, double *y, double h, unsigned elim);

struct sw_ode_fast {
    sw_deriv_part_fn *deriv_part;           /* NULL: coupled; else slices of 2 */
    sw_fused_step_fn *fused_euler, *fused_rk4; /* NULL: the generic step */
    /* A second-order system: 1 when its acceleration depends on positions
     * (and t) alone, as a Runge-Kutta-Nyström method (rkn) needs; 0 when
     * some force uses velocities (drag, spring damping). NULL: unknown,
     * taken as 0. */
    int (*position_only)(const void *ctx);
    /* One particle in one central field and no other force (the orbit):
     * 1, and the field and the particle into *c, for a method to compute
     * the acceleration inline (sw_central1_accel, the same bits as the
     * derivative's) instead of calling the derivative. NULL or 0: no. */
    int (*central1)(const void *ctx, sw_central1 *c);
    /* One particle on one undamped anchored spring, perhaps under gravity,
     * and no other force (the stiff-spring pendulum): the same for
     * sw_spring1_accel. NULL or 0: no. */
    int (*spring1)(const void *ctx, sw_spring1 *s);
    /* 1 when ode's derivative, as set now, ignores t (f(t, y) the same bits
     * at every t): a Rosenbrock method's ∂f/∂t is then +0 exactly where f
     * is finite, and need not be evaluated. NULL or 0: unknown. */
    int (*autonomous)(const sw_ode *ode);
    /* ode->solve, where the caller promises y's contents are those of the
     * last solve (stepper.h's sw_ode_solve_same): factors kept for the
     * same c are reused without comparing y. NULL: ode->solve always. */
    sw_solve_fn *solve_same;
    /* ode->solve, where the caller will ask for these factors again only
     * through solve_same (stepper.h's sw_ode_solve_new): the system need
     * not keep y to compare. NULL: ode->solve always. */
    sw_solve_fn *solve_new;
};

/* The fast path of ode, or NULL. */
static inline sw_deriv_part_fn *sw_ode_deriv_part(const sw_ode *ode)
{
    return ode->fast ? ode->fast->deriv_part : NULL;
}

/* 1 when ode's acceleration is known to depend on positions alone. */
static inline int sw_ode_position_only(const sw_ode *ode)
{
    return ode->fast && ode->fast->position_only && ode->fast->position_only(ode->ctx);
}

/* 1 when ode is one particle in one central field alone, with *c set. */
static inline int sw_ode_central1(const sw_ode *ode, sw_central1 *c)
{
    return ode->fast && ode->fast->central1 && ode->fast->central1(ode->ctx, c);
}

/* 1 when ode is one particle on one anchored spring alone, with *s set. */
static inline int sw_ode_spring1(const sw_ode *ode, sw_spring1 *s)
{
    return ode->fast && ode->fast->spring1 && ode->fast->spring1(ode->ctx, s);
}

/* 1 when ode's derivative is known not to depend on t. */
static inline int sw_ode_autonomous(const sw_ode *ode)
{
    return ode->fast && ode->fast->autonomous && ode->fast->autonomous(ode);
}

static inline sw_fused_step_fn *sw_ode_fused_euler(const sw_ode *ode)
{
    return ode->fast ? ode->fast->fused_euler : NULL;
}

static inline sw_fused_step_fn *sw_ode_fused_rk4(const sw_ode *ode)
{
    return ode->fast ? ode->fast->fused_rk4 : NULL;
}

#endif
