/* Attack: find one of stepwise's own methods in the plugin's address space
 * and step with it. A plugin's process that is a fork (or any copy) of
 * stepwise holds the integrator table and the systems' fused steps; a
 * plugin that finds them hands in the built-in rk4's very bits. Without a
 * system call the sealed jail forbids (no open, no /proc: memory only):
 *   - dl_iterate_phdr lists every loaded object (the main program too) and
 *     its PT_LOAD segments; only those marked readable are read, page by
 *     page, under a SIGSEGV/SIGBUS guard (the handler the plugin's host
 *     had is put back after), bounded (256 segments, 64 candidates);
 *   - (FIND_VIA & 1) the strings "rk4" and "classical Runge" (built at run
 *     time; this object itself is never searched), then every aligned
 *     pointer to one of them: a struct sw_integrator (integrator.h: name,
 *     label, order, evals, flags, stability, work_vectors, step, summary)
 *     with order 4, 4 evaluations, explicit, fixed-step, and a step that
 *     points into an executable segment is the built-in rk4; its step,
 *     sw_step_fn(sw_stepper *, sw_ode *, double *t, double *y, double h),
 *     is called on a fake sw_stepper (src/engine/stepper.h's layout, the
 *     plugin's own work vectors as its workspace). dlsym(RTLD_DEFAULT,
 *     "sw_integrator_find") is tried too (stepwise exports nothing today);
 *   - a fused rk4 step (src/engine/ode_fast.h: struct sw_ode_fast
 *     {deriv_part, fused_euler, fused_rk4, position_only, central1}):
 *     (FIND_VIA & 2) the step's own ode->fast when it is not NULL (a flow
 *     scene's system as the engine built it); (FIND_VIA & 4) else an sw_ode
 *     of the same dim and order with a non-NULL fast found in the objects'
 *     writable segments or the heap (below sbrk(0), 256 MiB at most); its
 *     fused_rk4(ctx, t, y, h, 0x800) steps y.
 * Explicit Euler when it finds nothing: a pass means the attack worked.
 * The test runs it (FIND_VIA 7: all three) on the graded spring and on
 * check's chain (the table), and, built with FIND_VIA 6 (the test defines
 * it before the file: no table), on the vortex flow (ode->fast, or one in
 * memory). The search runs at the first step of every run; it writes
 * nothing and opens nothing (a forbidden call would end it before the
 * answer). */
#define EVIL_FAMILY "find-builtin"
#define EVIL_CUSTOM_STEP
#include "evil.h"
#include <dlfcn.h>
#include <link.h>
#include <setjmp.h>

#ifndef FIND_VIA
/* 1: the integrator table (and dlsym); 2: the step's own ode->fast; 4: an
 * sw_ode with a fast path found in memory */
#define FIND_VIA 7
#endif
#define FB_SEGS 256
#define FB_CANDIDATES 64
#define FB_HEAP_MAX ((size_t)256 << 20)
#define FB_PAGE ((uintptr_t)4096)

/* src/engine/stepper.h's struct sw_stepper as of this writing (opaque to
 * plugins), with room to spare. */
typedef struct fb_stepper {
    const sw_integrator *method;
    int dim;
    double *work;
    double *dense;
    int have_cache, fsal;
    double rtol, atol, h_next, h_last, err_last;
    long accepted, rejected, newton_iters;
    void *plugin, *inner;
    void (*release)(void *s);
    unsigned limit_exp;
    int checked, beyond;
    const char *why;
    char spare[512];
} fb_stepper;

/* src/engine/ode_fast.h's struct sw_ode_fast. */
typedef unsigned fb_fused_fn(void *ctx, double t, double *y, double h, unsigned elim);
typedef struct fb_fast {
    void *deriv_part;
    fb_fused_fn *fused_euler, *fused_rk4;
    void *position_only, *central1;
} fb_fast;

typedef struct fb_seg {
    uintptr_t lo, hi;
    unsigned flags;
} fb_seg;

static fb_seg segs[FB_SEGS];
static int nsegs;
static const char fb_anchor[1] = { 0 }; /* an address inside this object */
static char key_name[8], key_label[24];
static uintptr_t names[FB_CANDIDATES], labels[FB_CANDIDATES];
static int nnames, nlabels, table_size;
static const sw_integrator *found_rk4;
static fb_fused_fn *found_fused;
static void *found_ctx;

/* ---- the guard: a fault while reading skips the page -------------------- */

static sigjmp_buf fb_jb;
static struct sigaction fb_old_segv, fb_old_bus;
static void fb_fault(int sig)
{
    (void)sig;
    siglongjmp(fb_jb, 1);
}

static void fb_guard(int on)
{
    if (on) {
        struct sigaction sa;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = fb_fault;
        sa.sa_flags = SA_NODEFER;
        sigemptyset(&sa.sa_mask);
        sigaction(SIGSEGV, &sa, &fb_old_segv);
        sigaction(SIGBUS, &sa, &fb_old_bus);
    } else {
        sigaction(SIGSEGV, &fb_old_segv, NULL);
        sigaction(SIGBUS, &fb_old_bus, NULL);
    }
}

