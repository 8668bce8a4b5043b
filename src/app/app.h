/* The live app, without a terminal: the sims on screen (main, compare,
 * ghost), the clock that turns wall time into steps, and every action a key
 * can trigger. The ncurses front end, `play --frames N --ascii` and the
 * lesson drive-tests all run this same model; only drawing differs. */
#ifndef SW_APP_APP_H
#define SW_APP_APP_H

#include <stddef.h>

#include "lesson/controls.h"
#include "stepwise/sim.h"

#define SW_APP_SIMS 3          /* main + two compare runs */
#define SW_APP_GRAPH 600       /* graph samples kept per sim (bounded) */
#define SW_APP_SPEED_MIN (1.0 / 64)
#define SW_APP_SPEED_MAX 1024.0

/* A bounded time series for the graph pane. */
typedef struct sw_series {
    double t[SW_APP_GRAPH], v[SW_APP_GRAPH];
    int len, stride, skip;  /* decimation: keep every stride-th sample */
} sw_series;

typedef struct sw_app {
    const sw_scene *scene;
    double p[SW_MAX_PARAMS];
    double dt;
    sw_sim sims[SW_APP_SIMS];
    int nsims;                  /* 1, or 3 with compare on */
    const sw_integrator *compare_methods[SW_APP_SIMS - 1];
    int compare, ghost, trails, graph, braille, panel, help, paused;
    int workprec;               /* 0 off, 1 error against evaluations, 2 against time */
    void *bench;                /* the work-precision sweep behind it (sw_bench_report) */
    int param_sel;
    double speed;               /* simulated seconds per wall second */
    double t_goal;              /* simulated time the clock asks for */
    double slowmo;              /* 1, or how many times slower than asked (>1) */
    double steps_per_sec;       /* measured by the front end */
    /* ghost: exact state, or a tight rk45 reference run in lockstep */
    double *ghost_y;
    double ghost_t;             /* time ghost_y holds the exact state for (NaN: none) */
    int exact_ok;               /* the scene has a closed form for these parameters */
    sw_sim ref;
    int have_ref;
    /* live error measurement at the scene's report time */
    double meas_dt[2], meas_err[2];
    const sw_integrator *meas_method[2];
    int nmeas;
    double error_ratio;         /* err(previous) / err(latest), NaN until comparable */
    sw_series series[SW_APP_SIMS];
    sw_lock_mask locked;        /* lock groups (SW_LOCK_*) a lesson page has taken away */
    char message[SW_ERRLEN + 64]; /* one-line feedback for the last action */
    int quit;
    int recorded;               /* a trace has been recorded this session */
    char record_path[256];      /* non-empty while recording */
    const sw_integrator *record_method;
    double record_dt;
    /* cache for sw_app_stability */
    const sw_integrator *growth_method;
    double growth_w, growth_g, growth_dt, growth;
} sw_app;

/* Build scene sc (p NULL: defaults) under method m (NULL: the scene's default)
 * with step dt (<= 0: the scene's default). 0 or a status with err filled. */
int sw_app_init(sw_app *a, const sw_scene *sc, const double *p, const sw_integrator *m, double dt,
                char *err, size_t errlen);
void sw_app_free(sw_app *a);
/* Replace scene and parameters (lessons, the parameter panel); keeps the methods. */
int sw_app_set_scene(sw_app *a, const sw_scene *sc, const double *p, char *err, size_t errlen);
/* Make m the main method (keeps state and time); 0 or SW_EINVAL with a message. */
int sw_app_set_method(sw_app *a, const sw_integrator *m);
/* Set dt for every sim (keeps state and time); 0 or SW_EINVAL. */
int sw_app_set_dt(sw_app *a, double dt);
/* Turn compare on with these two methods (NULL: a sensible pair) or off. */
int sw_app_set_compare(sw_app *a, int on, const sw_integrator *m1, const sw_integrator *m2);
void sw_app_set_ghost(sw_app *a, int on);
/* Apply an action (arg: which of its keys, 1-based: 1-9 pick that
 * integrator); sets a->message. Returns 1 when it changed anything. */
int sw_app_apply(sw_app *a, sw_action act, int arg);
/* Turn a key into its action (honouring locks and context) and apply it. */
int sw_app_key(sw_app *a, int key, int in_lesson);
/* Advance by wall seconds: simulated time wall·speed in whole steps of dt,
 * stopping early after max_steps steps per sim (then slowmo > 1). */
void sw_app_advance(sw_app *a, double wall, long max_steps);
/* Back to t = 0 for every sim. */
void sw_app_reset(sw_app *a);

/* The stiffest mode under the main method: ω·Δt, the method's limit on an
 * undamped oscillator (0: none, INFINITY: any step) and the growth factor
 * per step of that mode (spectral radius of the one-step map: > 1 grows);
 * returns 0 when the scene has no stiffest frequency. */
int sw_app_stability(sw_app *a, double *omega_dt, double *limit, double *growth);
/* The state the ghost shows now (exact, or the reference run advanced to
 * the main sim's time), or NULL when there is neither. */
const double *sw_app_ghost(sw_app *a);
/* The error of sim i now: against the exact solution or the reference. */
double sw_app_error(sw_app *a, int i);
/* One status line for sim i (exact integrator name, dt=, t, steps, evals, ...). */
void sw_app_status(sw_app *a, int i, char *buf, size_t len);
/* Start recording the main sim to path (NULL: a time-stamped name in the
 * working directory); restarts at t = 0. */
void sw_app_record_start(sw_app *a, const char *path);
/* Stop and write the trace (replaying the run exactly); sets a->message. */
void sw_app_record_stop(sw_app *a);

/* Error at the scene's report time for (method, dt), from a fresh headless
 * run; NaN when there is no exact solution or reference or it blew up. */
double sw_app_measure(sw_app *a, const sw_integrator *m, double dt);

#endif
