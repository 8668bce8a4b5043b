/* Event location: a step that crosses one of the scene's events is cut at
 * the crossing, found by regula falsi (Illinois) on the method's own step
 * map h' -> y(t0 + h') from the sub-step's start, the jump applied there and
 * the step completed, so every method keeps its order through a contact.
 * The workspace comes once, when locate mode is chosen: a step allocates
 * nothing. Steps that cross nothing are the plain steps, bit for bit. */
#include "sim/events.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/stepper.h"
#include "stepwise/stepwise.h"

struct sw_sim_events {
    int count, dim;
    double *buf;          /* the one allocation below */
    double *g0, *g1;      /* g at the sub-step's start and at its end (count each) */
    double *y0, *ya, *yb; /* the sub-step's start; the bracket's near and far ends */
    long located;         /* events located so far */
    double last_time;     /* time of the last one located (NaN: none yet) */
    int cut;              /* the last step was cut at an event */
};

const char *sw_events_mode_name(sw_events_mode mode)
{
    switch (mode) {
    case SW_EVENTS_STEP: return "step";
    case SW_EVENTS_LOCATE: return "locate";
    }
    return "?";
}

int sw_events_mode_parse(const char *text, sw_events_mode *out, char *err, size_t errlen)
{
    if (strcmp(text, "step") == 0)
        *out = SW_EVENTS_STEP;
    else if (strcmp(text, "locate") == 0)
        *out = SW_EVENTS_LOCATE;
    else {
        snprintf(err, errlen, "unknown events mode '%.40s'; allowed: locate, step", text);
        return SW_EINVAL;
    }
    return SW_OK;
}

void sw_sim_events_free(sw_sim *s)
{
    if (s->ev) {
        free(s->ev->buf);
        free(s->ev);
    }
    s->ev = NULL;
}

void sw_sim_events_arm(sw_sim *s)
{
    const sw_scene_events *se = s->sys.scene->events;
    if (se && se->arm)
        se->arm(&s->sys, s->sys.y, s->events == SW_EVENTS_LOCATE && s->ev);
}

int sw_sim_events_set_mode(sw_sim *s, sw_events_mode mode, char *err, size_t errlen)
{
    int count = sw_system_event_count(&s->sys), dim = s->sys.ode->dim;
    if (mode == SW_EVENTS_LOCATE && !s->ev && count > 0) {
        struct sw_sim_events *ev = calloc(1, sizeof *ev);
        double *buf = ev ? malloc((2 * (size_t)count + 3 * (size_t)dim) * sizeof *buf) : NULL;
        if (!buf) {
            free(ev);
            snprintf(err, errlen, "out of memory for locating %d events", count);
            return SW_ENOMEM;
        }
        ev->count = count;
        ev->dim = dim;
        ev->last_time = NAN;
        ev->buf = buf;
        ev->g0 = buf;
        ev->g1 = buf + count;
        ev->y0 = buf + 2 * (size_t)count;
        ev->ya = ev->y0 + dim;
        ev->yb = ev->ya + dim;
        s->ev = ev;
    }
    s->events = mode;
    sw_sim_events_arm(s);
    sw_stepper_touch(s->stepper);
    return SW_OK;
}

void sw_sim_events_reset(sw_sim *s)
{
    if (s->ev) {
        s->ev->located = 0;
        s->ev->last_time = NAN;
        s->ev->cut = 0;
    }
}

void sw_sim_events_restore(sw_sim *s, long located, double last_time)
{
    if (s->ev) {
        s->ev->located = located;
        s->ev->last_time = last_time;
        s->ev->cut = 0;
    }
}

long sw_sim_events_located(const sw_sim *s) { return s->ev ? s->ev->located : 0; }

double sw_sim_events_last_time(const sw_sim *s) { return s->ev ? s->ev->last_time : NAN; }

/* Whether g went from ga to gb across zero in the declared direction (from
 * a side strictly, to the other strictly: a state left exactly on zero
 * starts no event). */
