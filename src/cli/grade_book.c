/* The CSV gradebook, and regrading into an existing one: rows of the files
 * graded now replace their rows, every other row is kept as it was, so a
 * teacher can regrade one student without losing the class. Invariants:
 * the old gradebook is read back bounded before any grading (util/csv.h)
 * and refused unless its columns are ours (or the first of them, from an
 * older stepwise); every cell is written through sw_csv_field, old ones
 * too, so the file stays inert in a spreadsheet whatever was in it. */
#include "cli/grade.h"

#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "util/csv.h"
#include "util/escape.h"
#include "util/outfile.h"

/* New columns go last, so an older gradebook's header is a prefix of ours. */
static const char *const columns[] = { "student", "file", "verdict", "first_failing_step",
                                       "message", "id", "remarks", "similar", "score", "max", "part" };
enum { NCOLS = sizeof columns / sizeof columns[0], COL_STUDENT = 0, COL_FILE = 1,
       COL_VERDICT = 2 };

int grade_book_load(grade_list *l, const char *csv)
{
    char err[SW_ERRLEN + 512];
    sw_outfile_target t;
    if (!csv || l->fresh || sw_outfile_resolve(csv, &t, err, sizeof err) != SW_OK || t.is_stdout ||
        t.direct || !t.exists)
        return SW_EXIT_OK;
    sw_csv_doc *d = calloc(1, sizeof *d);
    if (!d)
        return sw_cli_error("grade: out of memory");
    int rc = sw_csv_read(t.path, d, err, sizeof err);
    const char *bad = NULL;
    long line = 0;
    if (rc == SW_OK && d->nrows > 0) {
        const sw_csv_row *h = &d->rows[0];
        if (h->n > NCOLS)
            bad = "it has more columns than a stepwise gradebook";
        for (int c = 0; !bad && c < h->n; c++)
            if (strcmp(h->cells[c], columns[c]) != 0)
                bad = "its header is not a stepwise gradebook's";
        if (!bad && h->n < COL_VERDICT + 1)
            bad = "its header is not a stepwise gradebook's";
        for (int r = 1; !bad && r < d->nrows; r++)
            if (d->rows[r].n != h->n && !(d->rows[r].n == 1 && !d->rows[r].cells[0][0])) {
                bad = "a row has another number of cells than the header";
                line = d->rows[r].line;
            }
    }
    if (rc != SW_OK || bad) {
        sw_csv_doc_free(d);
        free(d);
        if (bad)
            return sw_cli_error("grade: --csv '%.200s' exists and is not a gradebook to update "
                                "(%s%s%.0ld): give --fresh to start it over, or another name",
                                csv, bad, line ? " on line " : "", line);
        return sw_cli_error("grade: --csv: the existing gradebook cannot be read back: %s; give "
                            "--fresh to start it over", err);
    }
    if (d->nrows == 0) {
        sw_csv_doc_free(d);
        free(d);
        return SW_EXIT_OK;
    }
    l->old_book = d;
    return SW_EXIT_OK;
}

/* One row written as a line; its cells as read back, for comparing. */
typedef struct book_row {
    char *line;
    sw_csv_doc cells;
    int used;
} book_row;

/* A row's text: its cells point into e and into the caller's buffers. */
typedef struct row_text {
    char student[4 * SW_TRACE_STUDENT_MAX + 8], step[24], score[32], max[32];
    char file[4 * PATH_MAX + 8];
} row_text;

/* The student and file cells, a row's keys: the text with every
 * backslash escaped too (\x5c), so two names never give one cell (the
 * message rule keeps backslashes, and "Jos\xe9" written as is would read
 * as the Latin-1 "Jos" + é escaped). A path too long for a cell (over
 * 3800 bytes escaped) ends in a digest of the whole. */
