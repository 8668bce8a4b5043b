/* Private to the engine: the particle derivative for small systems
 * (particles_small.c), picked when the forces are compiled. */
#ifndef SW_ENGINE_PARTICLES_SMALL_H
#define SW_ENGINE_PARTICLES_SMALL_H

#include "engine/central.h"
#include "engine/particles_model.h"
#include "engine/spring1.h"

/* Largest system the small path takes: particles, and springs in all. */
#define SWP_SMALL_PARTICLES 32
#define SWP_SMALL_SPRINGS 2

/* The small path for p's compiled forces, or NULL when p is larger than the
 * limits above or has a force it does not model (anything but springs, one
 * central field, the fused gravity and drag). */
swp_small_fn *swp_small_pick(const sw_particles *p);

/* 1, and the field and the particle into *c, when p's compiled small path
 * is one particle in one central field and no other force; else 0. */
int swp_small_central1(const sw_particles *p, sw_central1 *c);

/* 1, and the spring and the particle into *s, when p's compiled small path
 * is one particle on one undamped anchored spring, perhaps with gravity,
 * and no other force; else 0. */
int swp_small_spring1(const sw_particles *p, sw_spring1 *s);

#endif
