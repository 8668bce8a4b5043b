/* Private to the engine: the particle system's forces compiled into flat
 * arrays by kind, and the derivative that evaluates them (particles_deriv.c).
 * particles.c keeps the force list a scene builds (the description) and
 * calls these to size, compile and free the compiled form. */
#ifndef SW_ENGINE_PARTICLES_DERIV_H
#define SW_ENGINE_PARTICLES_DERIV_H

#include <stddef.h>

#include "engine/ode_fast.h"
#include "stepwise/particles.h"

/* The compiled form, empty (to be compiled on first use), and the
 * system's two rows of fast paths (ode_fast.h, static, the caller's):
 * fast[0] plain, fast[1] with the chain's fused rk4; compiling points
 * p->ode.fast at the one that fits, touching at fast[0]. 0 or SW_ENOMEM. */
int swp_model_init(sw_particles *p, const struct sw_ode_fast fast[2]);
/* Room for nsprings springs in all; 0 or SW_ENOMEM. */
int swp_model_springs(sw_particles *p, int nsprings);
void swp_model_free(sw_particles *p);
/* The description changed: compile again before the next evaluation. */
void swp_model_touch(sw_particles *p);
/* Compile the description; 0, or SW_EINVAL (err says which spring) when a
 * spring names a particle that does not exist (such springs are left out). */
int swp_model_compile(sw_particles *p, char *err, size_t errlen);
/* The derivative (sw_deriv_fn) over the compiled form, compiling first when
 * the description changed: the small-system path (particles_small.c) where
 * compiling picked one, else the generic passes. */
void swp_deriv(void *ctx, double t, const double *y, double *dydt);
/* The generic passes always (for tests: the small path must give their
 * bits), and whether swp_deriv takes the small path for p. */
void swp_deriv_generic(void *ctx, double t, const double *y, double *dydt);
int swp_deriv_is_small(const sw_particles *p);

#endif