static void key_cell(const char *path, char *out, size_t outlen)
{
    sw_escape(path, strlen(path), out, outlen);
    size_t n = strlen(out);
    if (n > 3800) {
        uint64_t h = 1469598103934665603u; /* FNV-1a 64 of the path as named */
        for (const unsigned char *c = (const unsigned char *)path; *c; c++)
            h = (h ^ *c) * 1099511628211u;
        snprintf(out + 3760, outlen - 3760, "...#%016llx", (unsigned long long)h);
    }
}

static void row_cells(const grade_list *l, const grade_entry *e, const char **cells, row_text *t)
{
    char student[SW_TRACE_STUDENT_MAX];
    grade_student_of(e, student, sizeof student);
    key_cell(student, t->student, sizeof t->student);
    key_cell(e->path ? e->path : "", t->file, sizeof t->file);
    t->step[0] = t->score[0] = t->max[0] = '\0';
    if (e->failing_step >= 0)
        snprintf(t->step, sizeof t->step, "%ld", e->failing_step);
    double points, most;
    grade_points_of(l, e, &points, &most);
    snprintf(t->score, sizeof t->score, "%g", points);
    snprintf(t->max, sizeof t->max, "%g", most);
    const char *c[NCOLS] = { t->student, t->file, grade_verdict_word(e->status), t->step, e->message,
                             e->owner_id, e->remarks, e->similar, t->score, t->max,
                             l->hw && e->part >= 0 && e->part < l->hw->nparts ? l->hw->parts[e->part].name : "" };
    memcpy(cells, c, sizeof c);
}

static int render(const grade_list *l, const grade_entry *e, book_row *out)
{
    row_text text;
    const char *cells[NCOLS];
    row_cells(l, e, cells, &text);
    size_t len = 0;
    out->line = NULL;
    out->used = 0;
    FILE *f = open_memstream(&out->line, &len);
    if (!f)
        return SW_ENOMEM;
    for (int c = 0; c < NCOLS; c++) {
        sw_csv_field(f, cells[c]);
        fputs(c + 1 < NCOLS ? "," : "\r\n", f);
    }
    if (fclose(f) != 0)
        return SW_ENOMEM;
    char err[SW_ERRLEN];
    return sw_csv_parse("row", out->line, len, &out->cells, err, sizeof err);
}

static const char *cell(const sw_csv_doc *d, int col)
{
    return d->nrows > 0 && col < d->rows[0].n ? d->rows[0].cells[col] : "";
}

/* Whether two file cells name one file as given: "./class//a.trace" and
 * "class/a.trace" do (a regrade names files its own way). */
static int same_path(const char *a, const char *b)
{
    int at_component = 1; /* a and b are at the start of a component */
    if ((a[0] == '/') != (b[0] == '/'))
        return 0;
    for (;;) {
        if (at_component) {
            for (;;) {
                if (a[0] == '.' && a[1] == '/')
                    a += 2;
                else if (a[0] == '/')
                    a++;
                else
                    break;
            }
            for (;;) {
                if (b[0] == '.' && b[1] == '/')
                    b += 2;
                else if (b[0] == '/')
                    b++;
                else
                    break;
            }
        }
        if (!*a || !*b || *a != *b)
            return *a == *b;
        at_component = *a == '/';
        a++;
        b++;
    }
}

static void write_old(FILE *f, const sw_csv_row *row)
{
    for (int c = 0; c < NCOLS; c++) {
        sw_csv_field(f, c < row->n ? row->cells[c] : "");
        fputs(c + 1 < NCOLS ? "," : "\r\n", f);
    }
}

