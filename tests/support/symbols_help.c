/* What the symbol tests share (symbols_help.h). */
#include "symbols_help.h"

#include <check.h>
#include <ctype.h>
#include <stdio.h>
#include <string.h>

static int first_page_points; /* the course's first page says where its lines are explained */

int sym_first_page_points(void) { return first_page_points; }

void sym_form_of(const char *s, char *out, size_t len)
{
    size_t n = 0;
    while (*s && n + 2 < len) {
        if (*s == '[' && (s[1] == '#' || s[1] == '.')) {
            while (*s && *s != ']')
                s++;
            s += *s == ']';
            n += (size_t)snprintf(out + n, len - n, "[#]");
            continue;
        }
        int sign = (*s == '-' || *s == '+') && isdigit((unsigned char)s[1]);
        if (isdigit((unsigned char)*s) || sign) {
            s += sign;
            while (isdigit((unsigned char)*s) || *s == '.' ||
                   ((*s == 'e' || *s == 'E') && (isdigit((unsigned char)s[1]) || s[1] == '-' || s[1] == '+')))
                s += (*s == 'e' || *s == 'E') && (s[1] == '-' || s[1] == '+') ? 2 : 1;
            out[n++] = '#';
            continue;
        }
        out[n++] = *s++;
    }
    out[n] = '\0';
}

/* The place in the course (lesson index, page index) of page `page` of
 * `file`, from the lesson list, whose text must hold key (the form's first
 * word: the page that explains a field names it). */
int sym_place_of(const sw_lesson_entry *e, int n, const char *file, const char *title, const char *key,
                    int *page)
{
    for (int i = 0; i < n; i++) {
        if (strcmp(e[i].file, file) != 0)
            continue;
        char err[SW_LESSON_ERRLEN];
        sw_lesson lesson;
        ck_assert_msg(sw_lesson_load(e[i].path, &lesson, err, sizeof err) == SW_OK, "%s", err);
        int found = -1;
        int named = 0;
        for (int p = 0; p < lesson.npages; p++)
            if (strcmp(lesson.pages[p].title, title) == 0) {
                found = p;
                for (int b = 0; b < lesson.pages[p].nblocks; b++)
                    named |= strstr(lesson.pages[p].blocks[b].text, key) != NULL;
            }
        sw_lesson_free(&lesson);
        ck_assert_msg(found < 0 || named, "%s's page '%s' is said to explain '%s' but does not name it", file, title,
                      key);
        ck_assert_msg(found >= 0, "the symbol list names page '%s' of %s, which it does not have", title, file);
        *page = found;
        return i;
    }
    ck_abort_msg("the symbol list names %s, which is not a lesson", file);
    return -1;
}

/* On the course's first page: whether its text points to the next two
 * (lines joined with spaces). */
void sym_read_first_page(const sw_runner *r, int lesson, int page)
{
    if (lesson != 0 || page != 0)
        return;
    char text[4096] = "";
    const sw_lesson_page *pg = &r->lesson.pages[0];
    for (int b = 0; b < pg->nblocks; b++)
        strncat(text, pg->blocks[b].text, sizeof text - strlen(text) - 2);
    for (char *c = text; *c; c++)
        *c = *c == '\n' ? ' ' : *c;
    first_page_points = strstr(text, FIRST_PAGE_POINTS) != NULL;
}
