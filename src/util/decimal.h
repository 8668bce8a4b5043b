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

/* The same, eight digits at a time: s's terminating NUL must be followed
 * by at least 7 more readable, initialised bytes (the trace reader's line
 * buffer keeps them zero), because a test of eight bytes may start at any
 * digit. */
double sw_decimal_parse_padded(const char *s, char **end);

/* Builds the table of powers of ten now rather than at first use: a parent
 * about to fork many readers (`stepwise grade`) builds it once for all. */
void sw_decimal_init(void);

#endif
