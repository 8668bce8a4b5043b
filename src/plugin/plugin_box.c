/* The sandboxed plugin step. A plugin's steps run in its host (host_link.c,
 * plugin/host_proto.h), never here: each stepper of a plugin method owns a
 * slot there, where the host has built the same system again from what its
 * maker said (a scene and its parameters, or a 2x2 test system). The
 * stepper asks for a run of steps at once and serves the steps from what
 * came back, while each call asks for exactly the state, time and step the
 * host ran ahead from (the runs grow 1, 4, 16, ... up to a bound, and start
 * again at 1 when the caller goes elsewhere: contact, an event, a reset).
 * No round trip per step. Invariant: every number read is checked before
 * it is used; the host's derivative at the start of each run is compared
 * bit for bit with ours (it is the system we step, or nothing is served);
 * a fault is reported at the step it happened in, and only when the
 * caller asks for that step. */
#include "plugin/plugin_box.h"

#include <math.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/uio.h>
#include <unistd.h>

#include "engine/linear2.h"
#include "stepwise/scene.h"

/* The longest run asked for, the most bytes of states one may bring, and
 * how much longer each run is than the last while the caller keeps up. */
#define BATCH_MAX SW_HOST_BATCH_MAX
#define BATCH_BYTES ((size_t)8 << 20)
#define BATCH_GROWTH 4

static const char *const ode_fields[] = SW_HOST_ODE_FIELDS;

/* A plugin that printed this much before it ran out of CPU time is told
 * that printing was the likely cost. */
#define SW_PRINTED_MUCH ((long long)1 << 20)

typedef struct step_box {
    sw_plugin_entry *entry;
    int slot, generation;    /* the slot on the entry's host, open while generation matches */
    int dim, wv, nextra;
    size_t vec;              /* dim doubles, in bytes */
    sw_host_cmd opened;      /* the system the slot holds */
    int batch, batch_cap;    /* the next run's length, and its bound */
    /* the last run: states as read, each step's counts, how many were served */
    double *rows, *sent, *extra_sent, *print;
    sw_host_reply *meta;
    int have, used, ran;
    double t_next, h;
    int ended;               /* the host stopped the run itself (a failed step, a non-finite state) */
    int pending;             /* the host died after `have` steps: the next step is its fault */
    int careful;             /* runs reply by reply (after a host died in one) */
    int exact;               /* the host said every step before its death was sent */
    sw_child_end pending_end;
    sw_host_reply pending_fault;
    int pending_rc;          /* how the read failed: 0 ended, -1 cancelled, -2 timed out, -4 forged */
    long long pending_printed; /* what the plugin had printed when its host said DYING */
    sw_plugin_fault fault;   /* set once, then every step fails */
    char why[SW_ERRLEN];     /* what happened ... */
    char hint[96];           /* ... and, after the step, what to do */
    char message[SW_ERRLEN + 128]; /* both, for the stepper's why (the sim's blow-up reason) */
} step_box;

/* ---- faults ------------------------------------------------------------------ */

static void box_fail(step_box *b, sw_plugin_fault f, const char *why, const char *hint)
{
    if (b->fault != SW_PF_NONE)
        return;
    b->fault = f;
    snprintf(b->why, sizeof b->why, "%s", why);
    snprintf(b->hint, sizeof b->hint, "%s", hint ? hint : "");
    snprintf(b->message, sizeof b->message, "the plugin %.*s%s%s", (int)(sizeof b->why), b->why,
             b->hint[0] ? " " : "", b->hint);
    if (b->entry && f != SW_PF_CANCELLED && f != SW_PF_DISABLED) {
        b->entry->last_fault = f;
        /* in two writes: gcc -O0 cannot bound the three parts' sum (-Wformat-truncation) */
        size_t room = sizeof b->entry->last_failure;
        int n = snprintf(b->entry->last_failure, room, "%.200s", why);
        if (hint && n >= 0 && (size_t)n + 1 < room)
            snprintf(b->entry->last_failure + n, room - (size_t)n, " %.90s", hint);
    }
}

