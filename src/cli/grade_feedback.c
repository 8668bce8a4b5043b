/* `grade --feedback DIR`: one plain-text report per student, ready to hand
 * back. Invariants: DIR is checked before grading like every output (a
 * writable directory, not among the submissions); a file name comes from
 * the student's name, its accents folded as the roster folds them, reduced
 * to [A-Za-z0-9._-] (never a path, never hidden, never a link followed),
 * made unique whatever the case (a Mac's disk ignores it); each file is
 * written whole or not at all (util/outfile.h). */
#include "cli/grade.h"

#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli/cli.h"
#include "grade/roster.h"
#include "util/escape.h"
#include "util/outfile.h"

int grade_feedback_check(const grade_list *l, const char *dir)
{
    struct stat st;
    char real[PATH_MAX];
    if (!dir[0])
        return sw_cli_error("grade: --feedback needs a directory");
    if (lstat(dir, &st) != 0) {
        if (errno != ENOENT || mkdir(dir, 0755) != 0)
            return sw_cli_error("grade: --feedback '%.200s': cannot create it: %s", dir,
                                strerror(errno));
    } else if (!S_ISDIR(st.st_mode))
        return sw_cli_error("grade: --feedback '%.200s' is not a directory", dir);
    if (!realpath(dir, real) || access(real, W_OK | X_OK) != 0)
        return sw_cli_error("grade: --feedback '%.200s': not a directory that can be written: %s",
                            dir, strerror(errno));
    const char *among = grade_inside_submissions(l, real);
    if (among)
        return sw_cli_error("grade: --feedback '%.200s' is inside the submissions directory "
                            "'%.200s'; write the feedback elsewhere", dir, among);
    return SW_EXIT_OK;
}

/* The student's name as a file name: letters, digits, '.', '-', '_', its
 * Latin letters folded as the roster folds them (Poincaré: Poincare). */
void grade_safe_name(const char *name, char *out, size_t len)
{
    char folded[4 * SW_TRACE_STUDENT_MAX];
    sw_roster_fold_latin(name, strlen(name), folded, sizeof folded);
    size_t n = 0;
    for (const unsigned char *s = (const unsigned char *)folded; *s && n + 1 < len && n < 80; s++) {
        char c = (char)*s;
        int keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                   c == '-' || (c == '.' && n > 0);
        if (keep)
            out[n++] = c;
        else if (n > 0 && out[n - 1] != '_')
            out[n++] = '_';
    }
    while (n > 0 && (out[n - 1] == '_' || out[n - 1] == '.'))
        n--;
    out[n] = '\0';
    if (n == 0)
        snprintf(out, len, "student");
}

void grade_name_unique(char (*names)[112], int n, const char *base)
{
    snprintf(names[n], sizeof names[n], "%s", base);
    for (int k = 2, clash = 1; clash; k++) { /* names that fold alike: -2, -3, ... */
        clash = 0;
        for (int j = 0; j < n && !clash; j++)
            clash = strcasecmp(names[j], names[n]) == 0;
        if (clash)
            snprintf(names[n], sizeof names[n], "%s-%d", base, k);
    }
}

static const grade_entry *row(const grade_list *l, int i)
{
    return i < l->n ? &l->items[i] : &l->refused[i - l->n];
}

/* Whether rows i and j belong to one student. */
static int same_student(const grade_list *l, int i, int j)
{
    const grade_entry *a = row(l, i), *b = row(l, j);
    if (l->roster)
        return a->who >= 0 ? a->who == b->who : i == j;
    char sa[SW_TRACE_STUDENT_MAX], sb[SW_TRACE_STUDENT_MAX];
    grade_student_of(a, sa, sizeof sa);
    grade_student_of(b, sb, sizeof sb);
    return strcmp(sa, sb) == 0;
}

/* A graded file's points, check by check, on the parts shown now: what a
 * PASS report alone does not tell (a stability limit not measured, an
 * order missed). A part not shown yet gives nothing away, its points
 * included. */
/* The checks of the parts shown now (a hidden part's are the teacher's). */
static void write_points(FILE *f, const grade_list *l, const grade_entry *e)
{
    if (!e->plugin && e->part < 0 && l->hw && l->hw->nparts > 1) {
        /* a trace not read far enough to tell its part: its zeros on every
         * part would read as points lost where another file scored */
        fprintf(f, "points: none from this file: it could not be matched to a part (each part counts "
                "your best file for it)\n");
        return;
    }
    static sw_score shown; /* 22 kB: not on a stack */
    memset(&shown, 0, sizeof shown);
    for (int k = 0; k < e->score.n; k++) {
        const sw_score_check *c = &e->score.checks[k];
        if (l->hw && l->hw->parts[c->part].visibility != SW_VIS_VISIBLE)
            continue;
        shown.checks[shown.n++] = *c;
        shown.score += c->score;
        shown.max += c->max;
    }
    sw_score_print(f, &shown, "", shown.n < e->score.n ? " on the parts shown now" : "");
}

