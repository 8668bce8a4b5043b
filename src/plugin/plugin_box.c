/* The sandboxed plugin step. Each stepper of a plugin method owns a jailed
 * child (plugin/sandbox.h), forked at its first step so that it holds the
 * very system the sim built, that loads the plugin and steps copies of y
 * it is sent over a socket: nothing writable is shared. In the child, y and
 * the work vectors end exactly at a guard page (PROT_NONE), so writing one
 * element past them faults, and the fault handler names the region; the
 * pad before each holds a canary checked after every step, and the ode's
 * fields are compared with a copy. Invariant: the parent reads only
 * fixed-size records and dim doubles, validates every field before using
 * it, and changes its state only from a step the child finished cleanly. */
#include "plugin/plugin_box.h"

#include <dlfcn.h>
#include <errno.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <sys/uio.h>
#include <unistd.h>

#include "plugin/sandbox.h"

#define GUARD_PAGES 16
#define CANARY 0xa5
#define CANARY_BYTES 64
/* The most derivative evaluations (and solves) one step may report. */
#define MAX_COUNT_PER_STEP 1000000000LL

enum { OP_STEP = 1, OP_QUIT = 2 };
enum { TAG_READY = 'R', TAG_DONE = 'D', TAG_FAULT = 'F', TAG_START = 'E' };
enum { START_RELOAD = 1, START_CHANGED = 2 };

/* Parent to child: a command, then dim doubles of y for OP_STEP. */
typedef struct box_cmd {
    int32_t op, pad;
    double t, h;
} box_cmd;

/* Child to parent: a reply, then dim doubles of y for TAG_DONE. */
typedef struct box_reply {
    int32_t tag;
    int32_t rc;          /* TAG_DONE: the plugin's return value; TAG_START: START_* */
    int32_t fault;       /* TAG_FAULT: SW_PF_OVERRUN_WORK, _OVERRUN_Y, _UNDERRUN or _ODE */
    int32_t field;       /* SW_PF_ODE: which field; SW_PF_UNDERRUN: 0 y, 1 work */
    int64_t index;       /* the element touched, relative to the vector */
    int64_t was, now;    /* SW_PF_ODE: the field's value before and after */
    int64_t evals, solves, iters; /* the child's ode counters after the step */
} box_reply;

typedef struct step_box {
    sw_plugin_entry *entry;
    sw_child child;
    sw_ode *ode;             /* the parent's; the child has a copy at the same address */
    int dim, wv;
    size_t vec;              /* dim doubles, in bytes */
    double *buf;             /* the parent's landing place for y (dim doubles) */
    sw_plugin_fault fault;   /* parent's view: set once, then every step fails */
    char why[SW_ERRLEN];     /* what happened ... */
    char hint[96];           /* ... and, after the step, what to do */
    char message[SW_ERRLEN + 128]; /* both, for the stepper's why (the sim's blow-up reason) */
    long evals, solves, iters;
    box_reply last_fault;    /* a TAG_FAULT the child sent before it died */
    int have_fault;
} step_box;

static const char *const ode_fields[] = { "dim", "order", "deriv", "solve", "ctx", "prepare", "fast" };
enum { ODE_FIELDS = sizeof ode_fields / sizeof ode_fields[0] };

/* ---- the child -------------------------------------------------------------- */

/* The child's own memory: y and the work vectors each end at a guard. */
typedef struct child_mem {
    unsigned char *y_area, *work_area;
    size_t y_area_len, work_area_len, guard;
    double *y, *work;
    int fd;                  /* the channel */
} child_mem;

static child_mem mem;
static sw_ode *child_ode;
static sw_ode child_ode_copy;

/* The ode's fields in ode_fields' order, as numbers to compare. */
static void ode_values(const sw_ode *o, int64_t v[ODE_FIELDS])
{
    int64_t f[ODE_FIELDS] = { o->dim, o->order, (int64_t)(uintptr_t)o->deriv, (int64_t)(uintptr_t)o->solve,
                              (int64_t)(uintptr_t)o->ctx, (int64_t)(uintptr_t)o->prepare,
                              (int64_t)(uintptr_t)o->fast };
    memcpy(v, f, sizeof f);
}

/* Which ode field differs from the copy taken before the step; -1 none. */
static int ode_changed(const sw_ode *o, int64_t *was, int64_t *now)
{
    int64_t a[ODE_FIELDS], b[ODE_FIELDS];
    ode_values(&child_ode_copy, a);
    ode_values(o, b);
    for (int i = 0; i < ODE_FIELDS; i++)
        if (a[i] != b[i]) {
            *was = a[i];
            *now = b[i];
            return i;
        }
    return -1;
}

