/* Number parsing shared by every parser (flags, --set, lessons, traces).
 * Invariant: a value is accepted only when the whole text is the number. */
#include "util/num.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
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

void sw_fmt_shortest(char *buf, size_t len, double v)
{
    if (isnan(v)) {
        snprintf(buf, len, "nan");
        return;
    }
    if (isinf(v)) {
        snprintf(buf, len, v > 0 ? "inf" : "-inf");
        return;
    }
    if (v == floor(v) && fabs(v) < 1e15) {
        snprintf(buf, len, "%.0f", v); /* 60, not 6e+01 */
        return;
    }
    for (int prec = 1; prec <= 17; prec++) {
        snprintf(buf, len, "%.*g", prec, v);
        if (strtod(buf, NULL) == v)
            return;
    }
}
