/* Lesson files: a line-oriented parser turning a teacher's text into pages.
 * Invariant: each line is checked as bytes (length, UTF-8, control
 * characters) before it is read as words, and every name and number is
 * checked against the catalog, so a lesson that parses can be run as is.
 * The first error stops the parse; its message is "FILE:LINE:COL: ...". */
#include "lesson/lesson.h"

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- memory: chunks that never move, so pointers into them stay valid ---- */

struct sw_lesson_chunk {
    struct sw_lesson_chunk *next;
    size_t used, cap;
    max_align_t data[];
};

static void *mem_alloc(sw_lesson *l, size_t n)
{
    size_t a = _Alignof(max_align_t);
    n = (n + a - 1) / a * a;
    struct sw_lesson_chunk *c = l->mem;
    if (!c || c->cap - c->used < n) {
        size_t cap = n > 16384 ? n : 16384;
        c = malloc(sizeof *c + cap);
        if (!c)
            return NULL;
        c->next = l->mem;
        c->used = 0;
        c->cap = cap;
        l->mem = c;
    }
    void *p = (char *)c->data + c->used;
    c->used += n;
    return p;
}

static char *mem_strdup(sw_lesson *l, const char *s, size_t len)
{
    char *d = mem_alloc(l, len + 1);
    if (d) {
        memcpy(d, s, len);
        d[len] = '\0';
    }
    return d;
}

void sw_lesson_free(sw_lesson *lesson)
{
    if (!lesson)
        return;
    struct sw_lesson_chunk *c = lesson->mem;
    while (c) {
        struct sw_lesson_chunk *next = c->next;
        free(c);
        c = next;
    }
    free(lesson->pages);
    memset(lesson, 0, sizeof *lesson);
}

/* ---- parser state ----------------------------------------------------------- */

typedef struct where { int line, col; } where;

enum hint_target { HINT_NONE, HINT_GOAL, HINT_QUESTION };

typedef struct parser {
    sw_lesson *out;
    const char *name;
    char *err;
    size_t errlen;
    int status;               /* SW_OK until the first error */
    int line;                 /* number of the line being read */
    const char *ln;           /* its bytes, newline and trailing blanks removed */
    size_t lnlen;
    int cap_pages;
    where title_at;

    /* What the next page inherits. */
    const sw_scene *scene;
    double p[SW_MAX_PARAMS];
    const sw_integrator *method;
    double dt;
    unsigned locked;
    sw_system sys;            /* the system of the settings so far, to check methods against */
    int have_sys;

    /* The page being read (out->pages[out->npages - 1]). */
    where at_scene, at_set, at_integrator, at_dt, at_compare, at_ghost, at_pause, at_reset;
    where at_question, at_correct;
    where at_goal[SW_LESSON_MAX_GOALS];
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
} parser;

#define SW_LESSON_NAME_MAX 64 /* longest word in a directive (names, keys) */

/* 1-based character column of byte offset off in the current line. */
static int col_of(const parser *ps, size_t off)
{
    int col = 1;
    for (size_t i = 0; i < off && i < ps->lnlen; i++)
        if (((unsigned char)ps->ln[i] & 0xC0) != 0x80)
            col++;
    return col;
}

static int fail_at(parser *ps, int line, int col, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));
static int fail_at(parser *ps, int line, int col, const char *fmt, ...)
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

#define FAIL(ps, off, ...) fail_at((ps), (ps)->line, col_of((ps), (off)), __VA_ARGS__)

static int oom(parser *ps)
{
    if (ps->status == SW_OK) {
        ps->status = SW_ENOMEM;
        if (ps->err && ps->errlen)
            snprintf(ps->err, ps->errlen, "%.200s: out of memory reading the lesson", ps->name);
    }
    return SW_ENOMEM;
}

static sw_lesson_page *page(parser *ps)
{
    return ps->out->npages ? &ps->out->pages[ps->out->npages - 1] : NULL;
}

/* ---- names and suggestions ----------------------------------------------------- */

/* Edit distance, capped: enough to suggest "rk4" for "rk-4". */
static int distance(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b);
    if (la > 40 || lb > 40)
        return 99;
    int row[41];
    for (size_t j = 0; j <= lb; j++)
        row[j] = (int)j;
    for (size_t i = 1; i <= la; i++) {
        int diag = row[0];
        row[0] = (int)i;
        for (size_t j = 1; j <= lb; j++) {
            int up = row[j];
            int best = diag + (a[i - 1] != b[j - 1]);
            if (up + 1 < best)
                best = up + 1;
            if (row[j - 1] + 1 < best)
                best = row[j - 1] + 1;
            row[j] = best;
            diag = up;
        }
    }
    return row[lb];
}

typedef const char *name_at_fn(int i);

static const char *scene_name_at(int i) { return sw_scene_at(i)->name; }
static const char *integrator_name_at(int i) { return sw_integrator_at(i)->name; }

/* " (did you mean 'x'?)" when one name is close, else "". */
static const char *suggest_with(const char *prefix, const char *word, name_at_fn *at, int n, char *buf,
                                size_t len)
{
    const char *best = NULL;
    int bestd = 3;
    for (int i = 0; i < n; i++) {
        int d = distance(word, at(i));
        if (d < bestd) {
            bestd = d;
            best = at(i);
        }
    }
    if (best && bestd < (int)strlen(word))
        snprintf(buf, len, " (did you mean '%s%s'?)", prefix, best);
    else
        buf[0] = '\0';
    return buf;
}

static const char *suggest(const char *word, name_at_fn *at, int n, char *buf, size_t len)
{
    return suggest_with("", word, at, n, buf, len);
}

static void name_list(name_at_fn *at, int n, char *buf, size_t len)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < n && used < len; i++) {
        int w = snprintf(buf + used, len - used, "%s%s", i ? ", " : "", at(i));
        if (w < 0)
            break;
        used += (size_t)w;
    }
}

/* ---- fields: whitespace-separated words of a directive --------------------------- */

static int is_blank(char c) { return c == ' ' || c == '\t'; }

/* Next field of the current line at or after *pos; 0 when none. */
static int next_field(const parser *ps, size_t *pos, size_t *start, size_t *len)
{
    size_t i = *pos;
    while (i < ps->lnlen && is_blank(ps->ln[i]))
        i++;
    if (i >= ps->lnlen) {
        *pos = i;
        return 0;
    }
    *start = i;
    while (i < ps->lnlen && !is_blank(ps->ln[i]))
        i++;
    *len = i - *start;
    *pos = i;
    return 1;
}

/* The length of s[0..len) cut to at most max bytes on a character
 * boundary, for quoting a piece of a line in a message. */
static int clip(const char *s, size_t len, size_t max)
{
    if (len <= max)
        return (int)len;
    size_t n = max;
    while (n > 0 && ((unsigned char)s[n] & 0xC0) == 0x80)
        n--;
    return (int)n;
}

/* Copy a field into a NUL-terminated word, or fail when it is too long. */
static int field_word(parser *ps, size_t start, size_t len, char *word)
{
    if (len >= SW_LESSON_NAME_MAX)
        return FAIL(ps, start, "'%.*s...' is too long for a name (at most %d bytes)",
                    clip(ps->ln + start, len, 20), ps->ln + start, SW_LESSON_NAME_MAX - 1);
    memcpy(word, ps->ln + start, len);
    word[len] = '\0';
    return SW_OK;
}

/* Exactly one word after the directive name at *pos. */
static int one_word(parser *ps, size_t pos, const char *directive, const char *expected, char *word,
                    size_t *at)
{
    size_t start, len;
    if (!next_field(ps, &pos, &start, &len))
        return FAIL(ps, ps->lnlen, "%s needs a value; expected %s", directive, expected);
    if (field_word(ps, start, len, word) != SW_OK)
        return ps->status;
    *at = start;
    size_t extra, elen;
    if (next_field(ps, &pos, &extra, &elen))
        return FAIL(ps, extra, "unexpected '%.*s' after %s %s; expected only %s", clip(ps->ln + extra, elen, 40),
                    ps->ln + extra, directive, word, expected);
    return SW_OK;
}

