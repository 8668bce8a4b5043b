/* The one monotonic clock: never jumps with the time of day. */
#include "util/clock.h"

#include <time.h>

double sw_clock_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
