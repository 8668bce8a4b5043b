/* The grade reports: the table on stdout, the CSV gradebook and Gradescope's
 * results.json, and the checks on where they go. Invariants: every output
 * path is checked before grading starts and written whole or not at all at
 * the end (util/outfile.h), never over the assignment or a submission nor
 * among them; text that came from students reaches the terminal escaped
 * (util/escape.h), the CSV escaped and neutralised against formulas
 * (util/csv.h), results.json as valid JSON (cli/json.h). */
#include "cli/grade.h"

#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli/cli.h"
#include "cli/json.h"
#include "plugin/plugin.h"
#include "util/csv.h"
#include "util/escape.h"
#include "util/outfile.h"
#include "util/tmpdir.h"
#include "util/utf8.h"

/* Where the table goes: stdout, or stderr when a report is written there. */
static FILE *table_stream;

static FILE *table(void) { return table_stream ? table_stream : stdout; }


void grade_list_free(grade_list *l)
{
    for (int i = 0; i < l->n; i++) {
        free(l->items[i].path);
        free(l->items[i].rel);
        free(l->items[i].report);
        free(l->items[i].wrong);
    }
    for (int i = 0; i < l->ignored; i++) {
        free(l->refused[i].path);
        free(l->refused[i].rel);
        free(l->refused[i].report);
    }
    if (l->roster) {
        sw_roster_free(l->roster);
        free(l->roster);
    }
    if (l->old_book) {
        sw_csv_doc_free(l->old_book);
        free(l->old_book);
    }
    free(l->gs_metadata);
    free(l->similar_table);
    for (int i = 0; i < l->nplaces; i++)
        free(l->places[i].real);
    free(l->items);
    free(l->refused);
    free(l->places);
    memset(l, 0, sizeof *l);
}


/* The names this file used before grade.h shared them. */
#define verdict_word grade_verdict_word
#define student_of grade_student_of


/* "3/5": the points of the entry's checks ("-" when it has none). */
static void grade_score_text(const grade_entry *e, char *buf, size_t len)
{
    if (e->score.n == 0)
        snprintf(buf, len, "-");
    else
        snprintf(buf, len, "%g/%g", e->score.score, e->score.max);
}

void grade_print_head(const sw_homework *h, const grade_list *l)
{
    const sw_assignment *a = &h->parts[0].a;
    int n = l->n, ignored = 0, missing = 0;
    for (int i = 0; i < l->ignored; i++)
        *(l->refused[i].status == GRADE_MISSING ? &missing : &ignored) += 1;
    char dt[40], path[300];
    sw_fmt_shortest(dt, sizeof dt, a->meta.dt);
    sw_escape(a->path, 200, path, sizeof path);
    if (h->nparts > 1)
        fprintf(table(), "grading %d submission%s against %s (%d parts: %s on %s%s)", n, n == 1 ? "" : "s",
                path, h->nparts, a->methods[0]->name, a->meta.scene->name, h->nparts > 1 ? ", ..." : "");
    else
        fprintf(table(), "grading %d submission%s against %s (%s%s on %s, dt %s)", n, n == 1 ? "" : "s",
                path, a->nmethods > 1 ? "any of " : "", a->methods[0]->name, a->meta.scene->name, dt);
    if (ignored)
        fprintf(table(), "; %d other entr%s not graded", ignored, ignored == 1 ? "y" : "ies");
    if (missing)
        fprintf(table(), "%s %d student%s on the roster without a submission", ignored ? "," : ";", missing,
                missing == 1 ? "" : "s");
    if (ignored || missing)
        fprintf(table(), " (listed at the end)");
    fprintf(table(), "\n  %-20s %-24s %-7s %7s %6s  %s\n", "student", "file", "verdict", "score",
            "step", "what");
    fflush(table());
}

/* Text in a table cell of cells terminal cells: escaped, cut by display
 * width ("..." within it) and padded with spaces, so that the columns line
 * up on the terminal whatever the bytes (é is two bytes and one cell). */
