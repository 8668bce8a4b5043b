/* What every stepwise module shares: the version, the status codes library
 * calls return, and the size of the message buffers they fill. */
#ifndef STEPWISE_BASE_H
#define STEPWISE_BASE_H

#define SW_VERSION "0.1.0"
/* The version of the library linked in (SW_VERSION is the headers'). */
const char *sw_version(void);

/* Status codes returned by library calls; messages go to a caller buffer. */
enum {
    SW_OK = 0,
    SW_EINVAL = -1,  /* bad argument or input: the message says what is allowed */
    SW_ENOMEM = -2,  /* allocation failed */
    SW_EIO = -3,     /* a file could not be read or written */
    SW_EDIVERGED = -4 /* a step produced a non-finite or runaway state */
};

/* A message buffer that holds every library message whole. */
#define SW_ERRLEN 256

#endif
