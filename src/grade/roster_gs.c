/* Gradescope's submission_metadata.yml, read as the small YAML subset that
 * Gradescope writes: top-level "submission_<id>:" keys, each with a
 * ":submitters:" list of ":name:", ":sid:" and ":email:". Deeper entries
 * (a submission's history) are skipped. Invariant: each submitter is
 * resolved to a roster student once, here, by sid, else email, else name. */
#include "grade/roster.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grade/roster_int.h"
#include "stepwise/base.h"
#include "util/utf8.h"

#define GS_LINE_MAX 4096

typedef struct member {
    char name[SW_ROSTER_CELL_MAX + 1], sid[SW_ROSTER_CELL_MAX + 1], email[SW_ROSTER_CELL_MAX + 1];
    int open;
} member;

static int hexval(char c)
{
    return c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10
         : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
}

/* A scalar: 'single' ('' is '), "double" (\\ \" \n \t \xHH \uHHHH
 * \UHHHHHHHH), or plain up to a " #" comment; into out. 0, or -1 when
 * longer than outlen - 1 bytes. */
static int scalar(const char *v, size_t n, char *out, size_t outlen)
{
    size_t o = 0;
    while (n > 0 && v[0] == ' ')
        v++, n--;
    while (n > 0 && v[n - 1] == ' ')
        n--;
#define PUT(ch) do { if (o + 1 >= outlen) return -1; out[o++] = (char)(ch); } while (0)
    if (n > 0 && v[0] == '\'') {
        for (size_t i = 1; i < n; i++) {
            if (v[i] == '\'' && i + 1 < n && v[i + 1] == '\'')
                i++;
            else if (v[i] == '\'')
                break;
            PUT(v[i]);
        }
    } else if (n > 0 && v[0] == '"') {
        for (size_t i = 1; i < n && v[i] != '"'; i++) {
            if (v[i] != '\\' || i + 1 >= n) {
                PUT(v[i]);
                continue;
            }
            char e = v[++i];
            int digits = e == 'x' ? 2 : e == 'u' ? 4 : e == 'U' ? 8 : 0;
            if (digits == 0) {
                PUT(e == 'n' ? '\n' : e == 't' ? '\t' : e);
                continue;
            }
            uint32_t cp = 0;
            for (int d = 0; d < digits; d++) {
                int h = i + 1 < n ? hexval(v[i + 1]) : -1;
                if (h < 0)
                    break;
                cp = cp * 16 + (uint32_t)h;
                i++;
            }
            char enc[4];
            int len = cp ? sw_utf8_encode(cp, enc) : 0;
            for (int k = 0; k < len; k++)
                PUT(enc[k]);
        }
    } else {
        for (size_t i = 0; i < n; i++) {
            if (v[i] == '#' && i > 0 && v[i - 1] == ' ')
                break;
            PUT(v[i]);
        }
        while (o > 0 && out[o - 1] == ' ')
            o--;
    }
#undef PUT
    out[o] = '\0';
    return 0;
}

/* ":key: value" into the member; other keys are left alone. */
static int member_key(member *m, const char *s, size_t n)
{
    char *into = NULL;
    if (n >= 6 && strncmp(s, ":name:", 6) == 0)
        into = m->name, s += 6, n -= 6;
    else if (n >= 5 && strncmp(s, ":sid:", 5) == 0)
        into = m->sid, s += 5, n -= 5;
    else if (n >= 7 && strncmp(s, ":email:", 7) == 0)
        into = m->email, s += 7, n -= 7;
    return into ? scalar(s, n, into, SW_ROSTER_CELL_MAX + 1) : 0;
}

static int resolve_member(const sw_roster *r, const member *m)
{
    char key[RST_KEY_MAX];
    int hits[2], n;
    rst_norm_id(m->sid, strlen(m->sid), key, sizeof key);
    if ((n = rst_by_id(r, key, hits, 2)) > 0)
        return n == 1 ? hits[0] : SW_ROSTER_AMBIGUOUS;
    size_t i = 0;
    for (; m->email[i] && i + 1 < sizeof key; i++)
        key[i] = (char)(m->email[i] >= 'A' && m->email[i] <= 'Z' ? m->email[i] - 'A' + 'a' : m->email[i]);
    key[i] = '\0';
    if (strchr(key, '@') && (n = rst_by_email(r, key, hits, 2)) > 0)
        return n == 1 ? hits[0] : SW_ROSTER_AMBIGUOUS;
    sw_roster_fold(m->name, strlen(m->name), key, sizeof key);
    n = rst_by_name(r, key, hits, 2);
    return n == 1 ? hits[0] : n > 1 ? SW_ROSTER_AMBIGUOUS : SW_ROSTER_NONE;
}

/* Close the open member into g: resolved, and its name kept for messages. */
static int finish(sw_roster *r, sw_roster_gs *g, member *m, const char *name, long line,
                  char *err, size_t errlen)
{
    if (!m->open || !g)
        return SW_OK;
    m->open = 0;
    if (g->n == SW_ROSTER_GROUP_MAX)
        return rst_fail(err, errlen, name, line, "more than %d submitters in one submission",
                        SW_ROSTER_GROUP_MAX);
    const char *shown = m->name[0] ? m->name : m->sid[0] ? m->sid : m->email;
    if (!(g->who[g->n] = rst_dup(r, shown, strlen(shown))))
        return SW_ENOMEM;
    g->student[g->n++] = resolve_member(r, m);
    return SW_OK;
}