static const char *cell(const char *text, size_t cells, char *out, size_t outlen)
{
    sw_escape_fit(text, 0, cells, 0, out, outlen);
    size_t len = strlen(out), shown = sw_utf8_columns(out, len);
    for (; shown < cells && len + 1 < outlen; shown++)
        out[len++] = ' ';
    out[len] = '\0';
    return out;
}

void grade_print_row(grade_entry *e)
{
    char student[SW_TRACE_STUDENT_MAX], s_cell[128], f_cell[128], m_esc[400], step[24];
    student_of(e, student, sizeof student);
    const char *base = strrchr(e->path, '/');
    cell(student, 20, s_cell, sizeof s_cell);
    cell(base ? base + 1 : e->path, 24, f_cell, sizeof f_cell);
    /* The last column runs to the end of the line: long, it is cut after a
     * word. The message is escaped already (a student's bytes in it, as in
     * the gradebook and the feedback): its backslashes are kept. */
    sw_escape_fit(e->message, 1, 300, 1, m_esc, sizeof m_esc);
    if (e->failing_step >= 0)
        snprintf(step, sizeof step, "%ld", e->failing_step);
    else
        snprintf(step, sizeof step, "-");
    char score[48];
    grade_score_text(e, score, sizeof score);
    fprintf(table(), "  %s %s %-7s %7s %6s  %s\n", s_cell, f_cell, verdict_word(e->status), score,
            step, m_esc);
    if (e->remarks[0]) {
        sw_escape_fit(e->remarks, 1, 300, 1, m_esc, sizeof m_esc); /* escaped already */
        fprintf(table(), "  %-20s %-24s roster: %s\n", "", "", m_esc);
    }
    fflush(table());
}

/* ---- where the reports go ------------------------------------------------- */

static int same_file(const struct stat *a, dev_t dev, ino_t ino)
{
    return a->st_dev == dev && a->st_ino == ino;
}

/* The resolved directory path would be written in (its last component
 * left as it is), into real; 0 or -1 with errno. */
static int real_dir_of(const char *path, char *real)
{
    char dir[PATH_MAX];
    const char *slash = strrchr(path, '/');
    if (!slash)
        snprintf(dir, sizeof dir, ".");
    else
        snprintf(dir, sizeof dir, "%.*s", slash == path ? 1 : (int)(slash - path), path);
    return realpath(dir, real) ? 0 : -1;
}

/* What a file each output writes begins with: an existing file is written
 * over only when it is empty or begins so (one of ours from an earlier
 * run), never a roster, a source file or anything else a teacher keeps. */
static const char *ours_begins(const char *flag)
{
    static const struct {
        const char *flag, *begins;
    } kinds[] = { { "--csv", "student,file,verdict" }, { "--gradebook", "student,id,email," },
                  { "--lms", "name,id,email,score,max" }, { "--results", "{" }, { "--gradescope", "{" } };
    for (size_t i = 0; i < sizeof kinds / sizeof kinds[0]; i++)
        if (strcmp(flag, kinds[i].flag) == 0)
            return kinds[i].begins;
    return NULL;
}

/* Whether the regular file at path is empty or begins with begins. */
static int begins_with(const char *path, const char *begins)
{
    char head[64] = "";
    FILE *f = fopen(path, "rb");
    size_t n = f ? fread(head, 1, sizeof head - 1, f) : 0;
    if (f)
        fclose(f);
    head[n] = '\0';
    return f && (n == 0 || strncmp(head, begins, strlen(begins)) == 0);
}

