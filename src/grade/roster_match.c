/* Matching a submission's path to a roster student: the download names of
 * Gradescope, Canvas and Moodle, then a plain id, email or name prefix,
 * tried on each folder and the file, outermost first. Invariant: a match is
 * exact on folded keys, and two students fitting one name is never guessed
 * between: it is SW_ROSTER_AMBIGUOUS with both named. */
#include "grade/roster.h"

#include <assert.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "grade/roster_int.h"
#include "stepwise/base.h"
#include "util/escape.h"

/* ---- lookups ---------------------------------------------------------------- */

int rst_by_id(const sw_roster *r, const char *id, int *out, int max)
{
    int n = 0;
    if (!id[0])
        return 0;
    for (int i = 0; i < r->n && n < max; i++)
        for (int j = 0; j < r->students[i].nids; j++)
            if (strcmp(r->students[i].ids[j], id) == 0) {
                out[n++] = i;
                break;
            }
    return n;
}

int rst_by_email(const sw_roster *r, const char *text, int *out, int max)
{
    int n = 0;
    size_t len = strlen(text);
    if (len == 0)
        return 0;
    int local = strchr(text, '@') == NULL;
    for (int i = 0; i < r->n && n < max; i++) {
        const char *e = r->students[i].email;
        if (strcmp(e, text) == 0 || (local && strncmp(e, text, len) == 0 && e[len] == '@'))
            out[n++] = i;
    }
    return n;
}

/* Whether key is words read from start to the end and then from the
 * beginning up to start, spaces left out. */
static int rotation_is(const char *words, const char *start, const char *key)
{
    const char *k = key;
    for (const char *w = start; *w; w++)
        if (*w != ' ' && *k++ != *w)
            return 0;
    for (const char *w = words; w < start; w++)
        if (*w != ' ' && *k++ != *w)
            return 0;
    return *k == '\0';
}

static int name_fits(const char *words, const char *key)
{
    if (!key[0])
        return 0;
    for (const char *start = words; start; start = strchr(start, ' ')) {
        if (*start == ' ')
            start++;
        if (rotation_is(words, start, key))
            return 1;
    }
    return 0;
}

int rst_by_name(const sw_roster *r, const char *key, int *out, int max)
{
    int n = 0;
    for (int i = 0; i < r->n && n < max; i++)
        if (name_fits(r->students[i].words, key))
            out[n++] = i;
    return n;
}

/* ---- the rules, one folder or file name at a time --------------------------- */

enum { R_SKIP, R_NONE, R_ONE, R_AMBIG };

#define FOUND_MAX SW_ROSTER_GROUP_MAX

typedef struct found {
    int n;
    int idx[FOUND_MAX];
} found;

static void add_found(found *f, int i)
{
    for (int j = 0; j < f->n; j++)
        if (f->idx[j] == i)
            return;
    if (f->n < FOUND_MAX)
        f->idx[f->n++] = i;
}

/* A message into buf, cut to len (a why line is allowed to be cut). */
static void say(char *buf, size_t len, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
static void say(char *buf, size_t len, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, len, fmt, ap);
    va_end(ap);
}

/* "Name (roster line N)" for messages, escaped and cut. */
static const char *who(const sw_roster *r, int i, char *buf, size_t len)
{
    char e[96];
    sw_escape(r->students[i].name, 60, e, sizeof e);
    snprintf(buf, len, "%s (roster line %ld)", e, r->students[i].line);
    return buf;
}

static int all_digits(const char *s, size_t n)
{
    if (n == 0 || n > 18)
        return 0;
    for (size_t i = 0; i < n; i++)
        if (s[i] < '0' || s[i] > '9')
            return 0;
    return 1;
}

/* The result of an id and a name from a download's name: the id decides
 * unless the name is someone else's. */
