/* Private to the engine: the implicit-solve workspace of a particle system
 * and the solve behind its sw_ode.solve. */
#ifndef SW_ENGINE_PARTICLES_SOLVE_H
#define SW_ENGINE_PARTICLES_SOLVE_H

#include "stepwise/particles.h"

/* Allocate the per-particle workspace (after p->n is set); 0 or SW_ENOMEM. */
int sw_particles_solver_init(sw_particles *p);
/* Make room for nsprings springs' blocks in all; 0 or SW_ENOMEM. */
int sw_particles_solver_springs(sw_particles *p, int nsprings);
void sw_particles_solver_free(sw_particles *p);
/* (I - c·J) z = r at state y: the sw_solve_fn of a particle system. */
int sw_particles_solve(void *ctx, double t, const double *y, double c, const double *r, double *z);

#endif
