/* The solver's view of a system, as in the lecture (after Witkin & Baraff):
 * a dimension, a flat state y and a derivative f(t, y) = dy/dt. A second-order
 * system splits y = [x | v] (each dim/2 long) so that symplectic methods can
 * update positions and velocities separately. A solver sees nothing else. */
#ifndef STEPWISE_ODE_H
#define STEPWISE_ODE_H

#include <stddef.h>

/* dydt = f(t, y); both arrays are dim long and must not alias. */
typedef void sw_deriv_fn(void *ctx, double t, const double *y, double *dydt);

/* Solve (I - c·J) z = r, J = ∂f/∂y at (t, y); returns 0 or a negative status
 * when the solve fails. Used by implicit methods only. */
typedef int sw_solve_fn(void *ctx, double t, const double *y, double c,
                        const double *r, double *z);

/* The engine's fast paths for a system (slices in cache, steps fused with
 * the field): private to the engine (engine/ode_fast.h). A solver written
 * against this header, a plugin's included, never needs them. */
struct sw_ode_fast;

typedef struct sw_ode {
    int dim;             /* length of the state vector */
    int order;           /* 1: y = x (flow field); 2: y = [x | v] */
    sw_deriv_fn *deriv;  /* required */
    sw_solve_fn *solve;  /* NULL: a dense finite-difference fallback (small dim) */
    void *ctx;           /* the system behind the callbacks */
    long evals;          /* derivative evaluations so far (counted by sw_ode_eval) */
    long solves;         /* linear solves so far */
    long solver_iters;   /* inner iterations of iterative solves, summed */
    /* NULL, or: size the solve's workspace for the system as built (called
     * once when an implicit method is chosen); 0 or a status with err. */
    int (*prepare)(void *ctx, char *err, size_t errlen);
    const struct sw_ode_fast *fast; /* NULL: the generic methods only */
    /* Who made this system, so that a student plugin's host (a process of
     * its own) can build it again: SW_MAKER_SCENE (maker: the scene's
     * sw_system), SW_MAKER_LINEAR2 (the truth module's 2x2 test system),
     * or 0 (a plugin cannot step it). Set by stepwise; 0 in a plugin's view. */
    int maker_kind;
    const void *maker;
} sw_ode;

enum { SW_MAKER_NONE = 0, SW_MAKER_SCENE = 1, SW_MAKER_LINEAR2 = 2 };

/* Evaluate dy/dt and count it: every method goes through this. */
static inline void sw_ode_eval(sw_ode *ode, double t, const double *y, double *dydt)
{
    ode->evals++;
    ode->deriv(ode->ctx, t, y, dydt);
}

/* Largest dim for which the dense finite-difference solve is allowed. */
#define SW_DENSE_MAX 64

#endif
