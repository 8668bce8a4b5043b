/* Lesson files: a line-oriented sw_lp_parser turning a teacher's text into pages.
 * Invariant: each line is checked as bytes (length, UTF-8, control
 * characters) before it is read as words, and every name and number is
 * checked against the catalog, so a lesson that parses can be run as is.
 * The first error stops the parse; its message is "FILE:LINE:COL: ...".
 * This file reads lines and pages and calls the rest, which never call it:
 * directives.c -> goal_parse.c -> page_check.c -> parse_base.c (errors,
 * words, prose; lesson/parse.h is their shared state). */
#include "lesson/parse.h"

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/names.h"
#include "util/utf8.h"

/* A "--- TITLE" line: the page before it checked whole, a new one begun. */
static int begin_page(sw_lp_parser *ps, size_t title_at)
{
    if (sw_lp_end_page(ps) != SW_OK)
        return ps->status;
    sw_lesson *l = ps->out;
    if (!l->title)
        return sw_lp_fail_at(ps, ps->line, 1, "page before the lesson's title; expected a 'title: LESSON TITLE' "
                       "line at the top of the file");
    if (l->npages == SW_LESSON_MAX_PAGES)
        return FAIL(ps, 0, "too many pages; expected at most %d in one lesson (split it into two files)",
                    SW_LESSON_MAX_PAGES);
    /* Title: the rest of the line, trailing dashes ("--- Title ---") dropped. */
    size_t end = ps->lnlen;
    while (end > title_at && (ps->ln[end - 1] == '-' || sw_lp_blank(ps->ln[end - 1])))
        end--;
    while (title_at < end && sw_lp_blank(ps->ln[title_at]))
        title_at++;
    if (end == title_at)
        return FAIL(ps, title_at, "page without a title; expected '--- PAGE TITLE'");
    if (sw_lp_col(ps, end) - sw_lp_col(ps, title_at) > SW_LESSON_MAX_TITLE)
        return FAIL(ps, title_at, "page title longer than %d characters; expected a short title",
                    SW_LESSON_MAX_TITLE);
    if (l->npages == ps->cap_pages) {
        int cap = ps->cap_pages ? 2 * ps->cap_pages : 8;
        sw_lesson_page *pages = realloc(l->pages, (size_t)cap * sizeof *pages);
        if (!pages)
            return sw_lp_oom(ps);
        l->pages = pages;
        ps->cap_pages = cap;
    }
    sw_lesson_page *pg = &l->pages[l->npages++];
    memset(pg, 0, sizeof *pg);
    pg->title = sw_lp_strdup(l, ps->ln + title_at, end - title_at);
    if (!pg->title)
        return sw_lp_oom(ps);
    pg->line = ps->line;
    pg->compare = pg->ghost = pg->paused = pg->events = -1;
    pg->view = pg->follow = pg->lanes = pg->graph = -1;
    pg->locked = ps->locked;
    sw_lp_where none = { 0, 0 };
    ps->at_scene = ps->at_set = ps->at_integrator = ps->at_dt = ps->at_compare = none;
    ps->at_ghost = ps->at_pause = ps->at_reset = ps->at_question = ps->at_correct = none;
    ps->at_speed = ps->at_view = ps->at_events = none;
    memset(ps->set_line, 0, sizeof ps->set_line);
    ps->correct = -1;
    ps->hint_to = HINT_NONE;
    ps->nblocks = 0;
    ps->prose = 0;
    ps->paralen = 0;
    ps->para_open = 0;
    return SW_OK;
}

