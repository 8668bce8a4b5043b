/* dop853-lc: dop853 stepping one body about one centre in Levi-Civita's
 * variables (engine/regularise.h), as a method of the table (issue 26).
 *
 * A step from the particle's state takes [x | v] at t to w = [u, u', h, t],
 * takes one step of dop853 in the fictitious time s (at most dt of the
 * true clock, landed on t + dt where it would pass it), and takes w back.
 * The next step, where it starts from the state that step left, bit for
 * bit (sw_lc_resume), goes on from w and from dop853's first-same-as-last
 * derivative instead: the energy h stays the flow's constant rather than
 * taking up each step's error in u and u' (issue 41: 256 evaluations
 * where 298 reached the same error within 1e-6), and the step makes 12
 * evaluations, not 13, with no change of variables in. A step from any
 * other state (the first, one set from outside, a rewind's snapshot)
 * starts from the particle as above. So the same settings give the same
 * run, bit for bit; a snapshot keeps w, its field and dop853's derivative
 * (sw_dop853_lc_save, below), so a run restored and stepped on repeats
 * itself bit for bit as every method's does. The proposal in s is kept in
 * the stepper's h_next, where history keeps it. Its lecture form, the same
 * bits: sw_ref_dop853_lc in reference_adaptive.c. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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
    sw_lc_left left; /* where the last step left the particle, and w there */
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

/* The run for the field as the system holds it now (its centre and mu):
 * where it is the one the run was made for, only the evaluations are
 * cleared (all that sw_lc_init would change), else the run is made anew.
 * SW_OK, or SW_EINVAL where the system is no longer one body alone. */
static int same_field(lc_run *r, sw_ode *ode)
{
    sw_central1 c;
    if (ode == r->lc.base && ode->dim == 4 && sw_ode_central1(ode, &c) && c.cx == r->lc.cx && c.cy == r->lc.cy &&
        c.mu * c.mass * c.inv == r->lc.mu) {
        r->lc.ode.evals = 0;
        return SW_OK;
    }
    char err[SW_ERRLEN];
    return sw_lc_init_central(&r->lc, ode, err, sizeof err);
}

int sw_step_dop853_lc(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    lc_run *r = s->inner;
    if (same_field(r, ode) != SW_OK) {
        s->why = "dop853-lc: the system is no longer one body alone in one central field";
        return SW_EINVAL;
    }
    double *w = r->left.w;
    int resumed = sw_lc_resume(&r->left, &r->lc, *t, y);
    if (resumed < 0) {
        s->why = "dop853-lc: the body is at the centre, where its variables are not defined";
        return SW_EDIVERGED;
    }
    r->st.have_cache = resumed; /* the last step's first-same-as-last derivative: f at w */
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
    *t = w[5];
    sw_lc_leave(&r->left, &r->lc, y);
    return SW_OK;
}

/* What a snapshot keeps of the run (sw_stepper_memory_save): where the
 * last step left the particle, w, the field it was taken in (cx, cy, mu)
 * and dop853's first-same-as-last derivative at w with its slot. */
enum { M_W = 0, M_FIELD = SW_LC_DIM, M_SLOT = M_FIELD + 3, M_F = M_SLOT + 1, M_LEN = M_F + SW_LC_DIM };
_Static_assert((int)M_LEN <= (int)SW_STEPPER_MEMORY_MAX, "dop853-lc's memory fits a snapshot's room");

int sw_dop853_lc_save(const sw_stepper *s, double *out)
{
    const lc_run *r = s->inner;
    if (!r || !r->left.valid)
        return 0;
    memcpy(out + M_W, r->left.w, SW_LC_DIM * sizeof *out);
    out[M_FIELD] = r->left.cx;
    out[M_FIELD + 1] = r->left.cy;
    out[M_FIELD + 2] = r->left.mu;
    out[M_SLOT] = r->st.fsal;
    memcpy(out + M_F, r->work + (size_t)r->st.fsal * SW_LC_DIM, SW_LC_DIM * sizeof *out);
    return M_LEN;
}

/* The run as it was when its snapshot was taken: the next step from the
 * restored (t, y) goes on from w, as the first run's did, where the field
 * is still the one w was taken in (sw_lc_resume compares it). */
void sw_dop853_lc_load(sw_stepper *s, const double *in, int n, double t, const double *y)
{
    lc_run *r = s->inner;
    int slot = n == M_LEN ? (int)in[M_SLOT] : -1;
    if (!r || slot < 0 || slot >= SW_DOP853_VECTORS)
        return;
    memcpy(r->left.w, in + M_W, SW_LC_DIM * sizeof *in);
    r->left.valid = 1;
    r->left.base = r->lc.base;
    r->left.cx = in[M_FIELD];
    r->left.cy = in[M_FIELD + 1];
    r->left.mu = in[M_FIELD + 2];
    r->left.t = t;
    memcpy(r->left.y, y, sizeof r->left.y);
    r->st.fsal = slot;
    memcpy(r->work + (size_t)slot * SW_LC_DIM, in + M_F, SW_LC_DIM * sizeof *in);
}
