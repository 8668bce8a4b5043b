/* Private to sim/ and the app: a sim's recent past as a ring of snapshots,
 * so the student can step back and forward again. A snapshot holds all a
 * step reads besides the system's fixed data: time, counters, the state,
 * the scene's discrete data (sys->extra) and the method's carried memory
 * (the FSAL derivative, the adaptive step proposal), so a run restored and
 * stepped on gives the forward run's states bit for bit. */
#ifndef SW_SIM_HISTORY_H
#define SW_SIM_HISTORY_H

#include <stddef.h>

#include "stepwise/sim.h"

/* Snapshots kept per sim, and the memory they may take (a large system
 * keeps fewer; below SW_HISTORY_MIN it keeps none: rewind is off). */
#define SW_HISTORY_STATES 4096
#define SW_HISTORY_BYTES ((size_t)16 << 20)
#define SW_HISTORY_MIN 16

struct sw_history_meta;

typedef struct sw_history {
    int cap;                       /* snapshots the ring holds; 0: rewind off */
    int dim, nextra;               /* what one snapshot copies */
    int head, count;               /* the newest is at (head - 1), count of them */
    double *vec;                   /* cap × (2·dim + nextra) doubles */
    struct sw_history_meta *meta;  /* cap of them */
} sw_history;

/* Room for sim s's snapshots, allocated once (at most SW_HISTORY_STATES and
 * SW_HISTORY_BYTES); cap 0 (rewind off, not an error) when fewer than
 * SW_HISTORY_MIN fit or memory is short. Starts empty. */
void sw_history_init(sw_history *h, const sw_sim *s);
void sw_history_free(sw_history *h);
/* Forget every snapshot (a reset, a new method or dt: the past no longer
 * steps the same way). */
void sw_history_clear(sw_history *h);
/* Keep s's state now as the newest snapshot (the oldest goes when full); a
 * blown-up sim is not kept. */
void sw_history_push(sw_history *h, const sw_sim *s);
/* Time of the k-th newest snapshot (k = 0: the newest); NaN when there are
 * not that many. */
double sw_history_time(const sw_history *h, int k);
/* The newest snapshot's time set to t (the sim's clock landed on a stop
 * time its rounding had missed by less than 1e-9·dt). */
void sw_history_retime(sw_history *h, double t);
/* Drop the snapshots later than t (keeping at least one) and put s back to
 * the newest left. 1 when s moved, 0 when there was nothing earlier. */
int sw_history_back_to(sw_history *h, sw_sim *s, double t);

#endif
