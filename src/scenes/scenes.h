/* Private to the scene files: the scene objects and the helpers they share. */
#ifndef SW_SCENES_SCENES_H
#define SW_SCENES_SCENES_H

#include <stdint.h>

#include "stepwise/scene.h"

/* A scene's parameter count, from its array: never counted by hand. */
#define SW_NPARAMS(params) ((int)(sizeof(params) / sizeof((params)[0])))

extern const sw_scene sw_scene_vortex, sw_scene_river, sw_scene_gyre;
extern const sw_scene sw_scene_projectile, sw_scene_bounce, sw_scene_fireworks;
extern const sw_scene sw_scene_spring, sw_scene_stiff_spring, sw_scene_chain;
extern const sw_scene sw_scene_orbit, sw_scene_galaxy;
extern const sw_scene sw_scene_fire, sw_scene_explosion, sw_scene_water;

/* Set sys up as a flow of n points under a field written per point
 * (engine/pointwise.h; jac may be NULL). */
int sw_scene_flow(sw_system *sys, int n, const sw_point_field *pf, sw_field_jac_fn *jac,
                  char *err, size_t errlen);
/* Set sys up as n particles of mass m, all at rest at the origin. */
int sw_scene_particles(sw_system *sys, int n, double m, char *err, size_t errlen);
/* A deterministic pseudo-random number in [0, 1) from two integers
 * (splitmix64): a scene's seeded randomness, the same on every machine. */
double sw_scene_hash01(uint64_t a, uint64_t b);
/* Energy of a particle scene: the particle system's own energy. */
double sw_scene_particle_energy(const sw_system *sys, const double *y);

#endif
