/* What the symbol tests share (tests/check_symbols.c, the status line and
 * meter; tests/check_view_symbols.c, the views): a field's form, where in
 * the course a page is, and the course's first page's pointer. */
#ifndef SW_TEST_SYMBOLS_HELP_H
#define SW_TEST_SYMBOLS_HELP_H

#include <stddef.h>

#include "app/runner.h"
#include "lesson/lesson.h"

/* The words by which the course's first page says the next two explain
 * its status line and meter. */
#define FIRST_PAGE_POINTS "explained field by field on the next two pages"

/* s with every number (digits, a point, an exponent; a sign before it)
 * as one '#', and the meter's bar as "[#]". */
void sym_form_of(const char *s, char *out, size_t len);
/* The place in the course (lesson index, and page index into *page) of
 * the page titled title of file, whose text must hold key. */
int sym_place_of(const sw_lesson_entry *e, int n, const char *file, const char *title, const char *key, int *page);
/* On the course's first page (lesson 0, page 0): read whether its text
 * points to the next two pages; sym_first_page_points says what it read. */
void sym_read_first_page(const sw_runner *r, int lesson, int page);
int sym_first_page_points(void);

#endif
