/* Private to the engine: the chain's rk4 fused (particles_chain.c), the
 * particle system's fused step where its springs are a chain between two
 * anchors; the same bits as the generic rk4 step. */
#ifndef SW_ENGINE_PARTICLES_CHAIN_H
#define SW_ENGINE_PARTICLES_CHAIN_H

#include <stddef.h>

#include "stepwise/particles.h"

/* Doubles of tile workspace the fused step needs (a fixed number, not n). */
size_t swp_chain_work_size(void);
/* 1 when m's springs (surveyed, their a rows written) lie as a chain
 * between two anchors: beads 0 .. n - 1 (n >= 2), paired spring j joining
 * bead j + 1 to bead j, then anchored springs on bead 0 and on bead n - 1. */
struct sw_particles_model;
int swp_chain_layout(const struct sw_particles_model *m, int n);
/* 1 when p's compiled forces are what the fused step handles: that
 * layout, all springs sharing k, c and rest; gravity and drag fused, no
 * other force; its workspace allocated. */
int swp_chain_shaped(const sw_particles *p);
/* Largest chain whose derivative takes the fused path below. */
#define SWP_LINE_BEADS 128
/* The chain's derivative fused, for p's compiled forces (a chain layout
 * of at most SWP_LINE_BEADS beads, shared k, c and rest, gravity and drag
 * fused, no other force, no small path), or NULL: the generic passes'
 * bits (particles_chain.c). It returns 0, dydt unfinished, where a
 * spring's length² is below 1e-290 or NaN: the generic passes then. */
typedef int swp_line_fn(const sw_particles *p, const double *y, double *dydt);
swp_line_fn *swp_line_pick(const sw_particles *p);
/* The fused rk4 step (sw_fused_step_fn) on a chain-shaped p. */
unsigned swp_chain_rk4(void *ctx, double t, double *y, double h, unsigned elim);

#endif
