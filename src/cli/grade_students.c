/* `grade --gradebook FILE` and `--lms FILE`: one row per student. With a
 * roster, every roster student in its order (a `missing` row for those
 * with nothing), then any file that matched nobody, each its own row; with
 * none, each student a file names. Each row's score is the counted
 * submissions' (grade_count.c) out of the homework's points, the same max
 * on every row. A regrade keeps the rows of students this run saw nothing
 * of. Invariant: every cell goes through sw_csv_field; each file is
 * written whole or not at all. */
#include "cli/grade.h"

#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "util/csv.h"
#include "util/escape.h"
#include "util/outfile.h"

static const char *const book_columns[] = { "student", "id", "email", "score", "max", "verdict",
                                            "counted", "also", "message", "remarks" };
enum { BOOK_NCOLS = sizeof book_columns / sizeof book_columns[0] };

/* One student's row: which entries are theirs. */
typedef struct student_row {
    char name[SW_TRACE_STUDENT_MAX];
    int who;                 /* roster index, or -1 */
    int *entries;            /* indices into l->items */
    int n;
    int missing;             /* a roster student with no file */
    const grade_entry *any;  /* an entry of theirs, for id and remarks */
} student_row;

static int add_entry(student_row *r, int i)
{
    int *e = realloc(r->entries, (size_t)(r->n + 1) * sizeof *e);
    if (!e)
        return -1;
    r->entries = e;
    r->entries[r->n++] = i;
    return 0;
}

/* The rows, in roster order then in the order files came. */
static student_row *group(const grade_list *l, int *nrows)
{
    int cap = (l->roster ? l->roster->n : 0) + l->n + l->ignored + 1;
    student_row *rows = calloc((size_t)cap, sizeof *rows);
    int n = 0;
    if (!rows)
        return NULL;
    if (l->roster)
        for (int s = 0; s < l->roster->n; s++) {
            rows[n].who = s;
            snprintf(rows[n].name, sizeof rows[n].name, "%s", l->roster->students[s].name);
            rows[n].missing = -1; /* not yet known */
            n++;
        }
    for (int i = 0; i < l->n + l->ignored; i++) {
        const grade_entry *e = i < l->n ? &l->items[i] : &l->refused[i - l->n];
        if (i >= l->n && e->status != GRADE_MISSING)
            continue;
        int r = -1;
        if (l->roster && e->who >= 0)
            r = e->who;
        else {
            char name[SW_TRACE_STUDENT_MAX];
            grade_student_of(e, name, sizeof name);
            for (int k = l->roster ? l->roster->n : 0; r < 0 && k < n && !l->roster; k++)
                if (strcmp(rows[k].name, name) == 0)
                    r = k;
            if (r < 0) {
                r = n++;
                rows[r].who = -1;
                snprintf(rows[r].name, sizeof rows[r].name, "%s", name);
            }
        }
        if (!rows[r].any)
            rows[r].any = e;
        if (e->status == GRADE_MISSING)
            rows[r].missing = 1;
        else if (add_entry(&rows[r], i) != 0) {
            for (int k = 0; k < n; k++)
                free(rows[k].entries);
            free(rows);
            return NULL;
        }
    }
    *nrows = n;
    return rows;
}

/* The files of entries, "; "-joined, escaped; counted ones (in c) or the
 * others. */
static void file_list(const grade_list *l, const student_row *r, const grade_counted *c, int counted,
                      char *out, size_t outlen)
{
    size_t used = 0;
    out[0] = '\0';
    for (int k = 0; k < r->n && used + 1 < outlen; k++) {
        int i = r->entries[k], is = 0;
        for (int p = 0; p < l->hw->nparts; p++)
            is |= c->entry[p] == i;
        int again = 0; /* a plugin counted for every part: named once */
        for (int j = 0; j < k; j++)
            again |= r->entries[j] == i;
        if (is != counted || again)
            continue;
        char shown[600];
        sw_escape(l->items[i].path, 300, shown, sizeof shown);
        used += (size_t)snprintf(out + used, outlen - used, "%s%s", used ? "; " : "", shown);
    }
}

