/* Roster CSV reading: RFC 4180 records (quoted cells, doubled quotes), a
 * header row that names the columns, and each row checked. Invariant: every
 * string a student holds sits in the roster's pool, folded once here, so
 * matching a path never allocates; a bad byte anywhere is an error with its
 * line, never a crash (tests/fuzz/fuzz_roster.c). */
#include "grade/roster.h"

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "grade/roster_int.h"
#include "stepwise/base.h"
#include "util/escape.h"
#include "util/infile.h"
#include "util/utf8.h"

/* ---- the pool and messages -------------------------------------------------- */

struct sw_roster_block {
    sw_roster_block *next;
    size_t used, cap;
    char data[];
};

#define BLOCK_MIN ((size_t)64 << 10)

const char *rst_dup(sw_roster *r, const char *s, size_t n)
{
    sw_roster_block *b = r->pool;
    if (!b || b->cap - b->used < n + 1) {
        size_t cap = n + 1 > BLOCK_MIN ? n + 1 : BLOCK_MIN;
        b = malloc(sizeof *b + cap);
        if (!b)
            return NULL;
        b->next = r->pool;
        b->used = 0;
        b->cap = cap;
        r->pool = b;
    }
    char *d = b->data + b->used;
    memcpy(d, s, n);
    d[n] = '\0';
    b->used += n + 1;
    return d;
}

int rst_fail(char *err, size_t errlen, const char *name, long line, const char *fmt, ...)
{
    if (!err || errlen == 0)
        return SW_EINVAL;
    int used = snprintf(err, errlen, "%.200s:%ld: ", name, line > 0 ? line : 1);
    if (used >= 0 && (size_t)used < errlen) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err + used, errlen - (size_t)used, fmt, ap);
        va_end(ap);
    }
    return SW_EINVAL;
}

/* ---- CSV records ------------------------------------------------------------ */

typedef char csv_cell[SW_ROSTER_CELL_MAX + 1];

typedef struct csv {
    const char *name;
    const char *p, *end;
    char sep;
    long line;
} csv;

static int blank(char c, char sep) { return c == ' ' || (c == '\t' && sep != '\t'); }

/* The next record's cells (trimmed, NUL-terminated) into cells; *at is its
 * first line. 1, 0 at the end, or SW_EINVAL. */
static int csv_next(csv *c, csv_cell *cells, int *ncells, long *at, char *err, size_t errlen)
{
    if (c->p >= c->end)
        return 0;
    *at = c->line;
    int n = 0;
    for (;;) {
        if (n == SW_ROSTER_COLS_MAX)
            return rst_fail(err, errlen, c->name, c->line, "more than %d cells in a row",
                            SW_ROSTER_COLS_MAX);
        char *cell = cells[n++];
        size_t len = 0;
        const char *p = c->p;
        while (p < c->end && blank(*p, c->sep))
            p++;
        if (p < c->end && *p == '"') {
            long opened = c->line;
            for (p++;;) {
                if (p >= c->end)
                    return rst_fail(err, errlen, c->name, opened,
                                    "a quoted cell opened on this line is never closed");
                char ch = *p++;
                if (ch == '"') {
                    if (p >= c->end || *p != '"')
                        break;
                    p++;
                } else if (ch == '\n' || ch == '\r') {
                    return rst_fail(err, errlen, c->name, opened, "a quoted cell opened on this "
                                    "line runs past its end (a missing closing quote, or a line "
                                    "break in a cell)");
                } else if ((unsigned char)ch < 0x20 || ch == 0x7f) {
                    return rst_fail(err, errlen, c->name, c->line, "a cell holds a control character");
                }
                if (len == SW_ROSTER_CELL_MAX)
                    return rst_fail(err, errlen, c->name, c->line, "a cell longer than %d bytes",
                                    SW_ROSTER_CELL_MAX);
                cell[len++] = ch;
            }
            while (p < c->end && blank(*p, c->sep))
                p++;
            if (p < c->end && *p != c->sep && *p != '\n' && *p != '\r')
                return rst_fail(err, errlen, c->name, c->line,
                                "text after a quoted cell's closing quote (a quote inside a "
                                "quoted cell is written twice: \"\")");
        } else {
            while (p < c->end && *p != c->sep && *p != '\n' && *p != '\r') {
                char ch = *p++;
                if (((unsigned char)ch < 0x20 && ch != '\t') || ch == 0x7f)
                    return rst_fail(err, errlen, c->name, c->line,
                                    "a cell holds a control character");
                if (len == SW_ROSTER_CELL_MAX)
                    return rst_fail(err, errlen, c->name, c->line, "a cell longer than %d bytes",
                                    SW_ROSTER_CELL_MAX);
                cell[len++] = ch;
            }
            while (len > 0 && (cell[len - 1] == ' ' || cell[len - 1] == '\t'))
                len--;
            for (size_t i = 0; i < len; i++)
                if (cell[i] == '\t')
                    return rst_fail(err, errlen, c->name, c->line,
                                    "a cell holds a control character (a tab)");
        }
        cell[len] = '\0';
        c->p = p;
        if (p < c->end && *p == c->sep) {
            c->p = p + 1;
            continue;
        }
        if (p < c->end && *p == '\r')
            p++;
        if (p < c->end && *p == '\n')
            p++;
        c->line++;
        c->p = p;
        *ncells = n;
        return 1;
    }
}

