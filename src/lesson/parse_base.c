/* The lesson parser's base, shared by its files: errors that name file,
 * line and column, fields and words, names with a suggestion, paragraphs
 * of prose. It calls no other parser file (parse.c, directives.c,
 * goal_parse.c and page_check.c call down to it). */
#include "lesson/parse.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "util/names.h"
#include "util/utf8.h"

/* 1-based character column of byte offset off in the current line. */
int sw_lp_col(const sw_lp_parser *ps, size_t off)
{
    return 1 + (int)sw_utf8_count(ps->ln, off < ps->lnlen ? off : ps->lnlen);
}

int sw_lp_fail_at(sw_lp_parser *ps, int line, int col, const char *fmt, ...)
{
    if (ps->status != SW_OK)
        return ps->status;
    ps->status = SW_EINVAL;
    if (ps->err && ps->errlen) {
        int n = snprintf(ps->err, ps->errlen, "%.200s:%d:%d: ", ps->name, line, col);
        if (n >= 0 && (size_t)n < ps->errlen) {
            va_list ap;
            va_start(ap, fmt);
            vsnprintf(ps->err + n, ps->errlen - (size_t)n, fmt, ap);
            va_end(ap);
        }
    }
    return SW_EINVAL;
}

int sw_lp_oom(sw_lp_parser *ps)
{
    if (ps->status == SW_OK) {
        ps->status = SW_ENOMEM;
        if (ps->err && ps->errlen)
            snprintf(ps->err, ps->errlen, "%.200s: out of memory reading the lesson", ps->name);
    }
    return SW_ENOMEM;
}

sw_lesson_page *sw_lp_page(sw_lp_parser *ps)
{
    return ps->out->npages ? &ps->out->pages[ps->out->npages - 1] : NULL;
}

/* Next field of the current line at or after *pos; 0 when none. */
int sw_lp_next_field(const sw_lp_parser *ps, size_t *pos, size_t *start, size_t *len)
{
    size_t i = *pos;
    while (i < ps->lnlen && sw_lp_blank(ps->ln[i]))
        i++;
    if (i >= ps->lnlen) {
        *pos = i;
        return 0;
    }
    *start = i;
    while (i < ps->lnlen && !sw_lp_blank(ps->ln[i]))
        i++;
    *len = i - *start;
    *pos = i;
    return 1;
}

/* Copy a field into a NUL-terminated word, or fail when it is too long. */
int sw_lp_field_word(sw_lp_parser *ps, size_t start, size_t len, char *word)
{
    if (len >= SW_LESSON_NAME_MAX)
        return FAIL(ps, start, "'%.*s...' is too long for a name (at most %d bytes)",
                    sw_lp_clip(ps->ln + start, len, 20), ps->ln + start, SW_LESSON_NAME_MAX - 1);
    memcpy(word, ps->ln + start, len);
    word[len] = '\0';
    return SW_OK;
}

/* Exactly one word after the directive name at *pos. */
int sw_lp_one_word(sw_lp_parser *ps, size_t pos, const char *directive, const char *expected, char *word,
                    size_t *at)
{
    size_t start, len;
    if (!sw_lp_next_field(ps, &pos, &start, &len))
        return FAIL(ps, ps->lnlen, "%s needs a value; expected %s", directive, expected);
    if (sw_lp_field_word(ps, start, len, word) != SW_OK)
        return ps->status;
    *at = start;
    size_t extra, elen;
    if (sw_lp_next_field(ps, &pos, &extra, &elen))
        return FAIL(ps, extra, "unexpected '%.*s' after %s %s; expected only %s", sw_lp_clip(ps->ln + extra, elen, 40),
                    ps->ln + extra, directive, word, expected);
    return SW_OK;
}

int sw_lp_on_off(sw_lp_parser *ps, size_t pos, const char *directive, int *out)
{
    char word[SW_LESSON_NAME_MAX];
    size_t at;
    if (sw_lp_one_word(ps, pos, directive, "on or off", word, &at) != SW_OK)
        return ps->status;
    if (strcmp(word, "on") == 0)
        *out = 1;
    else if (strcmp(word, "off") == 0)
        *out = 0;
    else
        return FAIL(ps, at, "%s takes on or off, not '%s'", directive, word);
    return SW_OK;
}

