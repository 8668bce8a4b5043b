/* stepwise — numerical integration of particle systems, taught in a terminal.
 * Umbrella header: every public module. An embedder includes this; a plugin
 * needs only <stepwise/integrator.h> (see docs/plugins.md). */
#ifndef STEPWISE_STEPWISE_H
#define STEPWISE_STEPWISE_H

#include "stepwise/base.h"        /* version, status codes */
#include "stepwise/ode.h"         /* the solver's view of a system */
#include "stepwise/integrator.h"  /* the method table and the plugin description */
#include "stepwise/flow.h"        /* first-order flow-field systems */
#include "stepwise/particles.h"   /* particle systems and their forces */
#include "stepwise/scene.h"       /* the scene catalog */
#include "stepwise/sim.h"         /* a running simulation */

#endif
