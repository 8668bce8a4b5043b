/* Integrators: one table entry per method, stepping a flat state vector
 * through the sw_ode interface. A step allocates nothing: its workspace comes
 * once, when a sim chooses the method. This header is also what a student's
 * plugin integrator includes (see examples/ and docs/plugins.md). */
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
    SW_PLUGIN = 1u << 5,             /* loaded from a shared object */
    SW_NEWTON = 1u << 6,             /* implicit, Newton iterated: evals is a lower bound */
    SW_POSITION_ONLY = 1u << 7,      /* x'' = f(x): refuses forces that read velocities */
    SW_ONE_BODY = 1u << 8            /* one body alone in one central field (Kepler's problem) */
};

/* The running state of one method on one system: its workspace and what it
 * keeps between steps. Opaque here; a sim owns one (stepwise/sim.h). */
typedef struct sw_stepper sw_stepper;

/* Advance (t, y) by one step of at most h; set *t to the new time. Returns 0,
 * or a negative status when the step cannot be taken (a failed solve). */
typedef int sw_step_fn(sw_stepper *s, sw_ode *ode, double *t, double *y, double h);

/* More set-up for a new stepper of a method, after its workspace: SW_OK, or
 * a status with err saying why the method cannot step ode. */
typedef int sw_prepare_fn(sw_stepper *s, const sw_ode *ode, char *err, size_t errlen);

struct sw_stage_script; /* a step as the lecture writes it (private: engine/lecture.h) */
struct sw_mistake;      /* a mistaken version of a method (private: engine/mistakes.h) */

typedef struct sw_integrator {
    const char *name;     /* fixed command-line name, e.g. "rk4" */
    const char *label;    /* human name, e.g. "classical Runge-Kutta"; a plugin's is its
                           * author's text (SW_PLUGIN): shown only escaped */
    int order;            /* global order of accuracy */
    int evals;            /* derivative evaluations per step (nominal) */
    unsigned flags;       /* SW_EXPLICIT, SW_IMPLICIT, ... */
    double stability;     /* largest stable ω·h on x'' = -ω²x: 0 none, INFINITY unbounded */
    int work_vectors;     /* workspace, in vectors of dim doubles */
    sw_step_fn *step;
    const char *summary;  /* one line: the update rule */
    /* What the rest of the tool knows about the method, kept in its row and
     * read from nowhere else (a plugin's row: NULL but for no_lecture). */
    sw_prepare_fn *prepare; /* more set-up for a new stepper, or NULL */
    const struct sw_stage_script *lecture; /* its step as the lecture writes it,
                                            * drawn by the stage view; or NULL */
    const char *no_lecture; /* when lecture is NULL: why the stage view draws
                             * none, in a few words ("it solves an equation") */
    const struct sw_mistake *mistakes; /* the explainer's mistaken versions of
                                        * it, ended by a NULL kind; or NULL */
    const char *twin;       /* a method students write instead of this one, or NULL */
    const char *twin_hint;  /* what the explainer asks when numbers match twin */
    int compare;            /* its place among the partners compare picks (1 first), 0 none */
    int reference;          /* 1: the truth module's reference (one built-in) */
    int resting;            /* 1: steps a scene to its resting state (one built-in) */
} sw_integrator;

#define SW_RTOL_DEFAULT 1e-6
#define SW_ATOL_DEFAULT 1e-9
/* Tolerances this loose switch an adaptive method's error control off: every
 * trial is accepted and every step is the largest allowed (dt, or shorter to
 * land on a time asked for): the method's formula on fixed steps, whose
 * global error is what its order describes (bench measures it so). Finite,
 * so that rtol·0 stays 0 in the error norms. */
#define SW_TOL_NONE 1e300

/* The most methods the table holds, built-ins and registered plugins
 * together (engine/integrators.c checks its rows at compile time): the UI
 * has a key to pick each (lesson/controls.c checks, at compile time too). */
#define SW_METHODS_MAX 28
/* The most methods registered after the built-ins (loaded plugins). */
#define SW_REGISTERED_MAX 8

/* The built-in methods, in list order (positions 1..count in the UI). */
int sw_integrator_count(void);
const sw_integrator *sw_integrator_at(int index);
/* The method names joined with ", " into buf (cut to len); returns the
 * bytes written. */
size_t sw_integrator_names(char *buf, size_t len);
/* Look a method up by its exact name; NULL when there is none. */
const sw_integrator *sw_integrator_find(const char *name);
/* Register a method (a loaded plugin) after the built-ins; 0 or SW_EINVAL. */
int sw_integrator_register(const sw_integrator *method, char *err, size_t errlen);
/* Whether the method can step this system; when not, err says why. */
int sw_integrator_accepts(const sw_integrator *m, const sw_ode *ode, char *err, size_t errlen);

/* For a program that owns its state and steps it itself (the engine as a
 * library of integrators): a stepper of method m for systems like ode (its
 * workspace allocated here, once), NULL with err filled when m cannot
 * step ode or memory is short; then one step of at most h from (*t, y),
 * *t advanced, 0 or a negative status (a failed solve); then freed.
 * Adaptive methods use SW_RTOL_DEFAULT and SW_ATOL_DEFAULT. A stepper
 * belongs to one thread at a time. */
sw_stepper *sw_stepper_new(const sw_integrator *m, const sw_ode *ode, char *err, size_t errlen);
int sw_stepper_step(sw_stepper *s, sw_ode *ode, double *t, double *y, double h);
void sw_stepper_delete(sw_stepper *s);

/* Student plugins: a shared object exports
 *     const sw_plugin *sw_plugin_info(void);
 * returning a description of its integrator (see examples/euler_plugin.c). */
#define SW_PLUGIN_ABI 2
typedef int sw_plugin_step_fn(sw_ode *ode, double t, double *y, double h, double *work);
/* How a run's end reads where the step returned non-zero: the plugin
 * refused the step (a run that stopped, not one that diverged). */
#define SW_PLUGIN_REFUSED "the plugin's step function returned"
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