int sw_lp_once(sw_lp_parser *ps, sw_lp_where *seen, const char *directive)
{
    if (seen->line)
        return FAIL(ps, 0, "second %s on this page (the first is on line %d); expected one per page",
                    directive, seen->line);
    seen->line = ps->line;
    seen->col = 1;
    return SW_OK;
}

const char *sw_lp_scene_at(const void *ctx, int i)
{
    (void)ctx;
    return sw_scene_at(i)->name;
}

static const char *method_at(const void *ctx, int i)
{
    (void)ctx;
    return sw_integrator_at(i)->name;
}

const char *sw_lp_suggest(const char *prefix, const char *word, sw_name_at_fn *at, const void *ctx, int n,
                          char *buf, size_t len)
{
    const char *best = sw_names_nearest(word, at, ctx, n);
    if (best)
        snprintf(buf, len, " (did you mean '%s%s'?)", prefix, best);
    else
        buf[0] = '\0';
    return buf;
}

int sw_lp_find_integrator(sw_lp_parser *ps, const char *word, size_t at, const sw_integrator **out)
{
    *out = sw_integrator_find(word);
    if (*out)
        return SW_OK;
    char names[300], near[80];
    sw_integrator_names(names, sizeof names);
    return FAIL(ps, at, "unknown integrator '%s'%s; expected one of %s", word,
                sw_lp_suggest("", word, method_at, NULL, sw_integrator_count(), near, sizeof near), names);
}
int sw_lp_need_scene(sw_lp_parser *ps, const char *directive)
{
    if (!ps->scene)
        return FAIL(ps, 0, "%s needs a scene; expected '@scene NAME' on this page first", directive);
    return SW_OK;
}

/* ---- prose ------------------------------------------------------------------------------------ */

int sw_lp_flush_block(sw_lp_parser *ps)
{
    if (!ps->para_open)
        return SW_OK;
    ps->para_open = 0;
    if (ps->nblocks == SW_LESSON_MAX_BLOCKS)
        return sw_lp_fail_at(ps, ps->para_line, 1, "too many paragraphs on this page; expected at most %d "
                       "(split the page)", SW_LESSON_MAX_BLOCKS);
    char *text = sw_lp_strdup(ps->out, ps->para, ps->paralen);
    if (!text)
        return sw_lp_oom(ps);
    ps->blocks[ps->nblocks++] = (sw_lesson_block){ ps->para_verbatim, text, ps->para_line };
    ps->prose += ps->paralen;
    ps->paralen = 0;
    return SW_OK;
}

int sw_lp_add_prose(sw_lp_parser *ps, const char *s, size_t len, int verbatim)
{
    if (ps->para_open && ps->para_verbatim != verbatim && sw_lp_flush_block(ps) != SW_OK)
        return ps->status;
    size_t need = len + (ps->para_open ? 1 : 0);
    if (verbatim)
        for (size_t i = 0; i < len; i++)
            need += s[i] == '\t' ? 7 : 0;
    if (ps->prose + ps->paralen + need > SW_LESSON_MAX_PROSE)
        return FAIL(ps, 0, "this page has more than %d bytes of text; expected a shorter page (split it "
                    "with another '--- TITLE')", SW_LESSON_MAX_PROSE);
    if (ps->para_open) {
        ps->para[ps->paralen++] = verbatim ? '\n' : ' ';
    } else {
        ps->para_open = 1;
        ps->para_verbatim = verbatim;
        ps->para_line = ps->line;
    }
    int col = 0;
    for (size_t i = 0; i < len; i++) {
        unsigned char c = (unsigned char)s[i];
        if (c == '\t' && verbatim) {
            /* Tab stops every 8 columns, counted in characters. */
            do
                ps->para[ps->paralen++] = ' ';
            while (++col % 8);
            continue;
        }
        ps->para[ps->paralen++] = c == '\t' ? ' ' : (char)c;
        if ((c & 0xC0) != 0x80)
            col++;
    }
    return SW_OK;
}