static int header_line(sw_lp_parser *ps, size_t at)
{
    static const char key[] = "title:";
    if (ps->lnlen - at < sizeof key - 1 || memcmp(ps->ln + at, key, sizeof key - 1) != 0)
        return FAIL(ps, at, "text before the first page; expected 'title: LESSON TITLE' at the top, then "
                    "pages starting with '--- PAGE TITLE'");
    if (ps->out->title)
        return FAIL(ps, at, "second title (the first is on line %d); expected one 'title:' line",
                    ps->title_at.line);
    size_t s = at + sizeof key - 1;
    while (s < ps->lnlen && sw_lp_blank(ps->ln[s]))
        s++;
    if (s >= ps->lnlen)
        return FAIL(ps, s, "empty title; expected 'title: LESSON TITLE'");
    if (sw_lp_col(ps, ps->lnlen) - sw_lp_col(ps, s) > SW_LESSON_MAX_TITLE)
        return FAIL(ps, s, "title longer than %d characters; expected a short title", SW_LESSON_MAX_TITLE);
    ps->out->title = sw_lp_strdup(ps->out, ps->ln + s, ps->lnlen - s);
    ps->title_at = (sw_lp_where){ ps->line, sw_lp_col(ps, at) };
    return ps->out->title ? SW_OK : sw_lp_oom(ps);
}

static int read_line(sw_lp_parser *ps)
{
    size_t at = 0;
    while (at < ps->lnlen && sw_lp_blank(ps->ln[at]))
        at++;
    if (at == ps->lnlen) {
        /* A blank line ends a paragraph. */
        return sw_lp_flush_block(ps);
    }
    char c = ps->ln[at];
    if (c == '#')
        return SW_OK;
    if (c == '-' && ps->lnlen - at >= 3 && memcmp(ps->ln + at, "---", 3) == 0)
        return begin_page(ps, at + 3);
    if (!sw_lp_page(ps)) {
        if (c == '@')
            return sw_lp_directive(ps, at);
        return header_line(ps, at);
    }
    if (c == '@') {
        if (sw_lp_flush_block(ps) != SW_OK)
            return ps->status;
        return sw_lp_directive(ps, at);
    }
    if (c != '\\')
        return sw_lp_add_prose(ps, ps->ln, ps->lnlen, at > 0);
    /* A leading backslash shows the rest literally ("\@home", "\# 1"), and
     * an indented line keeps its indentation. */
    char line[SW_LESSON_MAX_LINE];
    memcpy(line, ps->ln, at);
    memcpy(line + at, ps->ln + at + 1, ps->lnlen - at - 1);
    return sw_lp_add_prose(ps, line, ps->lnlen - 1, at > 0);
}

/* Check the bytes of one line: length, UTF-8, no control characters.
 * Returns the line's length (up to the newline) via *len. */
static int check_bytes(sw_lp_parser *ps, const unsigned char *s, size_t avail, size_t *len)
{
    size_t i = 0;
    ps->ln = (const char *)s;
    while (i < avail && s[i] != '\n') {
        ps->lnlen = i;
        if (i >= SW_LESSON_MAX_LINE)
            return FAIL(ps, i, "line longer than %d bytes; expected shorter lines (break the "
                        "paragraph: lines are joined)", SW_LESSON_MAX_LINE);
        unsigned char c = s[i];
        if (c == 0)
            return FAIL(ps, i, "NUL byte: this looks like a binary file; expected UTF-8 text");
        if (c == '\r' && (i + 1 == avail || s[i + 1] == '\n')) {
            i++;
            continue;
        }
        if (c == '\r')
            return FAIL(ps, i, "carriage return (CR) without a line feed after it; expected plain text with "
                        "LF or CRLF line endings");
        if ((c < 0x20 && c != '\t') || c == 0x7F)
            return FAIL(ps, i, "control character 0x%02X; expected plain text (tabs are fine)", c);
        if (c < 0x80) {
            i++;
            continue;
        }
        size_t seq;
        uint32_t cp;
        switch (sw_utf8_check(s + i, avail - i, &seq, &cp)) {
        case SW_UTF8_BAD_LEAD:
            return FAIL(ps, i, "invalid UTF-8 (byte 0x%02X); expected the file saved as UTF-8", c);
        case SW_UTF8_CUT:
            return FAIL(ps, i, "invalid UTF-8 (byte 0x%02X starts a character that is cut short); "
                        "expected the file saved as UTF-8", c);
        case SW_UTF8_BAD_RANGE:
            return FAIL(ps, i, "invalid UTF-8 (byte 0x%02X starts an overlong or out-of-range sequence); "
                        "expected the file saved as UTF-8", c);
        default:
            break;
        }
        size_t more = seq - 1;
        if (cp >= 0x80 && cp <= 0x9F)
            return FAIL(ps, i, "control character U+%04X; expected plain text", (unsigned)cp);
        if (i + more >= SW_LESSON_MAX_LINE) {
            ps->lnlen = i + more + 1;
            return FAIL(ps, i, "line longer than %d bytes; expected shorter lines (break the "
                        "paragraph: lines are joined)", SW_LESSON_MAX_LINE);
        }
        i += seq;
    }
    *len = i;
    size_t n = i;
    if (n && s[n - 1] == '\r')
        n--;
    while (n && sw_lp_blank((char)s[n - 1]))
        n--;
    ps->lnlen = n;
    return SW_OK;
}

