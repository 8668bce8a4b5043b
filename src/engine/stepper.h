/* Private to the engine and the layers above it: the running state of one
 * method on one system (workspace and the little memory some methods keep
 * between steps), and the step functions of the built-in methods. The
 * installed headers see sw_stepper only as an opaque type. */
#ifndef SW_ENGINE_STEPPER_H
#define SW_ENGINE_STEPPER_H

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "engine/clones.h"
#include "engine/ode_fast.h"
#include "stepwise/integrator.h"

struct sw_stepper {
    const sw_integrator *method;
    int dim;
    double *work;         /* work_vectors * dim doubles, owned */
    double *dense;        /* dense finite-difference Jacobian workspace, or NULL */
    int have_cache;       /* FSAL derivative is valid (in work[0..dim), or slot fsal) */
    int fsal;             /* adaptive RK: workspace slot of the cached first-stage derivative */
    double rtol, atol;    /* adaptive error control (rk45, dop853, rkn, rkn12, rodas4, vern8, vern9) */
    double h_next;        /* adaptive: proposed size of the next step (0: use h) */
    double h_last;        /* size of the last step taken */
    double err_last;      /* adaptive: the last accepted step's error norm, at least 0.01 (0: none) */
    long accepted;        /* adaptive: accepted steps */
    long rejected;        /* adaptive: rejected trial steps */
    long newton_iters;    /* implicit: Newton iterations, summed */
    void *plugin;         /* SW_PLUGIN methods: the plugin's sandbox (plugin/plugin_box.c) */
    void *inner;          /* what a method's prepare made (dop853-lc: the regularised run) */
    void (*release)(sw_stepper *s); /* frees what `plugin` holds; called by sw_stepper_free */
    unsigned limit_exp;   /* 0, or: flag |y_i| >= 2^(limit_exp - 1023), inf or NaN */
    int checked;          /* the last step tested the whole state against limit_exp */
    int beyond;           /* ... and found a component beyond it */
    const char *why;      /* why the last failed step failed (static text), or NULL */
};

/* Prepare a stepper for ode; 0, SW_EINVAL (wrong system kind) or SW_ENOMEM. */
int sw_stepper_init(sw_stepper *s, const sw_integrator *m, const sw_ode *ode,
                    char *err, size_t errlen);
void sw_stepper_free(sw_stepper *s);
/* Forget caches after the state was changed from outside (contact, reset). */
void sw_stepper_touch(sw_stepper *s);
/* Refuse a registered (plugin) method from now on: sw_integrator_accepts
 * then fails with `why` (play disables a plugin that crashed). */
void sw_integrator_disable(const sw_integrator *m, const char *why);
/* One step through the method's table entry: sw_stepper_step, public
 * (stepwise/integrator.h). */

/* Solve (I - c·J) z = r through ode->solve, or the dense finite-difference
 * fallback (dim <= SW_DENSE_MAX) using s->dense. */
int sw_ode_solve(sw_stepper *s, sw_ode *ode, double t, const double *y, double c,
                 const double *r, double *z);
/* The same, where the caller promises that y's contents are those of its
 * last solve on ode (the same point, not written since: Newton's kept J,
 * a Rosenbrock step's later stages): a system that keeps its factors
 * keyed by y may then skip comparing them (ode_fast.h's solve_same). The
 * same bits as sw_ode_solve; counted as a solve. */
int sw_ode_solve_same(sw_stepper *s, sw_ode *ode, double t, const double *y, double c,
                      const double *r, double *z);
/* The same as sw_ode_solve, where the caller will solve at this y again
 * only through sw_ode_solve_same (a step's first solve: Newton's at a
 * fresh J, a Rosenbrock step's first stage, the linearly implicit step):
 * the system need not keep y to compare later solves with. */
int sw_ode_solve_new(sw_stepper *s, sw_ode *ode, double t, const double *y, double c,
                     const double *r, double *z);

/* The built-in methods' steps, one file per family. */
sw_step_fn sw_step_euler, sw_step_symplectic_euler, sw_step_midpoint, sw_step_heun,
    sw_step_rk4, sw_step_verlet, sw_step_yoshida4;     /* explicit.c */
sw_step_fn sw_step_implicit_euler, sw_step_linear_implicit_euler,
    sw_step_implicit_midpoint;                        /* implicit.c */
sw_step_fn sw_step_rk45;                               /* rk45.c */
sw_step_fn sw_step_dop853;                             /* dop853.c */
enum { SW_DOP853_VECTORS = 12 };                       /* its workspace */
sw_step_fn sw_step_rkn;                                /* rkn.c */
sw_step_fn sw_step_rkn12;                              /* rkn12.c */
sw_step_fn sw_step_rodas4;                             /* rosenbrock.c */
sw_step_fn sw_step_dop853_lc;                          /* dop853_lc.c */
sw_step_fn sw_step_vern8, sw_step_vern9;               /* vern.c */
enum { SW_V8_VECTORS = 16, SW_V9_VECTORS = 19 };       /* their workspaces */

/* dop853-lc's preparation (its row's prepare, dop853_lc.c): the regularised
 * run it steps; SW_OK, or SW_EINVAL / SW_ENOMEM with err. */