/* The pending fault, now that the caller asked for the step it is in. */
static void box_fault_now(step_box *b)
{
    char why[SW_ERRLEN], how[120];
    const sw_host_reply *r = b->pending_fault.tag == SW_HOST_FAULT ? &b->pending_fault : NULL;
    const sw_child_end *end = &b->pending_end;
    if (b->pending_rc == -4) {
        box_fail(b, SW_PF_FORGED, "sent the sandbox a reply it could not have sent (a record out of range)",
                 "(a plugin may only compute)");
        return;
    }
    if (b->pending_rc == -1) {
        box_fail(b, SW_PF_CANCELLED, "was interrupted in its step", NULL);
        return;
    }
    if (b->pending_rc == -2) {
        char said[96];
        sw_host_watch_says(&b->entry->host, sw_plugin_timeout(), said, sizeof said);
        snprintf(why, sizeof why, "%s from its step", said);
        box_fail(b, SW_PF_TIMEOUT, why,
                 b->entry->host.watched == SW_WATCH_ASLEEP ? "(a step must not wait; --plugin-timeout sets the limit)"
                                                           : "(an endless loop? --plugin-timeout sets the limit)");
        return;
    }
    if (b->pending_rc == -5) {
        box_fail(b, SW_PF_FORGED, "sent the sandbox a reply it could not have sent (not a step's result)",
                 "(a plugin may only compute)");
        return;
    }
    sw_sandbox_describe(end, how, sizeof how);
    switch (r ? r->fault : SW_PF_NONE) {
    case SW_PF_OVERRUN_WORK: {
        char fix[80];
        snprintf(why, sizeof why, "wrote past its %d work vector%s (work[%lld], %d doubles each)", b->wv,
                 b->wv == 1 ? "" : "s", (long long)r->index, b->dim);
        /* the vectors work[index] needs: a number, checked when read */
        snprintf(fix, sizeof fix, "(its sw_plugin asks for .work_vectors = %d; work[%lld] needs %lld)", b->wv,
                 (long long)r->index, b->dim > 0 ? (long long)r->index / b->dim + 1 : 0);
        box_fail(b, SW_PF_OVERRUN_WORK, why, fix);
        return;
    }
    case SW_PF_OVERRUN_Y:
        snprintf(why, sizeof why, "wrote past the end of y (y[%lld]; y has ode->dim = %d doubles)",
                 (long long)r->index, b->dim);
        box_fail(b, SW_PF_OVERRUN_Y, why, NULL);
        return;
    case SW_PF_UNDERRUN:
        snprintf(why, sizeof why, "wrote before the start of %s", r->field ? "its work vectors" : "y");
        box_fail(b, SW_PF_UNDERRUN, why, NULL);
        return;
    case SW_PF_ODE:
        if (r->field <= 1)
            snprintf(why, sizeof why, "changed ode->%s from %lld to %lld", ode_fields[r->field],
                     (long long)r->was, (long long)r->now);
        else
            snprintf(why, sizeof why, "changed ode->%s", ode_fields[r->field]);
        box_fail(b, SW_PF_ODE, why, "(a plugin must not write to the ode)");
        return;
    case SW_PF_ALLOC:
        box_fail(b, SW_PF_ALLOC, "allocated memory in its step (malloc, calloc, realloc, or a call that "
                 "allocates, such as fopen or strdup)",
                 "(a step must not allocate: ask for work vectors in sw_plugin_info)");
        return;
    default:
        break;
    }
    if (end->exited) {
        snprintf(why, sizeof why, "ended its process with exit(%d) in its step", end->code);
        box_fail(b, SW_PF_EXIT, why, "(a step must return, never exit)");
    } else if (end->signal == SIGXCPU) {
        /* printing is the usual cause nobody suspects: say so */
        if (b->pending_printed >= SW_PRINTED_MUCH) {
            double mib = (double)b->pending_printed / 1048576;
            snprintf(why, sizeof why, "%s after printing %.3g %s to stdout and stderr (printing costs CPU "
                     "time: take the printf out of the step)", how, mib < 1024 ? mib : mib / 1024,
                     mib < 1024 ? "MiB" : "GiB");
        }
        else
            snprintf(why, sizeof why, "%s", how);
        box_fail(b, SW_PF_LIMIT, why, b->entry->host.graders
                 ? "(the grader's budget for its measuring runs, 4 x --cpu + 30 s, never the submission's)"
                 : "(the submission's CPU-time limit, --cpu: it counts the plugin's own time only)");
    } else {
        box_fail(b, SW_PF_CRASH, how, NULL);
    }
}

