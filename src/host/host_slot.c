/* The systems a plugin's host keeps built and the runs it steps on them.
 * Each slot holds one system, built again here from what its maker said
 * (a scene by name and parameters, or a 2x2 test system), and gives the
 * plugin a view of it with no fast path and a derivative counted here. y
 * and the work vectors each end exactly at a guard page (PROT_NONE), so a
 * write one element past them faults and the handler names the region; the
 * pad before each holds a canary checked after every step, and the view's
 * fields are compared with a copy. A run is a batch of steps whose states
 * go back as they are made; the parent decides what they are worth. */
#include "host/host.h"

#include <math.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/time.h>
#include <time.h>
#include <unistd.h>

#include "engine/linear2.h"
#include "plugin/plugin.h"
#include "stepwise/scene.h"

#define GUARD_PAGES 16
#define CANARY 0xa5
#define CANARY_BYTES 64

struct sw_host_slot {
    int used, maker_kind;
    sw_system sys;
    sw_linear2 lin;
    sw_ode *inner;          /* the system's own ode */
    sw_ode view;            /* what the plugin is handed */
    sw_ode view_copy;       /* the view before the step, to compare */
    int dim, wv, nextra;
    long evals, solves;     /* counted here, where the step does not write */
    unsigned char *map, *y_area, *work_area;
    size_t map_len, y_area_len, work_area_len, guard;
    double *y, *work;       /* what the plugin steps */
    double *scratch;        /* dim doubles: the state read in, f(t, y) */
    double *y_start, *work_start; /* the last run's start, to replay part of it */
    double t_start, h_start;
    int ran;                /* steps the last run took */
};

static int out_flush(int fd);
static void say_dying(void);
static double ms_since(const struct timespec *a);
static size_t outlen;
static struct timespec oldest;

static sw_host_slot slots[SW_HOST_SLOTS];
static sw_host_slot *current; /* the slot whose step runs (the fault handler's) */
static int fault_fd = -1;

/* ---- the view: counted, no fast path ----------------------------------------- */

static void counted_deriv(void *ctx, double t, const double *y, double *dydt)
{
    sw_host_slot *s = ctx;
    s->evals++;
    s->inner->deriv(s->inner->ctx, t, y, dydt);
}

static int counted_solve(void *ctx, double t, const double *y, double c, const double *r, double *z)
{
    sw_host_slot *s = ctx;
    s->solves++;
    return s->inner->solve(s->inner->ctx, t, y, c, r, z);
}

static void view_values(const sw_ode *o, int64_t v[SW_HOST_ODE_NFIELDS])
{
    int64_t f[SW_HOST_ODE_NFIELDS] = { o->dim, o->order, (int64_t)(uintptr_t)o->deriv,
                                       (int64_t)(uintptr_t)o->solve, (int64_t)(uintptr_t)o->ctx,
                                       (int64_t)(uintptr_t)o->prepare, (int64_t)(uintptr_t)o->fast,
                                       (int64_t)(uintptr_t)o->maker };
    memcpy(v, f, sizeof f);
}

/* Which field of the view differs from its copy; -1 none. */
static int view_changed(const sw_host_slot *s, int64_t *was, int64_t *now)
{
    int64_t a[SW_HOST_ODE_NFIELDS], b[SW_HOST_ODE_NFIELDS];
    view_values(&s->view_copy, a);
    view_values(&s->view, b);
    for (int i = 0; i < SW_HOST_ODE_NFIELDS; i++)
        if (a[i] != b[i]) {
            *was = a[i];
            *now = b[i];
            return i;
        }
    if (s->view.maker_kind != s->view_copy.maker_kind) {
        *was = s->view_copy.maker_kind;
        *now = s->view.maker_kind;
        return SW_HOST_ODE_NFIELDS - 1;
    }
    return -1;
}

/* ---- faults ------------------------------------------------------------------ */