static int crossing(int direction, double ga, double gb)
{
    if (!((ga > 0 && gb < 0) || (ga < 0 && gb > 0)))
        return 0;
    return direction == 0 || (direction < 0) == (ga > 0);
}

static void eval_all(const sw_sim *s, double t, const double *y, double *g)
{
    const sw_scene_events *se = s->sys.scene->events;
    for (int k = 0; k < s->ev->count; k++)
        g[k] = se->g(&s->sys, k, t, y);
}

/* The method's own step of size h from (t0, ev->y0) into the sim's y; the
 * time it reached into *t_out (an adaptive method may stop sooner when its
 * error control rejects h). */
static int probe(sw_sim *s, double t0, double h, double *t_out)
{
    memcpy(s->sys.y, s->ev->y0, (size_t)s->ev->dim * sizeof *s->sys.y);
    sw_stepper_touch(s->stepper);
    if (s->method->flags & SW_ADAPTIVE)
        s->stepper->h_next = h;
    double t = t0;
    int rc = sw_stepper_step(s->stepper, s->sys.ode, &t, s->sys.y, h);
    *t_out = t;
    return rc;
}

/* Illinois on event k over the bracket [*a, *b] (offsets from t0; g_k =
 * *ga before, *gb past the crossing; states ev->ya, ev->yb) until it is a
 * few ulps wide. The far end stays strictly past the crossing, so the step
 * resumes on the smooth side. */
static int refine(sw_sim *s, int k, double t0, double *a, double ga, double *b, double gb)
{
    struct sw_sim_events *ev = s->ev;
    const sw_scene_events *se = s->sys.scene->events;
    size_t bytes = (size_t)ev->dim * sizeof *ev->y0;
    double sigma = ga > 0 ? 1.0 : -1.0;
    double tol = 4.0 * DBL_EPSILON * fmax(fabs(t0) + *b, 1e-3);
    int side = 0;
    for (int it = 0; it < 200 && *b - *a > 2 * tol; it++) {
        double c = *b - gb * (*b - *a) / (gb - ga);
        if (!(c > *a && c < *b))
            c = 0.5 * (*a + *b);
        /* at least tol from either end, so a side whose g sits at the
         * rounding floor still moves */
        c = fmin(fmax(c, *a + tol), *b - tol);
        double tc;
        int rc = probe(s, t0, c, &tc);
        if (rc != SW_OK)
            return rc;
        /* the step's own size (t0 + c rounds to the clock's ulp; the state
         * is the step of size c) */
        double hc = (s->method->flags & SW_ADAPTIVE) ? s->stepper->h_last : c;
        if (!(hc > *a && hc < *b))
            break; /* the error control would not step that far: keep the bracket */
        double gc = se->g(&s->sys, k, tc, s->sys.y);
        if (sigma * gc < 0) { /* past the crossing */
            *b = hc;
            gb = gc;
            memcpy(ev->yb, s->sys.y, bytes);
            if (side < 0)
                ga *= 0.5;
            side = -1;
        } else {
            *a = hc;
            ga = gc;
            memcpy(ev->ya, s->sys.y, bytes);
            if (side > 0)
                gb *= 0.5;
            side = 1;
        }
    }
    return SW_OK;
}

/* The earliest crossing of the sub-step from g0 to g1 by linear
 * interpolation of g (the candidate to refine), or -1. */
static int first_crossing(const sw_sim *s)
{
    const struct sw_sim_events *ev = s->ev;
    int direction = s->sys.scene->events->direction, best = -1;
    double best_frac = INFINITY;
    for (int k = 0; k < ev->count; k++) {
        if (!crossing(direction, ev->g0[k], ev->g1[k]))
            continue;
        double frac = ev->g0[k] / (ev->g0[k] - ev->g1[k]);
        if (frac < best_frac) {
            best_frac = frac;
            best = k;
        }
    }
    return best;
}