/* The separator: the first of , ; TAB found outside quotes on the first line. */
static char csv_separator(const char *p, const char *end)
{
    int quoted = 0, seen[3] = { 0, 0, 0 };
    for (; p < end && (quoted || (*p != '\n' && *p != '\r')); p++) {
        if (*p == '"')
            quoted = !quoted;
        else if (!quoted)
            seen[0] |= *p == ',', seen[1] |= *p == ';', seen[2] |= *p == '\t';
    }
    return seen[0] ? ',' : seen[1] ? ';' : seen[2] ? '\t' : ',';
}

/* ---- the header ------------------------------------------------------------- */

enum { COL_NONE, COL_NAME, COL_FIRST, COL_LAST, COL_ID, COL_EMAIL, COL_ROLE };

static const struct header_name { const char *label; int role; } header_names[] = {
    { "name", COL_NAME }, { "student", COL_NAME }, { "student name", COL_NAME },
    { "full name", COL_NAME }, { "fullname", COL_NAME },
    { "first name", COL_FIRST }, { "firstname", COL_FIRST }, { "first", COL_FIRST },
    { "given name", COL_FIRST }, { "given names", COL_FIRST }, { "forename", COL_FIRST },
    { "last name", COL_LAST }, { "lastname", COL_LAST }, { "last", COL_LAST },
    { "surname", COL_LAST }, { "family name", COL_LAST },
    { "id", COL_ID }, { "sid", COL_ID }, { "student id", COL_ID }, { "studentid", COL_ID },
    { "student number", COL_ID }, { "id number", COL_ID }, { "matriculation number", COL_ID },
    { "sis user id", COL_ID }, { "sis login id", COL_ID }, { "login id", COL_ID },
    { "user id", COL_ID }, { "username", COL_ID },
    { "email", COL_EMAIL }, { "e mail", COL_EMAIL }, { "email address", COL_EMAIL },
    { "e mail address", COL_EMAIL },
    { "role", COL_ROLE },
};