static int on_off(parser *ps, size_t pos, const char *directive, int *out)
{
    char word[SW_LESSON_NAME_MAX];
    size_t at;
    if (one_word(ps, pos, directive, "on or off", word, &at) != SW_OK)
        return ps->status;
    if (strcmp(word, "on") == 0)
        *out = 1;
    else if (strcmp(word, "off") == 0)
        *out = 0;
    else
        return FAIL(ps, at, "%s takes on or off, not '%s'", directive, word);
    return SW_OK;
}

/* ---- settings directives ----------------------------------------------------------- */

static int once(parser *ps, where *seen, const char *directive)
{
    if (seen->line)
        return FAIL(ps, 0, "second %s on this page (the first is on line %d); expected one per page",
                    directive, seen->line);
    seen->line = ps->line;
    seen->col = 1;
    return SW_OK;
}

static int find_integrator(parser *ps, const char *word, size_t at, const sw_integrator **out)
{
    *out = sw_integrator_find(word);
    if (*out)
        return SW_OK;
    char names[300], near[80];
    name_list(integrator_name_at, sw_integrator_count(), names, sizeof names);
    return FAIL(ps, at, "unknown integrator '%s'%s; expected one of %s", word,
                suggest(word, integrator_name_at, sw_integrator_count(), near, sizeof near), names);
}

static int d_scene(parser *ps, size_t pos)
{
    sw_lesson_page *pg = page(ps);
    if (once(ps, &ps->at_scene, "@scene") != SW_OK)
        return ps->status;
    const char *later = ps->at_set.line ? "@set" : ps->at_integrator.line ? "@integrator"
                      : ps->at_dt.line ? "@dt" : ps->at_compare.line ? "@compare"
                      : pg->ngoals ? "@goal" : NULL;
    if (later)
        return FAIL(ps, 0, "@scene comes after %s on this page; expected @scene first, since it "
                    "resets parameters, integrator and dt to the scene's defaults", later);
    char word[SW_LESSON_NAME_MAX];
    size_t at;
    if (one_word(ps, pos, "@scene", "a scene name", word, &at) != SW_OK)
        return ps->status;
    const sw_scene *sc = sw_scene_find(word);
    if (!sc) {
        char names[300], near[80];
        name_list(scene_name_at, sw_scene_count(), names, sizeof names);
        return FAIL(ps, at, "unknown scene '%s'%s; expected one of %s", word,
                    suggest(word, scene_name_at, sw_scene_count(), near, sizeof near), names);
    }
    ps->at_scene.col = col_of(ps, at);
    ps->scene = sc;
    /* Entries past the scene's parameters stay 0, so two setups of one
     * scene compare equal as whole arrays. */
    memset(ps->p, 0, sizeof ps->p);
    sw_scene_defaults(sc, ps->p);
    ps->method = sw_integrator_find(sc->integrator);
    ps->dt = sc->dt;
    ps->rebuild = 1;
    pg->restart = 1;
    if (!ps->method)
        return FAIL(ps, at, "scene '%s' names a default integrator '%s' that does not exist", sc->name,
                    sc->integrator);
    return SW_OK;
}

static int need_scene(parser *ps, const char *directive)
{
    if (!ps->scene)
        return FAIL(ps, 0, "%s needs a scene; expected '@scene NAME' on this page first", directive);
    return SW_OK;
}

/* @set NAME=VALUE [NAME=VALUE ...], spaces around '=' allowed. */
static int d_set(parser *ps, size_t pos)
{
    if (need_scene(ps, "@set") != SW_OK)
        return ps->status;
    const sw_scene *sc = ps->scene;
    if (!ps->at_set.line) {
        ps->at_set.line = ps->line;
        ps->at_set.col = 1;
    }
    int count = 0;
    for (;;) {
        size_t i = pos;
        while (i < ps->lnlen && is_blank(ps->ln[i]))
            i++;
        if (i >= ps->lnlen)
            break;
        size_t name_at = i;
        while (i < ps->lnlen && ps->ln[i] != '=' && !is_blank(ps->ln[i]))
            i++;
        char name[SW_LESSON_NAME_MAX];
        if (field_word(ps, name_at, i - name_at, name) != SW_OK)
            return ps->status;
        while (i < ps->lnlen && is_blank(ps->ln[i]))
            i++;
        if (i >= ps->lnlen || ps->ln[i] != '=' || name[0] == '\0')
            return FAIL(ps, name[0] ? i : name_at, "@set wants NAME=VALUE; expected '=' after '%s'",
                        name[0] ? name : "the parameter name");
        i++;
        while (i < ps->lnlen && is_blank(ps->ln[i]))
            i++;
        size_t val_at = i;
        while (i < ps->lnlen && !is_blank(ps->ln[i]))
            i++;
        char val[SW_LESSON_NAME_MAX];
        if (field_word(ps, val_at, i - val_at, val) != SW_OK)
            return ps->status;
        int idx = sw_scene_param_index(sc, name);
        if (idx < 0) {
            char names[200];
            size_t used = 0;
            names[0] = '\0';
            for (int k = 0; k < sc->nparams && used < sizeof names; k++) {
                int w = snprintf(names + used, sizeof names - used, "%s%s", k ? ", " : "",
                                 sc->params[k].name);
                used += w > 0 ? (size_t)w : 0;
            }
            return FAIL(ps, name_at, "scene '%s' has no parameter '%s'; expected one of %s", sc->name,
                        name, names);
        }
        double v;
        if (sw_parse_double(val, &v) != SW_OK)
            return FAIL(ps, val_at, "'%s' is not a number; expected %s = a number in [%g, %g]",
                        val[0] ? val : "(nothing)", name, sc->params[idx].min, sc->params[idx].max);
        char why[SW_ERRLEN];
        if (sw_scene_check_value(sc, idx, v, why, sizeof why) != SW_OK)
            return FAIL(ps, val_at, "%s", why);
        if (ps->set_line[idx])
            return FAIL(ps, name_at, "'%s' is set twice on this page (also on line %d); expected "
                        "each parameter once", name, ps->set_line[idx]);
        ps->set_line[idx] = ps->line;
        ps->p[idx] = v;
        ps->rebuild = 1;
        page(ps)->restart = 1;
        pos = i;
        count++;
    }
    if (!count)
        return FAIL(ps, ps->lnlen, "@set needs NAME=VALUE; expected e.g. '@set %s=%g'",
                    sc->nparams ? sc->params[0].name : "k", sc->nparams ? sc->params[0].def : 1.0);
    return SW_OK;
}

static int d_integrator(parser *ps, size_t pos)
{
    if (need_scene(ps, "@integrator") != SW_OK || once(ps, &ps->at_integrator, "@integrator") != SW_OK)
        return ps->status;
    char word[SW_LESSON_NAME_MAX];
    size_t at;
    if (one_word(ps, pos, "@integrator", "an integrator name", word, &at) != SW_OK)
        return ps->status;
    if (find_integrator(ps, word, at, &ps->method) != SW_OK)
        return ps->status;
    ps->at_integrator.col = col_of(ps, at);
    page(ps)->restart = 1;
    return SW_OK;
}

static int d_dt(parser *ps, size_t pos)
{
    if (need_scene(ps, "@dt") != SW_OK || once(ps, &ps->at_dt, "@dt") != SW_OK)
        return ps->status;
    char word[SW_LESSON_NAME_MAX];
    size_t at;
    if (one_word(ps, pos, "@dt", "a step size in seconds", word, &at) != SW_OK)
        return ps->status;
    double v;
    if (sw_parse_double(word, &v) != SW_OK || !(v >= SW_DT_MIN && v <= SW_DT_MAX))
        return FAIL(ps, at, "@dt '%s' is not allowed; expected a number in [%g, %g]", word, SW_DT_MIN,
                    SW_DT_MAX);
    ps->dt = v;
    page(ps)->restart = 1;
    return SW_OK;
}

