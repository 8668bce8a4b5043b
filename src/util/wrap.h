/* Word wrapping to a width in display cells (a CJK character takes two),
 * for every layer: the lesson pane, the help and notes, messages. */
#ifndef SW_UTIL_WRAP_H
#define SW_UTIL_WRAP_H

#include <stddef.h>

/* One line of the result: lead spaces, then len bytes of text (not
 * NUL-terminated; a part of the text given). */
typedef void sw_wrap_line_fn(void *ctx, int lead, const char *text, size_t len);

/* Word-wrap a paragraph ('\n' ends a line) to lines of at most width cells
 * (width < 1 counts as 1), counting a line as written, its runs of spaces
 * included; a bracket opened and closed within a line's width stays on one
 * line, and an operator goes on with what it joins; a word wider than a
 * line (a path; CJK text has no spaces) is broken between characters, never
 * inside one. Calls emit once per line, lead always 0. */
void sw_wrap_paragraph(const char *text, int width, sw_wrap_line_fn *emit, void *ctx);

/* A verbatim line (a formula, a table row) as written; too wide, it goes on
 * on the next lines, indented under itself (lead). Breaks are chosen among
 * its spaces: outside brackets before inside them, before an operator
 * rather than after one, never leaving a lone closing bracket or a single
 * operand for the next line when a better break exists, the first line as
 * full as that allows. A line narrower than its indent plus 12 is emitted
 * whole. */
void sw_wrap_verbatim(const char *text, int width, sw_wrap_line_fn *emit, void *ctx);

#endif
