/* Private to sim/: event location inside a step (events.c). */
#ifndef SW_SIM_EVENTS_H
#define SW_SIM_EVENTS_H

#include "stepwise/sim.h"

/* Most events met inside one step; past it the rest of the step is taken
 * whole and post_step meets what is left (a ball coming to rest, whose
 * hops shrink without end). */
#define SW_EVENTS_PER_STEP 64

/* One step of at most h with the scene's events located: each crossing cut
 * at its time (regula falsi, Illinois, on the method's own step from the
 * sub-step's start), the jump applied, the step completed. A fixed-step
 * method ends at t + h exactly; an adaptive one where its first accepted
 * step ended. 0, or the stepper's failing status (s->t then is where the
 * step stopped). */
int sw_sim_locate_step(sw_sim *s, double h);
/* 1 when the last step was cut at an event (its state changed from outside
 * the method: the whole state is checked again). */
int sw_sim_events_cut(const sw_sim *s);
/* sw_sim_set_events without forgetting what the sim worked out from its
 * state (sim.c's wrapper does that: arming may change sys->extra). */
int sw_sim_events_set_mode(sw_sim *s, sw_events_mode mode, char *err, size_t errlen);
/* Set the scene's discrete state for the sim's mode from its state. */
void sw_sim_events_arm(sw_sim *s);
/* Back to none located (the sim was reset). */
void sw_sim_events_reset(sw_sim *s);
/* Put back the count of events located and the last one's time (a sim
 * restored from its history); nothing in step mode. */
void sw_sim_events_restore(sw_sim *s, long located, double last_time);
/* Release the location workspace. */
void sw_sim_events_free(sw_sim *s);

#endif
