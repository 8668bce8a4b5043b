/* Untrusted text in messages: arguments, file names, names read from files
 * or plugins may hold newlines, escape sequences (which can clear a screen
 * or fake a PASS) or invalid UTF-8. One rule, used by every message. */
#ifndef SW_UTIL_ESCAPE_H
#define SW_UTIL_ESCAPE_H

#include <stddef.h>

/* Quote text for a message: printable UTF-8 is kept (é, Δ, 日本, emoji);
 * everything else becomes \xNN, one per byte, lower-case hex, so that the
 * result is printable ASCII there and reads back unambiguously:
 *   - each control character (C0, DEL; a C1 control, U+0080..U+009F, as
 *     its two bytes: U+009B is "\xc2\x9b"),
 *   - each character of invisible formatting (sw_utf8_invisible: the
 *     bidirectional controls, zero-width characters, U+2028/U+2029, ...),
 *     as all its bytes: U+202E is "\xe2\x80\xae", U+200B "\xe2\x80\x8b",
 *   - each byte of invalid UTF-8, and each backslash ("\x5c").
 * At most max bytes of text are shown (text[max] is read when no NUL comes
 * before it, to tell whether the text goes on); "..." marks text cut by max
 * or by outlen, and a cut falls between characters, never inside one or
 * inside the escapes of one. out is always NUL-terminated within outlen
 * (outlen > 0); text NULL reads as "". */
void sw_escape(const char *text, size_t max, char *out, size_t outlen);

/* The same rule for a whole message about to be printed, in place within
 * its buffer of len bytes, except that backslashes are kept (parts of it may
 * already be escaped): the message stays one line of printable text. */
void sw_escape_message(char *msg, size_t len);

/* The message rule (backslashes kept) from at most max bytes of text into
 * out: text that is already escaped and fits comes out unchanged. */
void sw_escape_kept(const char *text, size_t max, char *out, size_t outlen);

/* Text for a fixed space, a table's cell or a message's buffer: the
 * sw_escape rule (keep_backslash 0) or the message rule (1), fitted to at
 * most cells terminal cells (an escape takes one per byte; é one, 日 two)
 * and outlen bytes. Text that does not fit is cut and marked "..." within
 * both; with words, the cut falls after the last whole word that ends in
 * the second half of the room ("..." after it, a hanging ',' ';' or ':'
 * dropped), else between characters (a long name, a path); never inside a
 * character or the escapes of one. */
void sw_escape_fit(const char *text, int keep_backslash, size_t cells, int words, char *out,
                   size_t outlen);

#endif
