/* The stages of one step, recorded: the method's own step function run once
 * on a copy of a sim's state through a solver view that notes every
 * derivative it is asked for (where, when, and what it gave). Nothing is
 * re-derived from formulas, so what the stage view draws is what the run
 * computes, bit for bit. */
#ifndef SW_SIM_STAGES_H
#define SW_SIM_STAGES_H

#include <stddef.h>

#include "stepwise/sim.h"

/* Most evaluations a drawn step makes (RK4: 4). */
#define SW_STAGES_MAX 8

/* Points of the true path drawn over one step (plus its start). */
#define SW_STAGES_PATH 16

/* One evaluation of f inside the step. */
typedef struct sw_stage {
    double t;      /* the time f was evaluated at */
    double *y;     /* the state it was evaluated at (dim doubles) */
    double *k;     /* f(t, y) (dim doubles) */
    int cached;    /* 1: not evaluated in this step but kept from the last
                      (Verlet's a0, first same as last): y is the step's start */
} sw_stage;

typedef struct sw_stages {
    const sw_integrator *method; /* the method recorded, NULL before any */
    int dim;
    double t0, h;                /* the step: from t0 by h */
    double *y0, *y1;             /* the state before and after the method's step */
    int n;                       /* stages recorded, in the order they were made */
    sw_stage st[SW_STAGES_MAX];
    int particle;                /* the particle the step moves furthest (the one drawn) */
    int path_n;                  /* 0, or: points of the true path below */
    double path[2 * (SW_STAGES_PATH + 1)]; /* that particle's true positions over the step */
    double *mem;                 /* owned: every vector above */
    int cap;                     /* the dim mem is sized for */
} sw_stages;

/* Whether the stages of m are drawn (its row has a lecture form): 1, or 0
 * with why saying in one line what m does instead, from its row's
 * no_lecture ("stages: not drawn for implicit-euler — it solves an
 * equation, see lesson 7"). */
int sw_stages_supported(const sw_integrator *m, char *why, size_t len);
/* Record one step of s's method by s->dt from s's state and time (s is not
 * changed): SW_OK, SW_EINVAL with why (a method whose stages are not drawn,
 * a blown-up run) or SW_ENOMEM. r starts zeroed and is reused. */
int sw_stages_record(sw_stages *r, const sw_sim *s, char *why, size_t len);
/* The true path of r->particle over the recorded step: the system run from
 * r->y0 at t0 by the reference method at the truth module's tolerances,
 * its position at SW_STAGES_PATH + 1 equally spaced times into r->path.
 * SW_OK, or SW_EINVAL (path_n 0) when the run fails. */
int sw_stages_true_path(sw_stages *r, const sw_sim *s);
void sw_stages_free(sw_stages *r);

#endif