/* One output path: usable, and nothing the grading reads. */
static int check_output(const grade_list *l, const struct stat *assign_st, const char *flag,
                        const char *path, sw_outfile_target *t)
{
    char err[SW_ERRLEN + 256];
    if (sw_outfile_resolve(path, t, err, sizeof err) != SW_OK)
        return sw_cli_error("grade: %s: %s", flag, err);
    if (t->is_stdout)
        return SW_EXIT_OK;
    /* The name as given (a link, perhaps) and the file it leads to. */
    struct stat named;
    int have_named = lstat(path, &named) == 0;
    if (t->exists && same_file(&t->st, assign_st->st_dev, assign_st->st_ino))
        return sw_cli_error("grade: %s '%.200s' is the assignment; give the gradebook another name",
                            flag, path);
    for (int i = 0; i < l->nplaces; i++) {
        const grade_place *p = &l->places[i];
        if (!p->real && ((t->exists && same_file(&t->st, p->dev, p->ino)) ||
                         (have_named && same_file(&named, p->dev, p->ino))))
            return sw_cli_error("grade: %s '%.200s' is one of the submissions; give the gradebook "
                                "another name", flag, path);
    }
    const char *names[] = { path, t->path };
    for (int i = 0; i < 2; i++) {
        char real[PATH_MAX];
        if (real_dir_of(names[i], real) != 0)
            return sw_cli_error("grade: %s '%.200s': cannot resolve its directory: %s", flag, path,
                                strerror(errno));
        const char *among = grade_inside_submissions(l, real);
        if (among)
            return sw_cli_error("grade: %s '%.200s' is inside the submissions directory '%.200s'; "
                                "write the gradebook elsewhere", flag, path, among);
    }
    const char *begins = ours_begins(flag);
    if (t->exists && S_ISREG(t->st.st_mode) && begins && !begins_with(t->path, begins))
        return sw_cli_error("grade: %s '%.200s' exists and is not what %s writes (it does not begin "
                            "'%s'): a roster, a source or a file of yours is never written over; "
                            "give another name", flag, path, flag, begins);
    if (!t->direct) {
        /* The real test of a directory (access() says yes to root on a
         * read-only mount): make the temporary the writing will use, and
         * take it away again. A device or FIFO is opened only at the end. */
        sw_outfile probe;
        if (sw_outfile_open(&probe, path, err, sizeof err) != SW_OK)
            return sw_cli_error("grade: %s: %s", flag, err);
        sw_outfile_abort(&probe);
    }
    return SW_EXIT_OK;
}

/* The file path will be written as: its directory resolved, then its name
 * ("m/x.csv" and "./m/x.csv" are one file before either exists). 1, or 0
 * when the directory cannot be resolved. */
static int where_written(const char *path, char *out)
{
    char real[PATH_MAX];
    if (real_dir_of(path, real) != 0)
        return 0;
    const char *slash = strrchr(path, '/');
    snprintf(out, 2 * PATH_MAX, "%s/%s", real, slash ? slash + 1 : path);
    return 1;
}

int grade_check_outputs(const grade_list *l, const struct stat *assign_st, const char *const *opts,
                        const char *const *paths, int n)
{
    sw_outfile_target t[8];
    for (int i = 0; i < n && i < 8; i++)
        if (paths[i] && check_output(l, assign_st, opts[i], paths[i], &t[i]) != SW_EXIT_OK)
            return SW_EXIT_USAGE;
    /* Two reports in one file would be neither; a device such as /dev/null
     * takes both. */
    for (int i = 0; i < n && i < 8; i++)
        for (int j = i + 1; paths[i] && j < n && j < 8; j++) {
            const sw_outfile_target *c = &t[i], *r = &t[j];
            if (!paths[j] || (c->exists && S_ISCHR(c->st.st_mode)))
                continue;
            char cw[2 * PATH_MAX], rw[2 * PATH_MAX];
            int same = (c->is_stdout && r->is_stdout) ||
                       (!c->is_stdout && !r->is_stdout && (strcmp(c->path, r->path) == 0 ||
                        (where_written(c->path, cw) && where_written(r->path, rw) && strcmp(cw, rw) == 0) ||
                        (c->exists && r->exists && same_file(&c->st, r->st.st_dev, r->st.st_ino))));
            if (same)
                return sw_cli_error("grade: %s and %s both write to '%.200s'; give each its own file",
                                    opts[i], opts[j], c->is_stdout ? "standard output" : paths[i]);
        }
    /* A report on stdout keeps stdout for itself: the table goes to stderr. */
    for (int i = 0; i < n && i < 8; i++)
        if (paths[i] && t[i].is_stdout)
            table_stream = stderr;
    return SW_EXIT_OK;
}

