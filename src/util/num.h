/* Numbers from text, read in full and in the C locale's syntax, and the
 * constant π: what every parser and every scene shares. */
#ifndef SW_UTIL_NUM_H
#define SW_UTIL_NUM_H

#include <stddef.h>

#define SW_PI 3.14159265358979323846

/* Parse a finite double in full (no trailing bytes); 0 or SW_EINVAL. */
int sw_parse_double(const char *text, double *out);
/* Parse a whole decimal number in [min, max] in full; 0 or SW_EINVAL. */
int sw_parse_long(const char *text, long min, long max, long *out);

/* Shortest text that reads back as v ("0.02", "1e-09"); "inf", "-inf",
 * "nan" for non-finite values. */
void sw_fmt_shortest(char *buf, size_t len, double v);

#endif
