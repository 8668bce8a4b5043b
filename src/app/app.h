/* The live app, without a terminal: the sims on screen (main, compare,
 * ghost), the clock that turns wall time into steps, and every action a key
 * can trigger. The ncurses front end, `play --frames N --ascii` and the
 * lesson drive-tests all run this same model; only drawing differs. */
#ifndef SW_APP_APP_H
#define SW_APP_APP_H

#include <stddef.h>

#include "app/dt_error.h"
#include "sim/history.h"
#include "sim/stages.h"
#include "sim/truth.h"
#include "sim/watch.h"
#include "lesson/controls.h"
#include "stepwise/sim.h"

#define SW_APP_SIMS 3          /* main + two compare runs */
#define SW_APP_GRAPH 600       /* graph samples kept per sim (bounded) */
#define SW_APP_BACK_MANY 50    /* steps the rewind key goes back */
#define SW_APP_UNTIL_MAX 1e6   /* the latest stop time, in seconds */
#define SW_APP_SPEED_MIN (1.0 / 64)
#define SW_APP_SPEED_MAX 1024.0
/* What a Δt change's measurement may spend on the picture's thread, in
 * state evaluations (about 4 ms at 2.5e8 a second): above it, it runs on a
 * worker and the message says so until the figure is in. */
#define SW_APP_WORK_INLINE 1e6
/* The message while it runs: "dt=NEW: " before it, the old and the new
 * step and the report time in it. */
#define SW_APP_MEASURING "measuring the error at dt=%g and dt=%g"

/* A bounded time series for the graph pane. */
typedef struct sw_series {
    double t[SW_APP_GRAPH], v[SW_APP_GRAPH];
    int len, stride, skip;  /* decimation: keep every stride-th sample */
} sw_series;

/* The stability meter: the current method on the current linearisation. */
typedef struct sw_app_meter {
    int ok;                     /* 0: no reading (an adaptive method, no spectrum) */
    const sw_integrator *method;
    double dt, t;               /* what it was read for */
    double stiff;               /* largest |λ| of the linearisation now */
    double limit;               /* largest stable dt in theory here: 0 none */
    double limit_undamped;      /* the same with every oscillating mode's damping taken away
                                   (what a lesson's closed form gives): 0 when no mode is damped */
    int unbounded;              /* ... no limit up to SW_DT_MAX */
    double growth;              /* ρ: growth per step of the worst mode at dt (the largest over the modes) */
    double growth_lambda;       /* |λ| of the mode ρ belongs to (NaN: unknown) */
    double fast_growth;         /* the stiffest mode's own growth per step at dt (NaN: unknown) */
    int grows;                  /* ρ grows the mode by > 1% over the horizon: a run shows it */
    int slow;                   /* 1: ρ > 1 + SW_TRUTH_NEUTRAL, -1: ρ < 1 - SW_TRUTH_NEUTRAL, but
                                   either by under 1% over the horizon: too slowly to show; else 0 */
    double horizon;             /* the horizon (sw_truth_horizon) */
    int complete;               /* every eigenvalue (0: the stiffest mode only) */
    int growing;                /* physically growing modes left out */
} sw_app_meter;

/* What the picture shows. */
typedef enum sw_app_view {
    SW_VIEW_SCENE = 0,   /* the particles in the plane */
    SW_VIEW_PHASE = 1,   /* a coordinate against its velocity */
    SW_VIEW_REGION = 2   /* the method's region of absolute stability, dt x eigenvalues marked */
} sw_app_view;

/* The phase view's coordinates (app/phase.c). */
typedef enum sw_phase_coord {
    SW_PHASE_STRETCH,    /* a spring's length minus its rest length, and its rate */
    SW_PHASE_ANGLE,      /* the angle about a spring's anchor from straight down, and its rate */
    SW_PHASE_RADIUS,     /* the distance from the central body, and its rate */
    SW_PHASE_X,          /* x and vx */
    SW_PHASE_Y,          /* y and vy */
    SW_PHASE_PLANE,      /* a flow's point: x against y (its whole state) */
    SW_PHASE_NCOORDS
} sw_phase_coord;