/* "submission_<digits>:" (trailing spaces allowed): the folder's length, or 0. */
static size_t folder_key(const char *l, size_t n)
{
    size_t d = 11;
    if (n < 13 || strncmp(l, "submission_", 11) != 0)
        return 0;
    while (d < n && l[d] >= '0' && l[d] <= '9')
        d++;
    if (d == 11 || d > 11 + 18 || d >= n || l[d] != ':')
        return 0;
    for (size_t i = d + 1; i < n; i++)
        if (l[i] != ' ')
            return 0;
    return d;
}

int sw_roster_parse_gradescope(sw_roster *r, const char *name, const char *text, size_t len,
                               char *err, size_t errlen)
{
    free(r->gs);
    r->gs = NULL;
    r->ngs = 0;
    sw_roster_gs *gs = NULL, *cur = NULL;
    int ngs = 0, in_sub = 0, item_indent = 0, rc = SW_OK;
    member *m = calloc(1, sizeof *m);
    long line = 0;
    if (!m)
        rc = SW_ENOMEM;
    for (const char *p = text, *end = text + len; rc == SW_OK && p < end;) {
        const char *l = p, *nl = memchr(p, '\n', (size_t)(end - p));
        size_t n = nl ? (size_t)(nl - p) : (size_t)(end - p);
        p = nl ? nl + 1 : end;
        line++;
        if (n > GS_LINE_MAX) {
            rc = rst_fail(err, errlen, name, line, "a line longer than %d bytes", GS_LINE_MAX);
            break;
        }
        if (memchr(l, '\0', n)) {
            rc = rst_fail(err, errlen, name, line, "a NUL byte: not a metadata file");
            break;
        }
        while (n > 0 && (l[n - 1] == '\r' || l[n - 1] == ' '))
            n--;
        size_t indent = 0;
        while (indent < n && l[indent] == ' ')
            indent++;
        if (indent == n || l[indent] == '#')
            continue;
        int item = in_sub && n >= indent + 2 && l[indent] == '-' && l[indent + 1] == ' ';
        if (indent == 0) {
            rc = finish(r, cur, m, name, line, err, errlen);
            cur = NULL;
            in_sub = 0;
            size_t fl = folder_key(l, n);
            if (rc != SW_OK || fl == 0)
                continue;
            for (int i = 0; i < ngs; i++)
                if (strlen(gs[i].folder) == fl && strncmp(gs[i].folder, l, fl) == 0)
                    rc = rst_fail(err, errlen, name, line, "%.*s appears twice (first on line %ld)",
                                  (int)fl, l, gs[i].line);
            if (rc == SW_OK && ngs == SW_ROSTER_MAX)
                rc = rst_fail(err, errlen, name, line, "more than %d submissions", SW_ROSTER_MAX);
            if (rc == SW_OK && ngs % 64 == 0) {
                sw_roster_gs *grown = realloc(gs, ((size_t)ngs + 64) * sizeof *grown);
                if (!grown)
                    rc = SW_ENOMEM;
                else
                    gs = grown;
            }
            if (rc != SW_OK)
                break;
            cur = &gs[ngs++];
            memset(cur, 0, sizeof *cur);
            cur->line = line;
            if (!(cur->folder = rst_dup(r, l, fl)))
                rc = SW_ENOMEM;
        } else if (!cur) {
            continue;
        } else if (item && (indent == 2 || indent == 4)) {
            rc = finish(r, cur, m, name, line, err, errlen);
            memset(m, 0, sizeof *m);
            m->open = 1;
            item_indent = (int)indent;
            if (rc == SW_OK && member_key(m, l + indent + 2, n - indent - 2) != 0)
                rc = rst_fail(err, errlen, name, line, "a value longer than %d bytes",
                              SW_ROSTER_CELL_MAX);
        } else if (indent == 2) {
            rc = finish(r, cur, m, name, line, err, errlen);
            in_sub = n == 14 && strncmp(l + 2, ":submitters:", 12) == 0;
        } else if (in_sub && m->open && (int)indent == item_indent + 2) {
            if (member_key(m, l + indent, n - indent) != 0)
                rc = rst_fail(err, errlen, name, line, "a value longer than %d bytes",
                              SW_ROSTER_CELL_MAX);
        }
    }
    if (rc == SW_OK)
        rc = finish(r, cur, m, name, line, err, errlen);
    free(m);
    if (rc == SW_OK && ngs == 0)
        rc = rst_fail(err, errlen, name, 1, "no 'submission_ID:' entries: not a Gradescope "
                      "export's submission_metadata.yml");
    if (rc == SW_ENOMEM)
        snprintf(err, errlen, "%.200s: out of memory for the metadata", name);
    if (rc != SW_OK) {
        free(gs);
        return rc;
    }
    r->gs = gs;
    r->ngs = ngs;
    return SW_OK;
}

int sw_roster_read_gradescope(sw_roster *r, const char *path, char *err, size_t errlen)
{
    char *text;
    size_t len;
    int rc = rst_read_file(path, "a Gradescope metadata file", &text, &len, err, errlen);
    if (rc != SW_OK)
        return rc;
    rc = sw_roster_parse_gradescope(r, path, text, len, err, errlen);
    free(text);
    return rc;
}
