/* stepwise — numerical integration of particle systems, taught in a terminal.
 * Umbrella header: version, status codes, and every public module. */
#ifndef STEPWISE_H
#define STEPWISE_H

#define SW_VERSION "0.1.0"

/* Status codes returned by library calls; messages go to a caller buffer. */
enum {
    SW_OK = 0,
    SW_EINVAL = -1,  /* bad argument or input: the message says what is allowed */
    SW_ENOMEM = -2,  /* allocation failed */
    SW_EIO = -3,     /* a file could not be read or written */
    SW_EDIVERGED = -4 /* a step produced a non-finite or runaway state */
};

#define SW_ERRLEN 256

#include "stepwise/vec2.h"
#include "stepwise/ode.h"
#include "stepwise/integrator.h"

#endif