/* ---- files, whole or not at all -------------------------------------------- */

typedef void grade_writer(FILE *f, const grade_list *l, const char *summary);

/* Lines in the file at path (-1: it cannot be read). */
static long count_lines(const char *path)
{
    FILE *f = path ? fopen(path, "rb") : NULL;
    if (!f)
        return -1;
    long n = 0;
    char buf[65536];
    for (size_t got; (got = fread(buf, 1, sizeof buf, f)) > 0;)
        for (size_t i = 0; i < got; i++)
            n += buf[i] == '\n';
    fclose(f);
    return n;
}

/* Through util/outfile.h: whole or not at all, devices and "-" in place;
 * max > 0: a file of more bytes is not written (what reads it back would
 * refuse it). */
static int write_whole(const char *path, grade_writer *write, const grade_list *l,
                       const char *summary, size_t max)
{
    sw_outfile o;
    char err[SW_ERRLEN + 256];
    if (sw_outfile_open(&o, path, err, sizeof err) != SW_OK)
        return sw_cli_error("grade: %s", err);
    write(o.f, l, summary);
    off_t size = fflush(o.f) == 0 ? ftello(o.f) : -1;
    long lines = max > 0 && !o.direct && o.tmp[0] ? count_lines(o.tmp) : 0;
    if (max > 0 && (size > (off_t)max || lines > SW_CSV_ROWS_MAX)) {
        sw_outfile_abort(&o);
        return sw_cli_error("grade: the gradebook would be %.1f MiB in %ld rows, more than the %zu MiB or %d rows "
                            "stepwise reads back: not written (a gradebook there is kept); grade the class in "
                            "parts, each with its own --csv", (double)size / 1048576, lines, max >> 20,
                            SW_CSV_ROWS_MAX);
    }
    if (sw_outfile_commit(&o, err, sizeof err) != SW_OK)
        return sw_cli_error("grade: %s", err);
    return SW_EXIT_OK;
}

/* Every row of the gradebook: the graded submissions, then the entries not
 * graded. */
static const grade_entry *row_at(const grade_list *l, int i)
{
    return i < l->n ? &l->items[i] : &l->refused[i - l->n];
}

/* What writing the gradebook said ("updated 1 row, kept 27"), for the end. */
static char book_said[200];

static void write_csv(FILE *f, const grade_list *l, const char *summary)
{
    (void)summary;
    grade_book_write(f, l, book_said, sizeof book_said);
}


/* Gradescope's format: a score, its maximum, and one test per entry. */
static void write_results(FILE *f, const grade_list *l, const char *summary)
{
    int rows = l->n + l->ignored, counted = 0;
    double score = 0, max = 0;
    for (int i = 0; i < rows; i++) {
        double s1, m1;
        if (row_at(l, i)->status == GRADE_SKIPPED)
            continue; /* not a submission */
        grade_points_of(l, row_at(l, i), &s1, &m1);
        score += s1;
        max = m1 > max ? m1 : max;
        counted++;
    }
    /* The class's figure: the mean of its rows (submissions, and students
     * without one), out of the homework's points; each test below is one
     * file's. */
    fputs("{\n  \"score\": ", f);
    sw_json_num(f, counted > 0 ? score / counted : 0);
    fputs(",\n  \"max_score\": ", f);
    /* (a homework of either kind: the larger of its rows' maxima) */
    sw_json_num(f, l->hw && (l->hw->kind != SW_KIND_ANY || counted == 0) ? l->hw->max : max);
    fputs(",\n  \"output\": ", f);
    sw_json_str(f, summary);
    fputs(",\n  \"tests\": [", f);
    for (int i = 0; i < rows; i++) {
        const grade_entry *e = row_at(l, i);
        char student[SW_TRACE_STUDENT_MAX], name[SW_TRACE_STUDENT_MAX + PATH_MAX];
        student_of(e, student, sizeof student);
        snprintf(name, sizeof name, "%s (%s)", student, e->path);
        char *shown_name = grade_text_shown(name);
        fprintf(f, "%s\n    {\n      \"name\": ", i ? "," : "");
        sw_json_str(f, shown_name ? shown_name : "?");
        free(shown_name);
        double points, most;
        grade_points_of(l, e, &points, &most);
        fputs(",\n      \"score\": ", f);
        sw_json_num(f, points);
        fputs(",\n      \"max_score\": ", f);
        sw_json_num(f, most);
        fprintf(f, ",\n      \"status\": \"%s\",\n      \"output\": ",
                e->status == 0 ? "passed" : "failed");
        char *text = e->report;
        char fallback[1400];
        if (!text) {
            snprintf(fallback, sizeof fallback, "%s: %s", verdict_word(e->status), e->message);
            text = fallback;
        }
        char *shown = grade_text_shown(text), *notes = grade_text_shown(e->notes);
        sw_json_str(f, shown ? shown : "(out of memory)");
        free(shown);
        if (e->notes[0]) {
            fputs(",\n      \"extra_data\": { \"notes\": ", f);
            sw_json_str(f, notes ? notes : "");
            fputs(" }", f);
        }
        free(notes);
        fputs("\n    }", f);
    }
    fputs(rows ? "\n  ]\n}\n" : "]\n}\n", f);
}