static int d_compare(parser *ps, size_t pos)
{
    sw_lesson_page *pg = page(ps);
    if (need_scene(ps, "@compare") != SW_OK || once(ps, &ps->at_compare, "@compare") != SW_OK)
        return ps->status;
    size_t start, len;
    int n = 0;
    while (next_field(ps, &pos, &start, &len)) {
        char word[SW_LESSON_NAME_MAX];
        if (field_word(ps, start, len, word) != SW_OK)
            return ps->status;
        if (n == 0 && (strcmp(word, "on") == 0 || strcmp(word, "off") == 0)) {
            pg->compare = word[1] == 'n';
            size_t extra, elen;
            if (next_field(ps, &pos, &extra, &elen))
                return FAIL(ps, extra, "unexpected '%.*s' after @compare %s; expected nothing more",
                            clip(ps->ln + extra, elen, 40), ps->ln + extra, word);
            return SW_OK;
        }
        if (n == SW_LESSON_MAX_COMPARE)
            return FAIL(ps, start, "too many methods in @compare; expected at most %d",
                        SW_LESSON_MAX_COMPARE);
        const sw_integrator *m;
        if (find_integrator(ps, word, start, &m) != SW_OK)
            return ps->status;
        for (int k = 0; k < n; k++)
            if (pg->compare_with[k] == m)
                return FAIL(ps, start, "'%s' is named twice in @compare; expected distinct methods", word);
        if (n == 0)
            ps->at_compare.col = col_of(ps, start);
        pg->compare_with[n++] = m;
    }
    if (!n)
        return FAIL(ps, ps->lnlen, "@compare needs a value; expected on, off, or the methods to run "
                    "beside the main one (e.g. '@compare rk4')");
    pg->ncompare_with = n;
    pg->compare = 1;
    return SW_OK;
}

/* Lock names: a control's name, or one of its keys. */
static const struct lock_name { const char *name; unsigned bit; } lock_names[] = {
    { "integrator", SW_LOCK_INTEGRATOR }, { "dt", SW_LOCK_DT }, { "run", SW_LOCK_RUN },
    { "reset", SW_LOCK_RESET }, { "speed", SW_LOCK_SPEED }, { "compare", SW_LOCK_COMPARE },
    { "ghost", SW_LOCK_GHOST }, { "trails", SW_LOCK_TRAILS }, { "graph", SW_LOCK_GRAPH },
    { "braille", SW_LOCK_BRAILLE }, { "params", SW_LOCK_PARAMS }, { "record", SW_LOCK_RECORD },
    { "plot", SW_LOCK_PLOT }, { "all", SW_LOCK_ALL }, { "space", SW_LOCK_RUN },
    { "tab", SW_LOCK_INTEGRATOR },
};

#define NLOCK_NAMES ((int)(sizeof lock_names / sizeof lock_names[0]))

unsigned sw_lesson_key_lock(int key)
{
    switch (key) {
    case 'i': case 'I': case '\t': case '1': case '2': case '3': case '4': case '5': case '6':
    case '7': case '8': case '9': case '0':
        return SW_LOCK_INTEGRATOR;
    case '+': case '=': case '-': return SW_LOCK_DT;
    case ' ': case '.': return SW_LOCK_RUN;
    case 'r': return SW_LOCK_RESET;
    case '[': case ']': return SW_LOCK_SPEED;
    case 'c': return SW_LOCK_COMPARE;
    case 'g': return SW_LOCK_GHOST;
    case 't': return SW_LOCK_TRAILS;
    case 'e': return SW_LOCK_GRAPH;
    case 'b': return SW_LOCK_BRAILLE;
    case 'p': return SW_LOCK_PARAMS;
    case 'R': return SW_LOCK_RECORD;
    case 'w': return SW_LOCK_PLOT;
    default: return 0;
    }
}

const char *sw_lesson_lock_name(unsigned bit)
{
    for (int i = 0; i < NLOCK_NAMES; i++)
        if (lock_names[i].bit == bit)
            return lock_names[i].name;
    return NULL;
}

static const char *lock_name_at(int i) { return lock_names[i].name; }

static int d_lock(parser *ps, size_t pos, int lock)
{
    const char *directive = lock ? "@lock" : "@unlock";
    sw_lesson_page *pg = page(ps);
    size_t start, len;
    int n = 0;
    while (next_field(ps, &pos, &start, &len)) {
        char word[SW_LESSON_NAME_MAX];
        if (field_word(ps, start, len, word) != SW_OK)
            return ps->status;
        unsigned bit = 0;
        for (int i = 0; i < NLOCK_NAMES && !bit; i++)
            if (strcmp(word, lock_names[i].name) == 0)
                bit = lock_names[i].bit;
        if (!bit && len == 1)
            bit = sw_lesson_key_lock((unsigned char)word[0]);
        if (!bit) {
            char near[80];
            return FAIL(ps, start, "%s: '%s' is not a control%s; expected integrator, dt, run, reset, "
                        "speed, compare, ghost, trails, graph, braille, params, record, plot, all, "
                        "or one of their keys (i + - space . r [ ] c g t e b p R w)",
                        directive, word, suggest(word, lock_name_at, NLOCK_NAMES, near, sizeof near));
        }
        if (lock)
            ps->locked |= bit;
        else
            ps->locked &= ~bit;
        n++;
    }
    if (!n) {
        if (lock)
            return FAIL(ps, ps->lnlen, "@lock needs the controls to lock; expected e.g. '@lock integrator dt'");
        ps->locked = 0;
    }
    pg->locked = ps->locked;
    return SW_OK;
}

/* ---- goals ---------------------------------------------------------------------------- */

typedef enum tkind { T_END, T_WORD, T_NUM, T_OP, T_BAR, T_PERCENT, T_LPAREN, T_RPAREN, T_COMMA } tkind;

typedef struct token {
    tkind kind;
    size_t at, len;                  /* bytes in the current line */
    char text[SW_LESSON_NAME_MAX];   /* the word, number, or normalised operator */
} token;

static int word_byte(unsigned char c)
{
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-' || c == '.' || c >= 0x80;
}

/* Whether s[i..n) starts with one of the signs ≤ ≥ ≠ (E2 89 A4/A5/A0);
 * returns the operator it stands for, or NULL. */
static const char *unicode_op(const char *s, size_t i, size_t n)
{
    if (i + 2 >= n || (unsigned char)s[i] != 0xE2 || (unsigned char)s[i + 1] != 0x89)
        return NULL;
    unsigned char d = (unsigned char)s[i + 2];
    return d == 0xA4 ? "<=" : d == 0xA5 ? ">=" : d == 0xA0 ? "!=" : NULL;
}

/* Read the token at *pos into tk. */
static int lex(parser *ps, size_t *pos, token *tk)
{
    const char *s = ps->ln;
    size_t i = *pos, n = ps->lnlen;
    while (i < n && is_blank(s[i]))
        i++;
    memset(tk, 0, sizeof *tk);
    tk->at = i;
    if (i >= n) {
        tk->kind = T_END;
        *pos = i;
        return SW_OK;
    }
    unsigned char c = (unsigned char)s[i];
    size_t j = i;
    const char *op = unicode_op(s, i, n);
    if (op) {
        tk->kind = T_OP;
        strcpy(tk->text, op);
        tk->len = 3;
        *pos = i + 3;
        return SW_OK;
    }
    if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c >= 0x80) {
        while (j < n && word_byte((unsigned char)s[j]) && !unicode_op(s, j, n))
            j++;
        tk->kind = T_WORD;
    } else if ((c >= '0' && c <= '9') || ((c == '.' || c == '-' || c == '+') && i + 1 < n &&
               (((unsigned char)s[i + 1] >= '0' && (unsigned char)s[i + 1] <= '9') || s[i + 1] == '.'))) {
        j++;
        while (j < n && (word_byte((unsigned char)s[j]) || s[j] == '+' ||
                         (s[j] == '-' && (s[j - 1] == 'e' || s[j - 1] == 'E'))))
            j++;
        tk->kind = T_NUM;
    } else if (strchr("<>=!", (int)c)) {
        /* Take every operator character, so "=>" is reported whole. */
        while (j < n && j - i < 3 && strchr("<>=!", (int)(unsigned char)s[j]))
            j++;
        tk->kind = T_OP;
    } else {
        j++;
        tk->kind = c == '|' ? T_BAR : c == '%' ? T_PERCENT : c == '(' ? T_LPAREN : c == ')' ? T_RPAREN
                 : c == ',' ? T_COMMA : T_END;
        if (tk->kind == T_END) {
            if (c >= 0x20 && c < 0x7F)
                return FAIL(ps, i, "unexpected '%c' in the goal; expected a name, a number or one of "
                            "== != < <= > >= |", c);
            return FAIL(ps, i, "unexpected character in the goal; expected a name, a number or one of "
                        "== != < <= > >= |");
        }
    }
    tk->len = j - i;
    if (field_word(ps, i, tk->len, tk->text) != SW_OK)
        return ps->status;
    if (tk->kind == T_OP) {
        static const char *const known[] = { "==", "!=", "<", "<=", ">", ">=", "=", "!" };
        int ok = 0;
        for (int k = 0; k < 8; k++)
            ok |= strcmp(tk->text, known[k]) == 0;
        if (!ok)
            return FAIL(ps, i, "'%s' is not an operator; expected one of == != < <= > >=", tk->text);
        if (strcmp(tk->text, "=") == 0)
            strcpy(tk->text, "==");
    }
    *pos = j;
    return SW_OK;
}