static void on_fault(int sig, siginfo_t *si, void *uctx)
{
    (void)sig;
    (void)uctx;
    sw_host_slot *s = current;
    if (!s)
        return;
    sw_host_reply r;
    memset(&r, 0, sizeof r);
    r.tag = SW_HOST_FAULT;
    uintptr_t a = (uintptr_t)si->si_addr;
    uintptr_t y0 = (uintptr_t)s->y, y_end = (uintptr_t)(s->y_area + s->y_area_len);
    uintptr_t w0 = (uintptr_t)s->work, w_end = (uintptr_t)(s->work_area + s->work_area_len);
    int field = view_changed(s, &r.was, &r.now);
    if (field >= 0) {
        r.field = field;
        r.fault = SW_PF_ODE;
    } else if (a >= y_end && a < y_end + s->guard / 2) {
        r.fault = SW_PF_OVERRUN_Y;
        r.index = (int64_t)((a - y0) / sizeof(double));
    } else if (a >= w_end && a < w_end + s->guard) {
        r.fault = SW_PF_OVERRUN_WORK;
        r.index = (int64_t)((a - w0) / sizeof(double));
    } else if (a >= y_end && a < (uintptr_t)s->work_area) {
        r.fault = SW_PF_UNDERRUN;
        r.field = 1;
    } else if (a < (uintptr_t)s->y_area && a + s->guard >= (uintptr_t)s->y_area) {
        r.fault = SW_PF_UNDERRUN;
    }
    if (r.fault && (out_flush(fault_fd) != 0 || write(fault_fd, &r, sizeof r) != (ssize_t)sizeof r))
        return; /* the parent is gone: nothing to tell */
    if (!r.fault && sw_host_in_step)
        say_dying();
    /* SA_RESETHAND: returning re-runs the access, which now kills the host
     * with the signal, as the parent expects. */
}

/* A fatal signal in a step (abort(), SIGFPE, out of CPU time, ...): the
 * steps before it go out first, then the signal ends the host as it
 * would have (raised again: blocked until this returns, then the default). */
static void say_dying(void)
{
    sw_host_reply r;
    memset(&r, 0, sizeof r);
    r.tag = SW_HOST_DYING;
    r.index = sw_host_printed;
    if (out_flush(fault_fd) != 0 || write(fault_fd, &r, sizeof r) != (ssize_t)sizeof r)
        return; /* the parent is gone: nothing to tell */
}

static void on_fatal(int sig)
{
    if (sw_host_in_step)
        say_dying();
    raise(sig);
}

/* exit() in a step: the same. */
static void on_exit_in_step(void)
{
    if (sw_host_in_step)
        say_dying();
}

/* Every SW_HOST_FLUSH_MS while a step runs: what waits in the buffer goes
 * out, so that a step that never returns leaves every step before it with
 * the parent. (Between steps the host's own code flushes.) */
static void on_tick(int sig)
{
    (void)sig;
    if (sw_host_in_step && outlen > 0 && ms_since(&oldest) >= SW_HOST_FLUSH_MS)
        out_flush(fault_fd);
}

void sw_host_watch_faults(int fd)
{
    static char alt[65536];
    fault_fd = fd;
    stack_t ss = { .ss_sp = alt, .ss_size = sizeof alt, .ss_flags = 0 };
    sigaltstack(&ss, NULL);
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_sigaction = on_fault;
    sa.sa_flags = SA_SIGINFO | SA_ONSTACK | SA_RESETHAND;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGSEGV, &sa, NULL);
    sigaction(SIGBUS, &sa, NULL);
    static const int fatal[] = { SIGFPE, SIGILL, SIGABRT, SIGXCPU, SIGTRAP, SIGXFSZ, SIGSYS };
    sa.sa_handler = on_fatal;
    sa.sa_flags = SA_ONSTACK | SA_RESETHAND;
    for (size_t i = 0; i < sizeof fatal / sizeof fatal[0]; i++)
        sigaction(fatal[i], &sa, NULL);
    sa.sa_handler = on_tick;
    sa.sa_flags = SA_RESTART | SA_ONSTACK;
    sigaction(SIGALRM, &sa, NULL);
    atexit(on_exit_in_step);
}

