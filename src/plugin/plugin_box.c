/* The sandboxed plugin step. Each stepper of a plugin method owns a child
 * process, forked at its first step (so the child holds the very system the
 * sim built), that loads the plugin and steps y in shared memory:
 *
 *     [control | guard | ...pad y | guard | ...pad work | guard]
 *
 * y and the work vectors end exactly at a guard (PROT_NONE), so writing one
 * element past them faults; the fault handler names the region from the
 * address. The pad before each vector holds a canary checked after every
 * step, and the ode's fields are compared with a copy. Invariant: the
 * parent's state changes only from a step the child finished cleanly. */
#include "plugin/plugin_box.h"

#include <dlfcn.h>
#include <errno.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <unistd.h>

#include "plugin/sandbox.h"

#define GUARD_PAGES 16
/* Each side spins this long on the shared counters before it sleeps on the
 * socket: when both processes have a core, a step costs no system call. */
#define SPIN_SECONDS 30e-6
#define CANARY 0xa5
#define CANARY_BYTES 64

/* Shared between the parent and the child. A step: the parent fills t, h
 * and y, bumps cmd; the child steps and sets done = cmd. A side that waits
 * spins briefly, then sets its *_waiting flag and sleeps on the socket;
 * the other side sends a byte when it sees that flag (checked after its
 * own store, so no wake-up is lost; a spare byte is only a spurious wake). */
typedef struct box_control {
    atomic_int cmd, done;
    atomic_int parent_waiting, child_waiting;
    int quit;
    double t, h;
    int rc;                  /* the plugin's return value */
    long evals, solves, iters; /* the child's ode counters after the step */
    volatile sig_atomic_t fault;   /* SW_PF_*, set by the child */
    long index;              /* the element touched, relative to the vector */
    int field;               /* SW_PF_ODE: which field */
    long was, now;           /* SW_PF_ODE: its value before and after */
    char detail[200];        /* SW_PF_START: what failed */
} box_control;

typedef struct step_box {
    sw_plugin_entry *entry;
    sw_child child;
    sw_ode *ode;             /* the parent's; the child has a copy at the same address */
    int dim, wv;
    unsigned char *map;
    size_t map_len, page, guard;
    box_control *ctl;
    double *y, *work;
    unsigned char *y_area, *work_area;  /* start of each vector's pages */
    size_t y_area_len, work_area_len;
    sw_plugin_fault fault;   /* parent's view: set once, then every step fails */
    char why[SW_ERRLEN];     /* what happened ... */
    char hint[96];           /* ... and, after the step, what to do */
    char message[SW_ERRLEN + 128]; /* both, for the stepper's why (the sim's blow-up reason) */
    long evals, solves, iters;
} step_box;

/* ---- the child -------------------------------------------------------------- */

static step_box *child_box;
static sw_ode child_ode_copy;
static const char *const ode_fields[] = { "dim", "order", "deriv", "solve", "deriv_part", "ctx", "fused_euler",
                                          "fused_rk4" };
enum { ODE_FIELDS = sizeof ode_fields / sizeof ode_fields[0] };

/* The ode's fields in ode_fields' order, as numbers to compare. */
static void ode_values(const sw_ode *o, long v[ODE_FIELDS])
{
    long f[ODE_FIELDS] = { o->dim, o->order, (long)(uintptr_t)o->deriv, (long)(uintptr_t)o->solve,
                           (long)(uintptr_t)o->deriv_part, (long)(uintptr_t)o->ctx,
                           (long)(uintptr_t)o->fused_euler, (long)(uintptr_t)o->fused_rk4 };
    memcpy(v, f, sizeof f);
}

