/* The explicit fixed-step methods as the lecture writes them (Witkin and
 * Baraff's EulerStep): plain loops over the whole state of an sw_ode, the
 * derivative into a k vector and y updated, no slices, no runaway test, no
 * fused or vectorised form. For reading, and for tests/check_reference.c,
 * which proves the production steps (explicit.c, and the systems' fused
 * steps) give these bits exactly; never on the production path. */
#ifndef SW_ENGINE_REFERENCE_H
#define SW_ENGINE_REFERENCE_H

#include "stepwise/integrator.h"

/* A reference step's vectors, dim doubles each, and what velocity Verlet
 * and Yoshida keep between steps (the last acceleration: first same as
 * last). Zero have_a after changing y from outside. */
typedef struct sw_ref {
    int dim;
    double *k1, *k2, *k3, *k4, *yt;
    int have_a; /* k1 holds f at the state the last Verlet step ended in */
} sw_ref;

/* 0, or SW_ENOMEM. */
int sw_ref_init(sw_ref *r, int dim);
void sw_ref_free(sw_ref *r);

/* One step of size h from (t, y), y replaced by the state at t + h. */
typedef void sw_ref_step_fn(sw_ref *r, sw_ode *ode, double t, double *y, double h);

sw_ref_step_fn sw_ref_euler, sw_ref_symplectic_euler, sw_ref_midpoint, sw_ref_heun, sw_ref_rk4,
    sw_ref_verlet, sw_ref_yoshida4;

/* The reference form of a production step (a method row's step), or NULL
 * for the methods that have none here (adaptive, implicit, plugins). */
sw_ref_step_fn *sw_ref_of(sw_step_fn *step);

#endif