static void send_reply(const box_reply *r)
{
    if (write(mem.fd, r, sizeof *r) != (ssize_t)sizeof *r)
        return; /* the parent is gone: nothing to tell */
}

static void on_fault(int sig, siginfo_t *si, void *uctx)
{
    (void)sig;
    (void)uctx;
    box_reply r;
    memset(&r, 0, sizeof r);
    r.tag = TAG_FAULT;
    uintptr_t a = (uintptr_t)si->si_addr;
    uintptr_t y0 = (uintptr_t)mem.y, y_end = (uintptr_t)(mem.y_area + mem.y_area_len);
    uintptr_t w0 = (uintptr_t)mem.work, w_end = (uintptr_t)(mem.work_area + mem.work_area_len);
    int field = ode_changed(child_ode, &r.was, &r.now);
    if (field >= 0) {
        r.field = field;
        r.fault = SW_PF_ODE;
    } else if (a >= y_end && a < y_end + mem.guard / 2) {
        r.fault = SW_PF_OVERRUN_Y;
        r.index = (int64_t)((a - y0) / sizeof(double));
    } else if (a >= w_end && a < w_end + mem.guard) {
        r.fault = SW_PF_OVERRUN_WORK;
        r.index = (int64_t)((a - w0) / sizeof(double));
    } else if (a >= y_end && a < (uintptr_t)mem.work_area) {
        r.fault = SW_PF_UNDERRUN;
        r.field = 1;
    } else if (a < (uintptr_t)mem.y_area && a + mem.guard >= (uintptr_t)mem.y_area) {
        r.fault = SW_PF_UNDERRUN;
    }
    if (r.fault)
        send_reply(&r);
    /* SA_RESETHAND: returning re-runs the access, which now kills the child
     * with the signal, as the parent expects. */
}

static int canary_ok(const double *v)
{
    const unsigned char *p = (const unsigned char *)v - CANARY_BYTES;
    for (int i = 0; i < CANARY_BYTES; i++)
        if (p[i] != CANARY)
            return 0;
    return 1;
}

static size_t round_up(size_t n, size_t page) { return (n + page - 1) / page * page; }

