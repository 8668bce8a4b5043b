/* The scene catalog: the lecture's examples as systems. A scene declares its
 * parameters, builds its system, and gives what it can of an exact solution,
 * an energy, an invariant, a viewport and its stiffest frequency. A scene
 * models only what it needs and never draws (drawing is the canvas's job). */
#ifndef STEPWISE_SCENE_H
#define STEPWISE_SCENE_H

#include <stddef.h>
#include "stepwise/ode.h"
#include "stepwise/flow.h"
#include "stepwise/particles.h"

#define SW_MAX_PARAMS 8

typedef struct sw_param {
    const char *name;
    double def, min, max;   /* default and allowed closed range */
    int integer;            /* 1: whole numbers only */
    const char *unit;       /* "" when dimensionless */
    const char *help;       /* one line */
} sw_param;

typedef enum sw_system_kind { SW_SYS_FLOW = 1, SW_SYS_PARTICLES = 2 } sw_system_kind;

typedef struct sw_view { double xmin, xmax, ymin, ymax; } sw_view;

struct sw_scene;
struct sw_system;

/* Where a scene's right-hand side is not smooth (docs/events.md): event
 * functions g_k(t, y), 0 <= k < count, each meeting its event where it
 * crosses zero in the declared direction, and the jump the state takes
 * there. With events located (sw_sim_set_events) a step that crosses one is
 * cut at the crossing, the jump applied and the step completed, so every
 * method keeps its order; stepped over, the scene's post_step meets it at
 * the step's end instead (first order). */
typedef struct sw_scene_events {
    /* How many event functions the built system has; 0: none for these parameters. */
    int (*count)(const struct sw_system *sys);
    /* g_k at (t, y): the event is where it crosses zero. */
    double (*g)(const struct sw_system *sys, int k, double t, const double *y);
    /* -1: only where g falls through zero, +1: only where it rises, 0: either. */
    int direction;
    /* Apply event k's jump to y (reached at the crossing, g_k just past zero);
     * NULL: nothing jumps in the state, the step must only end there. */
    void (*jump)(struct sw_system *sys, int k, double t, double *y);
    /* NULL, or: set the scene's discrete state for location from y (locate
     * 1: each side's force extended smoothly until an event's jump switches
     * it, so a step's stages never straddle a jump in f; 0: off, the plain
     * right-hand side). The sim calls it when the mode is set, on reset and
     * when the state is replaced. */
    void (*arm)(struct sw_system *sys, const double *y, int locate);
    /* What stepping over the events does to a method's order, one sentence
     * ending "see --events" (bench prints it); NULL: these parameters meet none. */
    const char *(*breaks)(const struct sw_system *sys);
} sw_scene_events;

/* A built scene: the system the solver steps plus the parameter values. */
typedef struct sw_system {
    const struct sw_scene *scene;
    sw_system_kind kind;
    double p[SW_MAX_PARAMS];  /* parameter values, in the scene's order */
    int n;                    /* particles (or flow points) */
    sw_ode *ode;              /* &flow.ode or &particles.ode */
    double *y;                /* the state, ode->dim doubles */
    sw_flow flow;
    sw_particles particles;
    double *extra;            /* scene-owned data (fireworks: birth times), or NULL */
    int nextra;
} sw_system;