sw_prepare_fn sw_dop853_lc_prepare;

/* A method's memory beyond the state and the stepper's own fields, for a
 * snapshot (sim/history.c), so that a run restored and stepped on repeats
 * itself bit for bit: at most SW_STEPPER_MEMORY_MAX doubles. _save writes
 * it and returns how many (0: none, the next step needs nothing kept);
 * _load puts back what _save wrote when the state restored with it is
 * (t, y). Only dop853-lc has any (its variables: dop853_lc.c). */
enum { SW_STEPPER_MEMORY_MAX = 16 };
int sw_stepper_memory_save(const sw_stepper *s, double *out);
void sw_stepper_memory_load(sw_stepper *s, const double *in, int n, double t, const double *y);
int sw_dop853_lc_save(const sw_stepper *s, double *out);
void sw_dop853_lc_load(sw_stepper *s, const double *in, int n, double t, const double *y);

/* Explicit Runge-Kutta steps run over the whole state for coupled systems,
 * or slice by slice (L1-sized) for pointwise ones (flow fields), where
 * every stage of a slice needs only that slice. The stage vectors of a
 * slice are then slice-local (the first `len` doubles of their work
 * vectors, reused by every slice, so they stay in L1); only what must
 * outlive a slice is kept state-long. The arithmetic is the same either
 * way; only the memory traffic differs. */
#define SW_SLICE 512

/* dydt at (t, y) for a slice of len components (y and dydt point at the
 * slice), or for the whole state (len = dim) of a coupled system. Not
 * counted: callers count per stage. */
static inline void sw_eval_slice(sw_ode *ode, double t, int len, const double *y, double *dydt)
{
    if (sw_ode_deriv_part(ode))
        ode->fast->deriv_part(ode->ctx, t, len, y, dydt);
    else
        ode->deriv(ode->ctx, t, y, dydt);
}

/* The same, with the system's functions read once: a step that evaluates
 * many stages takes them into locals, which the compiler keeps in
 * registers across the calls (it cannot know that a call leaves *ode
 * unchanged, so sw_eval_slice reloads them at every stage). */
typedef struct sw_evaluator {
    sw_deriv_part_fn *part; /* the system's slice derivative, or NULL */
    sw_deriv_fn *deriv;
    void *ctx;
} sw_evaluator;

static inline sw_evaluator sw_evaluator_of(const sw_ode *ode)
{
    return (sw_evaluator){ .part = sw_ode_deriv_part(ode), .deriv = ode->deriv, .ctx = ode->ctx };
}

static inline void sw_eval_with(const sw_evaluator *f, double t, int len, const double *y, double *dydt)
{
    if (f->part)
        f->part(f->ctx, t, len, y, dydt);
    else
        f->deriv(f->ctx, t, y, dydt);
}

/* The runaway test as one addition, so that a loop ORing it vectorises in
 * 64-bit lanes with no narrowing: v's exponent field plus 0x800 - elim
 * carries into the sign bit exactly when the exponent is at or beyond elim
 * (inf and NaN, 0x7FF, always are; elim = 0x800 never). OR the results over
 * a loop; sw_beyond_any says whether any was. add = sw_beyond_add(elim). */
static inline unsigned long long sw_beyond_add(unsigned elim)
{
    return (unsigned long long)(0x800u - elim) << 52;
}

#define SW_EXPONENT_BITS 0x7FF0000000000000ULL /* a double's exponent field */

static inline unsigned long long sw_beyond_bits(double v, unsigned long long add)
{
    unsigned long long bits;
    memcpy(&bits, &v, sizeof bits);
    return (bits & SW_EXPONENT_BITS) + add;
}

static inline unsigned sw_beyond_any(unsigned long long ored)
{
    return (unsigned)(ored >> 63);
}

/* 1 when some y_i in [lo, hi) is non-finite or has |y_i| >= 2^(limit_exp -
 * 1023): the same test over a range, for the sim's own rescan. */
static inline int sw_state_beyond(const double *y, int lo, int hi, unsigned limit_exp)
{
    unsigned long long over = 0, add = sw_beyond_add(limit_exp);
    for (int i = lo; i < hi; i++)
        over |= sw_beyond_bits(y[i], add);
    return (int)sw_beyond_any(over);
}

/* Largest |v_i| over n components; NaN when any is NaN (so a failed
 * iteration is never "converged"). */
static inline double sw_norm_inf(int n, const double *v)
{
    double m = 0.0;
    for (int i = 0; i < n; i++) {
        double a = fabs(v[i]);
        if (a > m || a != a)
            m = a; /* once NaN, m stays NaN: nothing compares greater */
    }
    return m;
}

/* out = y + a·k over n components (out may be y). */
static inline void sw_axpy(int n, double *out, const double *y, double a, const double *k)
{
    for (int i = 0; i < n; i++)
        out[i] = y[i] + a * k[i];
}

/* Workspace vector i of a stepper. */
#define SW_WORK(s, i) ((s)->work + (size_t)(i) * (size_t)(s)->dim)

#endif
