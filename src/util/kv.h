/* NAME=VALUE assignments, as `--set` and a lesson's `@set` write them:
 * blanks (spaces, tabs) may surround the '='; the value ends at a blank. */
#ifndef SW_UTIL_KV_H
#define SW_UTIL_KV_H

#include <stddef.h>

typedef struct sw_kv {
    size_t name_at, name_len;    /* the name: up to '=' or a blank */
    size_t eq_at;                /* where '=' is, or was expected */
    size_t value_at, value_len;  /* the value: after '=' up to a blank */
    size_t end;                  /* just past the value */
} sw_kv;

/* Read the assignment at or after s[pos] in s[0..len). 1: one was read into
 * kv; 0: only blanks remain; -1: no '=' after the name (name_* and eq_at
 * are filled). */
int sw_kv_next(const char *s, size_t len, size_t pos, sw_kv *kv);

#endif