static const char *var_list =
    "integrator, scene, dt, t, steps, evals, speed, energy_drift, error, drift, error_ratio, "
    "accepted, rejected, param NAME, blown, compare, ghost, paused, recorded";

static int var_is_name(int v) { return v == SW_LV_SCENE || v == SW_LV_INTEGRATOR; }
static int var_is_bool(int v) { return v >= SW_LV_BLOWN && v < SW_LV_COUNT; }

static const char *var_name_at(int i) { return sw_lesson_var_name((sw_lesson_var)i); }

static int goal_var(parser *ps, const token *tk, int *var)
{
    if (tk->kind != T_WORD)
        return FAIL(ps, tk->at, "expected a goal variable (%s)", var_list);
    *var = sw_lesson_var_find(tk->text);
    if (*var < 0) {
        char near[80];
        return FAIL(ps, tk->at, "unknown goal variable '%s'%s; expected one of %s", tk->text,
                    suggest(tk->text, var_name_at, SW_LV_COUNT, near, sizeof near), var_list);
    }
    return SW_OK;
}

static int goal_number(parser *ps, size_t *pos, int percent_ok, double *out)
{
    token tk;
    if (lex(ps, pos, &tk) != SW_OK)
        return ps->status;
    if (tk.kind == T_END)
        return FAIL(ps, tk.at, "the goal ends too soon; expected a number");
    if (tk.kind != T_NUM || sw_parse_double(tk.text, out) != SW_OK)
        return FAIL(ps, tk.at, "expected a number here, not '%s'", tk.text);
    size_t save = *pos;
    if (lex(ps, pos, &tk) != SW_OK)
        return ps->status;
    if (tk.kind == T_PERCENT) {
        if (!percent_ok)
            return FAIL(ps, tk.at, "'%%' only goes with energy_drift (a percentage); expected a plain number");
    } else {
        *pos = save;
    }
    return SW_OK;
}

/* Whether the scene in effect can ever give this variable a value. */
static int var_available(parser *ps, const token *tk, int var)
{
    const sw_scene *sc = ps->scene;
    const char *missing = NULL;
    if (var == SW_LV_ENERGY_DRIFT && !sc->energy)
        missing = "energy";
    else if ((var == SW_LV_ERROR || var == SW_LV_ERROR_RATIO) && !sc->exact && !sc->reference)
        missing = "exact solution or reference run to measure error against";
    else if (var == SW_LV_DRIFT && !sc->drift)
        missing = "invariant";
    if (missing)
        return FAIL(ps, tk->at, "scene '%s' has no %s, so a goal on %s can never be met; expected a "
                    "goal this scene can meet", sc->name, missing, tk->text);
    return SW_OK;
}

/* Check a method name in a goal: it must exist and be able to step the page's system. */
static int goal_method(parser *ps, const token *tk, const sw_integrator **out);

static int goal_bool_value(parser *ps, const token *tk, double *out)
{
    static const char *const yes[] = { "on", "yes", "true", "1" }, *const no[] = { "off", "no", "false", "0" };
    for (int i = 0; i < 4; i++) {
        if (strcmp(tk->text, yes[i]) == 0) {
            *out = 1;
            return SW_OK;
        }
        if (strcmp(tk->text, no[i]) == 0) {
            *out = 0;
            return SW_OK;
        }
    }
    return FAIL(ps, tk->at, "expected on/off (or yes/no) here, not '%s'", tk->kind == T_END ? "" : tk->text);
}

/* goal := ('not'|'!') BOOL | BOOL [op VALUE] | NAMEVAR ('=='|'!='|'is' ['not']) NAME
 *       | NAMEVAR 'in' NAME [','] NAME ... | TERM op NUMBER ['%']
 *       | TERM 'near' NUMBER ['%'] 'within' NUMBER ['%']
 * TERM := VAR | '|' VAR '|' | 'abs' '(' VAR ')'   VAR := NUMVAR | 'param' NAME */