/* The host is gone or stopped answering (rc as sw_host_reply_read): it is
 * killed and reaped; the run's next step is the fault. */
static void box_host_died(step_box *b, int rc)
{
    sw_host_link *h = &b->entry->host;
    b->pending = 1;
    b->pending_rc = rc;
    b->exact = h->dying || h->have_fault;
    b->pending_printed = h->dying ? h->printed : 0;
    h->dying = 0;
    memset(&b->pending_fault, 0, sizeof b->pending_fault);
    if (h->have_fault)
        b->pending_fault = h->fault;
    if (rc == 0 || rc == -3) {
        sw_host_lost(b->entry, &b->pending_end);
    } else {
        sw_sandbox_kill(&h->child, &b->pending_end);
        h->alive = 0;
        h->slots = 0;
    }
    h->have_fault = 0;
}

/* ---- the runs ------------------------------------------------------------------ */

/* What the system's maker says it is now: the command that builds it. 0,
 * or -1 when it is nothing a host can build. */
static int describe(const sw_ode *ode, sw_host_cmd *c, int wv)
{
    memset(c, 0, sizeof *c);
    c->op = SW_HOST_OPEN;
    c->maker_kind = ode->maker_kind;
    c->order = ode->order;
    c->dim = ode->dim;
    c->work_vectors = wv;
    if (ode->maker_kind == SW_MAKER_SCENE && ode->maker) {
        const sw_system *sys = ode->maker;
        size_t len = strlen(sys->scene->name);
        if (len >= SW_HOST_SCENE_MAX || sys->ode != ode)
            return -1;
        memcpy(c->scene, sys->scene->name, len);
        memcpy(c->p, sys->p, sizeof c->p);
        c->nextra = sys->nextra;
        return 0;
    }
    if (ode->maker_kind == SW_MAKER_LINEAR2 && ode->maker && ode->dim == 2) {
        memcpy(c->p, ((const sw_linear2 *)ode->maker)->j, 4 * sizeof(double));
        return 0;
    }
    return -1;
}

static const double *live_extra(const sw_ode *ode)
{
    return ode->maker_kind == SW_MAKER_SCENE ? ((const sw_system *)ode->maker)->extra : NULL;
}

static int same_system(const sw_host_cmd *a, const sw_host_cmd *b)
{
    return a->maker_kind == b->maker_kind && a->order == b->order && a->dim == b->dim && a->nextra == b->nextra &&
           memcmp(a->scene, b->scene, sizeof a->scene) == 0 && memcmp(a->p, b->p, sizeof a->p) == 0;
}

static int box_alloc(step_box *b, int dim, int nextra)
{
    b->dim = dim;
    b->vec = (size_t)dim * sizeof(double);
    size_t cap = BATCH_BYTES / (b->vec + sizeof(sw_host_reply));
    b->batch_cap = cap < 1 ? 1 : cap > BATCH_MAX ? BATCH_MAX : (int)cap;
    b->batch = 1;
    b->rows = malloc((size_t)b->batch_cap * b->vec);
    b->meta = malloc((size_t)b->batch_cap * sizeof *b->meta);
    b->sent = malloc(b->vec);
    b->print = malloc(b->vec);
    b->extra_sent = malloc(((size_t)nextra + 1) * sizeof(double));
    return b->rows && b->meta && b->sent && b->print && b->extra_sent ? 0 : -1;
}