int sw_host_start_ticks(void)
{
    struct itimerval every = { { 0, SW_HOST_FLUSH_MS * 1000 }, { 0, SW_HOST_FLUSH_MS * 1000 } };
    return setitimer(ITIMER_REAL, &every, NULL);
}

/* ---- memory ------------------------------------------------------------------ */

static size_t round_up(size_t n, size_t page) { return (n + page - 1) / page * page; }

/* [guard | ...pad y | guard | ...pad work | guard] */
static int slot_map(sw_host_slot *s)
{
    size_t page = (size_t)sysconf(_SC_PAGESIZE), vec = (size_t)s->dim * sizeof(double);
    s->guard = GUARD_PAGES * page;
    s->y_area_len = round_up(vec + CANARY_BYTES, page);
    s->work_area_len = round_up((size_t)s->wv * vec + CANARY_BYTES, page);
    s->map_len = s->guard + s->y_area_len + s->guard + s->work_area_len + s->guard;
    s->map = mmap(NULL, s->map_len, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (s->map == MAP_FAILED) {
        s->map = NULL;
        return -1;
    }
    s->y_area = s->map + s->guard;
    s->work_area = s->y_area + s->y_area_len + s->guard;
    mprotect(s->map, s->guard, PROT_NONE);
    mprotect(s->y_area + s->y_area_len, s->guard, PROT_NONE);
    mprotect(s->work_area + s->work_area_len, s->guard, PROT_NONE);
    memset(s->y_area, CANARY, s->y_area_len);
    memset(s->work_area, CANARY, s->work_area_len);
    s->y = (double *)(void *)(s->y_area + s->y_area_len - vec);
    s->work = (double *)(void *)(s->work_area + s->work_area_len - (size_t)s->wv * vec);
    memset(s->work, 0, (size_t)s->wv * vec);
    s->scratch = calloc((size_t)s->dim, sizeof(double));
    s->y_start = calloc((size_t)s->dim, sizeof(double));
    s->work_start = calloc((size_t)s->wv * (size_t)s->dim + 1, sizeof(double));
    return s->scratch && s->y_start && s->work_start ? 0 : -1;
}

static int canary_ok(const double *v)
{
    const unsigned char *p = (const unsigned char *)v - CANARY_BYTES;
    for (int i = 0; i < CANARY_BYTES; i++)
        if (p[i] != CANARY)
            return 0;
    return 1;
}

void sw_host_close(int i)
{
    if (i < 0 || i >= SW_HOST_SLOTS || !slots[i].used)
        return;
    sw_host_slot *s = &slots[i];
    if (s->maker_kind == SW_MAKER_SCENE)
        sw_system_free(&s->sys);
    if (s->map)
        munmap(s->map, s->map_len);
    free(s->scratch);
    free(s->y_start);
    free(s->work_start);
    memset(s, 0, sizeof *s);
}

int sw_host_open(const sw_host_cmd *cmd, int work_vectors)
{
    if (cmd->slot < 0 || cmd->slot >= SW_HOST_SLOTS || cmd->dim < 1 || cmd->dim > SW_HOST_DIM_MAX ||
        cmd->nextra < 0 || cmd->nextra > SW_HOST_EXTRA_MAX || cmd->work_vectors != work_vectors)
        return SW_EINVAL;
    sw_host_close(cmd->slot);
    sw_host_slot *s = &slots[cmd->slot];
    char err[SW_ERRLEN];
    if (cmd->maker_kind == SW_MAKER_SCENE) {
        char name[SW_HOST_SCENE_MAX + 1];
        memcpy(name, cmd->scene, SW_HOST_SCENE_MAX);
        name[SW_HOST_SCENE_MAX] = '\0';
        const sw_scene *sc = sw_scene_find(name);
        if (!sc || sw_system_build(&s->sys, sc, cmd->p, err, sizeof err) != SW_OK)
            return SW_EINVAL;
        s->maker_kind = SW_MAKER_SCENE;
        s->used = 1;
        s->inner = s->sys.ode;
        if (s->sys.nextra != cmd->nextra) {
            sw_host_close(cmd->slot);
            return SW_EINVAL;
        }
    } else if (cmd->maker_kind == SW_MAKER_LINEAR2 && (cmd->order == 1 || cmd->order == 2)) {
        sw_linear2_init(&s->lin, cmd->order, cmd->p);
        s->maker_kind = SW_MAKER_LINEAR2;
        s->used = 1;
        s->inner = &s->lin.ode;
        if (cmd->nextra != 0) {
            sw_host_close(cmd->slot);
            return SW_EINVAL;
        }
    } else {
        return SW_EINVAL;
    }
    s->dim = cmd->dim;
    s->wv = work_vectors;
    s->nextra = cmd->nextra;
    if (s->inner->dim != cmd->dim || s->inner->order != cmd->order || slot_map(s) != 0) {
        sw_host_close(cmd->slot);
        return SW_EINVAL;
    }
    /* the implicit solve's workspace, sized now: never in a step */
    if (s->inner->prepare && s->inner->prepare(s->inner->ctx, err, sizeof err) != SW_OK)
        s->inner->solve = NULL;
    s->view = (sw_ode){ .dim = s->dim, .order = s->inner->order, .deriv = counted_deriv,
                        .solve = s->inner->solve ? counted_solve : NULL, .ctx = s };
    return SW_OK;
}

/* ---- runs -------------------------------------------------------------------- */

int sw_host_read_all(int fd, void *buf, size_t len)
{
    char *p = buf;
    while (len > 0) {
        ssize_t n = read(fd, p, len);
        if (n <= 0)
            return -1;
        p += n;
        len -= (size_t)n;
    }
    return 0;
}

/* Replies gathered and written in large pieces: a run of small steps is a
 * few writes, not one a step. Sent at once in a careful run, when the
 * buffer fills, and SW_HOST_FLUSH_MS after the oldest was made. */
static unsigned char outbuf[1 << 18];
static int careful;

int sw_host_write_all(int fd, const void *buf, size_t len)
{
    const char *p = buf;
    while (len > 0) {
        ssize_t n = write(fd, p, len);
        if (n <= 0)
            return -1;
        p += n;
        len -= (size_t)n;
    }
    return 0;
}

static int out_flush(int fd)
{
    size_t len = outlen;
    outlen = 0;
    return sw_host_write_all(fd, outbuf, len);
}

static double ms_since(const struct timespec *a)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return 1e3 * (double)(now.tv_sec - a->tv_sec) + 1e-6 * (double)(now.tv_nsec - a->tv_nsec);
}