static int resolve(const sw_roster *r, const char *platform, const char *id, const char *name,
                   size_t namelen, found *f, char *why, size_t whylen)
{
    char idn[RST_KEY_MAX], key[RST_KEY_MAX], shown[96], a[160], b[160];
    int by_id[2], by_name[FOUND_MAX];
    rst_norm_id(id, strlen(id), idn, sizeof idn);
    sw_roster_fold(name, namelen, key, sizeof key);
    snprintf(a, sizeof a, "%.*s", (int)(namelen < 80 ? namelen : 80), name);
    sw_escape(a, 60, shown, sizeof shown);
    int ni = rst_by_id(r, idn, by_id, 2), nn = rst_by_name(r, key, by_name, FOUND_MAX);
    f->n = 0;
    if (ni == 1) {
        int agrees = nn == 0;
        for (int j = 0; j < nn; j++)
            agrees |= by_name[j] == by_id[0];
        if (!agrees) {
            add_found(f, by_id[0]);
            add_found(f, by_name[0]);
            say(why, whylen, "%s name: id %s is %s but '%s' is %s", platform, id,
                     who(r, by_id[0], a, sizeof a), shown, who(r, by_name[0], b, sizeof b));
            return R_AMBIG;
        }
        add_found(f, by_id[0]);
        say(why, whylen, "%s name: id %s%s is %s", platform, id, nn ? " and the name" : "",
                 who(r, by_id[0], a, sizeof a));
        return R_ONE;
    }
    for (int j = 0; j < nn; j++)
        add_found(f, by_name[j]);
    if (nn == 1) {
        say(why, whylen, "%s name: '%s' is %s", platform, shown, who(r, by_name[0], a, sizeof a));
        return R_ONE;
    }
    if (nn > 1) {
        say(why, whylen, "%s name: '%s' fits %s and %s; rename the file with the id",
                 platform, shown, who(r, by_name[0], a, sizeof a), who(r, by_name[1], b, sizeof b));
        return R_AMBIG;
    }
    say(why, whylen, "%s name '%s' (id %s): no roster student has that name or id",
             platform, shown, id);
    return R_NONE;
}

/* Gradescope's export: a folder "submission_<digits>", its submitters in
 * submission_metadata.yml. */
static int rule_gradescope(const sw_roster *r, const char *c, found *f, char *why, size_t whylen)
{
    if (strncmp(c, "submission_", 11) != 0 || !all_digits(c + 11, strlen(c + 11)))
        return R_SKIP;
    if (!r->gs) {
        say(why, whylen, "%s is a Gradescope export folder: its students are in the "
                 "export's submission_metadata.yml (give it with the roster)", c);
        return R_NONE;
    }
    for (int i = 0; i < r->ngs; i++) {
        const sw_roster_gs *g = &r->gs[i];
        if (strcmp(g->folder, c) != 0)
            continue;
        char a[160], e[96];
        f->n = 0;
        for (int j = 0; j < g->n; j++)
            if (g->student[j] >= 0)
                add_found(f, g->student[j]);
        if (f->n == 0) {
            sw_escape(g->n ? g->who[0] : "nobody", 60, e, sizeof e);
            say(why, whylen, "Gradescope's %s was submitted by %s, who is not on the roster",
                     c, e);
            return R_NONE;
        }
        if (f->n < g->n)
            say(why, whylen, "Gradescope's %s: %s; %d of its %d submitters are not on the "
                     "roster", c, who(r, f->idx[0], a, sizeof a), g->n - f->n, g->n);
        else if (f->n > 1)
            say(why, whylen, "Gradescope's %s: a group of %d, first %s", c, f->n,
                     who(r, f->idx[0], a, sizeof a));
        else
            say(why, whylen, "Gradescope's %s: %s", c, who(r, f->idx[0], a, sizeof a));
        return R_ONE;
    }
    say(why, whylen, "Gradescope's %s is not in submission_metadata.yml", c);
    return R_NONE;
}

/* Canvas: "<lastfirst>_[late_]<userid>_<fileid>_<original>", the name only
 * letters, digits and _ (older downloads: "last--first[-late]_..."); or
 * "<lastfirst>_<userid>_text.html" / "_link.html". */
