/* dop853-lc: dop853 stepping one body about one centre in Levi-Civita's
 * variables (engine/regularise.h), as a method of the table (issue 26).
 *
 * Each step starts from the particle's own state: [x | v] at t is taken to
 * w = [u, u', h, t], one step of dop853 is taken in the fictitious time s
 * (at most dt of the true clock, landed on t + dt where it would pass it),
 * and w is taken back. So a step is a function of (t, y), the tolerances
 * and the proposed step alone, as every other method's is: stepping back
 * and on again (sim/history.c), a reset and a change of method need
 * nothing of it kept. What that costs: dop853's first-same-as-last
 * derivative is evaluated anew each step (one more evaluation of the
 * regularised field, a handful of multiplications), and the two changes of
 * variables round each step to a few ulps. The proposal in s is kept in
 * the stepper's h_next, where history keeps it. Its lecture form, the
 * same bits: sw_ref_dop853_lc in reference_adaptive.c. */
#include <stdio.h>
#include <stdlib.h>

#include "engine/central.h"
#include "engine/regularise.h"
#include "stepwise/base.h"

/* dop853 as the regularised run steps it: its step and its workspace
 * (the table's entry is integrators.c's, which calls this file). */
static const sw_integrator dop853 = { .name = "dop853 (regularised)", .work_vectors = SW_DOP853_VECTORS, .step = sw_step_dop853,
                                      .flags = SW_EXPLICIT | SW_ADAPTIVE };

typedef struct lc_run {
    sw_lc lc;
    sw_stepper st; /* dop853 on lc.ode */
    double work[SW_DOP853_VECTORS * SW_LC_DIM];
} lc_run;

static void release(sw_stepper *s)
{
    free(s->inner);
    s->inner = NULL;
}

int sw_dop853_lc_prepare(sw_stepper *s, const sw_ode *ode, char *err, size_t errlen)
{
    lc_run *r = calloc(1, sizeof *r);
    if (!r) {
        snprintf(err, errlen, "out of memory for dop853-lc's regularised run");
        return SW_ENOMEM;
    }
    int rc = sw_lc_init_central(&r->lc, (sw_ode *)ode, err, errlen);
    r->st = (sw_stepper){ .method = &dop853, .dim = SW_LC_DIM, .work = r->work };
    if (rc != SW_OK) {
        free(r);
        return rc;
    }
    s->inner = r;
    s->release = release;
    return SW_OK;
}

int sw_step_dop853_lc(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    lc_run *r = s->inner;
    char err[SW_ERRLEN];
    double w[SW_LC_DIM];
    /* the field as the system holds it now (its centre and mu): where it is
     * the one the run was made for, only the evaluations are cleared (all
     * that sw_lc_init would change), else the run is made anew */
    sw_central1 c;
    if (ode == r->lc.base && ode->dim == 4 && sw_ode_central1(ode, &c) && c.cx == r->lc.cx && c.cy == r->lc.cy &&
        c.mu * c.mass * c.inv == r->lc.mu)
        r->lc.ode.evals = 0;
    else if (sw_lc_init_central(&r->lc, ode, err, sizeof err) != SW_OK) {
        s->why = "dop853-lc: the system is no longer one body alone in one central field";
        return SW_EINVAL;
    }
    if (sw_lc_from(&r->lc, *t, y, w) != SW_OK) {
        s->why = "dop853-lc: the body is at the centre, where its variables are not defined";
        return SW_EDIVERGED;
    }
    r->st.have_cache = 0;
    r->st.rtol = s->rtol;
    r->st.atol = s->atol;
    r->st.h_next = s->h_next;
    long rejected = r->st.rejected;
    int rc = sw_lc_step(&r->lc, &r->st, w, h);
    ode->evals += r->lc.ode.evals; /* the regularised field's: the particle's own is not called */
    /* the error control's rejections; the tries at a landing on t + h are
     * in the evaluations, not here (they are not the error control's) */
    s->rejected += r->st.rejected - rejected;
    if (rc != SW_OK) {
        s->why = r->lc.why;
        return rc;
    }
    s->accepted++;
    s->h_next = r->st.h_next;
    s->h_last = w[5] - *t;
    sw_lc_to(&r->lc, w, y);
    *t = w[5];
    return SW_OK;
}
