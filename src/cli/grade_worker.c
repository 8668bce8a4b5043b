/* The worker of one submission in `stepwise grade` (grade.c starts it in a
 * child process under limits): it forgets the rest of the class, checks the
 * submission, and sends back a grade_record, the report and, for
 * --similarity, a failing trace's wrong rows. Everything it sends is
 * checked again by the parent. */
#include "cli/grade.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli/check_report.h"
#include "cli/cli.h"
#include "plugin/sandbox.h"
#include "grade/similar.h"
#include "grade/verdict.h"

extern char **environ;

/* In a submission's worker, before anything of the submission runs: forget
 * what the parent knew of the others (their verdicts and reports) and every
 * environment variable but the few grading needs, so that nothing of them
 * is in the memory a plugin's process starts from. */
static void forget_the_class(const grade_job *job)
{
    for (int i = 0; job->list && i < job->list->n; i++) {
        grade_entry *e = &job->list->items[i];
        if (e->report) {
            explicit_bzero(e->report, strlen(e->report));
            free(e->report);
            e->report = NULL;
        }
        explicit_bzero(e->student, sizeof e->student);
        explicit_bzero(e->notes, sizeof e->notes);
        explicit_bzero(e->message, sizeof e->message);
        if (i != job->index)
            explicit_bzero(e->path, strlen(e->path));
    }
    static const char *const kept[] = { "PATH", "CC", "TMPDIR", "STEPWISE_INCLUDE", "STEPWISE_PLUGIN_TIMEOUT",
                                        "STEPWISE_SANDBOX", "STEPWISE_JAIL", "LC_ALL", "LANG" };
    char *keep[sizeof kept / sizeof kept[0]];
    for (size_t i = 0; i < sizeof kept / sizeof kept[0]; i++) {
        const char *v = getenv(kept[i]);
        keep[i] = v ? strdup(v) : NULL;
    }
    for (char **env = environ; env && *env; env++)
        explicit_bzero(*env, strlen(*env));
    clearenv();
    for (size_t i = 0; i < sizeof kept / sizeof kept[0]; i++)
        if (keep[i]) {
            setenv(kept[i], keep[i], 1);
            free(keep[i]);
        }
}

/* A plugin's worker: this program again, as `stepwise grade --worker ...`
 * with the command's own arguments (grade.h), in the environment just
 * cleaned, on the channel at descriptor 3. Returns only when it could not
 * be started, errno set. */
static void start_clean(const grade_job *job)
{
    char index[24], similarity[8];
    char **args = calloc((size_t)job->argc + 8, sizeof *args);
    if (!args) {
        errno = ENOMEM;
        return;
    }
    snprintf(index, sizeof index, "%d", job->index);
    snprintf(similarity, sizeof similarity, "%d", job->similarity);
    int n = 0;
    args[n++] = "stepwise";
    args[n++] = "grade";
    args[n++] = GRADE_WORKER_FLAG;
    args[n++] = index;
    args[n++] = (char *)job->build_dir;
    args[n++] = (char *)job->path;
    args[n++] = similarity;
    for (int i = 1; i < job->argc; i++)
        args[n++] = job->argv[i];
    args[n] = NULL;
    setenv("STEPWISE_GRADE_WORKER", "1", 1);
    execve("/proc/self/exe", args, environ);
    int e = errno;
    free(args);
    errno = e;
}

/* The mistake in a few words: explanation, plugin failure, header, values. */
static void short_reason(const sw_verdict *v, char *buf, size_t len)
{
    const sw_run_end *pf = v->got_end.fault ? &v->got_end : v->ref_end.fault ? &v->ref_end : NULL;
    if (v->status == SW_VERDICT_PASS && v->warning[0])
        snprintf(buf, len, "warning: %s", v->warning);
    else if (v->status == SW_VERDICT_PASS)
        buf[0] = '\0';
    else if (v->status == SW_VERDICT_ERROR)
        snprintf(buf, len, "%.1000s", v->error);
    else if (pf)
        snprintf(buf, len, "%.1000s", pf->reason);
    else if (v->have_explanation)
        snprintf(buf, len, "%s%s%s", v->ndiffs ? v->diffs[0].what : "", v->ndiffs ? " differs; " : "",
                 v->explanation.message);
    else if (v->ndiffs > 0)
        snprintf(buf, len, "%s: yours %s, the assignment's %s%s", v->diffs[0].what, v->diffs[0].got,
                 v->diffs[0].want, v->ndiffs > 1 ? " (and more)" : "");
    else
        snprintf(buf, len, "%.1000s", v->first);
}

/* Every check of the assignment at 0 points, for a submission that could
 * not be checked, with why. */
void grade_zero_score(sw_score *s, const sw_assignment *a, int plugin, const char *why)
{
    sw_score_facts f = { .is_plugin = plugin, .usable = 0, .error = why };
    sw_points_score(&a->points, &f, s);
}

/* A failing trace's rows from its first failing step on, each as its row
 * number and a digest of its values (bit for bit; -0 as 0, every NaN one
 * NaN), at most SW_SIMILAR_ROWS_MAX: what --similarity compares. */