/* Which ode field differs from the copy taken before the step; -1 none. */
static int ode_changed(const sw_ode *o, long *was, long *now)
{
    long a[ODE_FIELDS], b[ODE_FIELDS];
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

static void on_fault(int sig, siginfo_t *si, void *uctx)
{
    (void)sig;
    (void)uctx;
    step_box *b = child_box;
    box_control *ctl = b->ctl;
    uintptr_t a = (uintptr_t)si->si_addr;
    uintptr_t y0 = (uintptr_t)b->y, y_end = (uintptr_t)(b->y_area + b->y_area_len);
    uintptr_t w0 = (uintptr_t)b->work, w_end = (uintptr_t)(b->work_area + b->work_area_len);
    int field = ode_changed(b->ode, &ctl->was, &ctl->now);
    if (field >= 0) {
        ctl->field = field;
        ctl->fault = SW_PF_ODE;
    } else if (a >= y_end && a < y_end + b->guard / 2) {
        ctl->fault = SW_PF_OVERRUN_Y;
        ctl->index = (long)((a - y0) / sizeof(double));
    } else if (a >= w_end && a < w_end + b->guard) {
        ctl->fault = SW_PF_OVERRUN_WORK;
        ctl->index = (long)((a - w0) / sizeof(double));
    } else if (a >= y_end && a < (uintptr_t)b->work_area) {
        ctl->fault = SW_PF_UNDERRUN;
        ctl->index = -(long)((w0 - a + sizeof(double) - 1) / sizeof(double));
        ctl->field = 1;
    } else if (a < (uintptr_t)b->y_area && a + b->guard >= (uintptr_t)b->y_area) {
        ctl->fault = SW_PF_UNDERRUN;
        ctl->index = -(long)((y0 - a + sizeof(double) - 1) / sizeof(double));
        ctl->field = 0;
    }
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

/* Wait until *seq differs from old: spin, then sleep on fd (woken by a
 * byte) for at most `seconds` (< 0: no limit). The new value, or -1 the
 * other side is gone, -2 timed out, -3 cancelled. */
static int await_change(atomic_int *seq, int old, atomic_int *waiting, int fd, double seconds)
{
    double start = sw_sandbox_now();
    for (unsigned i = 0;; i++) {
        int v = atomic_load(seq);
        if (v != old)
            return v;
        if ((i & 63) == 63 && sw_sandbox_now() - start > SPIN_SECONDS)
            break;
    }
    for (;;) {
        atomic_store(waiting, 1);
        int v = atomic_load(seq);
        if (v != old) {
            atomic_store(waiting, 0);
            return v;
        }
        double left = seconds < 0 ? -1 : seconds - (sw_sandbox_now() - start);
        int w = seconds >= 0 && left <= 0 ? 0 : sw_sandbox_wait(fd, left);
        if (w <= 0) {
            atomic_store(waiting, 0);
            v = atomic_load(seq);
            return v != old ? v : w == 0 ? -2 : -3;
        }
        char drain[64];
        ssize_t n = recv(fd, drain, sizeof drain, MSG_DONTWAIT);
        atomic_store(waiting, 0);
        if (n == 0 || (n < 0 && errno != EAGAIN && errno != EINTR)) {
            v = atomic_load(seq);
            return v != old ? v : -1;
        }
    }
}

/* Publish a new value of *seq and wake the other side if it sleeps. */
static void publish(atomic_int *seq, int value, atomic_int *other_waiting, int fd)
{
    atomic_store(seq, value);
    if (atomic_load(other_waiting))
        sw_sandbox_write(fd, "w", 1);
}

static int step_child(void *ctx, int in, int out)
{
    step_box *b = ctx;
    box_control *ctl = b->ctl;
    child_box = b;
    void *lib = dlopen(b->entry->path, RTLD_NOW | RTLD_LOCAL);
    const sw_plugin *(*get)(void) = NULL;
    if (lib)
        *(void **)&get = dlsym(lib, "sw_plugin_info");
    const sw_plugin *info = get ? get() : NULL;
    if (!info || !info->step || info->work_vectors != b->wv || !info->name ||
        strcmp(info->name, b->entry->name) != 0) {
        snprintf(ctl->detail, sizeof ctl->detail, "%s", !lib ? "could not be loaded again"
                 : "changed since it was loaded (rebuilt?): load it again");
        ctl->fault = SW_PF_START;
        return 3;
    }
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
    char cmd = 'R';
    if (sw_sandbox_write(out, &cmd, 1) != 0)
        return 0;
    int last = 0;
    for (;;) {
        int seq = await_change(&ctl->cmd, last, &ctl->child_waiting, in, -1);
        if (seq < 0 || ctl->quit)
            return 0;
        last = seq;
        child_ode_copy = *ode;
        ctl->rc = info->step(ode, ctl->t, b->y, ctl->h, b->work);
        int field = ode_changed(ode, &ctl->was, &ctl->now);
        if (field >= 0) {
            ctl->field = field;
            ctl->fault = SW_PF_ODE;
        } else if (!canary_ok(b->y) || !canary_ok(b->work)) {
            ctl->fault = SW_PF_UNDERRUN;
            ctl->field = canary_ok(b->y);
            ctl->index = -1;
        }
        ctl->evals = ode->evals;
        ctl->solves = ode->solves;
        ctl->iters = ode->solver_iters;
        publish(&ctl->done, seq, &ctl->parent_waiting, out);
        if (ctl->fault)
            return 0;
    }
}

/* ---- the parent ------------------------------------------------------------- */

static size_t round_up(size_t n, size_t page) { return (n + page - 1) / page * page; }

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
        b->ctl->quit = 1;
        publish(&b->ctl->cmd, atomic_load(&b->ctl->cmd) + 1, &b->ctl->child_waiting,
                b->child.to_child);
        sw_child_end end;
        sw_sandbox_reap(&b->child, 0.2, &end);
    }
    if (b->map)
        munmap(b->map, b->map_len);
    free(b);
    s->plugin = NULL;
}