static void box_free(step_box *b)
{
    free(b->rows);
    free(b->meta);
    free(b->sent);
    free(b->print);
    free(b->extra_sent);
    free(b);
}

/* Start the host when it is not running (once per plugin, again only after
 * it died in a run the caller never asked for). */
static int box_host(step_box *b)
{
    sw_plugin_entry *e = b->entry;
    if (e->host.alive)
        return 0;
    sw_host_info info;
    char err[SW_ERRLEN];
    if (sw_host_start(e, &info, err, sizeof err) != SW_OK) {
        const char *at = strstr(err, "': ");
        box_fail(b, SW_PF_START, at ? at + 3 : err, NULL);
        return -1;
    }
    if (info.stage != SW_HOST_STAGE_OK || !info.has_step || info.work_vectors != e->work_vectors ||
        strncmp(info.name, e->own_name, sizeof e->own_name) != 0) {
        sw_child_end end;
        sw_host_lost(e, &end);
        box_fail(b, SW_PF_START, info.stage == SW_HOST_STAGE_OK ? "changed since it was loaded: load it again"
                 : "could not be loaded again", NULL);
        return -1;
    }
    return 0;
}

/* Open the box's slot on the host for the system cmd describes. */
static int box_open(step_box *b, const sw_host_cmd *cmd)
{
    sw_host_link *h = &b->entry->host;
    if (b->generation == h->generation && (h->slots >> b->slot & 1) && same_system(&b->opened, cmd))
        return 0;
    if (!(b->generation == h->generation && (h->slots >> b->slot & 1))) {
        int free_slot = -1;
        for (int i = 0; i < SW_HOST_SLOTS && free_slot < 0; i++)
            if (!(h->slots >> i & 1))
                free_slot = i;
        if (free_slot < 0) {
            box_fail(b, SW_PF_START, "could not be given a slot: more than 64 runs of it at once", NULL);
            return -1;
        }
        b->slot = free_slot;
    }
    sw_host_cmd c = *cmd;
    c.slot = b->slot;
    sw_host_reply r;
    int rc = sw_sandbox_write(h->child.to_child, &c, sizeof c) == 0 ? sw_host_reply_read(b->entry, &r, sw_plugin_timeout())
                                                                      : 0;
    if (rc != 1 || r.tag != SW_HOST_OPENED || r.rc != SW_OK) {
        if (rc == 1)
            box_fail(b, SW_PF_START, "could not have this system built in its sandbox (a stepwise bug: please report it)",
                     NULL);
        else {
            box_host_died(b, rc == 1 ? -5 : rc);
            box_fault_now(b);
        }
        return -1;
    }
    h->slots |= 1ull << b->slot;
    b->generation = h->generation;
    b->opened = c;
    b->have = b->used = b->ran = 0;
    return 0;
}

/* Ask for a run of b->batch steps from (t, y) and read it whole. keep: the
 * steps of the last run that were used (-1: all, or none was run). 1 when
 * the host died in it (pending set), else 0. */
