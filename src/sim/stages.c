/* Recording the stages of one step (see stages.h). Invariant: the step is
 * the method's own step function on a fresh stepper (the run's FSAL
 * derivative copied in), so the state it ends in is the run's next state
 * bit for bit; the run itself is never touched. */
#include "sim/stages.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/stepper.h"
#include "sim/truth.h"
#include "stepwise/stepwise.h"

/* The solver view the step sees: the run's system, every evaluation noted. */
typedef struct recorder {
    sw_ode *inner;
    sw_stages *r;
    int over;        /* evaluations past SW_STAGES_MAX (not recorded) */
} recorder;

static void record_deriv(void *ctx, double t, const double *y, double *dydt)
{
    recorder *rc = ctx;
    rc->inner->deriv(rc->inner->ctx, t, y, dydt);
    sw_stages *r = rc->r;
    if (r->n >= SW_STAGES_MAX) {
        rc->over++;
        return;
    }
    sw_stage *st = &r->st[r->n++];
    st->t = t;
    st->cached = 0;
    memcpy(st->y, y, (size_t)r->dim * sizeof *y);
    memcpy(st->k, dydt, (size_t)r->dim * sizeof *dydt);
}

int sw_stages_supported(const sw_integrator *m, char *why, size_t len)
{
    if (m->lecture)
        return 1;
    snprintf(why, len, "stages: not drawn for %s \xe2\x80\x94 %s", m->name,
             m->no_lecture ? m->no_lecture : "its row gives no lecture form of its step");
    return 0;
}

/* Vectors for dim: y0, y1 and each stage's y and k. */
static int reserve(sw_stages *r, int dim)
{
    if (r->mem && r->cap == dim)
        return SW_OK;
    free(r->mem);
    r->mem = calloc((size_t)(2 + 2 * SW_STAGES_MAX) * (size_t)dim, sizeof *r->mem);
    r->cap = r->mem ? dim : 0;
    if (!r->mem)
        return SW_ENOMEM;
    double *p = r->mem;
    r->y0 = p;
    r->y1 = p + dim;
    for (int i = 0; i < SW_STAGES_MAX; i++) {
        r->st[i].y = p + (size_t)(2 + 2 * i) * (size_t)dim;
        r->st[i].k = p + (size_t)(3 + 2 * i) * (size_t)dim;
    }
    return SW_OK;
}

int sw_stages_record(sw_stages *r, const sw_sim *s, char *why, size_t len)
{
    const sw_integrator *m = s->method;
    sw_ode *ode = s->sys.ode;
    r->n = 0;
    r->method = NULL;
    if (!sw_stages_supported(m, why, len))
        return SW_EINVAL;
    if (s->blown) {
        snprintf(why, len, "stages: not drawn \xe2\x80\x94 the run blew up (r resets)");
        return SW_EINVAL;
    }
    if (reserve(r, ode->dim) != SW_OK) {
        snprintf(why, len, "stages: out of memory");
        return SW_ENOMEM;
    }
    r->dim = ode->dim;
    recorder rc = { .inner = ode, .r = r, .over = 0 };
    /* no fast paths: the generic loops, which give the same bits (ode_fast.h) */
    sw_ode view = { .dim = ode->dim, .order = ode->order, .deriv = record_deriv, .ctx = &rc };
    sw_stepper st;
    char err[SW_ERRLEN];
    if (sw_stepper_init(&st, m, &view, err, sizeof err) != SW_OK) {
        snprintf(why, len, "stages: %s", err);
        return SW_EINVAL;
    }
    const sw_stepper *run = s->stepper;
    memcpy(r->y0, s->sys.y, (size_t)r->dim * sizeof *r->y0);
    memcpy(r->y1, s->sys.y, (size_t)r->dim * sizeof *r->y1);
    if (run->have_cache) {
        /* the derivative the run kept from its last step (Verlet's a0):
         * not evaluated now, so noted as a stage of its own */
        st.have_cache = 1;
        st.fsal = run->fsal;
        memcpy(SW_WORK(&st, st.fsal), SW_WORK(run, run->fsal), (size_t)r->dim * sizeof(double));
        sw_stage *c = &r->st[r->n++];
        c->t = s->t;
        c->cached = 1;
        memcpy(c->y, r->y0, (size_t)r->dim * sizeof *c->y);
        memcpy(c->k, SW_WORK(run, run->fsal), (size_t)r->dim * sizeof *c->k);
    }
    double t = s->t;
    int rc_step = sw_stepper_step(&st, &view, &t, r->y1, s->dt);
    sw_stepper_free(&st);
    if (rc_step != SW_OK || rc.over) {
        r->n = 0;
        snprintf(why, len, "stages: %s's step %s", m->name, rc.over ? "made too many evaluations to draw" : "failed");
        return SW_EINVAL;
    }
    r->method = m;
    r->t0 = s->t;
    r->h = s->dt;
    r->path_n = 0;
    r->particle = 0;
    double far = -1;
    for (int i = 0; i < s->sys.n && 2 * i + 1 < r->dim; i++) {
        double dx = r->y1[2 * i] - r->y0[2 * i], dy = r->y1[2 * i + 1] - r->y0[2 * i + 1], d = dx * dx + dy * dy;
        if (d > far) {
            far = d;
            r->particle = i;
        }
    }
    return SW_OK;
}

int sw_stages_true_path(sw_stages *r, const sw_sim *s)
{
    sw_sim ref;
    char err[SW_ERRLEN];
    r->path_n = 0;
    if (!r->method ||
        sw_sim_init(&ref, s->sys.scene, s->sys.p, sw_truth_reference_method(), r->h / SW_STAGES_PATH, err, sizeof err) != SW_OK)
        return SW_EINVAL;
    sw_sim_set_tolerances(&ref, SW_TRUTH_RTOL, SW_TRUTH_ATOL);
    int ok = ref.sys.ode->dim == r->dim;
    if (ok) {
        sw_sim_set_state(&ref, r->y0);
        ref.t = r->t0; /* the same clock: a time-dependent field (the gyre) */
    }
    for (int j = 0; ok && j <= SW_STAGES_PATH; j++) {
        if (j > 0)
            ok = sw_sim_run_until(&ref, r->t0 + r->h * j / SW_STAGES_PATH) == 0;
        r->path[2 * j] = ref.sys.y[2 * r->particle];
        r->path[2 * j + 1] = ref.sys.y[2 * r->particle + 1];
    }
    sw_sim_free(&ref);
    r->path_n = ok ? SW_STAGES_PATH + 1 : 0;
    return ok ? SW_OK : SW_EINVAL;
}

void sw_stages_free(sw_stages *r)
{
    free(r->mem);
    memset(r, 0, sizeof *r);
}
