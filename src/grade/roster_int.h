/* Private to the roster files (roster*.c): the string pool, folding, and
 * the lookups by id, email and name that the path rules, the claim check
 * and Gradescope's metadata share. */
#ifndef SW_GRADE_ROSTER_INT_H
#define SW_GRADE_ROSTER_INT_H

#include <stdarg.h>
#include <stddef.h>

#include "grade/roster.h"

/* Longest folded key or normalised id the lookups take. */
#define RST_KEY_MAX 512

/* A copy of s[0..n) in r's pool (NUL added; it never moves), or NULL when
 * memory runs out. */
const char *rst_dup(sw_roster *r, const char *s, size_t n);

/* s[0..n) folded word by word into out: "José  GARCÍA-López" gives
 * "jose garcialopez". Returns the length. */
size_t rst_fold_words(const char *s, size_t n, char *out, size_t outlen);
/* An id normalised into out: ASCII letters lower-cased and digits kept,
 * everything else dropped; all digits lose their leading zeros. */
size_t rst_norm_id(const char *s, size_t n, char *out, size_t outlen);

/* Students (up to max into out; returns how many) whose normalised id is
 * id; whose email, or its part before '@', is text (lower case); whose
 * name's words, read from any word on and round (so "smithjohn" and
 * "johnsmith" both fit John Smith), concatenate to the folded key. */
int rst_by_id(const sw_roster *r, const char *id, int *out, int max);
int rst_by_email(const sw_roster *r, const char *text, int *out, int max);
int rst_by_name(const sw_roster *r, const char *key, int *out, int max);

/* A whole file (at most SW_ROSTER_FILE_MAX bytes, never waiting on a FIFO)
 * into a new *text; kind ("a roster") names what it should be in errors.
 * 0, SW_EINVAL or SW_EIO with err filled. */
int rst_read_file(const char *path, const char *kind, char **text, size_t *len, char *err,
                  size_t errlen);

/* "FILE:LINE: " and the message into err; returns SW_EINVAL. */
int rst_fail(char *err, size_t errlen, const char *name, long line, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 5, 6)))
#endif
    ;

#endif
