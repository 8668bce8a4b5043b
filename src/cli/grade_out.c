/* The grade reports: the table on stdout, the CSV gradebook and Gradescope's
 * results.json. Files are written whole or not at all (util/outfile.h).
 * Names that came from students are escaped in the table and quoted in the
 * CSV. */
#include "cli/grade.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli/cli.h"
#include "cli/json.h"
#include "plugin/plugin.h"
#include "util/outfile.h"

int grade_list_add(grade_list *l, const char *path, int plugin)
{
    if (l->n == l->cap) {
        int cap = l->cap ? 2 * l->cap : 32;
        grade_entry *items = realloc(l->items, (size_t)cap * sizeof *items);
        if (!items)
            return SW_ENOMEM;
        l->items = items;
        l->cap = cap;
    }
    grade_entry *e = &l->items[l->n];
    memset(e, 0, sizeof *e);
    e->path = strdup(path);
    if (!e->path)
        return SW_ENOMEM;
    e->plugin = plugin;
    l->n++;
    return SW_OK;
}

void grade_list_free(grade_list *l)
{
    for (int i = 0; i < l->n; i++) {
        free(l->items[i].path);
        free(l->items[i].report);
    }
    free(l->items);
    memset(l, 0, sizeof *l);
}

static const char *verdict_word(int status)
{
    return status == 0 ? "pass" : status == 1 ? "fail" : "error";
}

/* The student: "# student:" when the trace gave one, else the file's name
 * without directory and extension. */
static void student_of(const grade_entry *e, char *buf, size_t len)
{
    if (e->student[0]) {
        snprintf(buf, len, "%s", e->student);
        return;
    }
    const char *base = strrchr(e->path, '/');
    base = base ? base + 1 : e->path;
    snprintf(buf, len, "%s", base);
    char *dot = strrchr(buf, '.');
    if (dot && dot != buf)
        *dot = '\0';
}

void grade_print_head(const sw_assignment *a, int n, int ignored)
{
    char dt[40];
    sw_fmt_shortest(dt, sizeof dt, a->meta.dt);
    printf("grading %d submission%s against %s (%s%s on %s, dt %s)", n, n == 1 ? "" : "s", a->path,
           a->nmethods > 1 ? "any of " : "", a->methods[0]->name, a->meta.scene->name, dt);
    if (ignored)
        printf("; %d other file%s ignored", ignored, ignored == 1 ? "" : "s");
    printf("\n  %-20s %-24s %-7s %6s  %s\n", "student", "file", "verdict", "step", "what");
    fflush(stdout);
}

void grade_print_row(grade_entry *e)
{
    char student[SW_TRACE_STUDENT_MAX], s_esc[80], f_esc[80], m_esc[400], step[24];
    student_of(e, student, sizeof student);
    sw_escape(student, 20, s_esc, sizeof s_esc);
    const char *base = strrchr(e->path, '/');
    sw_escape(base ? base + 1 : e->path, 24, f_esc, sizeof f_esc);
    sw_escape(e->message, 300, m_esc, sizeof m_esc);
    if (e->failing_step >= 0)
        snprintf(step, sizeof step, "%ld", e->failing_step);
    else
        snprintf(step, sizeof step, "-");
    printf("  %-20s %-24s %-7s %6s  %s\n", s_esc, f_esc, verdict_word(e->status), step, m_esc);
    fflush(stdout);
}

/* ---- files, whole or not at all -------------------------------------------- */

typedef void grade_writer(FILE *f, const grade_list *l, const char *summary);

/* Through util/outfile.h: whole or not at all, devices and "-" in place. */
static int write_whole(const char *path, grade_writer *write, const grade_list *l,
                       const char *summary)
{
    sw_outfile o;
    char err[SW_ERRLEN + 256];
    if (sw_outfile_open(&o, path, err, sizeof err) != SW_OK)
        return sw_cli_error("grade: %s", err);
    write(o.f, l, summary);
    if (sw_outfile_commit(&o, err, sizeof err) != SW_OK)
        return sw_cli_error("grade: %s", err);
    return SW_EXIT_OK;
}

/* One CSV field (RFC 4180): quoted when it holds a comma, quote or line break. */
static void csv_field(FILE *f, const char *s, int last)
{
    if (strpbrk(s, ",\"\r\n")) {
        putc('"', f);
        for (; *s; s++) {
            if (*s == '"')
                putc('"', f);
            putc(*s, f);
        }
        putc('"', f);
    } else
        fputs(s, f);
    fputs(last ? "\r\n" : ",", f);
}

