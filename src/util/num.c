/* Number parsing shared by every parser (flags, --set, lessons, traces).
 * Invariant: a value is accepted only when the whole text is the number. */
#include "util/num.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>

#include "stepwise/base.h"

int sw_parse_double(const char *text, double *out)
{
    if (!text || !*text)
        return SW_EINVAL;
    char *end;
    errno = 0;
    double v = strtod(text, &end);
    if (*end != '\0' || end == text || errno == ERANGE || !isfinite(v))
        return SW_EINVAL;
    *out = v;
    return SW_OK;
}

int sw_parse_long(const char *text, long min, long max, long *out)
{
    if (!text || !*text)
        return SW_EINVAL;
    char *end;
    errno = 0;
    long v = strtol(text, &end, 10);
    if (*end != '\0' || end == text || errno == ERANGE || v < min || v > max)
        return SW_EINVAL;
    *out = v;
    return SW_OK;
}
