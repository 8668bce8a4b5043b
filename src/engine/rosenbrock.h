/* Private to the engine: RODAS4 (rosenbrock.c) in pieces its lecture form
 * (reference_implicit.c) shares: the work slots, the controller's
 * settings, the time derivative and the stage pass (rosenbrock_wide.c). */
#ifndef SW_ENGINE_ROSENBROCK_H
#define SW_ENGINE_ROSENBROCK_H

#include "engine/adaptive.h"
#include "engine/rodas_tableau.h"

/* Slots: the FSAL derivative alternates between 0 and S_F1. */
enum { S_K1 = 1, S_K6 = S_K1 + SW_RODAS_STAGES - 1, S_YT, S_RHS, S_FT, S_SAVED, S_F1, ROSENBROCK_VECTORS };

/* RODAS4's trial and Hairer's controller settings for it. */
extern const sw_adaptive swr_rodas4;

/* ∂f/∂t at (t, y) by a forward difference (Hairer's RODAS: δ = √(u·max(1e-5,
 * |t|))), into ft; returns 0 when it is zero everywhere (an autonomous
 * system: the stages then skip the term). One evaluation. */
int swr_time_derivative(sw_ode *ode, double t, const double *y, const double *f0, double *ft);

/* One pass of a stage's arithmetic over n components (out is never one of
 * the vectors read; k holds five vector pointers, the first `terms` read):
 *     out_i = base_i + Σ_{j<terms} coef_j·k_j,i                 (with_ft 0)
 *     out_i = scale·((base_i + dh·ft_i) + Σ_{j<terms} coef_j·k_j,i)  (1)
 *     out_i = scale·((base_i + 0.0) + Σ_{j<terms} coef_j·k_j,i)      (2: f_t
 *             known +0, not read; the bits of (1) with ft = +0)
 * the sum taken j rising. terms 0..5. */
void swr_stage_combine(int n, int terms, int with_ft, double *restrict out, const double *restrict base, double dh,
                       const double *restrict ft, double scale, const double *coef, const double *const *k);

/* out = base + coef·k and keep = base in one pass (n long, none aliased):
 * swr_stage_combine's one-term point with the copy of y0 alongside. */
void swr_stage_point_keep(int n, double *restrict out, double *restrict keep, const double *restrict base,
                          double coef, const double *restrict k);

/* 1 when every one of v's n components is finite. */
int swr_all_finite(int n, const double *v);

#endif