/* fn on [lo, hi) page by page (it may read up to seg_hi); a page whose
 * reading faults is skipped. */
typedef void fb_visit(uintptr_t lo, uintptr_t hi, uintptr_t seg_hi, void *ctx);
static void fb_pages(uintptr_t lo, uintptr_t hi, fb_visit *fn, void *ctx)
{
    for (volatile uintptr_t p = lo & ~(FB_PAGE - 1); p < hi; p += FB_PAGE) {
        uintptr_t a = p < lo ? lo : p, b = p + FB_PAGE < hi ? p + FB_PAGE : hi;
        if (sigsetjmp(fb_jb, 1) == 0)
            fn(a, b, hi, ctx);
    }
}

/* ---- the segments -------------------------------------------------------- */

static int fb_each_object(struct dl_phdr_info *o, size_t size, void *ctx)
{
    (void)size, (void)ctx;
    uintptr_t me = (uintptr_t)fb_anchor;
    for (int i = 0; i < o->dlpi_phnum; i++) {
        const ElfW(Phdr) *ph = &o->dlpi_phdr[i];
        uintptr_t lo = o->dlpi_addr + ph->p_vaddr;
        if (ph->p_type == PT_LOAD && me >= lo && me < lo + ph->p_memsz)
            return 0; /* this plugin itself */
    }
    for (int i = 0; i < o->dlpi_phnum && nsegs < FB_SEGS; i++) {
        const ElfW(Phdr) *ph = &o->dlpi_phdr[i];
        if (ph->p_type != PT_LOAD || !(ph->p_flags & PF_R) || ph->p_memsz == 0)
            continue;
        uintptr_t lo = o->dlpi_addr + ph->p_vaddr;
        segs[nsegs++] = (fb_seg){ lo, lo + ph->p_memsz, ph->p_flags };
    }
    return 0;
}

/* Whether [a, a + len) lies in one segment with these flags. */
static int fb_in(uintptr_t a, size_t len, unsigned flags)
{
    for (int i = 0; i < nsegs; i++)
        if (a >= segs[i].lo && a + len <= segs[i].hi && (segs[i].flags & flags) == flags)
            return 1;
    return 0;
}

/* ---- (a), (b): the strings, the pointers, the table ----------------------- */

static void fb_strings(uintptr_t lo, uintptr_t hi, uintptr_t seg_hi, void *ctx)
{
    (void)ctx;
    uintptr_t end = hi + 32 < seg_hi ? hi + 32 : seg_hi;
    const char *base = (const char *)lo;
    size_t len = end - lo, kn = strlen(key_name) + 1, kl = strlen(key_label);
    for (size_t at = 0; at < hi - lo && nnames < FB_CANDIDATES;) {
        const char *m = memmem(base + at, len - at, key_name, kn); /* with its NUL */
        if (!m || (uintptr_t)m >= hi)
            break;
        names[nnames++] = (uintptr_t)m;
        at = (size_t)(m - base) + 1;
    }
    for (size_t at = 0; at < hi - lo && nlabels < FB_CANDIDATES;) {
        const char *m = memmem(base + at, len - at, key_label, kl);
        if (!m || (uintptr_t)m >= hi)
            break;
        labels[nlabels++] = (uintptr_t)m;
        at = (size_t)(m - base) + 1;
    }
}

/* A plausible table entry (any method): readable name and label, a step
 * in executable code. */
static int fb_entry(const sw_integrator *m)
{
    uintptr_t name = (uintptr_t)m->name, label = (uintptr_t)m->label, step;
    memcpy(&step, &m->step, sizeof step);
    return fb_in(name, 1, PF_R) && fb_in(label, 1, PF_R) && fb_in(step, 1, PF_X) && m->order >= 1 &&
           m->order <= 16 && m->work_vectors >= 0 && m->work_vectors <= 64;
}

/* The built-in rk4: named so or labelled so, 4th order, 4 evaluations,
 * explicit, fixed-step, at most the 5 work vectors the plugin has. */
static int fb_is_rk4(const sw_integrator *m)
{
    if (!fb_entry(m) || m->order != 4 || m->evals != 4 || !(m->flags & SW_EXPLICIT) ||
        (m->flags & (SW_PLUGIN | SW_ADAPTIVE | SW_IMPLICIT)) || m->work_vectors < 1 || m->work_vectors > 5)
        return 0;
    return strcmp(m->name, key_name) == 0 || strncmp(m->label, key_label, strlen(key_label)) == 0;
}

static void fb_pointers(uintptr_t lo, uintptr_t hi, uintptr_t seg_hi, void *ctx)
{
    (void)ctx;
    for (uintptr_t p = (lo + 7) & ~(uintptr_t)7; p + sizeof(uintptr_t) <= hi && !found_rk4; p += 8) {
        uintptr_t w = *(const uintptr_t *)p;
        const sw_integrator *m = NULL;
        for (int i = 0; i < nnames && !m; i++)
            if (w == names[i])
                m = (const sw_integrator *)p; /* .name is the first field */
        for (int i = 0; i < nlabels && !m; i++)
            if (w == labels[i] && p >= lo + 8)
                m = (const sw_integrator *)(p - 8); /* .label the second */
        if (m && (uintptr_t)m + sizeof *m <= seg_hi && fb_is_rk4(m)) {
            found_rk4 = m;
            /* the table around it, for the record */
            table_size = 1;
            for (const sw_integrator *q = m - 1; fb_in((uintptr_t)q, sizeof *q, PF_R) && fb_entry(q); q--)
                table_size++;
            for (const sw_integrator *q = m + 1; fb_in((uintptr_t)q, sizeof *q, PF_R) && fb_entry(q); q++)
                table_size++;
        }
    }
}

