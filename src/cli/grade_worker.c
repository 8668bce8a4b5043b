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
#include <sys/stat.h>
#include <unistd.h>

#include "cli/check_report.h"
#include "cli/cli.h"
#include "plugin/plugin_build.h"
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
    char index[24], similarity[8], own[8];
    char **args = calloc((size_t)job->argc + 10, sizeof *args);
    if (!args) {
        errno = ENOMEM;
        return;
    }
    snprintf(index, sizeof index, "%d", job->index);
    snprintf(similarity, sizeof similarity, "%d", job->similarity);
    snprintf(own, sizeof own, "%d", job->own_folder);
    int n = 0;
    args[n++] = "stepwise";
    args[n++] = "grade";
    args[n++] = GRADE_WORKER_FLAG;
    args[n++] = index;
    args[n++] = (char *)job->build_dir;
    args[n++] = (char *)job->path;
    args[n++] = similarity;
    args[n++] = own;
    args[n++] = (char *)(job->student_key ? job->student_key : "");
    for (int i = 1; i < job->argc; i++)
        args[n++] = job->argv[i];
    args[n] = NULL;
    setenv("STEPWISE_GRADE_WORKER", "1", 1);
    execve("/proc/self/exe", args, environ);
    int e = errno;
    free(args);
    errno = e;
}

int grade_worker_mode(int *argc, char ***argv, grade_worker_args *w)
{
    char **a = *argv;
    *w = (grade_worker_args){ .index = -1 };
    if (*argc <= 1 || strcmp(a[1], GRADE_WORKER_FLAG) != 0)
        return SW_EXIT_OK;
    /* only as grade starts it: its channel on descriptor 3, the mark in its
     * environment (a file named "--worker" in a teacher's glob is neither) */
    struct stat ch;
    const char *mark = getenv("STEPWISE_GRADE_WORKER");
    if (*argc <= 8 || !mark || strcmp(mark, "1") != 0 || fstat(3, &ch) != 0 || !S_ISSOCK(ch.st_mode))
        return sw_cli_error("grade: " GRADE_WORKER_FLAG " is how grade starts a plugin's worker, not an "
                            "option (to grade a file of that name, give it after --)");
    *w = (grade_worker_args){ .index = atoi(a[2]), .build = a[3], .path = a[4], .similarity = atoi(a[5]),
                              .own_folder = atoi(a[6]) == 1, .student = a[7] };
    *argc -= 7;
    *argv += 7;
    return SW_EXIT_OK;
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
    else if (v->got_end.blown && !v->ref_end.blown && strcmp(v->first_column, "step") == 0)
        /* the run ended there (a step that returned an error): its rows
         * stop, and the step column is the first to differ */
        snprintf(buf, len, "the plugin's run ended at step %ld (t = %g): %.900s", v->got_end.step, v->got_end.t,
                 v->got_end.reason);
    else
        snprintf(buf, len, "%.1000s", v->first);
}

/* Every check of the homework at 0 points, every part's, for a submission
 * that could not be checked, with why. */
