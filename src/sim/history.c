/* A sim's recent past: a ring of snapshots taken after each step (after
 * every stride-th step for a system too large to keep SW_HISTORY_SPAN of
 * them in the budget), allocated once when the sim is put on screen.
 * Invariant: restoring a snapshot and stepping gives the states the forward
 * run gave, bit for bit (the method's carried memory is restored with the
 * state, not rebuilt: the FSAL derivative, the controller's memory, and
 * what a method keeps beyond them, dop853-lc's variables). Going back
 * lands on a snapshot, never between. */
#include "sim/history.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "engine/stepper.h"
#include "sim/events.h"

struct sw_history_meta {
    double t;
    long steps, evals;
    double h_next, h_last;    /* the adaptive controller's proposal, the last step */
    double err_last;          /* ... and the last accepted step's error norm */
    long accepted, rejected, newton_iters;
    int have_cache, fsal;     /* the FSAL derivative (kept in the cache ring) */
    const sw_integrator *method; /* whose cache and memory they are */
    int nmemory;              /* the method's memory beyond these (sw_stepper_memory_save) */
    double memory[SW_STEPPER_MEMORY_MAX];
    long located;             /* events located so far, and the last one's time */
    double last_event;
};

static size_t width(const sw_history *h) { return (size_t)h->dim + (size_t)h->nextra; }

int sw_history_keeps_cache(const sw_integrator *m)
{
    return (m->flags & SW_ADAPTIVE) || m->step == sw_step_verlet || m->step == sw_step_yoshida4;
}

/* The memory allowed snapshots of `one` bytes, and how many fit in it. */
static size_t budget_for(size_t one)
{
    return SW_HISTORY_COPIES * one > SW_HISTORY_BYTES ? SW_HISTORY_COPIES * one : SW_HISTORY_BYTES;
}

static int fit(size_t one)
{
    size_t n = budget_for(one) / one;
    return n < SW_HISTORY_STATES ? (int)n : SW_HISTORY_STATES;
}

void sw_history_init(sw_history *h, const sw_sim *s)
{
    memset(h, 0, sizeof *h);
    h->dim = s->sys.ode->dim;
    h->nextra = s->sys.nextra;
    size_t state = width(h) * sizeof(double), fsal = (size_t)h->dim * sizeof(double);
    size_t meta = sizeof(struct sw_history_meta);
    /* Fewer than SW_HISTORY_SPAN snapshots: one every stride-th step, so the
     * oldest is still SW_HISTORY_SPAN steps or more behind the newest. The
     * stride is the one a method with an FSAL derivative needs, whatever the
     * method, so that compared runs keep their snapshots at the same steps;
     * a method without one keeps more of them. */
    int most = fit(state + fsal + meta);
    h->stride = most >= SW_HISTORY_SPAN ? 1 : (SW_HISTORY_SPAN + most - 2) / (most - 1);
    int keeps = sw_history_keeps_cache(s->method);
    size_t one = state + (keeps ? fsal : 0) + meta;
    int cap = fit(one);
    h->budget = budget_for(one);
    h->vec = malloc((size_t)cap * state);
    h->cache = keeps ? malloc((size_t)cap * fsal) : NULL;
    h->meta = malloc((size_t)cap * meta);
    if (!h->vec || (keeps && !h->cache) || !h->meta) {
        sw_history_free(h);
        return;
    }
    h->cap = cap;
    h->bytes = (size_t)cap * one;
}

void sw_history_free(sw_history *h)
{
    free(h->vec);
    free(h->cache);
    free(h->meta);
    h->vec = h->cache = NULL;
    h->meta = NULL;
    h->cap = h->head = h->count = h->since = h->wrapped = 0;
    h->bytes = 0;
}

void sw_history_restart(sw_history *h, const sw_sim *s)
{
    if (!h->cap || sw_history_keeps_cache(s->method) != (h->cache != NULL)) {
        sw_history_free(h);
        sw_history_init(h, s);
    }
    h->head = h->count = h->since = h->wrapped = 0;
    sw_history_push(h, s);
}

