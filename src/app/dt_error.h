/* The error at the scene's report time when Δt changes: fresh runs at the
 * old and the new step against the truth, their ratio and the message that
 * says whether it reads as an order. Everything it reads is a copy taken
 * from the app (sw_dt_in) or a cache it owns (sw_dt_cache), so that it can
 * run on a worker thread while the picture moves (issue 41: at n = 1e5 the
 * runs held the picture for 140 ms) and give the same bits there as here. */
#ifndef SW_APP_DT_ERROR_H
#define SW_APP_DT_ERROR_H

#include <stdatomic.h>
#include <stddef.h>

#include "sim/truth.h"
#include "stepwise/sim.h"

/* What the measurement reads, copied from the app when the key is pressed. */
typedef struct sw_dt_in {
    const sw_scene *sc;          /* read-only */
    double p[SW_MAX_PARAMS];
    sw_events_mode events;       /* the runs meet events as the run on screen does */
    const sw_integrator *m;      /* the main method */
    double old_dt, dt;           /* the step before and after the key */
    double work_key;             /* what one key press may spend (sw_app's) */
    double step_work;            /* sw_truth_step_work of m on the main run's system */
    int dim, order;              /* the main run's state: its length, 1 flow or 2 particles */
    int have_truth;              /* the app's truth was built ... */
    double truth_cost;           /* ... and a reference run to the report time costs this */
    char truth_why[SW_ERRLEN];   /* sw_app_truth_why: why there is no truth, or "" */
    const atomic_int *stop;      /* NULL, or set by another thread: end at the next sample time */
} sw_dt_in;

/* What a scene's measurements keep between key presses (freed with
 * sw_dt_cache_free; one thread at a time). */
typedef struct sw_dt_cache {
    double *truth_report;        /* the true state at the sample times to the report time
                                    (SW_TRUTH_SAMPLES × dim, sw_truth_sample_time) */
    int have_truth_report;
    sw_spectrum spec0;           /* the spectrum at the start */
    int have_spec0;
    sw_truth_work *work;         /* the spectrum's workspace */
} sw_dt_cache;

/* What the measurement found. */
typedef struct sw_dt_result {
    double err[2];               /* the errors at old_dt and dt (NaN: none) */
    double error_ratio;          /* err(previous) / err(latest) where it reads as an order, else NaN */
    char message[512];           /* which, or why not ("dt=...: ...") */
    int stopped;                 /* 1: asked to stop before the end (nothing else is set) */
} sw_dt_result;

void sw_dt_cache_free(sw_dt_cache *c);

/* The error of state y against truth for a system of dim components and
 * order 1 (a flow) or 2 (y = [x | v]): positions (velocity 0) or
 * velocities (1; NaN for a flow, which has none). */
double sw_dt_state_error(int dim, int order, const double *y, const double *truth, int velocity);

/* Error at the report time for (m, dt) from a fresh headless run: the
 * largest over SW_TRUTH_SAMPLES sample times. NaN when the run would cost
 * more than in->work_key, there is no truth, the run blew up or it was
 * stopped. */
double sw_dt_error(const sw_dt_in *in, sw_dt_cache *c, const sw_integrator *m, double dt);

/* The whole measurement for in->old_dt -> in->dt (and a third run at half
 * the smaller step where the order rule needs it). */
void sw_dt_change(const sw_dt_in *in, sw_dt_cache *c, sw_dt_result *out);

/* What sw_dt_change may spend, in state evaluations: an estimate (the runs
 * within the budget, the reference run when not cached, the spectrum's
 * passes), for deciding where to run it. */
double sw_dt_change_work(const sw_dt_in *in, const sw_dt_cache *c);

#endif