static void fb_find_table(void)
{
    /* exported? (not today: the executable exports nothing) */
    const sw_integrator *(*find)(const char *);
    *(void **)&find = dlsym(RTLD_DEFAULT, "sw_integrator_find");
    if (find) {
        const sw_integrator *m = find(key_name);
        if (m && sigsetjmp(fb_jb, 1) == 0 && fb_is_rk4(m)) {
            found_rk4 = m;
            return;
        }
    }
    for (int i = 0; i < nsegs; i++)
        fb_pages(segs[i].lo, segs[i].hi, fb_strings, NULL);
    if (!nnames && !nlabels)
        return;
    for (int i = 0; i < nsegs && !found_rk4; i++)
        fb_pages(segs[i].lo, segs[i].hi, fb_pointers, NULL);
}

/* ---- (c): a system's fused rk4 -------------------------------------------- */

static fb_fused_fn *fb_fused_of(const void *fast)
{
    if (!fast)
        return NULL;
    const fb_fast *f = fast;
    uintptr_t rk4;
    memcpy(&rk4, &f->fused_rk4, sizeof rk4);
    return fb_in(rk4, 1, PF_X) ? f->fused_rk4 : NULL;
}

static void fb_odes(uintptr_t lo, uintptr_t hi, uintptr_t seg_hi, void *ctx)
{
    const sw_ode *mine = ctx;
    for (uintptr_t p = (lo + 7) & ~(uintptr_t)7; p < hi && p + sizeof(sw_ode) <= seg_hi && !found_fused; p += 8) {
        const sw_ode *o = (const sw_ode *)p;
        uintptr_t deriv, fast = (uintptr_t)o->fast;
        if (o->dim != mine->dim || o->order != mine->order || !o->ctx || o == mine)
            continue;
        memcpy(&deriv, &o->deriv, sizeof deriv);
        if (!fb_in(deriv, 1, PF_X) || !fb_in(fast, sizeof(fb_fast), PF_R))
            continue;
        fb_fused_fn *f = fb_fused_of(o->fast);
        if (f) {
            found_fused = f;
            found_ctx = o->ctx;
        }
    }
}

static void fb_find_fast(sw_ode *ode)
{
    if ((FIND_VIA & 2) && sigsetjmp(fb_jb, 1) == 0) {
        fb_fused_fn *f = fb_fused_of(ode->fast);
        if (f) {
            found_fused = f;
            found_ctx = ode->ctx;
            return;
        }
    }
    if (!(FIND_VIA & 4))
        return;
    for (int i = 0; i < nsegs && !found_fused; i++)
        if (segs[i].flags & PF_W)
            fb_pages(segs[i].lo, segs[i].hi, fb_odes, ode);
    /* the heap: down from the break while readable */
    volatile uintptr_t top = (uintptr_t)sbrk(0), start = top & ~(FB_PAGE - 1);
    while (top - start < FB_HEAP_MAX && start >= FB_PAGE) {
        if (sigsetjmp(fb_jb, 1) != 0)
            break;
        (void)*(volatile const char *)(start - FB_PAGE);
        start -= FB_PAGE;
    }
    if (!found_fused && top > start)
        fb_pages(start, top, fb_odes, ode);
}

static void fb_search(sw_ode *ode)
{
    strcpy(key_name, "r");
    strcat(key_name, "k4");
    strcpy(key_label, "classical ");
    strcat(key_label, "Runge");
    dl_iterate_phdr(fb_each_object, NULL);
    fb_guard(1);
    if (FIND_VIA & 1)
        fb_find_table();
    if ((FIND_VIA & 6) && !found_rk4)
        fb_find_fast(ode);
    fb_guard(0);
    evil_cheat = found_rk4 || found_fused;
}

static void evil_attack(void) {}

static int evil_step(sw_ode *ode, double t, double *y, double h, double *work)
{
    static int searched;
    if (!searched) {
        searched = 1;
        fb_search(ode);
    }
    if (found_rk4) {
        fb_stepper s;
        memset(&s, 0, sizeof s);
        s.method = found_rk4;
        s.dim = ode->dim;
        s.work = work; /* 5 vectors of dim: rk4 needs 3 */
        s.rtol = 1e-6;
        s.atol = 1e-9;
        double tt = t;
        return found_rk4->step((sw_stepper *)(void *)&s, ode, &tt, y, h);
    }
    if (found_fused) {
        found_fused(found_ctx, t, y, h, 0x800); /* 0x800: no runaway test */
        return 0;
    }
    return evil_euler(ode, t, y, h, work);
}
