/* Private to the engine and the layers above it: the Jacobian of a particle
 * system's forces and the linear solve behind its sw_ode.solve. */
#ifndef SW_ENGINE_PARTICLES_SOLVE_H
#define SW_ENGINE_PARTICLES_SOLVE_H

#include <stddef.h>

#include "stepwise/particles.h"

/* Allocate the per-particle workspace (after p->n is set); 0 or SW_ENOMEM. */
int sw_particles_solver_init(sw_particles *p);
void sw_particles_solver_free(sw_particles *p);
/* Size the band the solve factors from the pairs the forces join, and the
 * room for their blocks (called once when an implicit method is chosen,
 * after the springs are filled in). 0, SW_ENOMEM, or SW_EINVAL when the
 * pairs' bandwidth makes the band too large. */
int sw_particles_solver_prepare(void *ctx, char *err, size_t errlen);
/* (I - c·J) z = r at state y: the sw_solve_fn of a particle system. A
 * second solve at the same y (compared by contents) and c reuses the first
 * one's factorisation. */
int sw_particles_solve(void *ctx, double t, const double *y, double c, const double *r, double *z);
/* The same, y promised to be the last solve's (ode_fast.h's solve_same). */
int sw_particles_solve_same(void *ctx, double t, const double *y, double c, const double *r, double *z);
/* The same, factored afresh, asked for again only through
 * sw_particles_solve_same (ode_fast.h's solve_new). */
int sw_particles_solve_new(void *ctx, double t, const double *y, double c, const double *r, double *z);
/* For tests: with generic 1, a chain's velocity system is always filled
 * into the band and factored from there, never in the fused pass along
 * the chain (particles_solve.c's factor_chain), the right-hand side's
 * own blocks are always read, even where they are zero, and its pairs'
 * ends read and tested a pair at a time on a chain too: each must give
 * the same bits as its shortcut; 0 restores the default. Returns how many factorisations the
 * fused pass has made and kept so far. */
long sw_particles_solver_generic(sw_particles *p, int generic);
/* Forget the kept factorisation: the forces or masses changed in place
 * (sw_particles_finish calls it). */
void sw_particles_solver_touch(sw_particles *p);

/* The force Jacobians at state y as dense 2n×2n row-major matrices:
 * fx = ∂f/∂x and fv = ∂f/∂v, every force included (the damping term's
 * dependence on positions too). For tests and the stability theory; n small. */
int sw_particles_jacobian(sw_particles *p, const double *y, double *fx, double *fv);
/* out = (a·∂f/∂x + b·∂f/∂v)·w at state y (2n long each), without forming the
 * matrices; assemble_first 0 reuses the blocks of the previous call at y. */
int sw_particles_jacobian_apply(sw_particles *p, const double *y, double a, double b, const double *w,
                                double *out, int assemble_first);
/* Each particle's own blocks at y, 8 per particle: ∂f_i/∂x_i (2x2,
 * row-major) then ∂f_i/∂v_i; NULL when out of memory. Without coupling
 * (below) they are the whole Jacobian. */
const double *sw_particles_own_blocks(sw_particles *p, const double *y);
/* 1 when a force joins particles (springs, mutual gravity), so they do not
 * move independently; 0 when each particle feels only fields. */
int sw_particles_coupled(const sw_particles *p);
/* The pairs the forces join (their Jacobian's off-diagonal blocks), and
 * the most whose blocks are ever kept: beyond it (a galaxy of 1e5 stars,
 * 5e9 pairs) there is no Jacobian, hence no spectrum and no implicit step. */
long sw_particles_pair_count(const sw_particles *p);
#define SW_PARTICLES_PAIRS_MAX (1L << 23)
/* What one derivative evaluation costs, in state components (the budgets'
 * unit: dim when each particle feels a few forces, as with fields, a chain
 * or a cloth; dim times the pairs per particle when a force joins many,
 * as mutual gravity does), and in *solve what one implicit solve costs in
 * the same unit (the band's factorisation: dim when particles join only
 * their neighbours, growing with the square of the band's width). */
double sw_particles_work(const sw_particles *p, double *solve);
/* The jacobian functions return 0, or SW_ENOMEM when forces added since
 * the last call need room their blocks cannot get. */

#endif
