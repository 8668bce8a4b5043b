/* Untrusted text in messages: arguments, file names, names read from files
 * or plugins may hold newlines, escape sequences (which can clear a screen
 * or fake a PASS) or invalid UTF-8. One rule, used by every message. */
#ifndef SW_UTIL_ESCAPE_H
#define SW_UTIL_ESCAPE_H

#include <stddef.h>

/* Quote text for a message: printable UTF-8 is kept; each control character
 * (C0, DEL, C1), each byte of invalid UTF-8 and each backslash becomes
 * \xNN (so the result reads back unambiguously). At most max bytes of text
 * are read; "..." marks text cut by max or by outlen. out is always
 * NUL-terminated (outlen > 0); text NULL reads as "". */
void sw_escape(const char *text, size_t max, char *out, size_t outlen);

/* The same rule for a whole message about to be printed, in place within
 * its buffer of len bytes, except that backslashes are kept (parts of it may
 * already be escaped): the message stays one line of printable text. */
void sw_escape_message(char *msg, size_t len);

/* The message rule (backslashes kept) from at most max bytes of text into
 * out: text that is already escaped and fits comes out unchanged. */
void sw_escape_kept(const char *text, size_t max, char *out, size_t outlen);

#endif