/* A reply and len bytes of v after it. */
static int out_put(int fd, const sw_host_reply *r, const void *v, size_t len)
{
    if (sizeof *r + len > sizeof outbuf - outlen && out_flush(fd) != 0)
        return -1;
    if (outlen == 0)
        clock_gettime(CLOCK_MONOTONIC, &oldest);
    if (sizeof *r + len > sizeof outbuf)
        return sw_host_write_all(fd, r, sizeof *r) == 0 && sw_host_write_all(fd, v, len) == 0 ? 0 : -1;
    memcpy(outbuf + outlen, r, sizeof *r);
    if (len)
        memcpy(outbuf + outlen + sizeof *r, v, len);
    outlen += sizeof *r + len;
    if (careful || ms_since(&oldest) >= SW_HOST_FLUSH_MS)
        return out_flush(fd);
    return 0;
}

static int finite_all(const double *y, int n)
{
    for (int i = 0; i < n; i++)
        if (!isfinite(y[i]))
            return 0;
    return 1;
}

/* One step of the plugin, checked; 0, or the fault (its record filled). */
static int one_step(sw_host_slot *s, sw_plugin_step_fn *step, double t, double h, sw_host_reply *r)
{
    memset(r, 0, sizeof *r);
    s->view_copy = s->view;
    long evals = s->evals, solves = s->solves, iters = s->inner->solver_iters;
    sw_host_allocated = 0;
    current = s;
    sw_host_in_step = 1;
    r->rc = step(&s->view, t, s->y, h, s->work);
    sw_host_in_step = 0;
    current = NULL;
    int field = view_changed(s, &r->was, &r->now);
    if (field >= 0) {
        r->field = field;
        r->fault = SW_PF_ODE;
    } else if (!canary_ok(s->y) || !canary_ok(s->work)) {
        r->fault = SW_PF_UNDERRUN;
        r->field = canary_ok(s->y);
    } else if (sw_host_allocated) {
        r->fault = SW_PF_ALLOC;
    }
    r->tag = r->fault ? SW_HOST_FAULT : SW_HOST_STEP;
    r->evals = s->evals - evals;
    r->solves = s->solves - solves;
    r->iters = s->inner->solver_iters - iters;
    return r->fault;
}

