/* Private to sim/ and the app: a sim's recent past as a ring of snapshots,
 * so the student can step back and forward again. A snapshot holds all a
 * step reads besides the system's fixed data: time, counters, the state,
 * the scene's discrete data (sys->extra) and the method's carried memory
 * (the FSAL derivative, the adaptive step proposal), so a run restored and
 * stepped on gives the forward run's states bit for bit. A large system
 * keeps a checkpoint every stride-th step, so that its ring still spans
 * SW_HISTORY_SPAN steps; stepping back lands on a checkpoint. */
#ifndef SW_SIM_HISTORY_H
#define SW_SIM_HISTORY_H

#include <stddef.h>

#include "stepwise/sim.h"

/* Snapshots kept per sim at most, and the memory they may take: the larger
 * of SW_HISTORY_BYTES and SW_HISTORY_COPIES snapshots (a system too large
 * for SW_HISTORY_SPAN snapshots with an FSAL derivative in it keeps a
 * checkpoint every stride-th step, the stride chosen so the ring still
 * spans SW_HISTORY_SPAN steps or more). */
#define SW_HISTORY_STATES 4096
#define SW_HISTORY_BYTES ((size_t)16 << 20)
#define SW_HISTORY_COPIES 2
#define SW_HISTORY_SPAN 64

struct sw_history_meta;

typedef struct sw_history {
    int cap;                       /* snapshots the ring holds; 0: rewind off */
    int stride;                    /* steps from one snapshot to the next (1: every step) */
    int since;                     /* steps taken since the newest snapshot */
    int dim, nextra;               /* what one snapshot copies */
    int head, count;               /* the newest is at (head - 1), count of them */
    int wrapped;                   /* an older snapshot made room for a newer one */
    size_t budget, bytes;          /* the memory allowed, and allocated */
    double *vec;                   /* cap × (dim + nextra) doubles: the state, scene data */
    double *cache;                 /* cap × dim doubles: FSAL derivatives; NULL for a
                                    * method without one (sw_history_keeps_cache) */
    struct sw_history_meta *meta;  /* cap of them */
} sw_history;

/* Room for sim s's snapshots under its method, allocated once within
 * h->budget (the larger of SW_HISTORY_BYTES and SW_HISTORY_COPIES
 * snapshots), at most SW_HISTORY_STATES of them, every stride-th step; cap
 * 0 (rewind off, not an error) only when memory is short. Starts empty. */
void sw_history_init(sw_history *h, const sw_sim *s);
void sw_history_free(sw_history *h);
/* Forget every snapshot (a reset, a new method or dt: the past no longer
 * steps the same way) and keep s's state as the first; room made again
 * when s's method keeps an FSAL derivative and the old one did not, or
 * the other way round. */
void sw_history_restart(sw_history *h, const sw_sim *s);
/* Whether a snapshot of a run of m needs room for an FSAL derivative: the
 * methods whose steps set the stepper's have_cache (tests/check_timeline.c
 * steps every built-in method to check it). */
int sw_history_keeps_cache(const sw_integrator *m);
/* s took a step: keep its state as the newest snapshot when it is the
 * stride-th step since the last one, or the first (the oldest goes when
 * full); a blown-up sim is not kept. */
void sw_history_push(sw_history *h, const sw_sim *s);
/* The snapshot (k = 0: the newest) that going back n steps from s lands on:
 * the newest at least n steps back (a blown-up s counts its failed step),
 * or the oldest; -1 when none is earlier than s. */
int sw_history_pick(const sw_history *h, const sw_sim *s, int n);
/* Time of the k-th newest snapshot (k = 0: the newest); NaN when there are
 * not that many. */
double sw_history_time(const sw_history *h, int k);
/* The sim's clock landed on a stop time t its rounding had missed by less
 * than 1e-9·dt: the newest snapshot's time set to t when it is that state. */
void sw_history_retime(sw_history *h, double t);
/* Drop the snapshots later than t (keeping at least one) and put s back to
 * the newest left. 1 when s moved, 0 when there was nothing earlier. */
int sw_history_back_to(sw_history *h, sw_sim *s, double t);

#endif
