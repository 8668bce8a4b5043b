/* The explicit adaptive methods as the lecture writes them (rk45, dop853,
 * rkn, rkn12, dop853-lc, vern8, vern9): one accepted step is trials — the stages, the
 * new state, the error estimate — until the error is within the
 * tolerances, each followed by the controller's new step. Plain loops over
 * the whole state, one line a row of the tableau; no slices, no vector
 * types, no runaway test. For reading, and for
 * tests/check_reference_adaptive.c, which proves the production steps
 * (rk45.c, dop853.c, rkn.c, rkn12.c, dop853_lc.c, vern.c over adaptive.c) give
 * these bits exactly; never on the production path. */
#ifndef SW_ENGINE_REFERENCE_ADAPTIVE_H
#define SW_ENGINE_REFERENCE_ADAPTIVE_H

#include "stepwise/integrator.h"

enum { SW_REF_STAGES = 17 }; /* the most stages of a method here (rkn12) */

/* A lecture-form run: its vectors, dim doubles each, and what the
 * controller keeps from step to step (the production stepper keeps the
 * same in the same-named fields of sw_stepper). */
typedef struct sw_ref_adaptive {
    int dim;
    double *vectors;              /* (SW_REF_STAGES + 3)·dim doubles, owned: */
    double *k[SW_REF_STAGES + 2]; /* k[1] .. k[18]: stage i's derivative in k[i] */
    double *yt;                   /* a stage's state */
    double *y0;                   /* the state a trial starts from (for a rejection) */
    double rtol, atol;            /* SW_RTOL_DEFAULT, SW_ATOL_DEFAULT after init */
    int have_k1;                  /* k[1] is f at the current state; zero it after changing y */
    double h_next;                /* the proposed next step (0: none yet) */
    double h_last, err_last;      /* the last accepted step and its error (rkn12's prediction) */
    long accepted, rejected;      /* steps accepted, trials rejected */
    struct sw_ref_lc *lc;         /* dop853-lc's run in Levi-Civita's variables, or NULL */
} sw_ref_adaptive;

/* 0, or SW_ENOMEM. */
int sw_ref_adaptive_init(sw_ref_adaptive *r, int dim);
void sw_ref_adaptive_free(sw_ref_adaptive *r);

/* One accepted step of at most h_max from (*t, y): y and *t replaced by
 * the new state and time. SW_OK, or SW_EDIVERGED (the step size
 * underflowed or 200 trials failed); dop853-lc also SW_EINVAL (not one
 * body in one central field). */
typedef int sw_ref_adaptive_fn(sw_ref_adaptive *r, sw_ode *ode, double *t, double *y, double h_max);

sw_ref_adaptive_fn sw_ref_rk45, sw_ref_dop853, sw_ref_rkn, sw_ref_rkn12, sw_ref_dop853_lc, sw_ref_vern8,
    sw_ref_vern9;

/* The lecture form of a production step (a method row's step), or NULL. */
sw_ref_adaptive_fn *sw_ref_adaptive_of(sw_step_fn *step);

#endif