static int parse_goal(parser *ps, size_t pos, sw_lesson_goal *g)
{
    token tk;
    memset(g, 0, sizeof *g);
    g->line = ps->line;
    if (lex(ps, &pos, &tk) != SW_OK)
        return ps->status;
    if (tk.kind == T_END)
        return FAIL(ps, ps->lnlen, "@goal needs a condition; expected e.g. 'integrator == rk4', "
                    "'dt >= 0.2', '|energy_drift| < 1', 'blown'");
    int negate = 0, var = -1, close = T_END;
    if ((tk.kind == T_WORD && strcmp(tk.text, "not") == 0) || (tk.kind == T_OP && strcmp(tk.text, "!") == 0)) {
        negate = 1;
        if (lex(ps, &pos, &tk) != SW_OK)
            return ps->status;
    } else if (tk.kind == T_BAR || (tk.kind == T_WORD && strcmp(tk.text, "abs") == 0)) {
        if (tk.kind == T_WORD) {
            if (lex(ps, &pos, &tk) != SW_OK)
                return ps->status;
            if (tk.kind != T_LPAREN)
                return FAIL(ps, tk.at, "expected '(' after abs");
        }
        close = tk.kind == T_BAR ? T_BAR : T_RPAREN;
        g->absolute = 1;
        if (lex(ps, &pos, &tk) != SW_OK)
            return ps->status;
    }
    token vtk = tk;
    if (goal_var(ps, &tk, &var) != SW_OK)
        return ps->status;
    g->var = (sw_lesson_var)var;
    if (negate && !var_is_bool(var))
        return FAIL(ps, vtk.at, "'not' goes with a yes/no variable (blown, compare, ghost, paused, "
                    "recorded), not '%s'; expected e.g. 'not blown'", vtk.text);
    if (g->absolute && (var_is_bool(var) || var_is_name(var)))
        return FAIL(ps, vtk.at, "|...| goes around a number, not '%s'", vtk.text);
    if (var_available(ps, &vtk, var) != SW_OK)
        return ps->status;
    if (var == SW_LV_PARAM) {
        token ptk;
        if (lex(ps, &pos, &ptk) != SW_OK)
            return ps->status;
        int idx = ptk.kind == T_WORD ? sw_scene_param_index(ps->scene, ptk.text) : -1;
        if (idx < 0) {
            char names[200];
            size_t used = 0;
            names[0] = '\0';
            for (int k = 0; k < ps->scene->nparams && used < sizeof names; k++) {
                int w = snprintf(names + used, sizeof names - used, "%s%s", k ? ", " : "",
                                 ps->scene->params[k].name);
                used += w > 0 ? (size_t)w : 0;
            }
            return FAIL(ps, ptk.at, "expected a parameter of scene '%s' after 'param' (%s)%s%s%s",
                        ps->scene->name, names, ptk.kind == T_END ? "" : ", not '",
                        ptk.kind == T_END ? "" : ptk.text, ptk.kind == T_END ? "" : "'");
        }
        g->param = ps->scene->params[idx].name;
    }
    if (close != T_END) {
        if (lex(ps, &pos, &tk) != SW_OK)
            return ps->status;
        if ((int)tk.kind != close)
            return FAIL(ps, tk.at, "expected '%c' to close the absolute value", close == T_BAR ? '|' : ')');
    }
    if (lex(ps, &pos, &tk) != SW_OK)
        return ps->status;
    /* "is" and "is not" read better in goals on names and yes/no. */
    if (tk.kind == T_WORD && strcmp(tk.text, "is") == 0) {
        size_t save = pos;
        token nt;
        if (lex(ps, &pos, &nt) != SW_OK)
            return ps->status;
        if (nt.kind == T_WORD && strcmp(nt.text, "not") == 0) {
            strcpy(tk.text, "!=");
        } else {
            strcpy(tk.text, "==");
            pos = save;
        }
        tk.kind = T_OP;
    }

    if (var_is_bool(var)) {
        g->op = SW_LOP_EQ;
        g->value = negate ? 0 : 1;
        if (tk.kind == T_OP && !negate && (strcmp(tk.text, "==") == 0 || strcmp(tk.text, "!=") == 0)) {
            int ne = tk.text[0] == '!';
            if (lex(ps, &pos, &tk) != SW_OK || goal_bool_value(ps, &tk, &g->value) != SW_OK)
                return ps->status;
            if (ne)
                g->value = 1 - g->value;
            if (lex(ps, &pos, &tk) != SW_OK)
                return ps->status;
        }
    } else if (var_is_name(var)) {
        int in = tk.kind == T_WORD && strcmp(tk.text, "in") == 0;
        if (!in && !(tk.kind == T_OP && (strcmp(tk.text, "==") == 0 || strcmp(tk.text, "!=") == 0)))
            return FAIL(ps, tk.at, "expected ==, != or 'in' after %s", vtk.text);
        g->op = in ? SW_LOP_IN : tk.text[0] == '!' ? SW_LOP_NE : SW_LOP_EQ;
        for (;;) {
            if (lex(ps, &pos, &tk) != SW_OK)
                return ps->status;
            if (tk.kind == T_COMMA && g->nnames > 0)
                continue;
            if (tk.kind == T_END && g->nnames > 0)
                break;
            if (tk.kind != T_WORD)
                return FAIL(ps, tk.at, "expected %s name here", var == SW_LV_SCENE ? "a scene" : "an integrator");
            if (g->nnames == SW_LESSON_MAX_NAMES)
                return FAIL(ps, tk.at, "too many names after 'in'; expected at most %d", SW_LESSON_MAX_NAMES);
            if (var == SW_LV_SCENE) {
                const sw_scene *sc = sw_scene_find(tk.text);
                if (!sc) {
                    char names[300], near[80];
                    name_list(scene_name_at, sw_scene_count(), names, sizeof names);
                    return FAIL(ps, tk.at, "unknown scene '%s'%s; expected one of %s", tk.text,
                                suggest(tk.text, scene_name_at, sw_scene_count(), near, sizeof near), names);
                }
                g->names[g->nnames++] = sc->name;
            } else {
                const sw_integrator *m;
                if (goal_method(ps, &tk, &m) != SW_OK)
                    return ps->status;
                g->names[g->nnames++] = m->name;
            }
            if (!in) {
                if (lex(ps, &pos, &tk) != SW_OK)
                    return ps->status;
                break;
            }
        }
    } else {
        int percent = var == SW_LV_ENERGY_DRIFT;
        if (tk.kind == T_WORD && strcmp(tk.text, "near") == 0) {
            g->op = SW_LOP_NEAR;
            if (goal_number(ps, &pos, percent, &g->value) != SW_OK)
                return ps->status;
            if (lex(ps, &pos, &tk) != SW_OK)
                return ps->status;
            if (!(tk.kind == T_WORD && strcmp(tk.text, "within") == 0))
                return FAIL(ps, tk.at, "expected 'within TOLERANCE' after 'near %g'", g->value);
            size_t tol_at = pos;
            while (tol_at < ps->lnlen && is_blank(ps->ln[tol_at]))
                tol_at++;
            if (goal_number(ps, &pos, percent, &g->tol) != SW_OK)
                return ps->status;
            if (!(g->tol > 0))
                return FAIL(ps, tol_at, "the tolerance after 'within' must be positive");
        } else if (tk.kind == T_OP && strcmp(tk.text, "!") != 0) {
            static const char *const ops[] = { "==", "!=", "<", "<=", ">", ">=" };
            for (int i = 0; i < 6; i++)
                if (strcmp(tk.text, ops[i]) == 0)
                    g->op = (sw_lesson_op)i;
            if (goal_number(ps, &pos, percent, &g->value) != SW_OK)
                return ps->status;
        } else {
            return FAIL(ps, tk.at, "expected a comparison after %s: one of == != < <= > >= or "
                        "'near X within Y'", vtk.text);
        }
        if (lex(ps, &pos, &tk) != SW_OK)
            return ps->status;
    }
    if (tk.kind != T_END)
        return FAIL(ps, tk.at, "unexpected '%s' after the goal; expected the end of the line "
                    "(write one condition per @goal)", tk.text[0] ? tk.text : "?");
    return SW_OK;
}

/* Check that a goal on an integrator can be met on the page's system. */
static int system_accepts(parser *ps, const sw_integrator *m, char *why, size_t len);

static int goal_method(parser *ps, const token *tk, const sw_integrator **out)
{
    if (find_integrator(ps, tk->text, tk->at, out) != SW_OK)
        return ps->status;
    char why[SW_ERRLEN];
    if (system_accepts(ps, *out, why, sizeof why) != SW_OK)
        return FAIL(ps, tk->at, "this goal can never be met on scene '%s': %s", ps->scene->name, why);
    return SW_OK;
}

/* ---- building the page's system, to check methods against it -------------------------- */

/* Build the scene with the settings so far (once per change): a build can
 * refuse parameter combinations that each lie in range. */
static int build_check(parser *ps)
{
    if (ps->have_sys && !ps->rebuild)
        return SW_OK;
    where at = ps->at_set.line ? ps->at_set : ps->at_scene.line ? ps->at_scene : (where){ ps->line, 1 };
    if (ps->have_sys)
        sw_system_free(&ps->sys);
    ps->have_sys = 0;
    char why[SW_ERRLEN];
    int rc = sw_system_build(&ps->sys, ps->scene, ps->p, why, sizeof why);
    if (rc == SW_ENOMEM)
        return oom(ps);
    if (rc != SW_OK)
        return fail_at(ps, at.line, at.col, "scene '%s' cannot be built with these parameters: %s; "
                       "expected other values", ps->scene->name, why);
    ps->have_sys = 1;
    ps->rebuild = 0;
    return SW_OK;
}

/* SW_OK when m can step the page's system, else SW_EINVAL with why filled
 * (ps->status stays SW_OK) or the build's error (ps->status set). */
static int system_accepts(parser *ps, const sw_integrator *m, char *why, size_t len)
{
    if (build_check(ps) != SW_OK)
        return ps->status;
    return sw_integrator_accepts(m, ps->sys.ode, why, len);
}

static int d_goal(parser *ps, size_t pos)
{
    sw_lesson_page *pg = page(ps);
    if (need_scene(ps, "@goal") != SW_OK)
        return ps->status;
    if (pg->ngoals == SW_LESSON_MAX_GOALS)
        return FAIL(ps, 0, "too many goals on this page; expected at most %d (split the page)",
                    SW_LESSON_MAX_GOALS);
    sw_lesson_goal *g = &pg->goals[pg->ngoals];
    if (parse_goal(ps, pos, g) != SW_OK)
        return ps->status;
    ps->at_goal[pg->ngoals] = (where){ ps->line, 1 };
    pg->ngoals++;
    ps->hint_to = HINT_GOAL;
    return SW_OK;
}

/* ---- text directives ---------------------------------------------------------------------- */

/* The rest of the line after the directive name, trimmed; fails when empty. */
static int rest_text(parser *ps, size_t pos, const char *directive, const char *expected, const char **text,
                     size_t *len, size_t *at)
{
    while (pos < ps->lnlen && is_blank(ps->ln[pos]))
        pos++;
    if (pos >= ps->lnlen)
        return FAIL(ps, pos, "%s needs text; expected %s", directive, expected);
    *text = ps->ln + pos;
    *len = ps->lnlen - pos;
    *at = pos;
    return SW_OK;
}