int sw_lesson_parse(const char *name, const char *text, size_t len, sw_lesson *out, char *err,
                    size_t errlen)
{
    memset(out, 0, sizeof *out);
    if (err && errlen)
        err[0] = '\0';
    sw_lp_parser *ps = calloc(1, sizeof *ps);
    if (!ps) {
        if (err && errlen)
            snprintf(err, errlen, "%.200s: out of memory reading the lesson", name ? name : "lesson");
        return SW_ENOMEM;
    }
    ps->out = out;
    ps->name = name ? name : "lesson";
    ps->err = err;
    ps->errlen = errlen;
    ps->correct = -1;
    ps->line = 1;
    if (!text)
        len = 0;
    out->name = sw_lp_strdup(out, ps->name, strlen(ps->name));
    if (!out->name)
        sw_lp_oom(ps);
    else if (len > SW_LESSON_MAX_BYTES)
        sw_lp_fail_at(ps, 1, 1, "file is %zu bytes; expected a lesson of at most %d bytes (split it)", len,
                SW_LESSON_MAX_BYTES);
    size_t pos = 0;
    const unsigned char *s = (const unsigned char *)text;
    /* A UTF-8 byte-order mark, as some editors write, is not text. */
    if (len >= 3 && s[0] == 0xEF && s[1] == 0xBB && s[2] == 0xBF)
        pos = 3;
    /* Line endings of classic Mac OS (CR alone) make the whole file one
     * line: say so, rather than what that one line then breaks. */
    if (ps->status == SW_OK && len > pos && memchr(s + pos, '\n', len - pos) == NULL) {
        const unsigned char *cr = memchr(s + pos, '\r', len - pos);
        if (cr && (size_t)(cr - s) + 1 < len) {
            ps->ln = (const char *)s + pos;
            ps->lnlen = (size_t)(cr - s) - pos;
            FAIL(ps, ps->lnlen, "this file ends its lines with CR alone (classic Mac line endings), so it "
                 "reads as one line; expected LF or CRLF line endings (convert it, e.g. tr '\\r' '\\n')");
        }
    }
    int nonblank = 0;
    while (ps->status == SW_OK && pos < len) {
        size_t n = 0;
        if (check_bytes(ps, s + pos, len - pos, &n) != SW_OK)
            break;
        nonblank |= ps->lnlen > 0;
        read_line(ps);
        pos += n;
        if (pos < len) {
            pos++; /* the newline */
            if (pos < len)
                ps->line++;
        }
    }
    if (ps->status == SW_OK) {
        ps->ln = "";
        ps->lnlen = 0;
        if (!nonblank)
            sw_lp_fail_at(ps, 1, 1, "empty file; expected 'title: LESSON TITLE', then pages starting with "
                    "'--- PAGE TITLE'");
        else if (!out->title)
            sw_lp_fail_at(ps, 1, 1, "no 'title:' line; expected 'title: LESSON TITLE' at the top");
        else if (!out->npages)
            sw_lp_fail_at(ps, ps->line, 1, "the lesson has no pages; expected '--- PAGE TITLE' lines after the title");
        else
            sw_lp_end_page(ps);
    }
    int rc = ps->status;
    if (ps->have_sys)
        sw_system_free(&ps->sys);
    free(ps);
    if (rc != SW_OK)
        sw_lesson_free(out);
    return rc;
}