void sw_history_push(sw_history *h, const sw_sim *s)
{
    if (!h->cap || s->blown)
        return;
    if (h->count > 0 && ++h->since < h->stride)
        return;
    h->since = 0;
    const sw_stepper *st = s->stepper;
    double *v = h->vec + (size_t)h->head * width(h);
    size_t dim = (size_t)h->dim;
    memcpy(v, s->sys.y, dim * sizeof *v);
    int cache = st->have_cache && h->cache; /* see sw_history_keeps_cache */
    if (cache)
        memcpy(h->cache + (size_t)h->head * dim, SW_WORK(st, st->fsal), dim * sizeof *v);
    if (h->nextra)
        memcpy(v + dim, s->sys.extra, (size_t)h->nextra * sizeof *v);
    struct sw_history_meta *m = &h->meta[h->head];
    *m = (struct sw_history_meta){
        .t = s->t, .steps = s->steps, .evals = s->sys.ode->evals,
        .h_next = st->h_next, .h_last = st->h_last, .err_last = st->err_last,
        .accepted = st->accepted, .rejected = st->rejected, .newton_iters = st->newton_iters,
        .have_cache = cache, .fsal = st->fsal, .method = st->method,
        .located = sw_sim_events_located(s), .last_event = sw_sim_events_last_time(s),
    };
    m->nmemory = sw_stepper_memory_save(st, m->memory);
    h->head = (h->head + 1) % h->cap;
    if (h->count < h->cap)
        h->count++;
    else
        h->wrapped = 1;
}

/* The k-th newest snapshot's index (k = 0: the newest). */
static int at(const sw_history *h, int k) { return ((h->head - 1 - k) % h->cap + h->cap) % h->cap; }

int sw_history_pick(const sw_history *h, const sw_sim *s, int n)
{
    if (h->count < 1)
        return -1;
    /* snapshot k is since + k·stride steps behind the newest state pushed;
     * a blown-up s is one step past that (its failed step is not kept) */
    int need = s->blown ? n - 1 : n, k = 0;
    if (need > h->since)
        k = (need - h->since + h->stride - 1) / h->stride;
    if (k > h->count - 1)
        k = h->count - 1;
    return k == 0 && h->since == 0 && !s->blown ? -1 : k;
}

double sw_history_time(const sw_history *h, int k)
{
    return k >= 0 && k < h->count ? h->meta[at(h, k)].t : NAN;
}

void sw_history_retime(sw_history *h, double t)
{
    if (h->count > 0 && h->since == 0)
        h->meta[at(h, 0)].t = t;
}

static void restore(const sw_history *h, int i, sw_sim *s)
{
    const struct sw_history_meta *m = &h->meta[i];
    const double *v = h->vec + (size_t)i * width(h);
    size_t dim = (size_t)h->dim;
    sw_stepper *st = s->stepper;
    memcpy(s->sys.y, v, dim * sizeof *v);
    /* A cache is its method's: after a change of method (which should
     * have cleared the history) it is not put into another's workspace. */
    int cache = m->have_cache && m->method == st->method;
    if (cache)
        memcpy(SW_WORK(st, m->fsal), h->cache + (size_t)i * dim, dim * sizeof *v);
    if (h->nextra)
        memcpy(s->sys.extra, v + dim, (size_t)h->nextra * sizeof *v);
    s->t = m->t;
    s->steps = m->steps;
    s->sys.ode->evals = m->evals;
    st->h_next = m->h_next;
    st->h_last = m->h_last;
    st->err_last = m->err_last;
    st->accepted = m->accepted;
    st->rejected = m->rejected;
    st->newton_iters = m->newton_iters;
    st->have_cache = cache;
    st->fsal = cache ? m->fsal : st->fsal;
    st->why = NULL;
    if (m->method == st->method)
        sw_stepper_memory_load(st, m->memory, m->nmemory, s->t, s->sys.y);
    sw_sim_events_restore(s, m->located, m->last_event);
    s->blown = 0; /* only states before a blow-up are kept */
    s->blow_step = 0;
    s->blow_time = 0;
    s->blow_reason[0] = '\0';
    sw_sim_state_changed(s);
}

int sw_history_back_to(sw_history *h, sw_sim *s, double t)
{
    if (h->count < 1)
        return 0;
    int dropped = 0;
    while (h->count > 1 && h->meta[at(h, 0)].t > t) {
        h->head = at(h, 0);
        h->count--;
        dropped = 1;
    }
    int moved = dropped || s->blown || h->since > 0 || s->t != h->meta[at(h, 0)].t;
    if (moved)
        restore(h, at(h, 0), s);
    h->since = 0;
    return moved;
}