#define SW_PHASE_HIST 2048     /* phase points kept per sim (a ring) */

/* A sim's path in the phase plane: one point per frame and per single step. */
typedef struct sw_phase_hist {
    double q[SW_PHASE_HIST], v[SW_PHASE_HIST], t[SW_PHASE_HIST];
    int head, count;
} sw_phase_hist;

typedef struct sw_app {
    const sw_scene *scene;
    double p[SW_MAX_PARAMS];
    double dt;
    sw_sim sims[SW_APP_SIMS];
    int nsims;                  /* 1, or 3 with compare on */
    const sw_integrator *compare_methods[SW_APP_SIMS - 1];
    int compare_one;            /* compare runs compare_methods[0] alone beside the main run */
    unsigned epoch;             /* counts fresh starts (reset, new scene, a lesson page): the picture
                                   forgets its trails when it changes */
    int err_velocity;           /* the status line's error: 0 positions (m), 1 velocities (m/s) */
    int compare, ghost, trails, graph, braille, panel, help, paused;
    sw_events_mode events;      /* how every sim meets the scene's events (x toggles) */
    int workprec;               /* 0 off, 1 error against evaluations, 2 against time */
    void *bench;                /* the work-precision sweep behind it (sw_bench_report) */
    const sw_integrator *wp_only[16]; /* a lesson page: the methods the plot shows (those the
                                   lesson has used so far); wp_nonly 0: every method swept */
    int wp_nonly;
    struct sw_sweep *sweep;     /* ... while it is measured on a worker thread (app/sweep.h) */
    int param_sel;
    double speed;               /* simulated seconds per wall second */
    double t_goal;              /* simulated time the clock asks for */
    double slowmo;              /* 1, or how many times slower than asked (>1) */
    double steps_per_sec;       /* measured by the front end */
    /* the truth for the scene on screen: the ghost and every error */
    sw_truth truth;
    int have_truth;
    int truth_live;             /* the truth can follow the run live (a reference within budget) */
    double truth_cost;          /* a reference run's cost per report time (0: closed form) */
    double work_key;            /* what one key press may spend, in state evaluations: SW_WORK_KEY
                                   (a sanitized fuzzer lowers it, so a unit stays short) */
    double work_inline;         /* what it may spend on the picture's thread: SW_APP_WORK_INLINE
                                   (a test sets 0 to send every measurement to the worker) */
    sw_dt_cache dt_cache;       /* the truth at the report time and the spectrum at the start,
                                   once asked for (the worker's while it runs) */
    struct sw_dt_job *dt_job;   /* a Δt change's measurement on a worker thread (app/dt_job.h) */
    /* live error measurement at the scene's report time (when the job is in) */
    double meas_dt[2], meas_err[2];
    const sw_integrator *meas_method[2];
    int nmeas;
    double error_ratio;         /* err(previous) / err(latest), NaN until comparable */
    sw_series series[SW_APP_SIMS];
    sw_lock_mask locked;        /* lock groups (SW_LOCK_*) a lesson page has taken away */
    char message[512];          /* one-line feedback for the last action */
    int quit;
    int recorded;               /* a trace has been recorded this session */
    char record_path[256];      /* non-empty while recording */
    const sw_integrator *record_method;
    double record_dt;
    /* the meter: spectra at the start and now, and what they gave */
    sw_spectrum spec;
    int have_spec;
    double spec_t;              /* time spec was taken at */
    sw_app_meter meter;         /* the last reading */
    sw_truth_work *meter_work;  /* the meter's reusable workspace (allocates nothing per frame) */
    sw_spectrum_job spec_job;   /* a large system's spectrum, a slice per call (meter.c) */
    /* the main run watched for growth of its motion's energy, since the
     * last reset or change of method or dt (relative to its value then) */
    sw_watch watch;
    double watch_m0;
    /* the picture (app/view.c): which view, the camera, compare's layout */
    sw_app_view view;
    unsigned view_gen;          /* changes when a view is chosen or a page entered: the region view fits its scale anew */
    int follow;                 /* 1: the camera follows the particles; 0: fixed on the scene's view */
    double zoom;                /* the view's spans times this (1: the scene's natural view) */
    int have_box;               /* 1: the camera shows box (a page's @view box=), not the scene's view */
    sw_view box;
    int lanes;                  /* compare: each method in its own lane */
    int phase_particle;         /* the phase view's particle and coordinate */
    sw_phase_coord phase_coord;
    sw_phase_hist phase[SW_APP_SIMS + 1]; /* the sims' paths, then the truth's (reference runs) */
    /* time under the student's control (app/timeline.c) */
    double until;               /* the stop time (play --until, a page's @until): 0 none */
    sw_history hist[SW_APP_SIMS]; /* each sim's recent states, for stepping back */
    /* the stage view (app/stages.c): one step of the main run, stage by stage */
    int stages_open;            /* 1 while shown (the run is paused) */
    int stage_shown;            /* 1..: how far through the step's script */
    sw_stages stages;           /* the step recorded (re-recorded when the run moved) */
    char stages_why[160];       /* why the method's stages are not drawn, or "" */
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
/* Compare on with exactly these n (1 or 2) methods beside the main one (a
 * lesson's @compare NAME [NAME]). */
int sw_app_compare_with(sw_app *a, const sw_integrator *const *m, int n);
void sw_app_set_ghost(sw_app *a, int on);
/* Meet events by mode in every sim from now on (state and time kept). */
void sw_app_set_events(sw_app *a, sw_events_mode mode);
/* Apply an action (arg: which of its keys, 1-based: the pick keys' place
 * is the integrator's); sets a->message. Returns 1 when it changed anything. */
int sw_app_apply(sw_app *a, sw_action act, int arg);
/* Turn a key into its action (honouring locks and context) and apply it. */
int sw_app_key(sw_app *a, int key, int in_lesson);
/* What key would work at for up to a key press's budget before it returns
 * (the work-precision sweep, the runs a Δt change measures, the run to the
 * stop time): a line for the screen to show first; NULL for a quick key. */
const char *sw_app_key_notice(const sw_app *a, int key, int in_lesson);
/* Advance by wall seconds: simulated time wall·speed in whole steps of dt,
 * stopping early after max_steps steps per sim (then slowmo > 1). */
void sw_app_advance(sw_app *a, double wall, long max_steps);
/* The work-precision sweep's worker: wait for its report (tests). */
void sw_app_sweep_wait(sw_app *a);
/* Back to t = 0 for every sim. */
void sw_app_reset(sw_app *a);
/* (plugins.c) After stepping: a sim whose plugin failed (crash, exit, loop,
 * overrun) has the plugin disabled and its method set to the scene's; msg
 * says what happened. Returns how many sims were switched (the caller
 * restarts them from t = 0). */
int sw_app_plugins_disable_failed(sw_app *a, char *msg, size_t len);

/* (view.c) The view actions, each 1 (handled): zoom out (out) or in, the
 * camera following or fixed, compare in lanes or overlaid, the phase view
 * and its coordinate (how: 1 the next coordinate, +2/-2 the next/previous
 * particle), the stability region. */
int sw_app_zoom(sw_app *a, int out);
int sw_app_toggle_follow(sw_app *a);
int sw_app_toggle_lanes(sw_app *a);
int sw_app_toggle_phase(sw_app *a);
int sw_app_phase_next(sw_app *a, int how);
int sw_app_toggle_region(sw_app *a);
/* (view.c) Set the view (the lesson's @view); resets nothing. */
void sw_app_set_view(sw_app *a, sw_app_view v);
/* (view.c) Forget the phase paths (a reset, a new scene or coordinate). */
void sw_app_phase_clear(sw_app *a);
/* (view.c) Add every sim's current phase point to its path (and the truth's). */
void sw_app_phase_push(sw_app *a);

/* (phase.c) Whether coordinate c of particle i exists in sys (a spring to an
 * anchor for stretch and angle, a central body for radius, particles for x
 * and y, a flow for the plane). */
int sw_phase_available(const sw_system *sys, int i, sw_phase_coord c);
/* (phase.c) The coordinate and its rate at state y: 1, or 0 when it is not
 * available or not finite. */
int sw_phase_point(const sw_system *sys, const double *y, int i, sw_phase_coord c, double *q, double *v);
/* (phase.c) The scene's natural choice: the spring's stretch, the pendulum's
 * angle, the chain's middle bead (y), the orbit's radius, a flow's first point. */
void sw_phase_default(const sw_system *sys, int *i, sw_phase_coord *c);
/* (phase.c) The names of a coordinate and its rate, with units ("stretch",
 * "m", "rate", "m/s"). */
void sw_phase_names(sw_phase_coord c, const char **q, const char **q_unit, const char **v, const char **v_unit);
/* (phase.c) The next available coordinate (dir +1) or particle (dir +-2: next/previous). */
void sw_phase_cycle(const sw_system *sys, int *i, sw_phase_coord *c, int dir);

/* (timeline.c) One step of sim i, never past t_stop when t_stop > its t
 * (sw_sim_step_until), kept in its history; 0, or 1 when it has blown up. */
int sw_app_step_sim(sw_app *a, int i, double t_stop);
/* (timeline.c) Sim i's history: made when the sim is (allocated once, its
 * first state kept), freed with it, started again from the state now when
 * the run's rules change (reset, method, dt, events). */
void sw_app_history_attach(sw_app *a, int i);
void sw_app_history_detach(sw_app *a, int i);
void sw_app_history_restart(sw_app *a, int i);
/* (timeline.c) The stop time the clock halts at (T <= 0: none). */
void sw_app_set_until(sw_app *a, double T);
/* (timeline.c) The stop time still ahead of the main run, else 0. */
double sw_app_stop_ahead(const sw_app *a);
/* (timeline.c) After advancing towards stop: when every run still going
 * has reached it, land each exactly on it, pause and say so; 1 then. */
int sw_app_stop_reached(sw_app *a, double stop);
/* (timeline.c) The run-to-stop key: every sim stepped to the stop time now
 * (the graph and phase paths sampled on the way), then paused. */
int sw_app_run_to_stop(sw_app *a);
/* (timeline.c) Back n steps of the main run (every sim to that time, the
 * graph and paths cut there), paused; 1 when anything moved. */
int sw_app_step_back(sw_app *a, int n);
/* (series.c) One graph sample and one phase point for every sim, now (what
 * a frame of the clock adds). */
void sw_app_sample(sw_app *a);
/* (series.c) Empty a graph series; keep only its samples up to time t. */
void sw_series_clear(sw_series *s);
void sw_series_cut(sw_series *s, double t);

/* (measure.c) Start watching the main run again from now. */
void sw_app_watch_restart(sw_app *a);
/* (measure.c) Feed the watch the main run's state after it advanced. */
void sw_app_watch_feed(sw_app *a);

/* The meter for the main method now (read from the truth module, cached:
 * the spectrum is refreshed as the state moves, twenty times per report
 * time). Returns m->ok. */
int sw_app_stability(sw_app *a, sw_app_meter *m);
/* (meter.c) Take the spectrum again when due, or run its job on by one
 * slice (a fixed number of passes for the system's size); the meter keeps
 * the last spectrum until the job is done. */
void sw_app_meter_refresh(sw_app *a);
/* (meter.c) 1 while a spectrum job is under way. */
int sw_app_meter_pending(const sw_app *a);
/* (meter.c) The pairs the forces join when there are too many to take a
 * spectrum from frame to frame (2^21): none is taken; else 0. */
long sw_app_meter_out_of_reach(const sw_app *a);
/* (meter.c) Run the spectrum job on, up to `calls` slices, until it is
 * done; 1 when no job is under way. */
int sw_app_meter_settle(sw_app *a, long calls);
/* The state the ghost shows now (exact, or the reference run advanced to
 * the main sim's time), or NULL when there is neither. */
const double *sw_app_ghost(sw_app *a);
/* The error of sim i now against the exact solution or the reference, in
 * metres: the largest distance of a position coordinate from the truth's
 * (with err_velocity set: of a velocity, in m/s; NaN for a flow). NaN when
 * there is no truth or the run blew up. */
double sw_app_error(sw_app *a, int i);
/* A field of a status line: its full and brief forms and how much it
 * matters (higher is kept longer when the line must shrink). */
typedef struct sw_field {
    char full[160];
    char brief[64];   /* "": none (the field is dropped whole) */
    int prio;
} sw_field;
#define SW_STATUS_FIELDS 12
/* (status.c) The fields of sim i's status line; returns how many. */
int sw_app_status_fields(sw_app *a, int i, sw_field *f, int max);
/* (status.c) The meter's line as fields (stiffness·dt against its limit,
 * the growth per step and its one word); *warn set when it should stand out. */
int sw_app_meter_fields(sw_app *a, sw_field *f, int max, int *warn);
/* (status.c) The growth per step rho as text "×1.000000" into num, with as
 * many digits as it takes for the printed number to agree with the word
 * returned ("grows", "grows slowly" and "decays slowly": too little to see
 * over the meter's horizon, "decays", "neutral"): grows is the meter's
 * visible growth, slow its invisible growth (1) or decay (-1); both 0: the
 * word from rho alone (beyond SW_TRUTH_NEUTRAL of 1: grows or decays). */
const char *sw_app_growth_text(double rho, int grows, int slow, char *num, size_t len);
/* (status.c) One status line for sim i, every field in full (exact
 * integrator name, dt=, t, steps, evals, ...). */
void sw_app_status(sw_app *a, int i, char *buf, size_t len);
/* (record.c) Begin recording the main sim to path (NULL: a time-stamped
 * name in the working directory) from the state now, which must be t = 0
 * (the caller has just reset: R does); sets a->message. */
void sw_app_record_begin(sw_app *a, const char *path);
/* (record.c) Stop and write the trace (replaying the run exactly); sets a->message. */
void sw_app_record_stop(sw_app *a);

/* (measure.c) Rebuild the truth for the app's scene and parameters. */
void sw_app_truth_reset(sw_app *a);
/* (measure.c) Why there is no ghost or error here, into buf ("" when there is). */
const char *sw_app_truth_why(const sw_app *a, char *buf, size_t len);
/* (measure.c) After a dt change: the errors at the report time at both
 * steps, their ratio in a->error_ratio only when it can be read as an order
 * (else NaN), and a message saying which, or why not. Where that may take
 * long (over a->work_inline) it runs on a worker: meanwhile the message
 * says so (SW_APP_MEASURING), nmeas is 0 and error_ratio NaN; the figures
 * and the message come in at the frame after it is done (sw_app_advance). */
void sw_app_measure_dt_change(sw_app *a, double old_dt);
/* (measure.c) Take the measurement's figures if its worker is done. */
void sw_app_dt_poll(sw_app *a);
/* (measure.c) Wait for the measurement under way, if any, and take its
 * figures (tests, lesson checks: a condition, never a timer). */
void sw_app_dt_wait(sw_app *a);
/* (measure.c) Stop the measurement under way, if any (its settings changed). */
void sw_app_dt_cancel(sw_app *a);

/* Error at the scene's report time for (method, dt), from a fresh headless
 * run, on this thread (after waiting for the worker's measurement); NaN
 * when there is no exact solution or reference or it blew up. */
double sw_app_measure(sw_app *a, const sw_integrator *m, double dt);

#endif