/* A header cell as a label: lower case, runs of space _ - . as one space. */
static int header_role(const char *cell)
{
    char label[64];
    size_t o = 0;
    for (const char *p = cell; *p && o + 1 < sizeof label; p++) {
        char c = *p;
        if (c == ' ' || c == '_' || c == '-' || c == '.') {
            if (o > 0 && label[o - 1] != ' ')
                label[o++] = ' ';
            continue;
        }
        label[o++] = (char)(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    }
    while (o > 0 && label[o - 1] == ' ')
        o--;
    label[o] = '\0';
    for (size_t i = 0; i < sizeof header_names / sizeof header_names[0]; i++)
        if (strcmp(label, header_names[i].label) == 0)
            return header_names[i].role;
    return COL_NONE;
}

typedef struct columns {
    int ncols;
    int name, first, last, email, role;  /* a column index, or -1 */
    int id[SW_ROSTER_IDS], nids;
} columns;

static int read_header(csv *c, csv_cell *cells, columns *k, char *err, size_t errlen)
{
    int n = 0, rc;
    long at;
    while ((rc = csv_next(c, cells, &n, &at, err, errlen)) == 1 && n == 1 && cells[0][0] == '\0')
        ; /* blank lines before the header */
    if (rc < 0)
        return rc;
    if (rc == 0)
        return rst_fail(err, errlen, c->name, c->line,
                        "empty: the first row names the columns (e.g. name,id,email)");
    memset(k, 0, sizeof *k);
    k->ncols = n;
    k->name = k->first = k->last = k->email = k->role = -1;
    char found[160] = "";
    for (int i = 0; i < n; i++) {
        int role = header_role(cells[i]), *slot = NULL;
        switch (role) {
        case COL_NAME: slot = &k->name; break;
        case COL_FIRST: slot = &k->first; break;
        case COL_LAST: slot = &k->last; break;
        case COL_EMAIL: slot = &k->email; break;
        case COL_ROLE: slot = &k->role; break;
        case COL_ID:
            if (k->nids == SW_ROSTER_IDS)
                return rst_fail(err, errlen, c->name, at, "more than %d id columns; keep the "
                                "ones submissions are named by", SW_ROSTER_IDS);
            k->id[k->nids++] = i;
            break;
        case COL_NONE: break;
        }
        if (slot && *slot >= 0) {
            char a[48], b[48];
            sw_escape(cells[*slot], 40, a, sizeof a);
            sw_escape(cells[i], 40, b, sizeof b);
            return rst_fail(err, errlen, c->name, at, "columns %d ('%s') and %d ('%s') say the "
                            "same thing; keep one", *slot + 1, a, i + 1, b);
        }
        if (slot)
            *slot = i;
        if (strlen(found) < 100) {
            char e[40];
            sw_escape(cells[i], 24, e, sizeof e);
            snprintf(found + strlen(found), sizeof found - strlen(found), "%s'%s'", i ? ", " : "", e);
        }
    }
    if (k->name < 0 && (k->first < 0 || k->last < 0))
        return rst_fail(err, errlen, c->name, at, "no name column: the header needs 'name', or "
                        "'first name' and 'last name' (it has %s)", found);
    return SW_OK;
}

/* ---- rows ------------------------------------------------------------------- */

static int ieq(const char *a, const char *b)
{
    for (; *a && *b; a++, b++) {
        char x = *a >= 'A' && *a <= 'Z' ? (char)(*a - 'A' + 'a') : *a;
        char y = *b >= 'A' && *b <= 'Z' ? (char)(*b - 'A' + 'a') : *b;
        if (x != y)
            return 0;
    }
    return *a == *b;
}

/* A role cell that does not say "student" (any case): staff. */
static int row_is_staff(const char *role)
{
    if (!role[0])
        return 0;
    for (const char *p = role; *p; p++) {
        const char *want = "student";
        size_t i = 0;
        while (want[i] && p[i] && (p[i] | 0x20) == want[i])
            i++;
        if (!want[i])
            return 0;
    }
    return 1;
}

/* Add the student of one row; 0 when added, 1 when the row is left out, or
 * an error. */
static int add_row(sw_roster *r, const columns *k, csv_cell *cells, int n, long at,
                   const char *name, char *err, size_t errlen)
{
    const char *cell_name = k->name >= 0 && k->name < n ? cells[k->name] : "";
    const char *first = k->first >= 0 && k->first < n ? cells[k->first] : "";
    const char *last = k->last >= 0 && k->last < n ? cells[k->last] : "";
    if ((k->role >= 0 && k->role < n && row_is_staff(cells[k->role])) ||
        ieq(cell_name, "Points Possible"))
        return 1;
    char display[2 * SW_ROSTER_CELL_MAX + 2], given[2 * SW_ROSTER_CELL_MAX + 2];
    const char *comma = strchr(cell_name, ',');
    if (first[0] || last[0]) {
        snprintf(given, sizeof given, "%s%s%s", first, first[0] && last[0] ? " " : "", last);
        snprintf(display, sizeof display, "%s", cell_name[0] ? cell_name : given);
    } else if (comma) { /* "Last, First" (Canvas's gradebook) */
        const char *f = comma + 1;
        while (*f == ' ')
            f++;
        snprintf(given, sizeof given, "%s %.*s", f, (int)(comma - cell_name), cell_name);
        snprintf(display, sizeof display, "%s", given);
    } else {
        snprintf(given, sizeof given, "%s", cell_name);
        snprintf(display, sizeof display, "%s", cell_name);
    }
    char words[RST_KEY_MAX];
    if (rst_fold_words(given, strlen(given), words, sizeof words) == 0)
        return rst_fail(err, errlen, name, at, "no name on this row (its name cell%s %s)",
                        k->name >= 0 ? "" : "s", given[0] ? "has no letters or digits" : "is empty");
    if (r->n == SW_ROSTER_MAX)
        return rst_fail(err, errlen, name, at, "more than %d students", SW_ROSTER_MAX);
    if (r->n % 256 == 0) {
        sw_student *grown = realloc(r->students, ((size_t)r->n + 256) * sizeof *grown);
        if (!grown)
            return SW_ENOMEM;
        r->students = grown;
    }
    sw_student *s = &r->students[r->n];
    memset(s, 0, sizeof *s);
    s->line = at;
    s->name = rst_dup(r, display, strlen(display));
    s->words = rst_dup(r, words, strlen(words));
    s->email = "";
    if (!s->name || !s->words)
        return SW_ENOMEM;
    for (int i = 0; i < k->nids; i++) {
        char id[RST_KEY_MAX];
        size_t len = k->id[i] < n ? rst_norm_id(cells[k->id[i]], SW_ROSTER_CELL_MAX, id, sizeof id) : 0;
        int dup = 0;
        for (int j = 0; j < s->nids; j++)
            dup |= strcmp(s->ids[j], id) == 0;
        if (len == 0 || dup)
            continue;
        if (!(s->ids[s->nids++] = rst_dup(r, id, len)))
            return SW_ENOMEM;
    }
    if (k->email >= 0 && k->email < n && cells[k->email][0]) {
        char mail[SW_ROSTER_CELL_MAX + 1];
        size_t len = 0;
        for (const char *p = cells[k->email]; *p; p++)
            mail[len++] = (char)(*p >= 'A' && *p <= 'Z' ? *p - 'A' + 'a' : *p);
        mail[len] = '\0';
        const char *at_sign = strchr(mail, '@');
        if (!at_sign || at_sign == mail || strchr(at_sign + 1, '@') || strchr(mail, ' ')) {
            char e[64];
            sw_escape(mail, 40, e, sizeof e);
            return rst_fail(err, errlen, name, at, "'%s' is not an email address", e);
        }
        if (!(s->email = rst_dup(r, mail, len)))
            return SW_ENOMEM;
    }
    r->n++;
    return 0;
}

typedef struct keyed { const char *key; int student; } keyed;

static int keyed_cmp(const void *a, const void *b)
{
    const keyed *x = a, *y = b;
    int c = strcmp(x->key, y->key);
    return c ? c : (x->student > y->student) - (x->student < y->student);
}

/* Two students with one id or one email would make matching guess. */
static int check_unique(sw_roster *r, const char *name, char *err, size_t errlen)
{
    keyed *all = malloc(((size_t)r->n * (SW_ROSTER_IDS + 1) + 1) * sizeof *all);
    if (!all)
        return SW_ENOMEM;
    for (int pass = 0; pass < 2; pass++) {
        size_t n = 0;
        for (int i = 0; i < r->n; i++) {
            const sw_student *s = &r->students[i];
            if (pass == 0)
                for (int j = 0; j < s->nids; j++)
                    all[n++] = (keyed){ s->ids[j], i };
            else if (s->email[0])
                all[n++] = (keyed){ s->email, i };
        }
        qsort(all, n, sizeof *all, keyed_cmp);
        for (size_t i = 1; i < n; i++)
            if (strcmp(all[i].key, all[i - 1].key) == 0 && all[i].student != all[i - 1].student) {
                const sw_student *a = &r->students[all[i - 1].student], *b = &r->students[all[i].student];
                char e[80];
                sw_escape(all[i].key, 60, e, sizeof e);
                free(all);
                return rst_fail(err, errlen, name, b->line, "%s %s is also line %ld's; each "
                                "student needs their own", pass == 0 ? "id" : "email", e, a->line);
            }
    }
    free(all);
    return SW_OK;
}

void sw_roster_free(sw_roster *r)
{
    if (!r)
        return;
    for (sw_roster_block *b = r->pool, *next; b; b = next) {
        next = b->next;
        free(b);
    }
    free(r->students);
    free(r->gs);
    memset(r, 0, sizeof *r);
}

int sw_roster_parse(const char *name, const char *text, size_t len, sw_roster *r, char *err,
                    size_t errlen)
{
    memset(r, 0, sizeof *r);
    if (len >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0) {
        text += 3;
        len -= 3;
    }
    long line = 1;
    for (size_t i = 0; i < len;) {
        size_t n = 1;
        uint32_t cp;
        if (text[i] == '\n')
            line++;
        if ((unsigned char)text[i] >= 0x80 &&
            sw_utf8_check((const unsigned char *)text + i, len - i, &n, &cp) != SW_UTF8_OK)
            return rst_fail(err, errlen, name, line, "not UTF-8 text (save the roster as "
                            "\"CSV UTF-8\")");
        if (text[i] == '\0')
            return rst_fail(err, errlen, name, line, "a NUL byte: not a CSV file");
        i += n;
    }
    csv c = { name, text, text + len, csv_separator(text, text + len), 1 };
    columns k;
    csv_cell *cells = malloc(SW_ROSTER_COLS_MAX * sizeof *cells);
    if (!cells) {
        snprintf(err, errlen, "%.200s: out of memory for the roster", name);
        return SW_ENOMEM;
    }
    int rc = read_header(&c, cells, &k, err, errlen);
    int n;
    long at;
    while (rc == SW_OK && (rc = csv_next(&c, cells, &n, &at, err, errlen)) == 1) {
        int empty = 1, used = 0;
        for (int i = 0; i < n; i++) {
            empty &= cells[i][0] == '\0';
            if (cells[i][0])
                used = i + 1;
        }
        rc = SW_OK;
        if (empty)
            continue;
        if (used > k.ncols) { /* trailing empty cells are harmless */
            rc = rst_fail(err, errlen, name, at, "%d cells, but the header has %d (a cell that "
                          "holds the separator must be quoted: \"Smith, John\")", used, k.ncols);
            break;
        }
        rc = add_row(r, &k, cells, used, at, name, err, errlen);
        if (rc == 1) {
            r->skipped++;
            rc = SW_OK;
        }
    }
    if (rc == SW_OK && r->n == 0)
        rc = rst_fail(err, errlen, name, c.line, "no students after the header");
    if (rc == SW_OK)
        rc = check_unique(r, name, err, errlen);
    free(cells);
    if (rc == SW_ENOMEM)
        snprintf(err, errlen, "%.200s: out of memory for the roster", name);
    if (rc != SW_OK)
        sw_roster_free(r);
    return rc;
}

int rst_read_file(const char *path, const char *kind, char **text, size_t *len, char *err,
                  size_t errlen)
{
    struct stat st;
    const char *what;
    int fd = sw_infile_open(path, &st, &what);
    if (fd < 0) {
        if (what)
            return rst_fail(err, errlen, path, 1, "is %s, not %s", what, kind);
        snprintf(err, errlen, "%.200s:1: cannot open: %s", path, strerror(errno));
        return SW_EIO;
    }
    int rc = sw_infile_read(fd, SW_ROSTER_FILE_MAX, text, len);
    int e = errno;
    close(fd);
    if (rc == 1)
        return rst_fail(err, errlen, path, 1, "larger than %u MiB: not %s",
                        SW_ROSTER_FILE_MAX >> 20, kind);
    if (rc != 0) {
        snprintf(err, errlen, "%.200s:1: cannot read: %s", path, strerror(e));
        return SW_EIO;
    }
    return SW_OK;
}

int sw_roster_read(const char *path, sw_roster *r, char *err, size_t errlen)
{
    char *text;
    size_t len;
    memset(r, 0, sizeof *r);
    int rc = rst_read_file(path, "a roster", &text, &len, err, errlen);
    if (rc != SW_OK)
        return rc;
    rc = sw_roster_parse(path, text, len, r, err, errlen);
    free(text);
    return rc;
}