/* Describe how the child ended, from its control block and wait status. */
static void box_dead(step_box *b, const sw_child_end *end)
{
    box_control *ctl = b->ctl;
    char why[SW_ERRLEN], how[120];
    sw_sandbox_describe(end, how, sizeof how);
    switch (ctl->fault) {
    case SW_PF_OVERRUN_WORK:
        snprintf(why, sizeof why, "wrote past its %d work vector%s (work[%ld], %d doubles each)",
                 b->wv, b->wv == 1 ? "" : "s", ctl->index, b->dim);
        box_fail(b, SW_PF_OVERRUN_WORK, why, NULL);
        return;
    case SW_PF_OVERRUN_Y:
        snprintf(why, sizeof why, "wrote past the end of y (y[%ld]; y has ode->dim = %d doubles)",
                 ctl->index, b->dim);
        box_fail(b, SW_PF_OVERRUN_Y, why, NULL);
        return;
    case SW_PF_UNDERRUN:
        snprintf(why, sizeof why, "wrote before the start of %s", ctl->field ? "its work vectors" : "y");
        box_fail(b, SW_PF_UNDERRUN, why, NULL);
        return;
    case SW_PF_ODE:
        if (ctl->field <= 1)
            snprintf(why, sizeof why, "changed ode->%s from %ld to %ld", ode_fields[ctl->field],
                     ctl->was, ctl->now);
        else
            snprintf(why, sizeof why, "changed ode->%s", ode_fields[ctl->field]);
        box_fail(b, SW_PF_ODE, why, "(a plugin must not write to the ode)");
        return;
    case SW_PF_START:
        snprintf(why, sizeof why, "%s", ctl->detail);
        box_fail(b, SW_PF_START, why, NULL);
        return;
    default:
        break;
    }
    if (end->exited) {
        snprintf(why, sizeof why, "ended its process with exit(%d) in its step", end->code);
        box_fail(b, SW_PF_EXIT, why, "(a step must return, never exit)");
    } else {
        box_fail(b, SW_PF_CRASH, how, NULL);
    }
}