static int d_hint(parser *ps, size_t pos)
{
    sw_lesson_page *pg = page(ps);
    const char **slot = NULL;
    if (ps->hint_to == HINT_GOAL)
        slot = &pg->goals[pg->ngoals - 1].hint;
    else if (ps->hint_to == HINT_QUESTION)
        slot = &pg->question.hint;
    if (!slot)
        return FAIL(ps, 0, "@hint must follow the @goal (or @question) it helps with");
    if (*slot)
        return FAIL(ps, 0, "this %s already has a hint; expected one @hint per goal",
                    ps->hint_to == HINT_GOAL ? "goal" : "question");
    const char *text;
    size_t len, at;
    if (rest_text(ps, pos, "@hint", "what to press or try, e.g. '@hint Press i until the status "
                  "line says rk4.'", &text, &len, &at) != SW_OK)
        return ps->status;
    *slot = mem_strdup(ps->out, text, len);
    return *slot ? SW_OK : oom(ps);
}

static int d_question(parser *ps, size_t pos)
{
    sw_lesson_page *pg = page(ps);
    if (pg->question.text)
        return FAIL(ps, 0, "second @question on this page (the first is on line %d); expected one "
                    "question per page", pg->question.line);
    const char *text;
    size_t len, at;
    if (rest_text(ps, pos, "@question", "the question, then @answer lines and @correct", &text, &len,
                  &at) != SW_OK)
        return ps->status;
    pg->question.text = mem_strdup(ps->out, text, len);
    if (!pg->question.text)
        return oom(ps);
    pg->question.line = ps->line;
    ps->at_question = (where){ ps->line, 1 };
    ps->hint_to = HINT_QUESTION;
    return SW_OK;
}

/* @answer X) TEXT | FEEDBACK — split at the first " | ". */
static int d_answer(parser *ps, size_t pos)
{
    sw_lesson_question *q = &page(ps)->question;
    if (!q->text)
        return FAIL(ps, 0, "@answer before any @question; expected '@question TEXT' first");
    if (q->nanswers == SW_LESSON_MAX_ANSWERS)
        return FAIL(ps, 0, "too many answers; expected at most %d (a) to %c))", SW_LESSON_MAX_ANSWERS,
                    'a' + SW_LESSON_MAX_ANSWERS - 1);
    char want = (char)('a' + q->nanswers);
    while (pos < ps->lnlen && is_blank(ps->ln[pos]))
        pos++;
    size_t at = pos;
    char c = pos < ps->lnlen ? ps->ln[pos] : '\0';
    if (c >= 'A' && c <= 'Z')
        c = (char)(c - 'A' + 'a');
    if (c != want || pos + 1 >= ps->lnlen || ps->ln[pos + 1] != ')')
        return FAIL(ps, at, "expected '%c)' to start this answer (answers go a), b), c), ... in order)", want);
    pos += 2;
    const char *text;
    size_t len, text_at;
    if (rest_text(ps, pos, "@answer", "'X) ANSWER | FEEDBACK'", &text, &len, &text_at) != SW_OK)
        return ps->status;
    if (text[0] == '|')
        return FAIL(ps, text_at, "the answer text is empty; expected '%c) ANSWER | FEEDBACK'", want);
    size_t bar = 0;
    while (bar + 2 < len && !(is_blank(text[bar]) && text[bar + 1] == '|' && is_blank(text[bar + 2])))
        bar++;
    if (bar + 2 >= len) {
        if (len >= 2 && text[len - 1] == '|')
            return FAIL(ps, ps->lnlen, "the feedback after '|' is empty; expected what the student is "
                        "told on choosing %c)", want);
        return FAIL(ps, ps->lnlen, "expected ' | FEEDBACK' after the answer: what the student is told "
                    "on choosing it");
    }
    size_t tlen = bar, fb = bar + 3;
    while (fb < len && is_blank(text[fb]))
        fb++;
    while (tlen && is_blank(text[tlen - 1]))
        tlen--;
    sw_lesson_choice *a = &q->answers[q->nanswers];
    a->letter = want;
    a->text = mem_strdup(ps->out, text, tlen);
    a->feedback = mem_strdup(ps->out, text + fb, len - fb);
    if (!a->text || !a->feedback)
        return oom(ps);
    q->nanswers++;
    ps->hint_to = HINT_QUESTION;
    return SW_OK;
}

static int d_correct(parser *ps, size_t pos)
{
    sw_lesson_question *q = &page(ps)->question;
    if (!q->text)
        return FAIL(ps, 0, "@correct before any @question; expected '@question TEXT' first");
    if (once(ps, &ps->at_correct, "@correct") != SW_OK)
        return ps->status;
    char word[SW_LESSON_NAME_MAX];
    size_t at;
    if (one_word(ps, pos, "@correct", "the letter of the right answer", word, &at) != SW_OK)
        return ps->status;
    char c = word[0];
    if (c >= 'A' && c <= 'Z')
        c = (char)(c - 'A' + 'a');
    if (word[1] == ')' && word[2] == '\0')
        word[1] = '\0';
    if (word[1] != '\0' || c < 'a' || c >= 'a' + SW_LESSON_MAX_ANSWERS)
        return FAIL(ps, at, "@correct takes one letter (a, b, ...), not '%s'", word);
    ps->correct = c - 'a';
    ps->at_correct.col = col_of(ps, at);
    return SW_OK;
}

/* ---- prose ------------------------------------------------------------------------------------ */

static int flush_block(parser *ps)
{
    if (!ps->para_open)
        return SW_OK;
    ps->para_open = 0;
    if (ps->nblocks == SW_LESSON_MAX_BLOCKS)
        return fail_at(ps, ps->para_line, 1, "too many paragraphs on this page; expected at most %d "
                       "(split the page)", SW_LESSON_MAX_BLOCKS);
    char *text = mem_strdup(ps->out, ps->para, ps->paralen);
    if (!text)
        return oom(ps);
    ps->blocks[ps->nblocks++] = (sw_lesson_block){ ps->para_verbatim, text, ps->para_line };
    ps->prose += ps->paralen;
    ps->paralen = 0;
    return SW_OK;
}