void grade_book_write(FILE *f, const grade_list *l, char *said, size_t saidlen)
{
    said[0] = '\0';
    for (int c = 0; c < NCOLS; c++) {
        fputs(columns[c], f);
        fputs(c + 1 < NCOLS ? "," : "\r\n", f);
    }
    int rows = l->n + l->ignored;
    book_row *nr = calloc((size_t)rows + 1, sizeof *nr);
    int ok = nr != NULL;
    for (int i = 0; ok && i < rows; i++)
        ok = render(l, i < l->n ? &l->items[i] : &l->refused[i - l->n], &nr[i]) == SW_OK;
    if (!ok) {
        /* Out of memory: the gradebook is written from this run alone. */
        for (int i = 0; i < rows; i++) {
            row_text text;
            const char *cells[NCOLS];
            row_cells(l, i < l->n ? &l->items[i] : &l->refused[i - l->n], cells, &text);
            for (int c = 0; c < NCOLS; c++) {
                sw_csv_field(f, cells[c]);
                fputs(c + 1 < NCOLS ? "," : "\r\n", f);
            }
        }
    } else if (!l->old_book) {
        for (int i = 0; i < rows; i++)
            fputs(nr[i].line, f);
    } else {
        const sw_csv_doc *old = l->old_book;
        int updated = 0, kept = 0, added = 0;
        for (int r = 1; r < old->nrows; r++) {
            const sw_csv_row *o = &old->rows[r];
            if (o->n == 1 && !o->cells[0][0])
                continue; /* a blank line */
            const char *file = o->cells[COL_FILE], *student = o->cells[COL_STUDENT];
            int with = -1;
            for (int i = 0; with < 0 && i < rows; i++) {
                if (nr[i].used)
                    continue;
                const char *nfile = cell(&nr[i].cells, COL_FILE);
                if (file[0] ? same_path(nfile, file)
                            : strcmp(cell(&nr[i].cells, COL_STUDENT), student) == 0 &&
                                  (nfile[0] || strcmp(cell(&nr[i].cells, COL_VERDICT), "missing") == 0))
                    with = i;
            }
            if (with >= 0) {
                fputs(nr[with].line, f);
                nr[with].used = 1;
                updated++;
            } else {
                write_old(f, o);
                kept++;
            }
        }
        for (int i = 0; i < rows; i++) {
            if (nr[i].used)
                continue;
            /* A student this run saw nothing of (the teacher regraded
             * others) keeps the rows the gradebook has of them. */
            int known = 0;
            if (strcmp(cell(&nr[i].cells, COL_VERDICT), "missing") == 0)
                for (int r = 1; !known && r < old->nrows; r++)
                    known = strcmp(old->rows[r].cells[COL_STUDENT],
                                   cell(&nr[i].cells, COL_STUDENT)) == 0;
            if (!known) {
                fputs(nr[i].line, f);
                added++;
            }
        }
        snprintf(said, saidlen, "updated %d row%s, kept %d", updated, updated == 1 ? "" : "s",
                 kept);
        if (added)
            snprintf(said + strlen(said), saidlen - strlen(said), ", added %d", added);
    }
    for (int i = 0; nr && i < rows; i++) {
        free(nr[i].line);
        sw_csv_doc_free(&nr[i].cells);
    }
    free(nr);
}

int grade_book_has_student(const grade_list *l, const char *name)
{
    if (!l->old_book)
        return 0;
    /* The name as the gradebook holds it: through sw_csv_field and back. */
    char *line = NULL, err[SW_ERRLEN];
    size_t len = 0;
    FILE *f = open_memstream(&line, &len);
    if (!f)
        return 0;
    char cut[SW_TRACE_STUDENT_MAX], held_as[4 * SW_TRACE_STUDENT_MAX + 8];
    snprintf(cut, sizeof cut, "%s", name); /* as grade_student_of gives it */
    key_cell(cut, held_as, sizeof held_as);
    sw_csv_field(f, held_as);
    fputs("\r\n", f);
    int known = 0;
    sw_csv_doc d;
    if (fclose(f) == 0 && sw_csv_parse("name", line, len, &d, err, sizeof err) == SW_OK) {
        const char *held = cell(&d, 0);
        for (int r = 1; !known && r < l->old_book->nrows; r++)
            known = strcmp(l->old_book->rows[r].cells[COL_STUDENT], held) == 0;
        sw_csv_doc_free(&d);
    }
    free(line);
    return known;
}
