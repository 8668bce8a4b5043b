/* Text laid out to a width without cutting a word or a number: fields of a
 * status line shortened or dropped by priority, and word wrapping. */
#ifndef SW_RENDER_TEXT_H
#define SW_RENDER_TEXT_H

#include <stddef.h>

#include "app/app.h"

#define SW_TEXT_LINE 512

/* Cells a UTF-8 text takes (one per character). */
int sw_text_cells(const char *s);
/* Lay out n fields in width cells, in their order, joined by sep: in full
 * when they fit; else the least important fields take their brief forms,
 * then the least important are dropped, until the line fits. Returns the
 * cells used (0 when not even the most important field fits). */
int sw_text_fit(char *out, size_t len, int width, const sw_field *f, int n, const char *sep);
/* The same over at most rows lines: the fields in order, each line filled
 * before the next, none split; brief forms, then drops, until they fit.
 * Returns the lines used (0: not even the most important field fits);
 * *dropped (when not NULL) counts the fields left out. */
int sw_text_fit_rows(char (*out)[SW_TEXT_LINE], int rows, int width, const sw_field *f, int n, const char *sep,
                     int *dropped);
/* Word-wrap text into lines of at most width cells by the one wrapper
 * (util/wrap.h: no word cut when it fits a line, a word longer than a
 * line split). Returns the number of lines the text needs; at most max
 * are written. */
int sw_text_wrap(const char *text, int width, char (*lines)[SW_TEXT_LINE], int max);
/* A method's name in brief for a legend: every part but the last cut to
 * four letters ("symplectic-euler" -> "symp-euler"); "" when that is no shorter. */
void sw_text_brief_name(const char *name, char *out, size_t len);

#endif
