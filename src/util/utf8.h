/* UTF-8: encoding a code point, decoding leniently for display, checking
 * strictly for input, counting characters and display cells. Pure, and the
 * same in every locale, except sw_utf8_locale, which asks the locale. */
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

/* 1 when cp is invisible formatting that can reorder or hide text on a
 * terminal: the bidirectional controls (U+061C, U+200E-F, U+202A-E,
 * U+2066-9), zero-width characters (U+180E, U+200B-D, U+2060-5, U+FEFF),
 * the line and paragraph separators (U+2028-9), the deprecated format
 * characters (U+206A-F), the interlinear annotation marks (U+FFF9-B) and
 * the tag characters (U+E0000-7F); else 0. */
int sw_utf8_invisible(uint32_t cp);

/* Characters (lead bytes) in s[0..len). */
size_t sw_utf8_count(const char *s, size_t len);

/* The length of s[0..len) cut to at most max bytes on a character boundary. */
size_t sw_utf8_clip(const char *s, size_t len, size_t max);

/* Cells a code point takes on a terminal: 0 (a control, a combining mark,
 * a zero-width character), 2 (East Asian wide, an emoji picture) or 1. */
int sw_utf8_width(uint32_t cp);

/* Display cells of s[0..len) (stops at a NUL; invalid bytes count one each). */
size_t sw_utf8_columns(const char *s, size_t len);

/* The bytes of s[0..len) that fit in cols cells, whole characters only;
 * the cells they take in *used (may be NULL). */
size_t sw_utf8_fit(const char *s, size_t len, size_t cols, size_t *used);

/* 1 when the current locale's character set (LC_CTYPE, after setlocale)
 * is UTF-8: Braille, ✓ and wide text can be shown. */
int sw_utf8_locale(void);

#endif
