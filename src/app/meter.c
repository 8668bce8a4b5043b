/* The meter's spectrum as the state moves: taken twenty times per report
 * time, or again after a reset (time went back). Where it takes a few
 * hundred products with a large system's Jacobian (the stiffest mode of a
 * chain of 1e5 beads by power iteration), or thousands of small
 * eigenproblems (a fluid's particles, each its own), it is a job run a
 * fixed number of passes per call, so no frame waits for it; the meter shows the last
 * spectrum until the next is done. Invariant: the number of passes per
 * call depends on the system's size only, never on the clock, so a run
 * reads the same numbers on any machine. */
#include "app/app.h"

#include <math.h>

#include "engine/particles_solve.h"
#include "stepwise/stepwise.h"

/* State components × passes one call may spend: 2^17, about a millisecond
 * here (a pass costs some 10 ns per component). Systems whose whole power
 * iteration fits are done at once, as before. */
#define METER_SLICE 131072L

static long passes_per_call(const sw_system *sys)
{
    /* a pass's cost: the state's components, or the pairs' blocks where a
     * force joins more pairs than there are particles (a galaxy: n²/2) */
    long pairs = sys->kind == SW_SYS_PARTICLES ? sw_particles_pair_count(&sys->particles) : 0;
    long per = METER_SLICE / (2L * (pairs > sys->n ? pairs : sys->n));
    return per < 1 ? 1 : per;
}

int sw_app_meter_pending(const sw_app *a) { return a->spec_job.active; }

/* The most pairs whose Jacobian the meter multiplies, a pass a frame at
 * the least: 2^21, a galaxy of 2000 stars (2e6 pairs, some 35 ms a pass
 * here); two of them (8e6) took 160 ms a frame, a galaxy of 1e5 has no
 * Jacobian at all (SW_PARTICLES_PAIRS_MAX). */
#define METER_PAIRS_MAX (1L << 21)

long sw_app_meter_out_of_reach(const sw_app *a)
{
    const sw_system *sys = &a->truth.sys;
    if (!a->have_truth || sys->kind != SW_SYS_PARTICLES)
        return 0;
    long pairs = sw_particles_pair_count(&sys->particles);
    return pairs > METER_PAIRS_MAX ? pairs : 0;
}

void sw_app_meter_refresh(sw_app *a)
{
    const sw_sim *s = &a->sims[0];
    sw_spectrum_job *j = &a->spec_job;
    double every = a->scene->duration / 20;
    int due = !a->have_spec || s->t < a->spec_t || s->t - a->spec_t >= every;
    if (j->active && s->t < j->t)
        j->active = 0; /* a reset: the job's state is gone */
    if (!j->active) {
        if (!due || sw_app_meter_out_of_reach(a)) /* (no Jacobian to take one from: said on the meter's line) */
            return;
        if (!sw_truth_spectrum_sliced(&a->truth.sys, METER_SLICE)) {
            a->have_spec = sw_truth_spectrum_with(a->meter_work, &a->truth.sys, s->t, s->sys.y, &a->spec) == 0;
            a->spec_t = s->t;
            a->meter.method = NULL; /* read again */
            return;
        }
        if (s->t < a->spec_t)
            j->warm_ok = 0; /* back in time: start afresh, as the first time */
        if (sw_spectrum_job_start(j, &a->truth.sys, s->t) != 0) {
            a->have_spec = 0;
            return;
        }
    }
    sw_spectrum sp;
    int rc = sw_spectrum_job_run(j, &a->truth.sys, s->sys.y, passes_per_call(&a->truth.sys), &sp);
    if (rc == 0)
        return;
    a->have_spec = rc == 1;
    if (rc == 1)
        a->spec = sp;
    a->spec_t = j->t;
    a->meter.method = NULL;
}

int sw_app_meter_settle(sw_app *a, long calls)
{
    for (long k = 0; k < calls && a->spec_job.active; k++)
        sw_app_meter_refresh(a);
    return !a->spec_job.active;
}
