/* Integrators: one table entry per method, stepping a flat state vector
 * through the sw_ode interface. A step allocates nothing: its workspace comes
 * once, from sw_stepper_init. This header is also what a student's plugin
 * integrator includes (see examples/ and docs/plugins.md). */
#ifndef STEPWISE_INTEGRATOR_H
#define STEPWISE_INTEGRATOR_H

#include <stddef.h>
#include "stepwise/ode.h"

enum {
    SW_EXPLICIT = 1u << 0,
    SW_IMPLICIT = 1u << 1,
    SW_SYMPLECTIC = 1u << 2,
    SW_ADAPTIVE = 1u << 3,
    SW_NEEDS_SECOND_ORDER = 1u << 4, /* refuses a first-order (flow) system */
    SW_PLUGIN = 1u << 5              /* loaded from a shared object */
};

typedef struct sw_stepper sw_stepper;

/* Advance (t, y) by one step of at most h; set *t to the new time. Returns 0,
 * or a negative status when the step cannot be taken (a failed solve). */
typedef int sw_step_fn(sw_stepper *s, sw_ode *ode, double *t, double *y, double h);

typedef struct sw_integrator {
    const char *name;     /* fixed command-line name, e.g. "rk4" */
    const char *label;    /* human name, e.g. "classical Runge-Kutta" */
    int order;            /* global order of accuracy */
    int evals;            /* derivative evaluations per step (nominal) */
    unsigned flags;       /* SW_EXPLICIT, SW_IMPLICIT, ... */
    double stability;     /* largest stable ω·h on x'' = -ω²x: 0 none, INFINITY unbounded */
    int work_vectors;     /* workspace, in vectors of dim doubles */
    sw_step_fn *step;
    const char *summary;  /* one line: the update rule */
} sw_integrator;

/* The running state of one method on one system: workspace and the little
 * memory some methods keep between steps. */
struct sw_stepper {
    const sw_integrator *method;
    int dim;
    double *work;         /* work_vectors * dim doubles, owned */
    double *dense;        /* dense finite-difference Jacobian workspace, or NULL */
    int have_cache;       /* FSAL derivative in work[0..dim) is valid */
    double rtol, atol;    /* rk45 error control; implicit-midpoint Newton tolerance */
    double h_next;        /* rk45: proposed size of the next step (0: use h) */
    double h_last;        /* size of the last step taken */
    long accepted;        /* rk45 accepted steps */
    long rejected;        /* rk45 rejected trial steps */
    long newton_iters;    /* implicit-midpoint Newton iterations, summed */
    void *plugin;         /* plugin step function, for SW_PLUGIN methods */
    unsigned limit_exp;   /* 0, or: flag |y_i| >= 2^(limit_exp - 1023), inf or NaN */
    int checked;          /* the last step tested the whole state against limit_exp */
    int beyond;           /* ... and found a component beyond it */
};

#define SW_RTOL_DEFAULT 1e-6
#define SW_ATOL_DEFAULT 1e-9

/* 1 when some y_i in [lo, hi) is non-finite or has |y_i| >= 2^(limit_exp -
 * 1023): a test on the exponent field alone, which compilers vectorise. */
static inline int sw_state_beyond(const double *y, int lo, int hi, unsigned limit_exp)
{
    unsigned over = 0;
    for (int i = lo; i < hi; i++) {
        unsigned long long bits;
        __builtin_memcpy(&bits, &y[i], sizeof bits);
        over |= (unsigned)((bits >> 52) & 0x7FF) >= limit_exp;
    }
    return over != 0;
}

/* The built-in methods, in list order (positions 1..count in the UI). */
int sw_integrator_count(void);
const sw_integrator *sw_integrator_at(int index);
/* Look a method up by its exact name; NULL when there is none. */
const sw_integrator *sw_integrator_find(const char *name);
/* Register a method (a loaded plugin) after the built-ins; 0 or SW_EINVAL. */
int sw_integrator_register(const sw_integrator *method, char *err, size_t errlen);
/* Whether the method can step this system; when not, err says why. */
int sw_integrator_accepts(const sw_integrator *m, const sw_ode *ode, char *err, size_t errlen);

/* Prepare a stepper for ode; 0, SW_EINVAL (wrong system kind) or SW_ENOMEM. */
int sw_stepper_init(sw_stepper *s, const sw_integrator *m, const sw_ode *ode,
                    char *err, size_t errlen);
void sw_stepper_free(sw_stepper *s);
/* Forget caches after the state was changed from outside (contact, reset). */
void sw_stepper_touch(sw_stepper *s);
/* One step through the method's table entry. */
int sw_stepper_step(sw_stepper *s, sw_ode *ode, double *t, double *y, double h);

/* Solve (I - c·J) z = r through ode->solve, or the dense finite-difference
 * fallback (dim <= SW_DENSE_MAX) using s->dense. */
int sw_ode_solve(sw_stepper *s, sw_ode *ode, double t, const double *y, double c,
                 const double *r, double *z);

/* Student plugins: a shared object exports
 *     const sw_plugin *sw_plugin_info(void);
 * returning a description of its integrator (see examples/euler_plugin.c). */
#define SW_PLUGIN_ABI 1
typedef int sw_plugin_step_fn(sw_ode *ode, double t, double *y, double h, double *work);
typedef struct sw_plugin {
    int abi;                  /* must be SW_PLUGIN_ABI */
    const char *name;         /* command-line name, e.g. "my-euler" */
    const char *label;        /* human name */
    int order;                /* claimed order (reported, not trusted) */
    int evals;                /* derivative evaluations per step (reported) */
    int work_vectors;         /* how many dim-long vectors `work` holds */
    sw_plugin_step_fn *step;  /* y(t) -> y(t + h) in place; return 0 */
} sw_plugin;

#endif