static void write_csv(FILE *f, const grade_list *l, const char *summary)
{
    (void)summary;
    fputs("student,file,verdict,first_failing_step,message\r\n", f);
    for (int i = 0; i < l->n; i++) {
        const grade_entry *e = &l->items[i];
        char student[SW_TRACE_STUDENT_MAX], step[24] = "";
        student_of(e, student, sizeof student);
        if (e->failing_step >= 0)
            snprintf(step, sizeof step, "%ld", e->failing_step);
        csv_field(f, student, 0);
        csv_field(f, e->path, 0);
        csv_field(f, verdict_word(e->status), 0);
        csv_field(f, step, 0);
        csv_field(f, e->message, 1);
    }
}

/* Gradescope's format: a score, its maximum, and one test per submission. */
static void write_results(FILE *f, const grade_list *l, const char *summary)
{
    int passed = 0;
    for (int i = 0; i < l->n; i++)
        passed += l->items[i].status == 0;
    fprintf(f, "{\n  \"score\": %d,\n  \"max_score\": %d,\n  \"output\": ", passed, l->n);
    sw_json_str(f, summary);
    fputs(",\n  \"tests\": [", f);
    for (int i = 0; i < l->n; i++) {
        const grade_entry *e = &l->items[i];
        char student[SW_TRACE_STUDENT_MAX], name[SW_TRACE_STUDENT_MAX + PATH_MAX];
        student_of(e, student, sizeof student);
        snprintf(name, sizeof name, "%s (%s)", student, e->path);
        fprintf(f, "%s\n    {\n      \"name\": ", i ? "," : "");
        sw_json_str(f, name);
        fprintf(f, ",\n      \"score\": %d,\n      \"max_score\": 1,\n      \"status\": \"%s\",\n"
                "      \"output\": ", e->status == 0, e->status == 0 ? "passed" : "failed");
        char *text = e->report;
        char fallback[1400];
        if (!text) {
            snprintf(fallback, sizeof fallback, "%s: %s", verdict_word(e->status), e->message);
            text = fallback;
        }
        sw_json_str(f, text);
        if (e->notes[0]) {
            fputs(",\n      \"extra_data\": { \"notes\": ", f);
            sw_json_str(f, e->notes);
            fputs(" }", f);
        }
        fputs("\n    }", f);
    }
    fputs(l->n ? "\n  ]\n}\n" : "]\n}\n", f);
}

int grade_finish(const grade_list *l, const sw_limits *lim, double wall, double seconds,
                 const char *csv, const char *results)
{
    int passed = 0, errors = 0;
    for (int i = 0; i < l->n; i++) {
        passed += l->items[i].status == 0;
        errors += l->items[i].status == 2;
    }
    char summary[400];
    snprintf(summary, sizeof summary, "%d submission%s: %d passed, %d failed (%d of them "
             "unusable) in %.1f s; limits per submission: %g s CPU, %zu MiB, %zu KiB output, %g s "
             "wall, %g s per plugin step", l->n, l->n == 1 ? "" : "s", passed, l->n - passed,
             errors, seconds, lim->cpu_seconds, lim->memory_bytes >> 20, lim->output_bytes >> 10,
             wall, sw_plugin_timeout());
    printf("%s\n", summary);
    int rc = SW_EXIT_OK;
    if (csv)
        rc = write_whole(csv, write_csv, l, summary);
    if (rc == SW_EXIT_OK && results)
        rc = write_whole(results, write_results, l, summary);
    if (sw_cli_flush_stdout() != SW_EXIT_OK)
        return SW_EXIT_USAGE;
    if (rc != SW_EXIT_OK)
        return rc;
    return passed == l->n ? SW_EXIT_OK : SW_EXIT_FAIL;
}

void grade_clean_dir(const char *dir, int n)
{
    char path[PATH_MAX + 40];
    for (int i = 0; i < n; i++) {
        snprintf(path, sizeof path, "%s/s%d.so", dir, i);
        unlink(path);
        snprintf(path, sizeof path, "%s/s%d.log", dir, i);
        unlink(path);
    }
    rmdir(dir);
}