/* Why the row has what it has: the first counted entry that did not pass,
 * or the parts with nothing counted. */
static void row_message(const grade_list *l, const student_row *r, const grade_counted *c, char *out,
                        size_t outlen)
{
    const sw_homework *h = l->hw;
    out[0] = '\0';
    if (r->n == 0) {
        /* a missing row: files may have come that were all left out (grade_roster.c) */
        int left_out = r->any && r->any->status == GRADE_MISSING && strcmp(r->any->kind, "left-out") == 0;
        snprintf(out, outlen, "%s", left_out ? "no gradable submission (the files sent were not graded)" : "no submission");
        return;
    }
    if (c->status == GRADE_MISSING) {
        snprintf(out, outlen, "nothing of the kind this homework asks for: %s",
                 sw_assignment_wanted(&h->parts[0].a));
        return;
    }
    size_t used = 0;
    for (int p = 0; p < h->nparts && used + 1 < outlen; p++) {
        if (c->entry[p] < 0)
            used += (size_t)snprintf(out + used, outlen - used, "%sno trace for part %s", used ? "; " : "",
                                     h->parts[p].name);
        else if (l->items[c->entry[p]].status != SW_VERDICT_PASS && (p == 0 || c->entry[p] != c->entry[p - 1]))
            used += (size_t)snprintf(out + used, outlen - used, "%s%s", used ? "; " : "",
                                     l->items[c->entry[p]].message);
    }
}

static void put_row(FILE *f, const char *const *cells, int n)
{
    for (int c = 0; c < n; c++) {
        sw_csv_field(f, cells[c]);
        fputs(c + 1 < n ? "," : "\r\n", f);
    }
}

/* The file already at path, read back when it has our columns (ncols,
 * the first named first): a regrade keeps its rows of the students it saw
 * nothing of. 1 when d holds it. */
static int read_old(const char *path, int ncols, const char *first, sw_csv_doc *d)
{
    char err[SW_ERRLEN + 512];
    if (sw_csv_read(path, d, err, sizeof err) != SW_OK)
        return 0;
    if (d->nrows > 0 && d->rows[0].n == ncols && strcmp(d->rows[0].cells[0], first) == 0)
        return 1;
    sw_csv_doc_free(d);
    return 0;
}

/* The old row of the student named name, once; NULL when none. */
static const sw_csv_row *old_row(sw_csv_doc *d, int have, int ncols, unsigned char *used, const char *name)
{
    for (int r = 1; have && r < d->nrows; r++)
        if (!used[r] && d->rows[r].n == ncols && strcmp(d->rows[r].cells[0], name) == 0) {
            used[r] = 1;
            return &d->rows[r];
        }
    return NULL;
}