void grade_zero_score(sw_score *s, const sw_homework *h, int plugin, const char *why)
{
    memset(s, 0, sizeof *s);
    for (int p = 0; p < h->nparts; p++) {
        sw_score part;
        sw_score_facts f = { .is_plugin = plugin, .usable = 0, .error = why };
        sw_points_score(&h->parts[p].a.points, &f, &part);
        sw_score_append(s, &part, h->parts[p].name, (int)h->parts[p].visibility, p);
    }
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

/* The homework with this submission's student's values: the parent's when
 * nothing is drawn per student, else read again here for the student. */
static const sw_homework *student_homework(const grade_job *job, char *err, size_t errlen)
{
    static sw_homework own;
    if (job->hw->nvarying == 0)
        return job->hw;
    if (!job->student_key || !job->student_key[0]) {
        snprintf(err, errlen, "whose values to grade this with could not be told (no roster student "
                 "matched it, or the roster has no e-mail for them): this homework gives each student "
                 "their own parameters, drawn from their e-mail");
        return NULL;
    }
    if (sw_homework_read(&own, job->hw->path, job->student_key, err, errlen) != SW_OK)
        return NULL;
    return &own;
}

/* A header that differs in a parameter drawn per student: made for other
 * parameters than this student's (whose is not said). */
static void other_parameters(const sw_homework *h, int part, const sw_verdict *v, char *buf,
                             size_t len)
{
    for (int i = 0; i < v->ndiffs && i < SW_VERDICT_DIFFS; i++)
        if (strncmp(v->diffs[i].what, "param ", 6) == 0 &&
            sw_homework_varies(h, part, v->diffs[i].what + 6)) {
            snprintf(buf, len, "made for other parameters than yours (%s: %s in the file, %s in "
                     "your assignment): each student has their own, on their assignment sheet",
                     v->diffs[i].what, v->diffs[i].got, v->diffs[i].want);
            return;
        }
}

/* A record for a submission not checked at all: status, kind, why. */
static void send_unchecked(int out, const sw_homework *h, int status, int plugin, const char *kind,
                           const char *why)
{
    static grade_record r;
    memset(&r, 0, sizeof r);
    r.status = status;
    r.failing_step = -1;
    r.part = -1;
    snprintf(r.message, sizeof r.message, "%s", why);
    snprintf(r.kind, sizeof r.kind, "%s", kind);
    grade_zero_score(&r.score, h, plugin, r.message);
    if (sw_sandbox_write(out, &r, sizeof r) != 0)
        _exit(1); /* the grader is gone, or its channel: it records the worker's end */
}

/* Check the submission on part p of h into v (a plugin: req.plugin set). */
static void check_part(const grade_job *job, const sw_homework *h, int p, sw_check_request *req,
                       sw_verdict *v)
{
    req->assignment = &h->parts[p].a;
    memset(v, 0, sizeof *v);
    v->failing_step = -1;
    if (job->plugin) {
        sw_plugin_forgive(req->plugin); /* a part is a check of its own */
        req->measure = 0;
        for (int i = 0; i < req->assignment->points.n; i++)
            req->measure |= req->assignment->points.items[i].kind == SW_POINTS_ORDER ||
                            req->assignment->points.items[i].kind == SW_POINTS_STABILITY;
    }
    sw_check_run(req, v);
    if (job->plugin && v->status == SW_VERDICT_FAIL && !v->got_end.fault && !req->measure) {
        /* A wrong plugin: its measured order says more than a value. */
        req->measure = 1;
        sw_check_run(req, v);
    }
}

/* The child: check one submission, send the record and the report. */
int grade_worker(void *ctx, int in, int out)
{
    (void)in;
    const grade_job *job = ctx;
    forget_the_class(job);
    char wrong_kind[200], err[SW_ERRLEN + 512];
    const sw_homework *h = student_homework(job, err, sizeof err);
    if (!h) {
        send_unchecked(out, job->hw, SW_VERDICT_ERROR, job->plugin, "student", err);
        return 0;
    }
    if (!sw_assignment_kind_ok(&h->parts[0].a, job->plugin, job->path, wrong_kind, sizeof wrong_kind)) {
        /* the other kind of upload: nothing of it is built, run or read;
         * scored out of what the homework pays for its own kind */
        snprintf(err, sizeof err, "%s: not graded", wrong_kind);
        send_unchecked(out, h, SW_VERDICT_FAIL, h->kind == SW_KIND_PLUGIN, "wrong_kind", err);
        return 0;
    }
    if (job->plugin && job->argv) {
        start_clean(job); /* a plugin never runs from the grader's memory */
        snprintf(err, sizeof err, "the grader could not start a fresh process to run this plugin "
                 "from (%s); not run", strerror(errno));
        send_unchecked(out, h, SW_VERDICT_ERROR, 1, "", err);
        return 0;
    }
    sw_plugin_set_limits(job->lim); /* the documented limits hold for the plugin's processes too */
    sw_check_request req = *job->base;
    static sw_verdict v;
    static grade_record rec;
    char so[PATH_MAX + 80], name[32];
    sw_build_warnings warned = { 0 };
    memset(&rec, 0, sizeof rec);
    const char *path = job->path;
    /* the student's file by its name: the grader's folders are not theirs to read */
    const char *file = strrchr(path, '/') ? strrchr(path, '/') + 1 : path;
    int rc = SW_OK, first = -1, first_lost = 0, lo = 0, hi = h->nparts;
    if (job->plugin) {
        size_t len = strlen(path);
        if (len > 2 && strcmp(path + len - 2, ".c") == 0) {
            snprintf(name, sizeof name, "s%d", job->index);
            rc = sw_plugin_compile(path, file, !job->own_folder, job->build_dir, name, so, sizeof so, &warned,
                                   err, sizeof err);
            path = so;
        }
        /* a name or label the tool would refuse is no reason to fail a
         * submission: graded under another, with a note */
        sw_plugin_set_any_name(1);
        if (rc == SW_OK)
            rc = sw_plugin_load(path, file, &req.plugin, err, sizeof err);
        rec.part = -1;
    } else {
        req.trace = path;
        sw_trace_reader r;
        rc = sw_trace_read_open(&r, path, err, sizeof err);
        if (rc == SW_OK) {
            lo = sw_homework_part_of_trace(h, job->path, &r.meta, err, sizeof err);
            sw_trace_read_close(&r);
            rc = lo < 0 ? SW_EINVAL : SW_OK;
            hi = lo + 1;
        }
        rec.part = lo;
    }
    if (rc != SW_OK) {
        send_unchecked(out, h, SW_VERDICT_ERROR, job->plugin, "", err);
        return 0;
    }
    char *report = NULL;
    size_t report_len = 0;
    FILE *f = open_memstream(&report, &report_len);
    const char *renamed = req.plugin ? sw_plugin_renamed(req.plugin) : NULL;
    if (f && renamed)
        fprintf(f, "note: %s; nothing is taken off for it (sw_plugin_info() sets them)\n", renamed);
    if (f && warned.count)
        fprintf(f, "note: the compiler warned %d time%s (nothing is taken off; a warning is often a bug); the "
                "first: %s\n", warned.count, warned.count == 1 ? "" : "s", warned.first);
    rec.status = SW_VERDICT_PASS;
    rec.failing_step = -1;
    for (int p = lo; p < hi; p++) {
        const sw_part *part = &h->parts[p];
        /* each part in a host of its own: what a plugin keeps in static
         * memory (a hidden part's system, its dt) never reaches the
         * values of the next, which its feedback may show */
        sw_plugin_hosts_end();
        check_part(job, h, p, &req, &v);
        int status = v.limit ? GRADE_LIMIT : (int)v.status;
        sw_score_append(&rec.score, &v.score, part->name, (int)part->visibility, p);
        if (f && h->nparts > 1)
            fprintf(f, "%s== part %s ==\n", p > lo ? "\n" : "", part->name);
        if (f && part->visibility != SW_VIS_VISIBLE) /* the student reads it */
            fprintf(f, "Graded; the results of this part are %s.\n",
                    part->visibility == SW_VIS_HIDDEN ? "not shown to you" : sw_visibility_words(part->visibility));
        else if (f && v.status == SW_VERDICT_ERROR)
            fprintf(f, "ERROR: %s\n", v.error);
        else if (f)
            sw_check_print_plain(f, &v);
        /* the row's message is the first part that lost points, else the
         * first that failed (a column the points do not read, student
         * pass: the message named one part where points went in others) */
        int lost = v.score.score < v.score.max;
        if (status != SW_VERDICT_PASS && (first < 0 || (lost && !first_lost))) {
            first = p;
            first_lost = lost;
            rec.status = status;
            rec.failing_step = v.failing_step;
            snprintf(rec.kind, sizeof rec.kind, "%s", v.have_explanation ? v.explanation.kind : "");
            char reason[1100] = "";
            other_parameters(h, p, &v, reason, sizeof reason);
            if (!reason[0])
                short_reason(&v, reason, sizeof reason);
            snprintf(rec.message, sizeof rec.message, "%s%s%s", h->nparts > 1 ? part->name : "",
                     h->nparts > 1 ? ": " : "", reason);
        } else if (first < 0 && !rec.message[0] && v.status == SW_VERDICT_PASS)
            short_reason(&v, rec.message, sizeof rec.message); /* a pass's warning */
        if (p == lo) {
            snprintf(rec.student, sizeof rec.student, "%s", v.student);
            snprintf(rec.notes, sizeof rec.notes, "%s", v.notes);
        }
    }
    if (f)
        fclose(f);
    rec.report_len = (unsigned)(report_len < job->report_max ? report_len : job->report_max);
    static grade_wrong_row wrong[SW_SIMILAR_ROWS_MAX];
    /* Explained mistakes are stepwise's own numbers, alike for everyone
     * who made them: not compared. */
    if (job->similarity && !job->plugin && rec.status == SW_VERDICT_FAIL && rec.failing_step >= 0 &&
        !v.have_explanation)
        rec.nwrong = wrong_rows(job->path, rec.failing_step, wrong);
    /* A write that fails (the grader gone, its channel closed) ends the
     * worker with status 1; the grader records how the worker ended. */
    int sent = sw_sandbox_write(out, &rec, sizeof rec) == 0 &&
               (!report || sw_sandbox_write(out, report, rec.report_len) == 0) &&
               (!rec.nwrong || sw_sandbox_write(out, wrong, rec.nwrong * sizeof wrong[0]) == 0);
    free(report);
    return sent ? 0 : 1;
}