/* [guard | ...pad y | guard | ...pad work | guard], private to the child. */
static int child_map(int dim, int wv)
{
    size_t page = (size_t)sysconf(_SC_PAGESIZE), vec = (size_t)dim * sizeof(double);
    mem.guard = GUARD_PAGES * page;
    mem.y_area_len = round_up(vec + CANARY_BYTES, page);
    mem.work_area_len = round_up((size_t)wv * vec + CANARY_BYTES, page);
    size_t len = mem.guard + mem.y_area_len + mem.guard + mem.work_area_len + mem.guard;
    unsigned char *map = mmap(NULL, len, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (map == MAP_FAILED)
        return -1;
    mem.y_area = map + mem.guard;
    mem.work_area = mem.y_area + mem.y_area_len + mem.guard;
    mprotect(map, mem.guard, PROT_NONE);
    mprotect(mem.y_area + mem.y_area_len, mem.guard, PROT_NONE);
    mprotect(mem.work_area + mem.work_area_len, mem.guard, PROT_NONE);
    memset(mem.y_area, CANARY, mem.y_area_len);
    memset(mem.work_area, CANARY, mem.work_area_len);
    mem.y = (double *)(mem.y_area + mem.y_area_len - vec);
    mem.work = (double *)(mem.work_area + mem.work_area_len - (size_t)wv * vec);
    memset(mem.work, 0, (size_t)wv * vec);
    return 0;
}

static int start_failed(int why)
{
    box_reply r;
    memset(&r, 0, sizeof r);
    r.tag = TAG_START;
    r.rc = why;
    send_reply(&r);
    return 3;
}

static int step_child(void *ctx, int in, int out)
{
    step_box *b = ctx;
    (void)in;
    mem.fd = out;
    child_ode = b->ode;
    if (child_map(b->dim, b->wv) != 0)
        return start_failed(START_RELOAD);
    void *lib = dlopen(sw_plugin_entry_file(b->entry), RTLD_NOW | RTLD_LOCAL);
    const sw_plugin *(*get)(void) = NULL;
    if (lib)
        *(void **)&get = dlsym(lib, "sw_plugin_info");
    if (sw_jail_seal() != 0)
        return start_failed(START_RELOAD);
    const sw_plugin *info = get ? get() : NULL;
    if (!info || !info->step || info->work_vectors != b->wv || !info->name ||
        strncmp(info->name, b->entry->name, sizeof b->entry->name) != 0)
        return start_failed(lib ? START_CHANGED : START_RELOAD);
    static char alt[65536];
    stack_t ss = { .ss_sp = alt, .ss_size = sizeof alt, .ss_flags = 0 };
    sigaltstack(&ss, NULL);
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_sigaction = on_fault;
    sa.sa_flags = SA_SIGINFO | SA_ONSTACK | SA_RESETHAND;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGSEGV, &sa, NULL);
    sigaction(SIGBUS, &sa, NULL);
    sw_ode *ode = b->ode;
    box_reply r;
    memset(&r, 0, sizeof r);
    r.tag = TAG_READY;
    send_reply(&r);
    for (;;) {
        box_cmd cmd;
        if (sw_sandbox_read(in, &cmd, sizeof cmd, -1) != 1 || cmd.op != OP_STEP ||
            sw_sandbox_read(in, mem.y, b->vec, -1) != 1)
            return 0;
        child_ode_copy = *ode;
        memset(&r, 0, sizeof r);
        r.rc = info->step(ode, cmd.t, mem.y, cmd.h, mem.work);
        int field = ode_changed(ode, &r.was, &r.now);
        if (field >= 0) {
            r.field = field;
            r.fault = SW_PF_ODE;
        } else if (!canary_ok(mem.y) || !canary_ok(mem.work)) {
            r.fault = SW_PF_UNDERRUN;
            r.field = canary_ok(mem.y);
        }
        r.tag = r.fault ? TAG_FAULT : TAG_DONE;
        r.evals = ode->evals;
        r.solves = ode->solves;
        r.iters = ode->solver_iters;
        if (r.fault) {
            send_reply(&r);
            return 0;
        }
        struct iovec parts[2] = { { &r, sizeof r }, { mem.y, b->vec } };
        if (sw_sandbox_writev(out, parts, 2) != 0)
            return 0;
    }
}

/* ---- the parent ------------------------------------------------------------- */

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

static void box_release(sw_stepper *s)
{
    step_box *b = s->plugin;
    if (!b)
        return;
    if (b->child.pid > 0) {
        box_cmd quit = { OP_QUIT, 0, 0, 0 };
        sw_sandbox_write(b->child.to_child, &quit, sizeof quit);
        sw_child_end end;
        sw_sandbox_reap(&b->child, 0.2, &end);
    }
    free(b->buf);
    free(b);
    s->plugin = NULL;
}

/* Whether a fault record from the child is one it could have sent. */
static int fault_valid(const step_box *b, const box_reply *r)
{
    switch (r->fault) {
    case SW_PF_OVERRUN_WORK:
        return r->index >= 0 && r->index < (int64_t)b->wv * b->dim + (1 << 20);
    case SW_PF_OVERRUN_Y:
        return r->index >= 0 && r->index < (int64_t)b->dim + (1 << 20);
    case SW_PF_UNDERRUN:
        return r->field == 0 || r->field == 1;
    case SW_PF_ODE:
        return r->field >= 0 && r->field < ODE_FIELDS;
    default:
        return 0;
    }
}

/* Describe how the child ended, from its last fault record and wait status. */
static void box_dead(step_box *b, const sw_child_end *end)
{
    const box_reply *r = b->have_fault ? &b->last_fault : NULL;
    char why[SW_ERRLEN], how[120];
    sw_sandbox_describe(end, how, sizeof how);
    switch (r ? r->fault : SW_PF_NONE) {
    case SW_PF_OVERRUN_WORK:
        snprintf(why, sizeof why, "wrote past its %d work vector%s (work[%lld], %d doubles each)",
                 b->wv, b->wv == 1 ? "" : "s", (long long)r->index, b->dim);
        box_fail(b, SW_PF_OVERRUN_WORK, why, NULL);
        return;
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
    default:
        break;
    }
    if (end->exited) {
        snprintf(why, sizeof why, "ended its process with exit(%d) in its step", end->code);
        box_fail(b, SW_PF_EXIT, why, "(a step must return, never exit)");
    } else if (end->signal == SIGXCPU) {
        box_fail(b, SW_PF_LIMIT, how, "(the grader's CPU-time limit: a correct but slow plugin "
                 "ends here too)");
    } else {
        box_fail(b, SW_PF_CRASH, how, NULL);
    }
}