static int rule_canvas(const sw_roster *r, const char *c, found *f, char *why, size_t whylen)
{
    const char *tok[32];
    size_t len[32];
    int n = 0;
    for (const char *p = c; n < 32;) {
        const char *u = strchr(p, '_');
        tok[n] = p;
        len[n++] = u ? (size_t)(u - p) : strlen(p);
        if (!u)
            break;
        p = u + 1;
    }
    for (int i = 1; i + 1 < n; i++) {
        if (!all_digits(tok[i], len[i]))
            continue;
        int file_id = all_digits(tok[i + 1], len[i + 1]) && i + 2 < n;
        int entry = i + 2 == n && (strcmp(tok[i + 1], "text.html") == 0 ||
                                   strcmp(tok[i + 1], "link.html") == 0);
        if (!file_id && !entry)
            continue;
        int name_toks = i;
        if (name_toks > 1 && len[name_toks - 1] == 4 && strncmp(tok[name_toks - 1], "late", 4) == 0)
            name_toks--;
        size_t name_len = (size_t)(tok[name_toks - 1] + len[name_toks - 1] - c);
        if (name_len > 5 && strncmp(c + name_len - 5, "-late", 5) == 0)
            name_len -= 5;
        for (size_t k = 0; k < name_len; k++) {
            unsigned char ch = (unsigned char)c[k];
            if (!(ch >= 0x80 || ch == '_' || ch == '-' || (ch >= '0' && ch <= '9') ||
                  (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z')))
                return R_SKIP;
        }
        char id[24];
        snprintf(id, sizeof id, "%.*s", (int)len[i], tok[i]);
        return resolve(r, "Canvas", id, c, name_len, f, why, whylen);
    }
    return R_SKIP;
}

/* Moodle: "<Full Name>_<id>_assignsubmission_<plugin>_[<original>]". */
static int rule_moodle(const sw_roster *r, const char *c, found *f, char *why, size_t whylen)
{
    const char *m = strstr(c, "_assignsubmission_");
    if (!m || m == c)
        return R_SKIP;
    const char *d = m;
    while (d > c && d[-1] >= '0' && d[-1] <= '9')
        d--;
    if (d == m || d == c || d[-1] != '_' || d - 1 == c)
        return R_SKIP;
    char id[24];
    snprintf(id, sizeof id, "%.*s", (int)(m - d < 20 ? m - d : 20), d);
    return resolve(r, "Moodle", id, c, (size_t)(d - 1 - c), f, why, whylen);
}

static int delim(char ch) { return ch == '_' || ch == '-' || ch == '.' || ch == ' ' || ch == '@' || ch == '+'; }

/* The one of f's students whose id or email is a word of c[0..stem)
 * ("wei_zhang_s1005"), or -1. */
static int settle_by_id(const sw_roster *r, const char *c, size_t stem, const found *f)
{
    int settled = -1;
    for (size_t at = 0; at < stem;) {
        size_t n = 0;
        while (at + n < stem && !delim(c[at + n]))
            n++;
        char word[RST_KEY_MAX], id[RST_KEY_MAX];
        snprintf(word, sizeof word, "%.*s", (int)n, c + at);
        for (char *w = word; *w; w++)
            *w = (char)(*w >= 'A' && *w <= 'Z' ? *w - 'A' + 'a' : *w);
        rst_norm_id(word, n, id, sizeof id);
        int hits[2], k = rst_by_id(r, id, hits, 2);
        if (k == 0)
            k = rst_by_email(r, word, hits, 2);
        for (int j = 0; k == 1 && j < f->n; j++)
            if (f->idx[j] == hits[0]) {
                if (settled >= 0 && settled != hits[0])
                    return -1;
                settled = hits[0];
            }
        at += n + 1;
    }
    return settled;
}

/* A plain prefix: the name (without its extension, for a file), or its
 * part before a _ - . space @ +, longest first, is an id, an email (or its
 * part before '@') or a name. */
static int rule_plain(const sw_roster *r, const char *c, int is_file, found *f, char *why,
                      size_t whylen)
{
    size_t stem = strlen(c);
    const char *dot = strrchr(c, '.');
    if (is_file && dot && dot != c && strlen(dot + 1) >= 1 && strlen(dot + 1) <= 10)
        stem = (size_t)(dot - c);
    for (size_t end = stem; end > 0; end--) {
        if (end < stem && !delim(c[end]))
            continue;
        if (delim(c[end - 1]))
            continue;
        char cand[RST_KEY_MAX], low[RST_KEY_MAX], key[RST_KEY_MAX], shown[96];
        snprintf(cand, sizeof cand, "%.*s", (int)end, c);
        size_t k;
        for (k = 0; cand[k]; k++)
            low[k] = (char)(cand[k] >= 'A' && cand[k] <= 'Z' ? cand[k] - 'A' + 'a' : cand[k]);
        low[k] = '\0';
        int hits[FOUND_MAX], n;
        const char *how = NULL;
        f->n = 0;
        rst_norm_id(cand, end, key, sizeof key);
        if ((n = rst_by_id(r, key, hits, FOUND_MAX)) > 0)
            how = "id";
        for (int j = 0; j < n; j++)
            add_found(f, hits[j]);
        if ((n = rst_by_email(r, low, hits, FOUND_MAX)) > 0 && !how)
            how = "email";
        for (int j = 0; j < n; j++)
            add_found(f, hits[j]);
        sw_roster_fold(cand, end, key, sizeof key);
        if ((n = rst_by_name(r, key, hits, FOUND_MAX)) > 0 && !how)
            how = "name";
        for (int j = 0; j < n; j++)
            add_found(f, hits[j]);
        if (f->n == 0)
            continue;
        char a[160], b[160];
        sw_escape(cand, 60, shown, sizeof shown);
        if (f->n > 1) {
            int settled = settle_by_id(r, c, stem, f);
            if (settled >= 0) {
                say(why, whylen, "%s name '%s' fits %d students; the id or email in it is %s",
                    is_file ? "file" : "folder", shown, f->n, who(r, settled, a, sizeof a));
                f->n = 1;
                f->idx[0] = settled;
                return R_ONE;
            }
            say(why, whylen, "'%s' fits %s and %s; rename the file with the id", shown,
                     who(r, f->idx[0], a, sizeof a), who(r, f->idx[1], b, sizeof b));
            return R_AMBIG;
        }
        say(why, whylen, "%s name '%s' is the %s of %s", is_file ? "file" : "folder", shown,
                 how, who(r, f->idx[0], a, sizeof a));
        return R_ONE;
    }
    return R_SKIP;
}

/* ---- the path --------------------------------------------------------------- */

static int contained(const found *inner, const found *outer)
{
    for (int i = 0; i < inner->n; i++) {
        int in = 0;
        for (int j = 0; j < outer->n; j++)
            in |= inner->idx[i] == outer->idx[j];
        if (!in)
            return 0;
    }
    return 1;
}

int sw_roster_match_all(const sw_roster *r, const char *relpath, int *out, int max, char *why,
                        size_t whylen)
{
    char scratch[SW_ERRLEN], note[SW_ERRLEN] = "", amb_why[SW_ERRLEN] = "", msg[SW_ERRLEN];
    if (!why || whylen == 0) {
        why = scratch;
        whylen = sizeof scratch;
    }
    why[0] = '\0';
    assert(out && max >= 1);
    if (!r || r->n == 0 || !relpath) {
        say(why, whylen, "the roster is empty");
        return SW_ROSTER_NONE;
    }
    found amb = { 0 }, f;
    const char *p = relpath;
    for (int depth = 0; *p && depth < 64; depth++) {
        size_t n = strcspn(p, "/\\");
        const char *next = p[n] ? p + n + 1 : p + n;
        int is_file = p[n] == '\0';
        char c[256];
        if (n == 0 || n >= sizeof c || (n == 1 && p[0] == '.')) {
            p = next;
            continue;
        }
        memcpy(c, p, n);
        c[n] = '\0';
        p = next;
        int res = R_SKIP;
        for (int rule = 0; rule < 4 && res != R_ONE && res != R_AMBIG; rule++) {
            int got = rule == 0 ? rule_gradescope(r, c, &f, msg, sizeof msg)
                    : rule == 1 ? rule_canvas(r, c, &f, msg, sizeof msg)
                    : rule == 2 ? rule_moodle(r, c, &f, msg, sizeof msg)
                    : rule_plain(r, c, is_file, &f, msg, sizeof msg);
            if (got == R_NONE && !note[0])
                say(note, sizeof note, "%s", msg);
            if (got != R_SKIP)
                res = got;
        }
        if (res == R_ONE) {
            if (amb.n > 0 && !contained(&f, &amb)) {
                say(why, whylen, "%s; and %s", amb_why, msg);
                return SW_ROSTER_AMBIGUOUS;
            }
            int k = 0;
            for (; k < f.n && k < max; k++)
                out[k] = f.idx[k];
            if (amb.n > 0)
                say(why, whylen, "%s (settles: %s)", msg, amb_why);
            else
                say(why, whylen, "%s", msg);
            return k;
        }
        if (res == R_AMBIG && amb.n == 0) {
            amb = f;
            say(amb_why, sizeof amb_why, "%s", msg);
        }
    }
    if (amb.n > 0) {
        say(why, whylen, "%s", amb_why);
        return SW_ROSTER_AMBIGUOUS;
    }
    if (note[0]) {
        say(why, whylen, "%s", note);
    } else {
        char e[96];
        sw_escape(relpath, 60, e, sizeof e);
        say(why, whylen, "no folder or file name in '%s' starts with a roster id, email or "
                 "name", e);
    }
    return SW_ROSTER_NONE;
}

int sw_roster_match(const sw_roster *r, const char *relpath, char *why, size_t whylen)
{
    int first;
    int n = sw_roster_match_all(r, relpath, &first, 1, why, whylen);
    return n > 0 ? first : n;
}

/* ---- what a file says about itself ------------------------------------------ */

/* Whether every word of a is one of b's. */
static int words_within(const char *a, const char *b)
{
    for (const char *w = a; *w;) {
        size_t n = strcspn(w, " ");
        int in = 0;
        for (const char *v = b; *v && !in;) {
            size_t m = strcspn(v, " ");
            in = m == n && strncmp(v, w, n) == 0;
            v += m + (v[m] == ' ');
        }
        if (!in)
            return 0;
        w += n + (w[n] == ' ');
    }
    return 1;
}

sw_roster_claim sw_roster_check_claim(const sw_roster *r, int student, const char *declared,
                                      int *other, char *why, size_t whylen)
{
    char scratch[SW_ERRLEN];
    if (!why || whylen == 0) {
        why = scratch;
        whylen = sizeof scratch;
    }
    why[0] = '\0';
    if (other)
        *other = SW_ROSTER_NONE;
    size_t len = declared ? strlen(declared) : 0;
    char words[RST_KEY_MAX], key[RST_KEY_MAX], idn[RST_KEY_MAX], low[RST_KEY_MAX], shown[96];
    if (len > RST_KEY_MAX - 1) /* a student's words are shorter: first + last cells */
        len = RST_KEY_MAX - 1;
    if (rst_fold_words(declared ? declared : "", len, words, sizeof words) == 0)
        return SW_CLAIM_NONE;
    sw_roster_fold(declared, len, key, sizeof key);
    rst_norm_id(declared, len, idn, sizeof idn);
    size_t k = 0;
    for (; k < len && k + 1 < sizeof low; k++)
        low[k] = (char)(declared[k] >= 'A' && declared[k] <= 'Z' ? declared[k] - 'A' + 'a' : declared[k]);
    low[k] = '\0';
    sw_escape(declared, 60, shown, sizeof shown);
    char a[160], b[160];
    if (r && student >= 0 && student < r->n) {
        const sw_student *s = &r->students[student];
        int self = name_fits(s->words, key) || words_within(words, s->words) ||
                   words_within(s->words, words);
        for (int j = 0; j < s->nids && !self; j++)
            self = strcmp(s->ids[j], idn) == 0;
        if (!self && s->email[0])
            self = strcmp(s->email, low) == 0 || (strncmp(s->email, low, strlen(low)) == 0 &&
                                                  s->email[strlen(low)] == '@');
        if (self) {
            say(why, whylen, "'# student: %s' is %s", shown, who(r, student, a, sizeof a));
            return SW_CLAIM_SELF;
        }
    }
    int hits[FOUND_MAX], n = 0;
    found f = { 0 };
    if (r) {
        n = rst_by_name(r, key, hits, FOUND_MAX);
        for (int j = 0; j < n; j++)
            add_found(&f, hits[j]);
        n = rst_by_id(r, idn, hits, FOUND_MAX);
        for (int j = 0; j < n; j++)
            add_found(&f, hits[j]);
        n = rst_by_email(r, low, hits, FOUND_MAX);
        for (int j = 0; j < n; j++)
            add_found(&f, hits[j]);
    }
    if (f.n > 0) {
        if (other)
            *other = f.idx[0];
        if (r && student >= 0 && student < r->n)
            say(why, whylen, "'# student: %s' names %s, but the file is %s's: not believed",
                     shown, who(r, f.idx[0], a, sizeof a), who(r, student, b, sizeof b));
        else
            say(why, whylen, "'# student: %s' names %s, but the file's name matched nobody: "
                     "not believed", shown, who(r, f.idx[0], b, sizeof b));
        return SW_CLAIM_OTHER;
    }
    say(why, whylen, "'# student: %s' is nobody on the roster", shown);
    return SW_CLAIM_UNKNOWN;
}