static int run_once(step_box *b, sw_ode *ode, double t, const double *y, double h, int keep)
{
    sw_plugin_entry *e = b->entry;
    sw_host_cmd c = b->opened;
    c.op = SW_HOST_RUN;
    c.steps = b->batch;
    c.keep = keep;
    c.careful = b->careful;
    c.t = t;
    c.h = h;
    const double *extra = live_extra(ode);
    size_t xbytes = (size_t)b->nextra * sizeof(double);
    memcpy(b->sent, y, b->vec);
    if (xbytes)
        memcpy(b->extra_sent, extra, xbytes);
    struct iovec parts[3] = { { &c, sizeof c }, { b->sent, b->vec }, { b->extra_sent, xbytes } };
    b->have = b->used = 0;
    b->ended = 0;
    b->t_next = t;
    b->h = h;
    sw_host_reply r;
    double wait = sw_plugin_timeout();
    int rc = sw_sandbox_writev(e->host.child.to_child, parts, xbytes ? 3 : 2) == 0
                 ? sw_host_reply_read(e, &r, wait * (1 + (keep > 0 ? keep : 0)))
                 : 0;
    if (rc == 1 && r.tag != SW_HOST_PRINT)
        rc = -5;
    if (rc == 1)
        rc = sw_host_read(e, b->print, b->vec, wait);
    if (rc != 1) {
        box_host_died(b, rc);
        return 1;
    }
    /* the host's f(t, y) against ours, bit for bit (not counted: no step's) */
    double *ours = b->rows;
    ode->deriv(ode->ctx, t, b->sent, ours);
    if (memcmp(ours, b->print, b->vec) != 0) {
        sw_host_stop(e);
        box_fail(b, SW_PF_START, "was given a system in its sandbox that is not the one stepped here "
                 "(a stepwise bug: please report it)", NULL);
        return 0;
    }
    for (;;) {
        rc = sw_host_reply_read(e, &r, wait);
        if (rc == 1 && r.tag == SW_HOST_END && r.rc == b->have && r.index >= e->host.printed_end &&
            r.index < ((int64_t)1 << 50)) {
            e->host.printed_end = r.index; /* a count that falls, or beyond reason: not an END */
            break;
        }
        if (rc == 1 && (r.tag != SW_HOST_STEP || b->have >= b->batch || b->ended || r.evals < 0 ||
                        r.evals > SW_HOST_COUNT_MAX || r.solves < 0 || r.solves > SW_HOST_COUNT_MAX ||
                        r.iters < 0 || r.iters > SW_HOST_COUNT_MAX))
            rc = -5;
        if (rc == 1)
            rc = sw_host_read(e, b->rows + (size_t)b->have * (size_t)b->dim, b->vec, wait);
        if (rc != 1) {
            box_host_died(b, rc);
            return 1;
        }
        b->meta[b->have++] = r;
        if (r.rc != 0)
            b->ended = 1;
    }
    b->ran = b->have;
    return 0;
}

/* A run; when the host dies in it by a death it could not see coming
 * (_exit(), a forbidden call, SIGKILL), replies it had not sent yet may be
 * lost with it: a new host runs the same steps again carefully, each reply
 * sent as it is made, so that the fault is named at its own step. (A step
 * that never returns has had every step before it sent by the host's tick,
 * and a crash or exit() by its handlers.) */
static void box_run(step_box *b, sw_ode *ode, double t, const double *y, double h, int keep)
{
    if (run_once(b, ode, t, y, h, keep) == 0 || b->careful || b->pending_rc != 0 || b->exact)
        return;
    b->careful = 1;
    b->pending = 0;
    sw_host_cmd cmd;
    double *start = b->rows; /* what was sent, kept while the host starts */
    memcpy(start, b->sent, b->vec);
    if (box_host(b) == 0 && describe(ode, &cmd, b->wv) == 0 && box_open(b, &cmd) == 0)
        run_once(b, ode, t, start, h, -1);
}

/* Whether the call asks for the next step of the run read in. */
static int box_hit(const step_box *b, const sw_ode *ode, double t, const double *y, double h)
{
    if (b->generation != b->entry->host.generation && !b->pending)
        return 0;
    if (t != b->t_next || h != b->h)
        return 0;
    const double *last = b->used == 0 ? b->sent : b->rows + (size_t)(b->used - 1) * (size_t)b->dim;
    if (memcmp(y, last, b->vec) != 0)
        return 0;
    const double *extra = live_extra(ode);
    if (b->nextra && memcmp(extra, b->extra_sent, (size_t)b->nextra * sizeof(double)) != 0)
        return 0;
    sw_host_cmd now;
    return describe(ode, &now, b->wv) == 0 && same_system(&now, &b->opened);
}

