/* The implicit and Rosenbrock methods as the lecture writes them: backward
 * Euler and the implicit midpoint rule solved by Newton's method with the
 * Jacobian, the linearly implicit Euler step (I - hJ)·Δy = h·f, and RODAS4's
 * stages with (I - γhJ). Plain loops over the whole state of an sw_ode, in
 * the order the formulas read, no vector lanes, no fused passes, no runaway
 * test. For reading, and for tests/check_reference_implicit.c, which proves
 * the production steps (implicit.c with implicit_wide.c, rosenbrock.c with
 * rosenbrock_wide.c) give these bits exactly; never on the production path.
 *
 * Each takes a stepper made for its method on this ode (sw_stepper_new) as
 * its workspace: its work vectors, the linear solve's kept factors (the
 * system's own solve, or the dense finite-difference fallback's), the
 * counters and, for rodas4, the step-size controller's state. */
#ifndef SW_ENGINE_REFERENCE_IMPLICIT_H
#define SW_ENGINE_REFERENCE_IMPLICIT_H

#include "engine/stepper.h"

/* One step of size h (rodas4: one accepted step of at most h) from (*t, y):
 * y replaced by the new state, *t advanced; 0, or SW_EDIVERGED with s->why
 * set, as the production step. */
sw_step_fn sw_refi_implicit_euler, sw_refi_implicit_midpoint, sw_refi_linear_implicit_euler, sw_refi_rodas4;

/* The lecture form of a production step (a method row's step), or NULL
 * for the methods that have none here. */
sw_step_fn *sw_refi_of(sw_step_fn *step);

#endif
