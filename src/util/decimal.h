/* A decimal number read as strtod reads it, bit for bit, at a fraction of
 * its cost: the trace reader's parser (a class's traces are millions of
 * numbers). */
#ifndef SW_UTIL_DECIMAL_H
#define SW_UTIL_DECIMAL_H

/* Exactly strtod(s, end) in the C locale: the same double, the same *end
 * (errno aside). A plain decimal ([+-]digits[.digits][e[+-]digits], at
 * most 19 significant digits, the power of ten within ±300) is converted
 * here, correctly rounded (Clinger's fast path, else Eisel and Lemire's
 * 128-bit product); anything else, and the rare product too close to a
 * halfway point to decide, is handed to strtod. */
double sw_decimal_parse(const char *s, char **end);

#endif