static void box_release(sw_stepper *s)
{
    step_box *b = s->plugin;
    if (!b)
        return;
    sw_host_link *h = b->entry ? &b->entry->host : NULL;
    if (h && h->alive && b->generation == h->generation && (h->slots >> b->slot & 1)) {
        sw_host_cmd c;
        memset(&c, 0, sizeof c);
        c.op = SW_HOST_CLOSE;
        c.slot = b->slot;
        /* a host that cannot be told is gone, its slots with it: the next
         * command to it finds that and says so */
        (void)sw_sandbox_write(h->child.to_child, &c, sizeof c);
        h->slots &= ~(1ull << b->slot);
    }
    box_free(b);
    s->plugin = NULL;
}

/* A new stepper's box, or the failure that keeps it from stepping. */
static step_box *box_new(sw_stepper *s, const sw_ode *ode)
{
    step_box *b = calloc(1, sizeof *b);
    sw_host_cmd cmd;
    int can = describe(ode, &cmd, s->method->work_vectors) == 0;
    if (!b || box_alloc(b, ode->dim, can ? cmd.nextra : 0) != 0) {
        if (b)
            box_free(b);
        return NULL;
    }
    b->entry = sw_plugin_entry_for(s->method);
    b->wv = s->method->work_vectors;
    b->nextra = can ? cmd.nextra : 0;
    b->generation = -1;
    s->plugin = b;
    s->release = box_release;
    if (!b->entry) {
        box_fail(b, SW_PF_START, "is not loaded", NULL);
    } else if (b->entry->disabled || (b->entry->last_fault != SW_PF_NONE && b->entry->last_fault != SW_PF_CANCELLED &&
                                      b->entry->last_fault != SW_PF_START)) {
        /* Broken once, not run again in this process: a looping plugin
         * costs one watchdog, not one per run (stability, bench). */
        char why[SW_ERRLEN];
        snprintf(why, sizeof why, "is not run again: it %.200s in an earlier run", b->entry->last_failure);
        box_fail(b, SW_PF_DISABLED, why, NULL);
    } else if (!can) {
        box_fail(b, SW_PF_START, "can step only systems stepwise builds (a scene, or the truth module's "
                 "test system): this one cannot be built again in its sandbox", NULL);
    }
    return b;
}

int sw_plugin_step(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    step_box *b = s->plugin;
    if (!b && !(b = box_new(s, ode)))
        return SW_ENOMEM;
    if (b->fault == SW_PF_NONE && (!(b->used < b->have || b->pending) || !box_hit(b, ode, *t, y, h))) {
        /* a miss, or the run is used up: run again from here */
        int continues = b->used == b->have && b->have > 0 && !b->ended && !b->pending && box_hit(b, ode, *t, y, h);
        int keep = b->used < b->ran ? b->used : -1;
        b->batch = continues ? (b->batch * BATCH_GROWTH < b->batch_cap ? b->batch * BATCH_GROWTH : b->batch_cap) : 1;
        if (b->pending) {
            /* it died ahead of the caller, in a step never asked for: a new host */
            b->pending = 0;
            keep = -1;
        }
        sw_host_cmd cmd;
        if (box_host(b) == 0 && describe(ode, &cmd, b->wv) == 0) {
            /* a slot opened anew (another host, another system) has no run to go back into */
            if (b->generation != b->entry->host.generation || !same_system(&cmd, &b->opened))
                keep = -1;
            if (box_open(b, &cmd) == 0)
                box_run(b, ode, *t, y, h, keep);
        }
    }
    if (b->fault == SW_PF_NONE && b->used == b->have && b->pending)
        box_fault_now(b);
    if (b->fault != SW_PF_NONE) {
        s->why = b->message;
        return SW_EDIVERGED;
    }
    const sw_host_reply *r = &b->meta[b->used];
    memcpy(y, b->rows + (size_t)b->used * (size_t)b->dim, b->vec);
    b->used++;
    ode->evals += (long)r->evals;
    ode->solves += (long)r->solves;
    ode->solver_iters += (long)r->iters;
    if (r->rc != 0) {
        /* the plugin's own refusal, not a divergence: said as such, with
         * the step it refused (its return value is a number, any number) */
        snprintf(b->message, sizeof b->message, SW_PLUGIN_REFUSED " %d (not 0) for the step from t = %g with "
                 "h = %g", (int)r->rc, *t, h);
        s->why = b->message;
    }
    *t += h;
    b->t_next = *t;
    return r->rc == 0 ? SW_OK : SW_EDIVERGED;
}

