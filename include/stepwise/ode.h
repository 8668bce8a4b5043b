/* The solver's view of a system, as in the lecture (after Witkin & Baraff):
 * a dimension, a flat state y and a derivative f(t, y) = dy/dt. A second-order
 * system splits y = [x | v] (each dim/2 long) so that symplectic methods can
 * update positions and velocities separately. A solver sees nothing else. */
#ifndef STEPWISE_ODE_H
#define STEPWISE_ODE_H

#include <stddef.h>

/* dydt = f(t, y); both arrays are dim long and must not alias. */
typedef void sw_deriv_fn(void *ctx, double t, const double *y, double *dydt);

/* For pointwise systems, where each point's derivative depends only on that
 * point (flow fields): dydt[0..len) from the slice y[0..len) alone. Lets
 * explicit methods step the state block by block in cache. */
typedef void sw_deriv_part_fn(void *ctx, double t, int len, const double *y, double *dydt);

/* A step of a fixed explicit method that a system takes itself, point by
 * point with each point's stages in registers, with exactly the arithmetic
 * of the generic method (so the same bits): y advanced from t by h in
 * place. Returns non-zero when a new component's exponent field is at or
 * beyond elim (the runaway test, 0x800: never). Flow fields written per
 * point offer Euler's and RK4's (src/engine/pointwise.h). */
typedef unsigned sw_fused_step_fn(void *ctx, double t, double *y, double h, unsigned elim);

/* Solve (I - c·J) z = r, J = ∂f/∂y at (t, y); returns 0 or a negative status
 * when the solve fails. Used by implicit methods only. */
typedef int sw_solve_fn(void *ctx, double t, const double *y, double c,
                        const double *r, double *z);

typedef struct sw_ode {
    int dim;             /* length of the state vector */
    int order;           /* 1: y = x (flow field); 2: y = [x | v] */
    sw_deriv_fn *deriv;  /* required */
    sw_solve_fn *solve;  /* NULL: a dense finite-difference fallback (small dim) */
    sw_deriv_part_fn *deriv_part; /* NULL: coupled (particles); else slices of 2 */
    void *ctx;           /* the system behind the callbacks */
    long evals;          /* derivative evaluations so far (counted by sw_ode_eval) */
    long solves;         /* linear solves so far */
    long solver_iters;   /* inner iterations of iterative solves, summed */
    /* NULL, or: size the solve's workspace for the system as built (called
     * once when an implicit method is chosen); 0 or a status with err. */
    int (*prepare)(void *ctx, char *err, size_t errlen);
    /* NULL: the generic methods. Last, so that the fields before keep the
     * places plugins built against SW_PLUGIN_ABI 1 know. */
    sw_fused_step_fn *fused_euler, *fused_rk4;
} sw_ode;

/* Evaluate dy/dt and count it: every method goes through this. */
static inline void sw_ode_eval(sw_ode *ode, double t, const double *y, double *dydt)
{
    ode->evals++;
    ode->deriv(ode->ctx, t, y, dydt);
}

/* Largest dim for which the dense finite-difference solve is allowed. */
#define SW_DENSE_MAX 64

#endif