/* The sub-step from (t0, y0) reached t0 + b with event k crossed: find the
 * earliest crossing (another event may have crossed before k's), end the
 * sub-step just past it and apply the jumps of every event crossed there. */
static int cut_at_event(sw_sim *s, int k, double t0, double b)
{
    struct sw_sim_events *ev = s->ev;
    const sw_scene_events *se = s->sys.scene->events;
    size_t bytes = (size_t)ev->dim * sizeof *ev->y0;
    double a = 0, ga = ev->g0[k], gb = ev->g1[k];
    memcpy(ev->ya, ev->y0, bytes);
    memcpy(ev->yb, s->sys.y, bytes);
    for (int rounds = 0; rounds <= ev->count; rounds++) {
        int rc = refine(s, k, t0, &a, ga, &b, gb);
        if (rc != SW_OK)
            return rc;
        eval_all(s, t0 + b, ev->yb, ev->g1);
        int earlier = -1;
        double g_at_a = 0;
        for (int j = 0; j < ev->count && earlier < 0 && a > 0; j++)
            if (j != k && crossing(se->direction, ev->g0[j], ev->g1[j])) {
                g_at_a = se->g(&s->sys, j, t0 + a, ev->ya);
                if (crossing(se->direction, ev->g0[j], g_at_a))
                    earlier = j;
            }
        if (earlier < 0)
            break;
        /* Event `earlier` crossed before k's bracket began: locate it in [0, a]. */
        k = earlier;
        b = a;
        gb = g_at_a;
        memcpy(ev->yb, ev->ya, bytes);
        a = 0;
        ga = ev->g0[k];
        memcpy(ev->ya, ev->y0, bytes);
    }
    memcpy(s->sys.y, ev->yb, bytes);
    s->t = t0 + b;
    for (int j = 0; j < ev->count; j++)
        if (crossing(se->direction, ev->g0[j], ev->g1[j])) {
            if (se->jump)
                se->jump(&s->sys, j, s->t, s->sys.y);
            ev->located++;
            ev->last_time = s->t;
        }
    sw_stepper_touch(s->stepper);
    eval_all(s, s->t, s->sys.y, ev->g0);
    ev->cut = 1;
    return SW_OK;
}

int sw_sim_locate_step(sw_sim *s, double h)
{
    struct sw_sim_events *ev = s->ev;
    double *y = s->sys.y;
    size_t bytes = (size_t)ev->dim * sizeof *y;
    int adaptive = (s->method->flags & SW_ADAPTIVE) != 0;
    double t_end = s->t + h;
    ev->cut = 0;
    eval_all(s, s->t, y, ev->g0);
    for (int sub = 0;; sub++) {
        double t0 = s->t, t1 = t0;
        memcpy(ev->y0, y, bytes);
        int rc;
        if (sub == 0) { /* the plain step first: most steps cross nothing */
            rc = sw_stepper_step(s->stepper, s->sys.ode, &t1, y, h);
            if (adaptive)
                t_end = t1;
        } else {
            if (adaptive)
                s->stepper->h_next = t_end - t0;
            rc = sw_stepper_step(s->stepper, s->sys.ode, &t1, y, t_end - t0);
            if (!adaptive)
                t1 = t_end;
        }
        if (rc != SW_OK)
            return rc;
        if (sub >= SW_EVENTS_PER_STEP) { /* taken whole: post_step meets the rest */
            s->t = t1;
            return SW_OK;
        }
        eval_all(s, t1, y, ev->g1);
        int k = first_crossing(s);
        if (k < 0) {
            s->t = t1;
            double *g = ev->g0;
            ev->g0 = ev->g1;
            ev->g1 = g;
            if (s->t >= t_end)
                return SW_OK;
            continue;
        }
        rc = cut_at_event(s, k, t0, t1 - t0);
        if (rc != SW_OK)
            return rc;
        if (s->t >= t_end) {
            s->t = t_end;
            return SW_OK;
        }
    }
}

int sw_sim_events_cut(const sw_sim *s) { return s->ev && s->ev->cut; }