/* Map the shared block, fork the child and wait for it to be ready. */
static void box_start(step_box *b)
{
    size_t page = (size_t)sysconf(_SC_PAGESIZE);
    b->page = page;
    b->guard = GUARD_PAGES * page;
    size_t ctl_len = round_up(sizeof(box_control), page);
    size_t vec = (size_t)b->dim * sizeof(double);
    b->y_area_len = round_up(vec + CANARY_BYTES, page);
    b->work_area_len = round_up((size_t)b->wv * vec + CANARY_BYTES, page);
    b->map_len = ctl_len + b->guard + b->y_area_len + b->guard + b->work_area_len + b->guard;
    void *map = mmap(NULL, b->map_len, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (map == MAP_FAILED) {
        b->map = NULL;
        box_fail(b, SW_PF_START, "could not be given its shared memory", NULL);
        return;
    }
    b->map = map;
    b->ctl = map;
    b->y_area = b->map + ctl_len + b->guard;
    b->work_area = b->y_area + b->y_area_len + b->guard;
    mprotect(b->map + ctl_len, b->guard, PROT_NONE);
    mprotect(b->y_area + b->y_area_len, b->guard, PROT_NONE);
    mprotect(b->work_area + b->work_area_len, b->guard, PROT_NONE);
    memset(b->y_area, CANARY, b->y_area_len);
    memset(b->work_area, CANARY, b->work_area_len);
    b->y = (double *)(b->y_area + b->y_area_len - vec);
    b->work = (double *)(b->work_area + b->work_area_len - (size_t)b->wv * vec);
    memset(b->work, 0, (size_t)b->wv * vec);
    char err[SW_ERRLEN];
    if (sw_sandbox_spawn(&b->child, step_child, b, NULL, -1, err, sizeof err) != SW_OK) {
        box_fail(b, SW_PF_START, "could not be given a child process", NULL);
        return;
    }
    char tag;
    int rc = sw_sandbox_read(b->child.from_child, &tag, 1, sw_plugin_timeout());
    if (rc == 1 && tag == 'R')
        return;
    sw_child_end end;
    if (rc == -2 || rc == -1) {
        sw_sandbox_kill(&b->child, &end);
        if (rc == -1)
            box_fail(b, SW_PF_CANCELLED, "was interrupted while loading", NULL);
        else {
            snprintf(err, sizeof err, "did not finish loading within %g s", sw_plugin_timeout());
            box_fail(b, SW_PF_TIMEOUT, err, "(an endless loop in sw_plugin_info()?)");
        }
        return;
    }
    sw_sandbox_reap(&b->child, 1.0, &end);
    box_dead(b, &end);
}

int sw_plugin_step(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    step_box *b = s->plugin;
    if (!b) {
        b = calloc(1, sizeof *b);
        if (!b)
            return SW_ENOMEM;
        b->entry = sw_plugin_entry_for(s->method);
        b->ode = ode;
        b->dim = ode->dim;
        b->wv = s->method->work_vectors;
        s->plugin = b;
        s->release = box_release;
        if (!b->entry)
            box_fail(b, SW_PF_START, "is not loaded", NULL);
        else if (b->entry->disabled || b->entry->last_fault == SW_PF_EXIT ||
                 b->entry->last_fault == SW_PF_CRASH || b->entry->last_fault == SW_PF_TIMEOUT ||
                 b->entry->last_fault == SW_PF_OVERRUN_WORK || b->entry->last_fault == SW_PF_OVERRUN_Y ||
                 b->entry->last_fault == SW_PF_UNDERRUN || b->entry->last_fault == SW_PF_ODE) {
            /* Broken once, not run again in this process: a looping plugin
             * costs one watchdog, not one per run (stability, bench). */
            char why[SW_ERRLEN];
            snprintf(why, sizeof why, "is not run again: it %.200s in an earlier run",
                     b->entry->last_failure);
            box_fail(b, SW_PF_DISABLED, why, NULL);
        }
        else {
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
    memcpy(b->y, y, (size_t)b->dim * sizeof *y);
    box_control *ctl = b->ctl;
    ctl->t = *t;
    ctl->h = h;
    int seq = atomic_load(&ctl->cmd) + 1;
    publish(&ctl->cmd, seq, &ctl->child_waiting, b->child.to_child);
    double limit = sw_plugin_timeout();
    int got = await_change(&ctl->done, seq - 1, &ctl->parent_waiting, b->child.from_child, limit);
    int rc = got == seq && !ctl->fault ? 1 : got == -2 ? -2 : got == -3 ? -1 : 0;
    sw_child_end end;
    if (rc == 1) {
        memcpy(y, b->y, (size_t)b->dim * sizeof *y);
        ode->evals += b->ctl->evals - b->evals;
        ode->solves += b->ctl->solves - b->solves;
        ode->solver_iters += b->ctl->iters - b->iters;
        b->evals = b->ctl->evals;
        b->solves = b->ctl->solves;
        b->iters = b->ctl->iters;
        *t += h;
        if (b->ctl->rc != 0)
            s->why = "the plugin's step function returned an error";
        return b->ctl->rc == 0 ? SW_OK : SW_EDIVERGED;
    }
    if (rc == -2 || rc == -1) {
        sw_sandbox_kill(&b->child, &end);
        char why[SW_ERRLEN];
        snprintf(why, sizeof why, "did not return from its step within %g s", limit);
        if (rc == -1)
            box_fail(b, SW_PF_CANCELLED, "was interrupted in its step", NULL);
        else
            box_fail(b, SW_PF_TIMEOUT, why, "(an endless loop?)");
        s->why = b->message;
        return SW_EDIVERGED;
    }
    sw_sandbox_reap(&b->child, 1.0, &end);
    box_dead(b, &end);
    s->why = b->message;
    return SW_EDIVERGED;
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