static int write_one(const grade_list *l, const char *path, int lms, student_row *rows, int n)
{
    sw_outfile o;
    char err[SW_ERRLEN + 256];
    if (sw_outfile_open(&o, path, err, sizeof err) != SW_OK)
        return sw_cli_error("grade: %s", err);
    FILE *f = o.f;
    static const char *const lms_columns[] = { "name", "id", "email", "score", "max" };
    put_row(f, lms ? lms_columns : book_columns, lms ? 5 : BOOK_NCOLS);
    int ncols = lms ? 5 : BOOK_NCOLS;
    sw_csv_doc old;
    int read = !o.direct && !l->fresh && read_old(path, ncols, lms ? "name" : "student", &old);
    unsigned char *used = read ? calloc((size_t)old.nrows + 1, 1) : NULL;
    int have = read && used; /* out of memory: this run's rows alone */
    for (int k = 0; k < n; k++) {
        student_row *r = &rows[k];
        if (r->n == 0 && r->missing != 1) {
            /* a roster student this regrade saw nothing of: their row as it was, in its place */
            const sw_csv_row *was = old_row(&old, have, ncols, used, r->name);
            if (was)
                put_row(f, (const char *const *)was->cells, ncols);
            continue;
        }
        if (have)
            while (old_row(&old, have, ncols, used, r->name))
                ; /* replaced by the row below */
        grade_counted c;
        grade_count(l, r->entries, r->n, &c);
        char score[32], max[32], counted[2400], also[2400], message[1600];
        snprintf(score, sizeof score, "%g", c.score);
        snprintf(max, sizeof max, "%g", c.max);
        const char *id = "", *email = "";
        if (l->roster && r->who >= 0) {
            const sw_student *s = &l->roster->students[r->who];
            id = s->nids ? s->ids[0] : "";
            email = s->email;
        }
        if (lms) {
            if (l->roster && r->who < 0)
                continue; /* a file that matched nobody: the gradebook has it, an LMS could not place it */
            const char *cells[] = { r->name, id, email, score, max };
            put_row(f, cells, 5);
            continue;
        }
        file_list(l, r, &c, 1, counted, sizeof counted);
        file_list(l, r, &c, 0, also, sizeof also);
        row_message(l, r, &c, message, sizeof message);
        char remarks[sizeof r->any->remarks + 240];
        snprintf(remarks, sizeof remarks, "%s", r->any ? r->any->remarks : "");
        if (c.close_times)
            snprintf(remarks + strlen(remarks), sizeof remarks - strlen(remarks),
                     "%scount: latest: files that scored otherwise were modified within %d s of the "
                     "counted one, so which is latest is a guess (files copied without their times?): "
                     "read the 'also' column", remarks[0] ? "; " : "", GRADE_CLOSE_SECONDS);
        const char *cells[] = { r->name, id, email, score, max,
                                grade_verdict_word(r->n == 0 ? GRADE_MISSING
                                                   : c.status == GRADE_MISSING ? SW_VERDICT_FAIL : c.status),
                                counted, also, message, remarks };
        put_row(f, cells, BOOK_NCOLS);
    }
    /* Rows of students neither on the roster nor in this run: kept, last. */
    for (int r = 1; have && r < old.nrows; r++)
        if (!used[r] && old.rows[r].n == ncols)
            put_row(f, (const char *const *)old.rows[r].cells, ncols);
    if (read)
        sw_csv_doc_free(&old);
    free(used);
    if (sw_outfile_commit(&o, err, sizeof err) != SW_OK)
        return sw_cli_error("grade: %s", err);
    return SW_EXIT_OK;
}

/* A regrade of some of a student's files: their row counts only these,
 * so say so when the --csv read back holds more files of theirs. */
static void warn_partial(const grade_list *l, const student_row *rows, int n)
{
    const sw_csv_doc *old = l->old_book;
    for (int k = 0; old && k < n; k++) {
        if (rows[k].n == 0)
            continue;
        int held = 0;
        for (int r = 1; r < old->nrows; r++) /* their files graded then (a header's row was not) */
            held += old->rows[r].n > 2 && strcmp(old->rows[r].cells[0], rows[k].name) == 0 &&
                    old->rows[r].cells[1][0] && strcmp(old->rows[r].cells[2], grade_verdict_word(GRADE_SKIPPED)) != 0;
        if (held > rows[k].n) {
            char shown[160];
            sw_escape(rows[k].name, 80, shown, sizeof shown);
            sw_cli_note("gradebook: %s's row counts the %d file%s graded now; the --csv holds %d of "
                        "theirs: give their whole folder to count every one", shown, rows[k].n,
                        rows[k].n == 1 ? "" : "s", held);
        }
    }
}

int grade_students_write(const grade_list *l, const char *gradebook, const char *lms)
{
    int n = 0, rc = SW_EXIT_OK;
    student_row *rows = group(l, &n);
    if (!rows)
        return sw_cli_error("grade: out of memory for the gradebook");
    warn_partial(l, rows, n);
    if (gradebook)
        rc = write_one(l, gradebook, 0, rows, n);
    if (rc == SW_EXIT_OK && lms)
        rc = write_one(l, lms, 1, rows, n);
    for (int k = 0; k < n; k++)
        free(rows[k].entries);
    free(rows);
    return rc;
}
