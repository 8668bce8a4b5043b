/* Private to the engine and the layers above it: the Jacobian of a particle
 * system's forces and the linear solve behind its sw_ode.solve. */
#ifndef SW_ENGINE_PARTICLES_SOLVE_H
#define SW_ENGINE_PARTICLES_SOLVE_H

#include <stddef.h>

#include "stepwise/particles.h"

/* Allocate the per-particle workspace (after p->n is set); 0 or SW_ENOMEM. */
int sw_particles_solver_init(sw_particles *p);
/* Make room for nsprings springs' blocks in all; 0 or SW_ENOMEM. */
int sw_particles_solver_springs(sw_particles *p, int nsprings);
void sw_particles_solver_free(sw_particles *p);
/* Size the band the solve factors from the spring graph (called once when an
 * implicit method is chosen, after the springs are filled in). 0, SW_ENOMEM,
 * or SW_EINVAL when the graph's bandwidth makes the band too large. */
int sw_particles_solver_prepare(void *ctx, char *err, size_t errlen);
/* (I - c·J) z = r at state y: the sw_solve_fn of a particle system. */
int sw_particles_solve(void *ctx, double t, const double *y, double c, const double *r, double *z);

/* The force Jacobians at state y as dense 2n×2n row-major matrices:
 * fx = ∂f/∂x and fv = ∂f/∂v, every force included (the damping term's
 * dependence on positions too). For tests and the stability theory; n small. */
void sw_particles_jacobian(sw_particles *p, const double *y, double *fx, double *fv);
/* out = (a·∂f/∂x + b·∂f/∂v)·w at state y (2n long each), without forming the
 * matrices; assemble_first 0 reuses the blocks of the previous call at y. */
void sw_particles_jacobian_apply(sw_particles *p, const double *y, double a, double b, const double *w,
                                 double *out, int assemble_first);

#endif