static void write_report(FILE *f, const grade_list *l, int first, const unsigned char *done)
{
    char student[SW_TRACE_STUDENT_MAX], heading[4 * SW_TRACE_STUDENT_MAX];
    grade_student_of(row(l, first), student, sizeof student);
    sw_escape(student, sizeof student, heading, sizeof heading);
    fprintf(f, "Feedback for %s\n\n", heading);
    for (int i = first; i < l->n + l->ignored; i++) {
        if (done[i] || !same_student(l, first, i))
            continue;
        const grade_entry *e = row(l, i);
        if (e->status == GRADE_MISSING) {
            fprintf(f, "No submission of yours was found.\n\n");
            continue;
        }
        const char *base = strrchr(e->path, '/');
        char shown[300];
        sw_escape(base ? base + 1 : e->path, 200, shown, sizeof shown);
        /* A graded file's verdict, step and message cover every part it was
         * graded on: with parts not shown yet, the report below (which
         * holds only the shown ones) speaks for it alone. */
        int partial = e->report && l->hw && sw_homework_hidden_parts(l->hw) > 0 &&
                      (e->part < 0 || l->hw->parts[e->part].visibility != SW_VIS_VISIBLE);
        if (partial)
            fprintf(f, "== %s ==\n", shown);
        else {
            fprintf(f, "== %s: %s ==\n", shown, grade_verdict_word(e->status));
            if (e->failing_step >= 0)
                fprintf(f, "first failing step: %ld\n", e->failing_step);
            if (e->message[0])
                fprintf(f, "%s\n", e->message);
        }
        if (e->remarks[0])
            fprintf(f, "note: %s\n", e->remarks);
        if (e->status != GRADE_SKIPPED)
            write_points(f, l, e);
        if (e->report)
            fprintf(f, "\n%s", e->report);
        fputc('\n', f);
    }
}

int grade_feedback_write(const grade_list *l, const char *dir)
{
    int rows = l->n + l->ignored, written = 0, rc = SW_EXIT_OK;
    unsigned char *done = calloc((size_t)rows + 1, 1);
    char (*names)[112] = calloc((size_t)rows + 1, sizeof *names);
    if (!done || !names) {
        free(done);
        free(names);
        return sw_cli_error("grade: out of memory");
    }
    /* With a roster its students name their files first, and a row no
     * student matched gets "unmatched-": a file's name reduced alike
     * ("Alice_Adams") never takes a student's file. */
    for (int pass = 0; pass < rows * (l->roster ? 2 : 1) && rc == SW_EXIT_OK; pass++) {
        int i = pass % rows, on_roster = l->roster && row(l, i)->who >= 0;
        if (done[i] || (l->roster && (pass < rows) != on_roster))
            continue;
        const grade_entry *e = row(l, i);
        if (e->status == GRADE_SKIPPED && !on_roster)
            continue; /* not a student's: a stray file */
        char student[SW_TRACE_STUDENT_MAX], base[90], path[PATH_MAX];
        grade_student_of(e, student, sizeof student);
        grade_safe_name(student, base + (l->roster && !on_roster ? 10 : 0), sizeof base - 10);
        if (l->roster && !on_roster)
            memcpy(base, "unmatched-", 10);
        grade_name_unique(names, written, base);
        snprintf(path, sizeof path, "%s/%s.txt", dir, names[written]);
        written++;
        struct stat st;
        char err[SW_ERRLEN + 256];
        if (lstat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
            rc = sw_cli_error("grade: --feedback: '%.200s' exists and is not a regular file", path);
            break;
        }
        sw_outfile o;
        if (sw_outfile_open(&o, path, err, sizeof err) != SW_OK) {
            rc = sw_cli_error("grade: --feedback: %s", err);
            break;
        }
        char *text = NULL, *shown = NULL;
        size_t text_len = 0;
        FILE *m = open_memstream(&text, &text_len);
        if (m) {
            write_report(m, l, i, done);
            fclose(m);
            shown = text ? grade_text_shown(text) : NULL;
        }
        fputs(shown ? shown : "(out of memory)\n", o.f);
        free(text);
        free(shown);
        if (sw_outfile_commit(&o, err, sizeof err) != SW_OK)
            rc = sw_cli_error("grade: --feedback: %s", err);
        for (int j = i; j < rows; j++)
            if (same_student(l, i, j))
                done[j] = 1;
    }
    if (rc == SW_EXIT_OK)
        sw_cli_note("feedback: %d file%s in %s", written, written == 1 ? "" : "s", dir);
    free(done);
    free(names);
    return rc;
}
