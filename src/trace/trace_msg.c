/* The trace reader's messages: every error names file and line, and
 * untrusted text is shown printable. Used by the reader (trace.c) and its
 * metadata parser (trace_meta.c); it calls neither. */
#include "trace/trace_read.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "stepwise/base.h"

/* "FILE:LINE: what" — every reader error names the place. */
int tr_fail(const sw_trace_reader *r, char *err, size_t errlen, const char *fmt, ...)
{
    int used = snprintf(err, errlen, "%s:%ld: ", r->name, r->line > 0 ? r->line : 1);
    if (used < 0 || (size_t)used >= errlen)
        return SW_EINVAL;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err + used, errlen - (size_t)used, fmt, ap);
    va_end(ap);
    return SW_EINVAL;
}

/* A printable copy of untrusted text for a message: at most 40 bytes, and
 * anything outside printable ASCII shown as '?'. */
const char *tr_shown(const char *text, size_t len, char out[48])
{
    size_t n = len < 40 ? len : 40;
    for (size_t i = 0; i < n; i++)
        out[i] = (text[i] >= 0x20 && text[i] < 0x7f) ? text[i] : '?';
    strcpy(out + n, len > 40 ? "..." : "");
    return out;
}

/* s without leading and trailing blanks (in place). */
char *tr_trim(char *s)
{
    while (*s == ' ' || *s == '\t')
        s++;
    size_t n = strlen(s);
    while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t'))
        s[--n] = '\0';
    return s;
}
