/* UTF-8: encoding a code point, decoding leniently for display, checking
 * strictly for input, and counting characters. Pure; no locale. */
#ifndef SW_UTIL_UTF8_H
#define SW_UTIL_UTF8_H

#include <stddef.h>
#include <stdint.h>

/* UTF-8 bytes of code point cp into out (not NUL-terminated); returns 1..4.
 * Surrogates and values above U+10FFFF encode as '?'. */
int sw_utf8_encode(uint32_t cp, char out[4]);

/* Decode the sequence at *p and advance past it; an invalid lead or a
 * missing continuation byte yields '?' and consumes one byte. *p must not
 * point at the terminating NUL. */
uint32_t sw_utf8_next(const unsigned char **p);

/* What sw_utf8_check found wrong. */
enum {
    SW_UTF8_OK = 0,
    SW_UTF8_BAD_LEAD,    /* a byte that cannot start a character */
    SW_UTF8_CUT,         /* a lead byte whose continuation bytes are missing */
    SW_UTF8_BAD_RANGE    /* overlong, a surrogate, or past U+10FFFF */
};

/* Strictly check the sequence starting at s[0] (avail bytes readable): on
 * SW_UTF8_OK, *len is its length in bytes (1..4) and *cp its code point. */
int sw_utf8_check(const unsigned char *s, size_t avail, size_t *len, uint32_t *cp);

/* Characters (lead bytes) in s[0..len). */
size_t sw_utf8_count(const char *s, size_t len);

/* The length of s[0..len) cut to at most max bytes on a character boundary. */
size_t sw_utf8_clip(const char *s, size_t len, size_t max);

#endif