sw_plugin_fault sw_plugin_box_fault(const sw_stepper *s, long step, char *buf, size_t len)
{
    const step_box *b = s->plugin;
    if (!b || b->fault == SW_PF_NONE)
        return SW_PF_NONE;
    if (b->fault == SW_PF_DISABLED)
        snprintf(buf, len, "the plugin %.230s", b->why);
    else
        snprintf(buf, len, "the plugin %.160s at step %ld%s%.90s", b->why, step, b->hint[0] ? " " : "", b->hint);
    return b->fault;
}

/* ---- replaying bytes (the fuzz target) ---------------------------------------- */

static void replay_deriv(void *ctx, double t, const double *y, double *dydt)
{
    (void)t;
    (void)y;
    memset(dydt, 0, (size_t)*(const int *)ctx * sizeof *dydt);
}

sw_plugin_fault sw_plugin_box_replay(const unsigned char *data, size_t len, int dim, int wv, char *why,
                                     size_t whylen)
{
    int sv[2];
    if (dim < 1 || dim > 4096 || wv < 0 || wv > 64 || socketpair(AF_UNIX, SOCK_STREAM, 0, sv) != 0) {
        snprintf(why, whylen, "cannot replay");
        return SW_PF_START;
    }
    /* the bytes as the host's, then its end of the socket shut for writing
     * (what the parent sends still goes in); the derivative the host's
     * must match is all zeros */
    size_t room = len < 65536 ? len : 65536;
    if (sw_sandbox_write(sv[1], data, room) != 0)
        room = 0;
    shutdown(sv[1], SHUT_WR);
    sw_plugin_entry e;
    memset(&e, 0, sizeof e);
    e.host.child.to_child = e.host.child.from_child = sv[0];
    e.host.child.status_fd = -1;
    e.host.alive = 1;
    e.work_vectors = wv;
    step_box b;
    memset(&b, 0, sizeof b);
    b.entry = &e;
    b.wv = wv;
    sw_plugin_fault f = SW_PF_START;
    if (box_alloc(&b, dim, 0) == 0) {
        b.batch = 4;
        b.careful = 1; /* no new host to run it again */
        double *y = calloc((size_t)dim, sizeof *y);
        sw_ode ode = { .dim = dim, .order = 1, .deriv = replay_deriv, .ctx = &dim };
        if (y) {
            box_run(&b, &ode, 0.0, y, 0.1, -1);
            if (b.fault == SW_PF_NONE && b.pending)
                box_fault_now(&b);
            if (b.fault == SW_PF_NONE && b.have == 0)
                box_fail(&b, SW_PF_FORGED, "sent no step", NULL);
            f = b.fault;
        }
        free(y);
    }
    snprintf(why, whylen, "%s", f == SW_PF_NONE ? "a run" : b.message[0] ? b.message : "cannot replay");
    sw_sandbox_kill(&e.host.child, NULL);
    close(sv[1]);
    free(b.rows);
    free(b.meta);
    free(b.sent);
    free(b.print);
    free(b.extra_sent);
    return f;
}