int sw_host_run(const sw_host_cmd *cmd, sw_plugin_step_fn *step, int fd)
{
    sw_host_slot *s = cmd->slot >= 0 && cmd->slot < SW_HOST_SLOTS && slots[cmd->slot].used
                          ? &slots[cmd->slot] : NULL;
    if (!s || cmd->steps < 1 || cmd->steps > SW_HOST_BATCH_MAX || cmd->keep > s->ran)
        return -1; /* the parent never sends this: end */
    size_t vec = (size_t)s->dim * sizeof(double);
    if (sw_host_read_all(fd, s->scratch, vec) != 0)
        return -1;
    double *extra = s->maker_kind == SW_MAKER_SCENE ? s->sys.extra : NULL;
    if (s->nextra > 0 && sw_host_read_all(fd, extra, (size_t)s->nextra * sizeof(double)) != 0)
        return -1;
    sw_host_reply r;
    /* Part of the last run was used: the work vectors go back to where that
     * part left them (a method may keep a derivative there from one step
     * to the next), by stepping it again. */
    if (cmd->keep >= 0 && cmd->keep < s->ran) {
        memcpy(s->y, s->y_start, vec);
        memcpy(s->work, s->work_start, (size_t)s->wv * vec);
        double t = s->t_start;
        for (int k = 0; k < cmd->keep; k++, t += s->h_start)
            if (one_step(s, step, t, s->h_start, &r) != 0) {
                out_put(fd, &r, NULL, 0);
                out_flush(fd);
                return -1;
            }
    }
    memcpy(s->y, s->scratch, vec);
    /* the derivative at the start, for the parent to compare with its own:
     * proof that this is the system it steps */
    s->inner->deriv(s->inner->ctx, cmd->t, s->y, s->scratch);
    memset(&r, 0, sizeof r);
    r.tag = SW_HOST_PRINT;
    careful = cmd->careful;
    if (out_put(fd, &r, s->scratch, vec) != 0)
        return -1;
    memcpy(s->y_start, s->y, vec);
    memcpy(s->work_start, s->work, (size_t)s->wv * vec);
    s->t_start = cmd->t;
    s->h_start = cmd->h;
    s->ran = 0;
    double t = cmd->t;
    for (int k = 0; k < cmd->steps; k++, t += cmd->h) {
        if (one_step(s, step, t, cmd->h, &r) != 0) {
            out_put(fd, &r, NULL, 0);
            out_flush(fd);
            return -1;
        }
        if (out_put(fd, &r, s->y, vec) != 0)
            return -1;
        s->ran++;
        if (r.rc != 0 || !finite_all(s->y, s->dim))
            break; /* the run ends here: no step past it is asked for */
    }
    memset(&r, 0, sizeof r);
    r.tag = SW_HOST_END;
    r.rc = s->ran;
    fflush(stdout); /* what the plugin printed in the run is counted when it leaves the buffer */
    r.index = sw_host_printed; /* bytes printed in this host so far (try says so) */
    if (out_put(fd, &r, NULL, 0) != 0)
        return -1;
    return out_flush(fd);
}
