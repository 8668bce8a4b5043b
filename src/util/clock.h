/* Wall-clock timing for frame pacing and benchmarks. */
#ifndef SW_UTIL_CLOCK_H
#define SW_UTIL_CLOCK_H

/* Seconds on a monotonic clock (an arbitrary origin; differences only). */
double sw_clock_now(void);

#endif