static unsigned wrong_rows(const char *path, long failing_step, grade_wrong_row *out)
{
    sw_trace_reader r;
    char err[SW_ERRLEN + SW_TRACE_PATH_MAX];
    unsigned n = 0;
    if (sw_trace_read_open(&r, path, err, sizeof err) != SW_OK)
        return 0;
    double *row = NULL;
    if (sw_trace_read_header(&r, err, sizeof err) == SW_OK && r.ncols > 0 &&
        (row = malloc((size_t)r.ncols * sizeof *row))) {
        for (long i = 0; n < SW_SIMILAR_ROWS_MAX && sw_trace_read_row(&r, row, err, sizeof err) == 1;
             i++) {
            if (!(row[0] >= (double)failing_step))
                continue;
            uint64_t h = 1469598103934665603u;
            for (int c = 0; c < r.ncols; c++) {
                double x = row[c] == 0 ? 0.0 : isnan(row[c]) ? NAN : row[c];
                uint64_t bits;
                memcpy(&bits, &x, sizeof bits);
                for (int b = 0; b < 8; b++)
                    h = (h ^ ((bits >> (8 * b)) & 0xff)) * 1099511628211u;
            }
            out[n].row = i;
            out[n].hash = h;
            n++;
        }
    }
    free(row);
    sw_trace_read_close(&r);
    return n;
}

/* The child: check one submission, send the record and the report. */
int grade_worker(void *ctx, int in, int out)
{
    (void)in;
    const grade_job *job = ctx;
    forget_the_class(job);
    char wrong_kind[200];
    if (!sw_assignment_kind_ok(job->base->assignment, job->plugin, wrong_kind, sizeof wrong_kind)) {
        /* the other kind of upload: nothing of it is built, run or read */
        static grade_record other;
        memset(&other, 0, sizeof other);
        other.status = SW_VERDICT_FAIL;
        other.failing_step = -1;
        snprintf(other.message, sizeof other.message, "%s: not graded", wrong_kind);
        snprintf(other.kind, sizeof other.kind, "wrong_kind");
        /* scored out of what the homework pays for its own kind: one max for every row */
        grade_zero_score(&other.score, job->base->assignment, job->base->assignment->kind == SW_KIND_PLUGIN,
                         other.message);
        sw_sandbox_write(out, &other, sizeof other);
        return 0;
    }
    if (job->plugin && job->argv) {
        start_clean(job); /* a plugin never runs from the grader's memory */
        static grade_record failed;
        memset(&failed, 0, sizeof failed);
        failed.status = SW_VERDICT_ERROR;
        failed.failing_step = -1;
        snprintf(failed.message, sizeof failed.message,
                 "the grader could not start a fresh process to run this plugin from (%s); not run",
                 strerror(errno));
        grade_zero_score(&failed.score, job->base->assignment, 1, failed.message);
        sw_sandbox_write(out, &failed, sizeof failed);
        return 0;
    }
    sw_plugin_set_limits(job->lim); /* the documented limits hold for the plugin's processes too */
    sw_check_request req = *job->base;
    static sw_verdict v;
    static grade_record rec;
    char err[SW_ERRLEN + 512], so[PATH_MAX + 80], name[32];
    memset(&rec, 0, sizeof rec);
    memset(&v, 0, sizeof v);
    v.failing_step = -1;
    const char *path = job->path;
    int rc = SW_OK;
    if (job->plugin) {
        size_t len = strlen(path);
        if (len > 2 && strcmp(path + len - 2, ".c") == 0) {
            snprintf(name, sizeof name, "s%d", job->index);
            rc = sw_cli_compile_plugin(path, job->build_dir, name, so, sizeof so, err, sizeof err);
            path = so;
        }
        if (rc == SW_OK)
            rc = sw_plugin_load(path, job->path, &req.plugin, err, sizeof err);
        req.measure = 0;
        for (int i = 0; i < req.assignment->points.n; i++)
            req.measure |= req.assignment->points.items[i].kind == SW_POINTS_ORDER ||
                           req.assignment->points.items[i].kind == SW_POINTS_STABILITY;
    } else
        req.trace = path;
    if (rc != SW_OK) {
        v.status = SW_VERDICT_ERROR;
        snprintf(v.error, sizeof v.error, "%s", err);
        grade_zero_score(&rec.score, req.assignment, job->plugin, err);
    } else {
        sw_check_run(&req, &v);
        if (job->plugin && v.status == SW_VERDICT_FAIL && !v.got_end.fault && !req.measure) {
            /* A wrong plugin: its measured order says more than a value. */
            req.measure = 1;
            sw_check_run(&req, &v);
        }
    }
    rec.status = v.limit ? GRADE_LIMIT : (int)v.status;
    if (rc == SW_OK)
        rec.score = v.score;
    rec.failing_step = v.failing_step;
    snprintf(rec.student, sizeof rec.student, "%s", v.student);
    snprintf(rec.notes, sizeof rec.notes, "%s", v.notes);
    snprintf(rec.kind, sizeof rec.kind, "%s", v.have_explanation ? v.explanation.kind : "");
    short_reason(&v, rec.message, sizeof rec.message);
    char *report = NULL;
    size_t report_len = 0;
    FILE *f = open_memstream(&report, &report_len);
    if (f) {
        if (v.status == SW_VERDICT_ERROR)
            fprintf(f, "ERROR: %s\n", v.error);
        else
            sw_check_print_plain(f, &v);
        fclose(f);
    }
    rec.report_len = (unsigned)(report_len < job->report_max ? report_len : job->report_max);
    static grade_wrong_row wrong[SW_SIMILAR_ROWS_MAX];
    /* Explained mistakes are stepwise's own numbers, alike for everyone
     * who made them: not compared. */
    if (job->similarity && !job->plugin && v.status == SW_VERDICT_FAIL && v.failing_step >= 0 &&
        !v.have_explanation)
        rec.nwrong = wrong_rows(job->path, v.failing_step, wrong);
    sw_sandbox_write(out, &rec, sizeof rec);
    if (report)
        sw_sandbox_write(out, report, rec.report_len);
    if (rec.nwrong)
        sw_sandbox_write(out, wrong, rec.nwrong * sizeof wrong[0]);
    free(report);
    return 0;
}