typedef struct sw_scene {
    const char *name;
    sw_system_kind kind;      /* a flow (positions only) or particles with masses */
    const char *summary;      /* one line for `list scenes` */
    const char *teaches;      /* one sentence: the hard case it is there to show */
    const sw_param *params;
    int nparams;
    double dt;                /* default step */
    /* The default step for parameters p where it depends on them, at most
     * dt (a fluid's CFL limit falls with its particles' spacing); NULL:
     * dt. Read it through sw_scene_dt. */
    double (*step)(const double *p);
    const char *integrator;   /* default method name */
    double duration;          /* report time for bench and error */
    /* Build the system from sys->p; 0 or a status with err filled. */
    int (*build)(sw_system *sys, char *err, size_t errlen);
    /* Exact state at time t into y (ode->dim doubles); 0, or -1 when these
     * parameters have no closed form. NULL: never. */
    int (*exact)(const sw_system *sys, double t, double *y);
    /* Why the closed form does not hold for these parameters (one clause,
     * e.g. "the mass swings through its anchor, where the spring force turns
     * around"), or NULL when it holds. NULL hook: it holds whenever exact
     * is given. exact returns -1 exactly when this gives a reason. */
    const char *(*exact_fails)(const sw_system *sys);
    /* The least energy the system can have (its resting state), so that
     * E - floor is the energy of the motion; NULL when the scene gives none
     * (the truth module then finds a resting state where it can). */
    double (*energy_floor)(const sw_system *sys);
    /* Total energy at y; NULL when the scene defines none. */
    double (*energy)(const sw_system *sys, const double *y);
    /* A bound on |energy(y) - the exact energy| where energy is summed
     * approximately (a large galaxy's tree); NULL: energy is exact. */
    double (*energy_error)(const sw_system *sys, const double *y);
    /* How far a quantity exact paths keep constant (stream function, angular
     * momentum, radius) has drifted from its start: 0 on exact paths. NULL
     * when the scene has none. */
    double (*drift)(const sw_system *sys, const double *y);
    const char *drift_name;
    /* 1 when a tight-tolerance rk45 run is a trustworthy reference (0 where
     * events at step boundaries make every run, rk45 too, only first order). */
    int reference;
    /* The region to draw; required to be drawn (play, lesson). NULL: the
     * scene is not drawn, and a sim takes its runaway limit from the
     * state's own extent. */
    sw_view (*view)(const sw_system *sys);
    /* After each step: contact, births and deaths. Returns 1 when y changed. */
    int (*post_step)(sw_system *sys, double t, double *y);
    /* Whether particle i exists at time t (fireworks); NULL: always. */
    int (*alive)(const sw_system *sys, double t, const double *y, int i);
    /* Where the right-hand side is not smooth; NULL: nowhere. */
    const sw_scene_events *events;
    /* NULL, or why no run measures this scene's error (one clause): the
     * truth module then gives none, even with events located. */
    const char *no_truth;
    /* How hot particle i is at y, 0 (ambient) to 1 (the hottest it is
     * born), for drawing by temperature (fire); NULL: one glyph for all. */
    double (*heat)(const sw_system *sys, const double *y, int i);
} sw_scene;

int sw_scene_count(void);
const sw_scene *sw_scene_at(int index);
/* Find a scene by exact name; NULL when unknown. */
const sw_scene *sw_scene_find(const char *name);
/* The scene names joined with ", " into buf (cut to len); returns the bytes
 * written. For messages that say what is allowed. */
size_t sw_scene_names(char *buf, size_t len);
/* The same for a scene's parameter names. */
size_t sw_scene_param_names(const sw_scene *sc, char *buf, size_t len);
/* Index of a parameter by name, or -1. */
int sw_scene_param_index(const sw_scene *sc, const char *name);
/* Fill p with the defaults. */
void sw_scene_defaults(const sw_scene *sc, double *p);
/* The default step for parameters p (NULL: the defaults): sc->dt unless
 * the scene's step hook gives a smaller one for them. */
double sw_scene_dt(const sw_scene *sc, const double *p);
/* out (SW_MAX_PARAMS doubles) = the scene's nparams values from p, or its
 * defaults when p is NULL, then zeros, so whole arrays compare equal. */
void sw_scene_fill(const sw_scene *sc, const double *p, double *out);
/* Parse "NAME=VALUE" (blanks around '=' allowed) into p, checking name, number and range; 0 or SW_EINVAL
 * with a message naming what was wrong and what is allowed. */
int sw_scene_set(const sw_scene *sc, double *p, const char *assignment, char *err, size_t errlen);
/* Check one value against a parameter's declared range. */
int sw_scene_check_value(const sw_scene *sc, int index, double value, char *err, size_t errlen);

/* Event functions of the built system (0 when the scene declares none). */
int sw_system_event_count(const sw_system *sys);
/* The sentence saying what stepping over its events does to the order, or
 * NULL when the built system meets none. */
const char *sw_system_events_break(const sw_system *sys);

/* Build sc with parameter values p (NULL: defaults); 0 or a status. */
int sw_system_build(sw_system *sys, const sw_scene *sc, const double *p, char *err, size_t errlen);
void sw_system_free(sw_system *sys);
/* Reset the state to the scene's initial state (rebuilds in place). */
int sw_system_reset(sw_system *sys, char *err, size_t errlen);

#endif