/* A reply that breaks the protocol: the child is stopped, the plugin fails. */
static void box_forged(step_box *b, const char *what)
{
    sw_child_end end;
    sw_sandbox_kill(&b->child, &end);
    char why[SW_ERRLEN];
    snprintf(why, sizeof why, "sent the sandbox a reply it could not have sent (%s)", what);
    box_fail(b, SW_PF_FORGED, why, "(a plugin may only compute)");
}

/* Read one reply within the watchdog: 1, or how the wait ended (as
 * sw_sandbox_read: 0 gone, -1 cancelled, -2 timed out, -3 error). */
static int box_reply_read(step_box *b, box_reply *r)
{
    int rc = sw_sandbox_read(b->child.from_child, r, sizeof *r, sw_plugin_timeout());
    if (rc == 1 && r->tag == TAG_FAULT) {
        if (!fault_valid(b, r)) {
            box_forged(b, "a fault record out of range");
            return -4;
        }
        b->last_fault = *r;
        b->have_fault = 1;
        return 0; /* the child dies next */
    }
    return rc;
}

/* The child ended or the wait did: say which, as a fault (loading: in
 * dlopen or sw_plugin_info(), else in a step). */
static void box_lost(step_box *b, int rc, int loading)
{
    sw_child_end end;
    char why[SW_ERRLEN];
    if (rc == -4)
        return; /* forged: said already */
    if (rc == -2 || rc == -1) {
        sw_sandbox_kill(&b->child, &end);
        if (rc == -1) {
            box_fail(b, SW_PF_CANCELLED, loading ? "was interrupted while loading"
                                                 : "was interrupted in its step", NULL);
        } else {
            snprintf(why, sizeof why, "did not %s within %g s", loading ? "finish loading"
                     : "return from its step", sw_plugin_timeout());
            box_fail(b, SW_PF_TIMEOUT, why, loading ? "(an endless loop in sw_plugin_info()?)"
                                                    : "(an endless loop?)");
        }
        return;
    }
    sw_sandbox_reap(&b->child, 1.0, &end);
    box_dead(b, &end);
}

/* Start the jailed child and wait for it to be ready. */
static void box_start(step_box *b)
{
    char err[SW_ERRLEN];
    sw_jail spec = { .profile = SW_JAIL_COMPUTE, .include_fd = -1 };
    sw_plugin_entry_jail_in(b->entry, &spec);
    sw_limits lim;
    sw_plugin_limits(&lim);
    if (sw_sandbox_spawn_jailed(&b->child, step_child, b, &lim, -1, &spec, err, sizeof err) != SW_OK) {
        box_fail(b, SW_PF_START, err, NULL);
        return;
    }
    box_reply r;
    int rc = box_reply_read(b, &r);
    if (rc == 1 && r.tag == TAG_READY)
        return;
    if (rc == 1 && r.tag == TAG_START && (r.rc == START_RELOAD || r.rc == START_CHANGED)) {
        sw_child_end end;
        sw_sandbox_reap(&b->child, 1.0, &end);
        box_fail(b, SW_PF_START, r.rc == START_RELOAD ? "could not be loaded again"
                 : "changed since it was loaded (rebuilt?): load it again", NULL);
        return;
    }
    if (rc == 1) {
        box_forged(b, "not the ready signal");
        return;
    }
    box_lost(b, rc, 1);
}

/* A step's result: the reply, checked, then y into b->buf. 1, or as
 * box_reply_read (-4: forged, said already). */
static int box_receive(step_box *b, box_reply *r)
{
    int rc = box_reply_read(b, r);
    if (rc == 1 && r->tag != TAG_DONE) {
        box_forged(b, "not a step's result");
        return -4;
    }
    if (rc == 1 && (r->evals < b->evals || r->evals - b->evals > MAX_COUNT_PER_STEP ||
                    r->solves < b->solves || r->solves - b->solves > MAX_COUNT_PER_STEP ||
                    r->iters < b->iters || r->iters - b->iters > MAX_COUNT_PER_STEP)) {
        box_forged(b, "evaluation counts that run backwards or beyond a billion a step");
        return -4;
    }
    if (rc == 1)
        rc = sw_sandbox_read(b->child.from_child, b->buf, b->vec, sw_plugin_timeout());
    return rc;
}