static int add_prose(parser *ps, const char *s, size_t len, int verbatim)
{
    if (ps->para_open && ps->para_verbatim != verbatim && flush_block(ps) != SW_OK)
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

/* ---- pages --------------------------------------------------------------------------------------- */

/* Checks that need the whole page: questions, hints, methods against the system, locks. */
static int end_page(parser *ps)
{
    sw_lesson_page *pg = page(ps);
    if (!pg)
        return SW_OK;
    if (flush_block(ps) != SW_OK)
        return ps->status;
    sw_lesson_question *q = &pg->question;
    if (q->text) {
        if (q->nanswers < 2)
            return fail_at(ps, q->line, 1, "this question has %d answer%s; expected at least two "
                           "'@answer X) TEXT | FEEDBACK' lines", q->nanswers, q->nanswers == 1 ? "" : "s");
        if (ps->correct < 0)
            return fail_at(ps, q->line, 1, "this question has no @correct line; expected '@correct X' "
                           "naming the right answer");
        if (ps->correct >= q->nanswers)
            return fail_at(ps, ps->at_correct.line, ps->at_correct.col, "@correct %c names no answer; "
                           "expected one of a to %c", 'a' + ps->correct, 'a' + q->nanswers - 1);
        q->correct = ps->correct;
    } else if (ps->correct >= 0) {
        return fail_at(ps, ps->at_correct.line, 1, "@correct without a @question");
    }
    for (int i = 0; i < pg->ngoals; i++)
        if (!pg->goals[i].hint)
            return fail_at(ps, ps->at_goal[i].line, ps->at_goal[i].col, "this goal has no hint; expected "
                           "a '@hint TEXT' line after it saying what to press");
    if (!ps->nblocks && !q->text)
        return fail_at(ps, pg->line, 1, "page '%s' has no text; expected a few lines for the student",
                       pg->title);
    if (ps->out->npages == 1 && !ps->scene) {
        char names[300];
        name_list(scene_name_at, sw_scene_count(), names, sizeof names);
        return fail_at(ps, pg->line, 1, "the first page chooses no scene; expected '@scene NAME' "
                       "(one of %s)", names);
    }
    where at_m = ps->at_integrator.line ? ps->at_integrator : ps->at_scene.line ? ps->at_scene : (where){ pg->line, 1 };
    char why[SW_ERRLEN];
    if (system_accepts(ps, ps->method, why, sizeof why) != SW_OK) {
        if (ps->status != SW_OK)
            return ps->status;
        return fail_at(ps, at_m.line, at_m.col, "%s cannot run scene '%s': %s", ps->method->name,
                       ps->scene->name, why);
    }
    for (int i = 0; i < pg->ncompare_with; i++)
        if (system_accepts(ps, pg->compare_with[i], why, sizeof why) != SW_OK) {
            if (ps->status != SW_OK)
                return ps->status;
            return fail_at(ps, ps->at_compare.line, ps->at_compare.col, "@compare: %s", why);
        }
    /* Error needs an exact solution or a reference run; some scenes have an
     * exact solution for some parameters only (bounce: no drag). */
    const sw_scene *sc = ps->scene;
    for (int i = 0; i < pg->ngoals; i++) {
        /* Energy drift is relative to the starting energy, so it needs one. */
        if (pg->goals[i].var == SW_LV_ENERGY_DRIFT && sc->energy) {
            double e0 = sc->energy(&ps->sys, ps->sys.y);
            if (!(fabs(e0) > 0 && isfinite(e0)))
                return fail_at(ps, ps->at_goal[i].line, ps->at_goal[i].col, "scene '%s' starts with zero "
                               "energy with these parameters, so its energy drift (relative to the start) "
                               "is undefined; expected other parameters or another goal", sc->name);
        }
        if (!(sc->exact && !sc->reference) ||
            (pg->goals[i].var != SW_LV_ERROR && pg->goals[i].var != SW_LV_ERROR_RATIO))
            continue;
        double *scratch = malloc((size_t)ps->sys.ode->dim * sizeof *scratch);
        if (!scratch)
            return oom(ps);
        int exact = sc->exact(&ps->sys, 0.0, scratch) == 0;
        free(scratch);
        if (!exact)
            return fail_at(ps, ps->at_goal[i].line, ps->at_goal[i].col, "scene '%s' has no exact solution "
                           "with these parameters and no reference run, so a goal on %s can never be met; "
                           "expected other parameters or another goal", sc->name,
                           sw_lesson_var_name(pg->goals[i].var));
    }
    pg->scene = ps->scene;
    memcpy(pg->p, ps->p, sizeof pg->p);
    pg->method = ps->method;
    pg->dt = ps->dt;
    pg->locked = ps->locked;
    /* A locked control keeps the value the page starts with; a goal that
     * value fails can never be met. */
    for (int i = 0; i < pg->ngoals && pg->restart; i++) {
        const sw_lesson_goal *g = &pg->goals[i];
        sw_lesson_obs obs;
        sw_lesson_obs_init(&obs);
        obs.integrator = pg->method->name;
        obs.dt = pg->dt;
        char start[80] = "";
        if (g->var == SW_LV_INTEGRATOR && (pg->locked & SW_LOCK_INTEGRATOR))
            snprintf(start, sizeof start, "the integrator is locked and the page starts with %s",
                     pg->method->name);
        else if (g->var == SW_LV_DT && (pg->locked & SW_LOCK_DT))
            snprintf(start, sizeof start, "dt is locked and the page starts with dt = %g", pg->dt);
        if (start[0] && !sw_lesson_goal_met(g, &obs)) {
            char text[120];
            sw_lesson_goal_text(g, text, sizeof text);
            return fail_at(ps, ps->at_goal[i].line, ps->at_goal[i].col, "goal '%s' can never be met: %s; "
                           "expected an @unlock or another goal", text, start);
        }
    }
    pg->blocks = NULL;
    if (ps->nblocks) {
        sw_lesson_block *b = mem_alloc(ps->out, (size_t)ps->nblocks * sizeof *b);
        if (!b)
            return oom(ps);
        memcpy(b, ps->blocks, (size_t)ps->nblocks * sizeof *b);
        pg->blocks = b;
    }
    pg->nblocks = ps->nblocks;
    return SW_OK;
}

static int begin_page(parser *ps, size_t title_at)
{
    if (end_page(ps) != SW_OK)
        return ps->status;
    sw_lesson *l = ps->out;
    if (!l->title)
        return fail_at(ps, ps->line, 1, "page before the lesson's title; expected a 'title: LESSON TITLE' "
                       "line at the top of the file");
    if (l->npages == SW_LESSON_MAX_PAGES)
        return FAIL(ps, 0, "too many pages; expected at most %d in one lesson (split it into two files)",
                    SW_LESSON_MAX_PAGES);
    /* Title: the rest of the line, trailing dashes ("--- Title ---") dropped. */
    size_t end = ps->lnlen;
    while (end > title_at && (ps->ln[end - 1] == '-' || is_blank(ps->ln[end - 1])))
        end--;
    while (title_at < end && is_blank(ps->ln[title_at]))
        title_at++;
    if (end == title_at)
        return FAIL(ps, title_at, "page without a title; expected '--- PAGE TITLE'");
    if (col_of(ps, end) - col_of(ps, title_at) > SW_LESSON_MAX_TITLE)
        return FAIL(ps, title_at, "page title longer than %d characters; expected a short title",
                    SW_LESSON_MAX_TITLE);
    if (l->npages == ps->cap_pages) {
        int cap = ps->cap_pages ? 2 * ps->cap_pages : 8;
        sw_lesson_page *pages = realloc(l->pages, (size_t)cap * sizeof *pages);
        if (!pages)
            return oom(ps);
        l->pages = pages;
        ps->cap_pages = cap;
    }
    sw_lesson_page *pg = &l->pages[l->npages++];
    memset(pg, 0, sizeof *pg);
    pg->title = mem_strdup(l, ps->ln + title_at, end - title_at);
    if (!pg->title)
        return oom(ps);
    pg->line = ps->line;
    pg->compare = pg->ghost = pg->paused = -1;
    pg->locked = ps->locked;
    where none = { 0, 0 };
    ps->at_scene = ps->at_set = ps->at_integrator = ps->at_dt = ps->at_compare = none;
    ps->at_ghost = ps->at_pause = ps->at_reset = ps->at_question = ps->at_correct = none;
    memset(ps->set_line, 0, sizeof ps->set_line);
    ps->correct = -1;
    ps->hint_to = HINT_NONE;
    ps->nblocks = 0;
    ps->prose = 0;
    ps->paralen = 0;
    ps->para_open = 0;
    return SW_OK;
}

/* ---- lines ------------------------------------------------------------------------------------------ */

static int d_ghost(parser *ps, size_t pos)
{
    if (once(ps, &ps->at_ghost, "@ghost") != SW_OK)
        return ps->status;
    return on_off(ps, pos, "@ghost", &page(ps)->ghost);
}

static int d_pause(parser *ps, size_t pos)
{
    if (once(ps, &ps->at_pause, "@pause") != SW_OK)
        return ps->status;
    return on_off(ps, pos, "@pause", &page(ps)->paused);
}

static int d_reset(parser *ps, size_t pos)
{
    if (once(ps, &ps->at_reset, "@reset") != SW_OK)
        return ps->status;
    size_t start, len;
    if (next_field(ps, &pos, &start, &len))
        return FAIL(ps, start, "@reset takes nothing after it");
    page(ps)->restart = 1;
    return SW_OK;
}

static int d_lock_on(parser *ps, size_t pos) { return d_lock(ps, pos, 1); }
static int d_lock_off(parser *ps, size_t pos) { return d_lock(ps, pos, 0); }

static const struct directive {
    const char *name;
    int (*run)(parser *ps, size_t pos);
} directives[] = {
    { "scene", d_scene }, { "set", d_set }, { "integrator", d_integrator }, { "dt", d_dt },
    { "compare", d_compare }, { "ghost", d_ghost }, { "pause", d_pause }, { "reset", d_reset },
    { "lock", d_lock_on }, { "unlock", d_lock_off }, { "goal", d_goal }, { "hint", d_hint },
    { "question", d_question }, { "answer", d_answer }, { "correct", d_correct },
};

#define NDIRECTIVES ((int)(sizeof directives / sizeof directives[0]))

static const char *directive_name_at(int i) { return directives[i].name; }

static int directive(parser *ps, size_t at)
{
    if (!page(ps))
        return FAIL(ps, at, "directive before the first page; expected '--- PAGE TITLE' first");
    size_t i = at + 1;
    while (i < ps->lnlen && ((ps->ln[i] >= 'a' && ps->ln[i] <= 'z') || (ps->ln[i] >= 'A' && ps->ln[i] <= 'Z')))
        i++;
    char name[SW_LESSON_NAME_MAX];
    size_t nlen = i - at - 1;
    if (nlen >= sizeof name)
        nlen = sizeof name - 1;
    memcpy(name, ps->ln + at + 1, nlen);
    name[nlen] = '\0';
    if (i < ps->lnlen && !is_blank(ps->ln[i]))
        return FAIL(ps, i, "expected a space after '@%s'", name);
    if (ps->hint_to == HINT_QUESTION && strcmp(name, "hint") != 0 && strcmp(name, "answer") != 0 &&
        strcmp(name, "correct") != 0)
        ps->hint_to = HINT_NONE;
    if (ps->hint_to == HINT_GOAL && strcmp(name, "hint") != 0)
        ps->hint_to = HINT_NONE;
    for (int k = 0; k < NDIRECTIVES; k++)
        if (strcmp(name, directives[k].name) == 0)
            return directives[k].run(ps, i);
    char near[80];
    return FAIL(ps, at, "unknown directive '@%s'%s; expected one of @scene @set @integrator @dt @compare "
                "@ghost @pause @reset @lock @unlock @goal @hint @question @answer @correct",
                name, suggest_with("@", name, directive_name_at, NDIRECTIVES, near, sizeof near));
}

static int header_line(parser *ps, size_t at)
{
    static const char key[] = "title:";
    if (ps->lnlen - at < sizeof key - 1 || memcmp(ps->ln + at, key, sizeof key - 1) != 0)
        return FAIL(ps, at, "text before the first page; expected 'title: LESSON TITLE' at the top, then "
                    "pages starting with '--- PAGE TITLE'");
    if (ps->out->title)
        return FAIL(ps, at, "second title (the first is on line %d); expected one 'title:' line",
                    ps->title_at.line);
    size_t s = at + sizeof key - 1;
    while (s < ps->lnlen && is_blank(ps->ln[s]))
        s++;
    if (s >= ps->lnlen)
        return FAIL(ps, s, "empty title; expected 'title: LESSON TITLE'");
    if (col_of(ps, ps->lnlen) - col_of(ps, s) > SW_LESSON_MAX_TITLE)
        return FAIL(ps, s, "title longer than %d characters; expected a short title", SW_LESSON_MAX_TITLE);
    ps->out->title = mem_strdup(ps->out, ps->ln + s, ps->lnlen - s);
    ps->title_at = (where){ ps->line, col_of(ps, at) };
    return ps->out->title ? SW_OK : oom(ps);
}

static int read_line(parser *ps)
{
    size_t at = 0;
    while (at < ps->lnlen && is_blank(ps->ln[at]))
        at++;
    if (at == ps->lnlen) {
        /* A blank line ends a paragraph. */
        return flush_block(ps);
    }
    char c = ps->ln[at];
    if (c == '#')
        return SW_OK;
    if (c == '-' && ps->lnlen - at >= 3 && memcmp(ps->ln + at, "---", 3) == 0)
        return begin_page(ps, at + 3);
    if (!page(ps)) {
        if (c == '@')
            return directive(ps, at);
        return header_line(ps, at);
    }
    if (c == '@') {
        if (flush_block(ps) != SW_OK)
            return ps->status;
        return directive(ps, at);
    }
    if (c != '\\')
        return add_prose(ps, ps->ln, ps->lnlen, at > 0);
    /* A leading backslash shows the rest literally ("\@home", "\# 1"), and
     * an indented line keeps its indentation. */
    char line[SW_LESSON_MAX_LINE];
    memcpy(line, ps->ln, at);
    memcpy(line + at, ps->ln + at + 1, ps->lnlen - at - 1);
    return add_prose(ps, line, ps->lnlen - 1, at > 0);
}

/* Check the bytes of one line: length, UTF-8, no control characters.
 * Returns the line's length (up to the newline) via *len. */
static int check_bytes(parser *ps, const unsigned char *s, size_t avail, size_t *len)
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
        if ((c < 0x20 && c != '\t') || c == 0x7F)
            return FAIL(ps, i, "control character 0x%02X; expected plain text (tabs are fine)", c);
        if (c < 0x80) {
            i++;
            continue;
        }
        /* UTF-8: lead byte, continuation count, smallest code point. */
        int more;
        uint32_t cp, min;
        if (c >= 0xC2 && c <= 0xDF) {
            more = 1; cp = c & 0x1F; min = 0x80;
        } else if (c >= 0xE0 && c <= 0xEF) {
            more = 2; cp = c & 0x0F; min = 0x800;
        } else if (c >= 0xF0 && c <= 0xF4) {
            more = 3; cp = c & 0x07; min = 0x10000;
        } else {
            return FAIL(ps, i, "invalid UTF-8 (byte 0x%02X); expected the file saved as UTF-8", c);
        }
        for (int k = 1; k <= more; k++) {
            if (i + (size_t)k >= avail || (s[i + k] & 0xC0) != 0x80)
                return FAIL(ps, i, "invalid UTF-8 (byte 0x%02X starts a character that is cut short); "
                            "expected the file saved as UTF-8", c);
            cp = (cp << 6) | (s[i + k] & 0x3F);
        }
        if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
            return FAIL(ps, i, "invalid UTF-8 (byte 0x%02X starts an overlong or out-of-range sequence); "
                        "expected the file saved as UTF-8", c);
        if (cp >= 0x80 && cp <= 0x9F)
            return FAIL(ps, i, "control character U+%04X; expected plain text", (unsigned)cp);
        if (i + (size_t)more >= SW_LESSON_MAX_LINE) {
            ps->lnlen = i + (size_t)more + 1;
            return FAIL(ps, i, "line longer than %d bytes; expected shorter lines (break the "
                        "paragraph: lines are joined)", SW_LESSON_MAX_LINE);
        }
        i += (size_t)more + 1;
    }
    *len = i;
    size_t n = i;
    if (n && s[n - 1] == '\r')
        n--;
    while (n && is_blank((char)s[n - 1]))
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
    parser *ps = calloc(1, sizeof *ps);
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
    out->name = mem_strdup(out, ps->name, strlen(ps->name));
    if (!out->name)
        oom(ps);
    else if (len > SW_LESSON_MAX_BYTES)
        fail_at(ps, 1, 1, "file is %zu bytes; expected a lesson of at most %d bytes (split it)", len,
                SW_LESSON_MAX_BYTES);
    size_t pos = 0;
    const unsigned char *s = (const unsigned char *)text;
    /* A UTF-8 byte-order mark, as some editors write, is not text. */
    if (len >= 3 && s[0] == 0xEF && s[1] == 0xBB && s[2] == 0xBF)
        pos = 3;
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
            fail_at(ps, 1, 1, "empty file; expected 'title: LESSON TITLE', then pages starting with "
                    "'--- PAGE TITLE'");
        else if (!out->title)
            fail_at(ps, 1, 1, "no 'title:' line; expected 'title: LESSON TITLE' at the top");
        else if (!out->npages)
            fail_at(ps, ps->line, 1, "the lesson has no pages; expected '--- PAGE TITLE' lines after the title");
        else
            end_page(ps);
    }
    int rc = ps->status;
    if (ps->have_sys)
        sw_system_free(&ps->sys);
    free(ps);
    if (rc != SW_OK)
        sw_lesson_free(out);
    return rc;
}