int grade_finish(const grade_list *l, const sw_limits *lim, double wall, double seconds,
                 const char *csv, const char *results)
{
    for (int i = 0; i < l->ignored; i++)
        grade_print_row(&l->refused[i]);
    int passed = 0, errors = 0, limits = 0;
    for (int i = 0; i < l->n; i++) {
        passed += l->items[i].status == 0;
        errors += l->items[i].status == 2;
        limits += l->items[i].status == GRADE_LIMIT;
    }
    char summary[600], others[200] = "";
    int missing = 0;
    for (int i = 0; i < l->ignored; i++)
        missing += l->refused[i].status == GRADE_MISSING;
    if (l->ignored > missing)
        snprintf(others, sizeof others, ", %d other entr%s not graded", l->ignored - missing,
                 l->ignored - missing == 1 ? "y" : "ies");
    if (missing)
        snprintf(others + strlen(others), sizeof others - strlen(others), ", %d student%s on the "
                 "roster without a submission", missing, missing == 1 ? "" : "s");
    if (others[0])
        snprintf(others + strlen(others), sizeof others - strlen(others), ",");
    snprintf(summary, sizeof summary, "%d submission%s: %d passed, %d failed (%d of them "
             "unusable, %d out of a limit)%s in %.1f s; the limits per submission: %g s CPU for its "
             "own processes (--cpu), %zu MiB, %zu KiB output, %g s wall, %g s per plugin step", l->n,
             l->n == 1 ? "" : "s", passed, l->n - passed, errors, limits, others, seconds, lim->cpu_seconds, lim->memory_bytes >> 20,
             lim->output_bytes >> 10, wall, sw_plugin_timeout());
    if (l->similar_table)
        fputs(l->similar_table, table());
    fprintf(table(), "%s\n", summary);
    fflush(table());
    int rc = SW_EXIT_OK;
    if (csv)
        rc = write_whole(csv, write_csv, l, summary, SW_CSV_FILE_MAX);
    if (csv && rc == SW_EXIT_OK && book_said[0])
        fprintf(table(), "gradebook: %s\n", book_said);
    if (rc == SW_EXIT_OK && l->feedback)
        rc = grade_feedback_write(l, l->feedback);
    if (rc == SW_EXIT_OK && results)
        rc = write_whole(results, write_results, l, summary, 0);
    if (sw_cli_flush_stdout() != SW_EXIT_OK)
        return SW_EXIT_USAGE;
    if (rc != SW_EXIT_OK)
        return rc;
    /* 0 only when every row is a pass: an entry not graded is no pass. */
    return passed == l->n && l->ignored == 0 ? SW_EXIT_OK : SW_EXIT_FAIL;
}

void grade_clean_dir(const char *dir, int n)
{
    (void)n; /* everything in it goes, whatever the compilers left */
    sw_tmpdir_remove(dir);
}