sw_plugin_fault sw_plugin_box_replay(const unsigned char *data, size_t len, int dim, int wv, char *why,
                                     size_t whylen)
{
    step_box b;
    memset(&b, 0, sizeof b);
    b.dim = dim;
    b.wv = wv;
    b.vec = (size_t)dim * sizeof(double);
    b.child.to_child = b.child.from_child = b.child.status_fd = -1;
    int sv[2];
    if (dim < 1 || dim > 4096 || wv < 0 || wv > 64 || socketpair(AF_UNIX, SOCK_STREAM, 0, sv) != 0 ||
        !(b.buf = malloc(b.vec))) {
        snprintf(why, whylen, "cannot replay");
        return SW_PF_START;
    }
    /* the bytes as the child's, then its end of the socket closed */
    size_t room = len < 65536 ? len : 65536;
    if (sw_sandbox_write(sv[1], data, room) != 0)
        room = 0;
    close(sv[1]);
    b.child.from_child = b.child.to_child = sv[0];
    box_reply r;
    int rc = box_receive(&b, &r);
    if (rc != 1)
        box_lost(&b, rc, 0);
    else
        sw_sandbox_kill(&b.child, NULL);
    free(b.buf);
    snprintf(why, whylen, "%s", b.fault == SW_PF_NONE ? "a step" : b.message);
    return b.fault;
}

int sw_plugin_step(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    step_box *b = s->plugin;
    if (!b) {
        b = calloc(1, sizeof *b);
        if (!b || !(b->buf = malloc((size_t)ode->dim * sizeof(double) + 1))) {
            free(b);
            return SW_ENOMEM;
        }
        b->entry = sw_plugin_entry_for(s->method);
        b->ode = ode;
        b->dim = ode->dim;
        b->vec = (size_t)ode->dim * sizeof(double);
        b->wv = s->method->work_vectors;
        s->plugin = b;
        s->release = box_release;
        if (!b->entry)
            box_fail(b, SW_PF_START, "is not loaded", NULL);
        else if (b->entry->disabled || (b->entry->last_fault != SW_PF_NONE &&
                                        b->entry->last_fault != SW_PF_CANCELLED &&
                                        b->entry->last_fault != SW_PF_START)) {
            /* Broken once, not run again in this process: a looping plugin
             * costs one watchdog, not one per run (stability, bench). */
            char why[SW_ERRLEN];
            snprintf(why, sizeof why, "is not run again: it %.200s in an earlier run",
                     b->entry->last_failure);
            box_fail(b, SW_PF_DISABLED, why, NULL);
        } else {
            b->evals = ode->evals; /* the child's counters start from the parent's at fork */
            b->solves = ode->solves;
            b->iters = ode->solver_iters;
            box_start(b);
        }
    }
    if (b->fault != SW_PF_NONE) {
        s->why = b->message;
        return SW_EDIVERGED;
    }
    box_cmd cmd = { OP_STEP, 0, *t, h };
    box_reply r;
    struct iovec parts[2] = { { &cmd, sizeof cmd }, { y, b->vec } };
    int rc = sw_sandbox_writev(b->child.to_child, parts, 2) == 0 ? box_receive(b, &r) : 0;
    if (rc != 1) {
        box_lost(b, rc, 0);
        s->why = b->message;
        return SW_EDIVERGED;
    }
    memcpy(y, b->buf, b->vec);
    ode->evals += (long)(r.evals - b->evals);
    ode->solves += (long)(r.solves - b->solves);
    ode->solver_iters += (long)(r.iters - b->iters);
    b->evals = (long)r.evals;
    b->solves = (long)r.solves;
    b->iters = (long)r.iters;
    *t += h;
    if (r.rc != 0)
        s->why = "the plugin's step function returned an error";
    return r.rc == 0 ? SW_OK : SW_EDIVERGED;
}

sw_plugin_fault sw_plugin_box_fault(const sw_stepper *s, long step, char *buf, size_t len)
{
    const step_box *b = s->plugin;
    if (!b || b->fault == SW_PF_NONE)
        return SW_PF_NONE;
    if (b->fault == SW_PF_DISABLED)
        snprintf(buf, len, "the plugin %.230s", b->why);
    else
        snprintf(buf, len, "the plugin %.160s at step %ld%s%.90s", b->why, step,
                 b->hint[0] ? " " : "", b->hint);
    return b->fault;
}
