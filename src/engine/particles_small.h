/* Private to the engine: the particle derivative for small systems
 * (particles_small.c), picked when the forces are compiled. */
#ifndef SW_ENGINE_PARTICLES_SMALL_H
#define SW_ENGINE_PARTICLES_SMALL_H

#include "engine/particles_model.h"

/* Largest system the small path takes: particles, and springs in all. */
#define SWP_SMALL_PARTICLES 32
#define SWP_SMALL_SPRINGS 2

/* The small path for p's compiled forces, or NULL when p is larger than the
 * limits above or has a force it does not model (anything but springs, one
 * central field, the fused gravity and drag). */
swp_small_fn *swp_small_pick(const sw_particles *p);

#endif
