/* Time under the student's control: a stop time the clock halts at (play
 * --until, a page's @until, the u key) and stepping back through each sim's
 * recent states (its history, sim/history.c). Invariant: every step the app
 * takes goes through sw_app_step_sim, so the history holds every state the
 * runs passed through (a large system's every stride-th: stepping back lands
 * on one of those), and a run stepped back and on again repeats itself bit
 * for bit. */
#include "app/app.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "stepwise/stepwise.h"

/* Steps the run-to-stop key takes per sim at most (a stop time far ahead of
 * a tiny dt: the key stops there and says so, as the clock would); fewer
 * where a step costs much: all sims together within 4 × a->work_key
 * (sw_truth_step_work), as the work-precision key. */
#define UNTIL_MAX_STEPS 20000000L

static long until_steps(const sw_app *a, const sw_sim *s)
{
    double steps = 4 * a->work_key / (a->nsims * sw_truth_step_work(&s->sys, s->method));
    return steps >= UNTIL_MAX_STEPS ? UNTIL_MAX_STEPS : steps >= 1 ? (long)steps : 1;
}

int sw_app_step_sim(sw_app *a, int i, double t_stop)
{
    int rc = sw_sim_step_until(&a->sims[i], t_stop);
    sw_history_push(&a->hist[i], &a->sims[i]);
    return rc;
}

void sw_app_history_attach(sw_app *a, int i)
{
    sw_history_init(&a->hist[i], &a->sims[i]);
    sw_history_push(&a->hist[i], &a->sims[i]);
}

void sw_app_history_detach(sw_app *a, int i) { sw_history_free(&a->hist[i]); }

void sw_app_history_restart(sw_app *a, int i)
{
    sw_history_restart(&a->hist[i], &a->sims[i]);
}

void sw_app_set_until(sw_app *a, double T) { a->until = T > 0 ? T : 0; }

/* Whether s is short of time T by more than the rounding of a sum of steps. */
static int short_of(const sw_sim *s, double T) { return T - s->t > 1e-9 * s->dt; }

double sw_app_stop_ahead(const sw_app *a)
{
    return a->until > 0 && short_of(&a->sims[0], a->until) ? a->until : 0;
}

int sw_app_stop_reached(sw_app *a, double stop)
{
    for (int i = 0; i < a->nsims; i++)
        if (!a->sims[i].blown && short_of(&a->sims[i], stop))
            return 0;
    /* The steps sum to the stop time up to rounding (0.01 added 250 times is
     * not 2.5 exactly): the last step was cut to land on it, and what is
     * left below 1e-9·dt is the sum's rounding, absorbed here. */
    for (int i = 0; i < a->nsims; i++)
        if (!a->sims[i].blown && a->sims[i].t != stop) {
            a->sims[i].t = stop;
            sw_sim_state_changed(&a->sims[i]);
            sw_history_retime(&a->hist[i], stop);
        }
    a->t_goal = stop;
    a->paused = 1;
    snprintf(a->message, sizeof a->message, "stopped at the stop time t = %g (space: run on past it; "
             "',': step back)", stop);
    /* a recording ends here: its trace (the until rule) can cut the last
     * step the same way, which a run going on past it could not describe */
    sw_app_record_stop(a);
    return 1;
}

int sw_app_run_to_stop(sw_app *a)
{
    if (!(a->until > 0)) {
        snprintf(a->message, sizeof a->message, "no stop time here: 'play --until T' or a page's @until T sets one");
        return 0;
    }
    double stop = sw_app_stop_ahead(a);
    if (!(stop > 0)) {
        a->paused = 1;
        snprintf(a->message, sizeof a->message, "already at or past the stop time t = %g (r: back to t = 0)",
                 a->until);
        return 1;
    }
    /* The graph and the phase paths get a sample every frame's worth of
     * simulated time, as if the clock had run there. */
    double every = a->speed / 60, next = a->sims[0].t + every;
    for (int i = 0; i < a->nsims; i++) {
        sw_sim *s = &a->sims[i];
        long most = until_steps(a, s);
        for (long n = 0; !s->blown && short_of(s, stop) && n < most; n++) {
            sw_app_step_sim(a, i, stop);
            if (i == 0)
                sw_app_watch_feed(a);
            if (i == a->nsims - 1 && s->t >= next) {
                sw_app_sample(a);
                next = s->t + every;
            }
        }
    }
    if (!sw_app_stop_reached(a, stop)) {
        a->paused = 1;
        a->t_goal = a->sims[0].t;
        snprintf(a->message, sizeof a->message, "%s short of the stop time t = %g (u goes on)",
                 a->sims[0].blown ? "blew up" : "stopped after many steps", stop);
    }
    sw_app_sample(a);
    return 1;
}

static void phase_cut(sw_phase_hist *h, double t)
{
    while (h->count > 0) {
        int newest = (h->head + SW_PHASE_HIST - 1) % SW_PHASE_HIST;
        if (!(h->t[newest] > t))
            break;
        h->head = newest;
        h->count--;
    }
}

int sw_app_step_back(sw_app *a, int n)
{
    sw_history *h = &a->hist[0];
    const sw_sim *s = &a->sims[0];
    a->paused = 1;
    if (!h->cap) {
        snprintf(a->message, sizeof a->message, "no rewind here: no memory to keep states of %d particles "
                 "(%.3g MB)", s->sys.n, (double)h->budget / 1e6);
        return 0;
    }
    int k = sw_history_pick(h, s, n);
    double target = sw_history_time(h, k);
    if (k < 0 || isnan(target)) {
        double from = sw_history_time(h, 0);
        if (h->wrapped && h->stride > 1)
            snprintf(a->message, sizeof a->message, "nothing earlier kept: %d checkpoints, %d steps apart, at "
                     "this size", h->cap, h->stride);
        else if (h->wrapped)
            snprintf(a->message, sizeof a->message, "nothing earlier kept: the last %d states are kept", h->cap);
        else
            snprintf(a->message, sizeof a->message, "nothing earlier kept: the history starts at t = %.4g (a "
                     "reset, or a change of method, dt or events, starts it)", isnan(from) ? s->t : from);
        return 0;
    }
    for (int i = 0; i < a->nsims; i++)
        sw_history_back_to(&a->hist[i], &a->sims[i], target);
    a->t_goal = s->t;
    for (int i = 0; i < SW_APP_SIMS; i++)
        sw_series_cut(&a->series[i], s->t);
    for (int i = 0; i <= SW_APP_SIMS; i++)
        phase_cut(&a->phase[i], s->t);
    sw_app_watch_restart(a);
    if (h->stride > 1)
        snprintf(a->message, sizeof a->message, "back to t = %.4g, step %ld (checkpoints every %d steps here; "
                 "%d earlier)", s->t, s->steps, h->stride, h->count - 1);
    else
        snprintf(a->message, sizeof a->message, "back to t = %.4g, step %ld (%d earlier states kept; . steps on)",
                 s->t, s->steps, h->count - 1);
    return 1;
}
