/* Private to the lesson parser's files (parse.c, directives.c, goal_parse.c,
 * page_check.c, parse_base.c, arena.c): the parser's state and the helpers they share. */
#ifndef SW_LESSON_PARSE_H
#define SW_LESSON_PARSE_H

#include <stddef.h>

#include "lesson/lesson.h"
#include "util/names.h"
#include "util/utf8.h"

/* Room for the directive table (directives.c checks it fits). */
#define SW_LP_DIRECTIVES_MAX 32

typedef struct sw_lp_where { int line, col; } sw_lp_where;

enum hint_target { HINT_NONE, HINT_GOAL, HINT_QUESTION };

typedef struct sw_lp_parser {
    sw_lesson *out;
    const char *name;
    char *err;
    size_t errlen;
    int status;               /* SW_OK until the first error */
    int line;                 /* number of the line being read */
    const char *ln;           /* its bytes, newline and trailing blanks removed */
    size_t lnlen;
    int cap_pages;
    sw_lp_where title_at;

    /* What the next page inherits. */
    const sw_scene *scene;
    double p[SW_MAX_PARAMS];
    const sw_integrator *method;
    double dt;
    sw_lock_mask locked;
    sw_system sys;            /* the system of the settings so far, to check methods against */
    int have_sys;

    /* The page being read (out->pages[out->npages - 1]). */
    sw_lp_where at_scene, at_set, at_integrator, at_dt, at_compare;
    sw_lp_where at_question, at_correct;
    sw_lp_where seen[SW_LP_DIRECTIVES_MAX]; /* a once-per-page directive's line, by table index */
    sw_lp_where at_goal[SW_LESSON_MAX_GOALS];
    int set_line[SW_MAX_PARAMS];
    int rebuild;              /* scene or parameters changed on this page */
    int correct;              /* letter index from @correct, -1 none */
    enum hint_target hint_to;
    sw_lesson_block blocks[SW_LESSON_MAX_BLOCKS];
    int nblocks;
    size_t prose;             /* bytes of prose kept on this page */
    char para[SW_LESSON_MAX_PROSE + 1];
    size_t paralen;
    int para_open, para_verbatim, para_line;
} sw_lp_parser;

#define SW_LESSON_NAME_MAX 64 /* longest word in a directive (names, keys) */
#define FAIL(ps, off, ...) sw_lp_fail_at((ps), (ps)->line, sw_lp_col((ps), (off)), __VA_ARGS__)

/* ---- arena.c ---- */
void *sw_lp_alloc(sw_lesson *l, size_t n);
char *sw_lp_strdup(sw_lesson *l, const char *s, size_t len);

/* ---- parse_base.c: errors, words, names, prose ---- */
/* 1-based character column of byte offset off in the current line. */
int sw_lp_col(const sw_lp_parser *ps, size_t off);
/* Record the first error as "NAME:LINE:COL: message"; returns the status. */
int sw_lp_fail_at(sw_lp_parser *ps, int line, int col, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
int sw_lp_oom(sw_lp_parser *ps);
/* The page being read, or NULL before the first. */
sw_lesson_page *sw_lp_page(sw_lp_parser *ps);
static inline int sw_lp_blank(char c) { return c == ' ' || c == '\t'; }
/* The length of s[0..len) cut to max bytes on a character boundary, for %.*s. */
static inline int sw_lp_clip(const char *s, size_t len, size_t max) { return (int)sw_utf8_clip(s, len, max); }
/* Next blank-separated field at or after *pos; 0 when none. */
int sw_lp_next_field(const sw_lp_parser *ps, size_t *pos, size_t *start, size_t *len);
/* Copy a field into word (SW_LESSON_NAME_MAX bytes), or fail when too long. */
int sw_lp_field_word(sw_lp_parser *ps, size_t start, size_t len, char *word);
/* Exactly one word after the directive at pos. */
int sw_lp_one_word(sw_lp_parser *ps, size_t pos, const char *directive, const char *expected, char *word,
                   size_t *at);
int sw_lp_on_off(sw_lp_parser *ps, size_t pos, const char *directive, int *out);
/* A directive allowed once per page. */
int sw_lp_once(sw_lp_parser *ps, sw_lp_where *seen, const char *directive);
int sw_lp_find_integrator(sw_lp_parser *ps, const char *word, size_t at, const sw_integrator **out);
int sw_lp_need_scene(sw_lp_parser *ps, const char *directive);
/* " (did you mean 'PREFIXname'?)" when a name is close to word, else "". */
const char *sw_lp_suggest(const char *prefix, const char *word, sw_name_at_fn *at, const void *ctx, int n,
                          char *buf, size_t len);
const char *sw_lp_scene_at(const void *ctx, int i);
/* End the paragraph being read (a blank line, a directive, the page's end). */
int sw_lp_flush_block(sw_lp_parser *ps);
/* Add a line of prose to the paragraph (verbatim: indented, tabs expanded). */
int sw_lp_add_prose(sw_lp_parser *ps, const char *s, size_t len, int verbatim);

/* ---- directives.c ---- */
int sw_lp_directive(sw_lp_parser *ps, size_t at);
/* The name of the table's i-th directive ("scene"), NULL past the last. */
const char *sw_lp_directive_name(int i);
/* A new page's "leave as is" settings, from every directive that has one. */
void sw_lp_page_defaults(sw_lesson_page *pg);

/* ---- goal_parse.c ---- */
int sw_lp_goal(sw_lp_parser *ps, size_t pos);

/* ---- page_check.c ---- */
/* SW_OK when m can step the page's system, else SW_EINVAL with why filled
 * (ps->status stays SW_OK) or the build's error (ps->status set). */
int sw_lp_system_accepts(sw_lp_parser *ps, const sw_integrator *m, char *why, size_t len);
int sw_lp_end_page(sw_lp_parser *ps);

#endif
