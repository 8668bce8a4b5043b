/* Private to the trace reader (trace.c) and its metadata parser
 * (trace_meta.c): the metadata state, the messages both write (trace_msg.c). */
#ifndef SW_TRACE_TRACE_READ_H
#define SW_TRACE_TRACE_READ_H

#include "trace/trace.h"

/* Metadata keys, in the order record writes them. */
enum { K_VERSION, K_SCENE, K_INTEGRATOR, K_DT, K_STEPS, K_UNTIL, K_EVERY, K_RTOL, K_ATOL,
       K_DIVERGED, K_STUDENT, K_NOTE, K_EVENTS, K_COUNT };
#define MAX_PARAM_LINES 32

typedef struct pending_param {
    char name[SW_TRACE_NAME_MAX];
    char value[64];
    long line;
} pending_param;

typedef struct meta_state {
    long seen[K_COUNT];              /* line where each key appeared; 0: not yet */
    pending_param params[MAX_PARAM_LINES];
    int nparams;
    char scene[SW_TRACE_NAME_MAX];
} meta_state;

/* "FILE:LINE: what" into err; returns SW_EINVAL. */
int tr_fail(const sw_trace_reader *r, char *err, size_t errlen, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
/* A printable copy of untrusted text for a message (at most 40 bytes). */
const char *tr_shown(const char *text, size_t len, char out[48]);
/* s without leading and trailing blanks (in place). */
char *tr_trim(char *s);
/* One "# key: value" line (r->buf) into the metadata. */
int tr_meta_line(sw_trace_reader *r, meta_state *ms, char *err, size_t errlen);
/* After the metadata: required keys, parameters, the run's length, the system. */
int tr_meta_finish(sw_trace_reader *r, meta_state *ms, char *err, size_t errlen);

#endif
