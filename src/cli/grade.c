/* `stepwise grade --assignment A FILES...|DIR`: grade a class. Each
 * submission (a trace, or a plugin as .so or .c) is checked in its own
 * child process under CPU-time, memory and output limits and a watchdog
 * on blocking (--wall), so a pathological file or plugin fails that
 * student alone.
 * Prints a summary table; writes a CSV gradebook and Gradescope's
 * results.json on request, each whole or not at all. Exit 0 when every
 * submission passed, 1 when any did not, 2 for bad usage. */
#include "cli/cli.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <poll.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli/check_report.h"
#include "cli/grade.h"
#include "plugin/plugin.h"
#include "plugin/proc_tree.h"
#include "plugin/sandbox.h"
#include "grade/similar.h"
#include "grade/verdict.h"
#include "util/decimal.h"
#include "util/escape.h"
#include "util/signals.h"
#include "util/tmpdir.h"

static const char grade_help[] =
    "usage: stepwise grade --assignment A [--csv FILE] [--results FILE] [--cpu S] [--memory MB]\n"
    "                      [--output KB] [--wall S] [--plugin-timeout S] [--rtol R] [--atol A]\n"
    "                      [--tol COL=REL[,ABS]]... [--ignore COL]... [--roster FILE] [--fresh]\n"
    "                      [--similarity] [--feedback DIR] [--gradebook FILE] [--lms FILE]\n"
    "                      [-j N] FILES...|DIR...\n"
    "\n"
    "Grades every submission against the assignment A (a small metadata file, or a\n"
    "reference trace whose header serves): traces (.trace, .csv) are checked like\n"
    "'stepwise check TRACE --assignment A'; plugins (.so, or .c built with the\n"
    "documented flags) like 'stepwise check --plugin P --assignment A'. A directory\n"
    "stands for the submissions in it; every other entry in it (a link, a FIFO, a\n"
    ".txt file, ...) gets a row 'skipped' saying why. Each runs in its own child\n"
    "process with limits, so a crash, a loop or a memory hog fails that student\n"
    "alone. Prints a table (student, file, verdict, first failing step, the mistake\n"
    "in words).\n"
    "\n"
    "options:\n"
    "      --assignment A     what the teacher set (required)\n"
    "      --csv FILE         write every file's row: student,file,verdict,first_failing_step,\n"
    "                         message,id,remarks,similar,score,max,part; an existing one is updated: the\n"
    "                         rows of the files graded now replaced, the others kept\n"
    "      --fresh            start the --csv gradebook over instead of updating it\n"
    "      --gradebook FILE   one row per student (the roster's, or each '# student:'): the\n"
    "                         counted submissions' score out of the homework's, by its\n"
    "                         '# count:' rule (best, or latest); a regrade keeps the rows\n"
    "                         of the students it saw nothing of\n"
    "      --lms FILE         name,id,email,score,max per student, for an LMS import (Moodle's\n"
    "                         maps it by email as it is)\n"
    "      --submission-metadata FILE  Gradescope's submission_metadata.json: whose\n"
    "                         submission this is, for per-student parameters\n"
    "      --roster FILE      the class (CSV: a name column, optional id and email): every\n"
    "                         row gets its student from the file's or folder's name\n"
    "                         (Gradescope, Canvas, Moodle downloads; folders are walked),\n"
    "                         a '# student:' line naming someone else is reported, and\n"
    "                         each student without a submission gets a row 'missing'\n"
    "      --similarity       list pairs of submissions that look copied: plugin sources\n"
    "                         (renamed, reformatted) and identical wrong traces\n"
    "      --feedback DIR     write each student's full report to DIR/NAME.txt\n"
    "  -j, --jobs N           grade N submissions at once, 1 to 256 (default: the online\n"
    "                         cores); the results are the same for every N\n"
    ;
static const char grade_help_more[] =
    "      --results FILE     write a class-wide results.json (score, max_score, tests)\n"
    "      --gradescope FILE  write Gradescope's results.json for one submission: one test\n"
    "                         per check of the assignment ('# points'), as run_autograder\n"
    "                         does ('stepwise autograder')\n"
    "      --cpu S            CPU seconds for a submission's own processes (its build and\n"
    "                         its plugin), 0.1 to 3600 (default 10); the grader's own\n"
    "                         work has its own budget (4 x cpu + 30)\n"
    "      --memory MB        address space per submission, 64 to 65536 MiB (default 1024)\n"
    "      --output KB        output per submission, 4 to 1048576 KiB: report kept, files\n"
    "                         written, the compiler's too (default 1024)\n"
    "      --wall S           seconds a submission may wait with nothing running, 0.1 to\n"
    "                         86400 (default 4 x cpu + 20): a guard against a submission\n"
    "                         that blocks, not a measure of its work (load only slows it)\n"
    "      --plugin-timeout S seconds of its own CPU time (or asleep) a plugin may take per step,\n"
    "                         0.01 to 3600 (default 2)\n"
    "      --no-sandbox       run plugins and compilers without the jail (namespaces,\n"
    "                         seccomp): only inside a disposable container that holds\n"
    "                         one submission (docs/sandbox.md)\n"
    "      --rtol R, --atol A, --tol COL=REL[,ABS], --ignore COL   as for check (rtol 1e-16\n"
    "                         to 1, atol 1e-300 to 1e6)\n"
    "  -h, --help             this help\n"
    "\n"
    "The --csv, --results and --feedback paths are checked before grading (writable, not the\n"
    "assignment nor a submission, not among the submissions; - or /dev/stdout writes\n"
    "to standard output and moves the table to stderr) and written whole at the end.\n"
    "\n"
    "exit status: 0 every entry passed, 1 some did not (or were skipped), 2 bad usage.\n";


/* One submission being graded: its worker and when it started. */
typedef struct grade_slot {
    int active;
    int index;
    grade_job job;
    sw_child child;
    double start;
    double idle, seen;           /* the watchdog's: time with nothing of it runnable, and when last looked */
} grade_slot;

/* The --wall watchdog, looked at every WALL_LOOK s: a submission's worker
 * and everything it started (the jail, the compiler, the plugin's host)
 * may sit with nothing runnable for `wall` seconds (a compiler reading a
 * FIFO: blocked), however long a busy machine keeps them waiting on a run
 * queue; within WALL_CAP times `wall` whatever they do. Where /proc cannot
 * tell, `wall` seconds, as a plain wall clock. */
#define WALL_LOOK 0.25
#define WALL_CAP 20

/* Whether slot's time is up at now (its idle time brought up to date). */
static int wall_is_up(grade_slot *slot, double now, double wall)
{
    sw_proc_tree tree;
    double dt = now - slot->seen;
    slot->seen = now;
    if (sw_proc_tree_read(slot->child.pid, &tree) != 0)
        slot->idle = now - slot->start;
    else if (tree.runnable == 0)
        slot->idle += dt;
    return slot->idle >= wall || now - slot->start >= WALL_CAP * wall;
}

/* Start the worker of slot->index; 0, or -1 with the entry filled (an
 * error row) when the worker could not be started. */
static int grade_start(grade_slot *slot, grade_entry *e)
{
    char err[SW_ERRLEN];
    slot->start = slot->seen = sw_sandbox_now();
    slot->idle = 0;
    e->status = SW_VERDICT_ERROR;
    e->failing_step = -1;
    sw_decimal_init(); /* the trace parser's table, built once here for every worker */
    /* The worker's CPU is the grader's own work (regenerating the
     * reference, comparing, measuring, explaining): its budget is the
     * grader's, never the submission's, whose --cpu holds for the
     * processes that run its code (its build and its plugin's host). */
    sw_limits worker = *slot->job.lim;
    worker.cpu_seconds = GRADE_WORKER_CPU(worker.cpu_seconds);
    if (sw_sandbox_spawn(&slot->child, grade_worker, &slot->job, &worker, -1, err, sizeof err) != SW_OK) {
        snprintf(e->message, sizeof e->message, "%s", err);
        e->seconds = sw_sandbox_now() - slot->start;
        return -1;
    }
    slot->active = 1;
    return 0;
}

/* Take the record of a worker whose channel is readable (or whose time is
 * up): always fills e and ends the worker. */
static void grade_finish_one(grade_slot *slot, grade_entry *e, double wall)
{
    const grade_job *job = &slot->job;
    const sw_limits *lim = job->lim;
    sw_child *child = &slot->child;
    /* a worker whose channel is readable has its record written or on the
     * way: read it within `wall` more (its time was up: no wait at all) */
    double start = slot->start, left = slot->idle >= wall || sw_sandbox_now() - start >= WALL_CAP * wall ? 0 : wall;
    grade_record rec;
    int rc = sw_sandbox_read(child->from_child, &rec, sizeof rec, left > 0.001 ? left : 0.001);
    /* The worker runs only stepwise's code, but its record is checked like
     * any bytes from a child: a status it can have, lengths within bounds
     * before anything is allocated, strings terminated here. */
    if (rc == 1 && ((rec.status < SW_VERDICT_PASS || rec.status > SW_VERDICT_ERROR) &&
                    rec.status != GRADE_LIMIT))
        rc = -3;
    if (rc == 1 && (rec.report_len > job->report_max || rec.failing_step < -1 ||
                    rec.score.n < 0 || rec.score.n > SW_SCORE_CHECKS || rec.nwrong > SW_SIMILAR_ROWS_MAX ||
                    rec.part < -1 || rec.part >= job->hw->nparts))
        rc = -3;
    if (rc == 1) {
        rec.student[sizeof rec.student - 1] = rec.notes[sizeof rec.notes - 1] = '\0';
        rec.kind[sizeof rec.kind - 1] = rec.message[sizeof rec.message - 1] = '\0';
        /* The scores are re-added here, each within its check's points. */
        rec.score.score = rec.score.max = 0;
        for (int i = 0; i < rec.score.n; i++) {
            sw_score_check *c = &rec.score.checks[i];
            c->name[sizeof c->name - 1] = c->output[sizeof c->output - 1] = '\0';
            if (!(c->max >= 0 && c->max <= SW_POINTS_LIMIT))
                c->max = 0;
            if (!(c->score >= 0 && c->score <= c->max))
                c->score = 0;
            if (c->part < 0 || c->part >= job->hw->nparts)
                c->part = 0;
            c->visibility = (int)job->hw->parts[c->part].visibility; /* the homework's word, not the record's */
            rec.score.score += c->score;
            rec.score.max += c->max;
        }
    }
    if (rc == 1 && rec.report_len > 0) {
        e->report = malloc(rec.report_len + 1);
        if (e->report && sw_sandbox_read(child->from_child, e->report, rec.report_len,
                                         left > 0.001 ? left : 0.001) == 1)
            e->report[rec.report_len] = '\0';
        else {
            free(e->report);
            e->report = NULL;
        }
    }
    if (rc == 1 && rec.nwrong > 0) {
        e->wrong = malloc(rec.nwrong * sizeof *e->wrong);
        if (e->wrong && sw_sandbox_read(child->from_child, e->wrong, rec.nwrong * sizeof *e->wrong,
                                        left > 0.001 ? left : 0.001) == 1)
            e->nwrong = (int)rec.nwrong;
        else {
            free(e->wrong);
            e->wrong = NULL;
        }
    }
    sw_child_end end;
    if (rc == 1) {
        sw_sandbox_reap(child, 2.0, &end);
        e->status = rec.status;
        e->failing_step = rec.failing_step;
        memcpy(e->student, rec.student, sizeof e->student);
        memcpy(e->notes, rec.notes, sizeof e->notes);
        memcpy(e->kind, rec.kind, sizeof e->kind);
        memcpy(e->message, rec.message, sizeof e->message);
        e->score = rec.score;
        e->part = rec.part;
    } else {
        char how[120];
        if (rc == -2 || rc == -1)
            sw_sandbox_kill(child, &end);
        else
            sw_sandbox_reap(child, 2.0, &end);
        sw_sandbox_describe(&end, how, sizeof how);
        if (rc == -2 && slot->idle >= wall)
            snprintf(e->message, sizeof e->message, "grading waited %g s with nothing running (the submission "
                     "slept or waited: a sleep, a read or a lock in its code) and was stopped (the grader's guard, --wall; the submission's own work is "
                     "held to --cpu)", wall);
        else if (rc == -2)
            snprintf(e->message, sizeof e->message, "grading went on for %g s of wall time, %d times --wall, and "
                     "was stopped (the grader's guard, --wall; the submission's own work is held to --cpu)",
                     WALL_CAP * wall, WALL_CAP);
        else if (rc == -1)
            snprintf(e->message, sizeof e->message, "interrupted");
        else if (rc == -3)
            snprintf(e->message, sizeof e->message, "the grading process sent a record it could not "
                     "have sent");
        else
            snprintf(e->message, sizeof e->message, "the grading process %s (the grader's limits: %g s "
                     "CPU, %zu MiB, --memory)", how, GRADE_WORKER_CPU(lim->cpu_seconds), lim->memory_bytes >> 20);
        snprintf(e->kind, sizeof e->kind, "%s", rc == -2 ? "wall-time" : "limit");
        /* Out of its wall-clock or CPU time: a limit, not a wrong answer. */
        if (rc == -2 || (rc == 0 && !end.exited && end.signal == SIGXCPU))
            e->status = GRADE_LIMIT;
        e->part = -1;
        grade_zero_score(&e->score, job->hw, job->plugin, e->message);
    }
    e->seconds = sw_sandbox_now() - start;
    slot->active = 0;
}

/* Grade every submission, up to jobs at once, each in its own worker with
 * its own wall-clock watchdog; rows are printed in the list's order as
 * soon as they and all before them are done, so the table, the CSV and
 * results.json are the same for every jobs. */
static void grade_all(grade_list *list, const grade_job *proto, double wall, int jobs)
{
    int n = list->n, next = 0, printed = 0, running = 0;
    grade_slot *slots = calloc((size_t)jobs, sizeof *slots);
    unsigned char *done = calloc((size_t)n + 1, 1);
    struct pollfd *fds = calloc((size_t)jobs, sizeof *fds);
    int *which = calloc((size_t)jobs, sizeof *which);
    if (!slots || !done || !fds || !which) {
        jobs = 0; /* out of memory: every entry an error row */
        for (int i = 0; i < n; i++) {
            snprintf(list->items[i].message, sizeof list->items[i].message, "out of memory");
            list->items[i].status = SW_VERDICT_ERROR;
            list->items[i].failing_step = -1;
        }
        printed = n;
    }
    while (printed < n && !sw_signal_caught) {
        for (int k = 0; k < jobs && next < n; k++) {
            if (slots[k].active)
                continue;
            slots[k].index = next;
            slots[k].job = *proto;
            slots[k].job.path = list->items[next].path;
            slots[k].job.plugin = list->items[next].plugin;
            slots[k].job.index = next;
            slots[k].job.student_key = grade_student_key(list, &list->items[next]);
            slots[k].job.own_folder = list->items[next].own_folder;
            if (grade_start(&slots[k], &list->items[next]) == 0)
                running++;
            else
                done[next] = 1;
            next++;
        }
        /* Wait for any worker's record, or the watchdog's next look. */
        int nfds = 0;
        for (int k = 0; k < jobs; k++)
            if (slots[k].active) {
                fds[nfds].fd = slots[k].child.from_child;
                fds[nfds].events = POLLIN;
                fds[nfds].revents = 0;
                which[nfds++] = k;
            }
        if (nfds > 0) {
            double look = wall < WALL_LOOK ? wall : WALL_LOOK;
            int ready = poll(fds, (nfds_t)nfds, (int)(look * 1000) + 1);
            if (ready < 0 && errno != EINTR)
                ready = 0;
            double now = sw_sandbox_now();
            for (int f = 0; f < nfds; f++) {
                grade_slot *sl = &slots[which[f]];
                if ((ready > 0 && fds[f].revents) || wall_is_up(sl, now, wall)) {
                    grade_finish_one(sl, &list->items[sl->index], wall);
                    done[sl->index] = 1;
                    running--;
                }
            }
        }
        for (; printed < n && done[printed]; printed++) {
            grade_roster_claim(list, &list->items[printed]);
            grade_print_row(&list->items[printed]);
        }
    }
    /* Interrupted: every worker still running is stopped. */
    for (int k = 0; k < jobs; k++)
        if (slots[k].active) {
            sw_child_end end;
            sw_sandbox_kill(&slots[k].child, &end);
            slots[k].active = 0;
        }
    free(slots);
    free(done);
    free(fds);
    free(which);
}

/* What the command line asked for. */
typedef struct grade_opts {
    const char *assignment, *csv, *results, *gradescope, *roster, *feedback, *gradebook, *lms, *metadata;
    int fresh, similarity, jobs;
    sw_limits lim;
    double wall;                 /* 0: the default, GRADE_WALL(cpu) */
    sw_check_request base;       /* the tolerance options */
    const char **files;          /* argc long */
    int nfiles;
    int wargc;                   /* wargv[0..wargc): what a plugin's worker is started with */
} grade_opts;

#define GRADE_HELP_SHOWN (-1)

/* Parse the options into o (o->files allocated by the caller, argc + 1
 * long); wargv receives the options that shape a check, never a file of
 * the class (grade.h). SW_EXIT_OK, GRADE_HELP_SHOWN, or SW_EXIT_USAGE with
 * the error printed. */
static int grade_parse(int argc, char **argv, grade_opts *o, char **wargv)
{
    char err[SW_ERRLEN + SW_TRACE_PATH_MAX];
    int first_file = 0, rc = SW_EXIT_OK;
    o->lim = (sw_limits){ .cpu_seconds = 10, .memory_bytes = (size_t)1024 << 20,
                          .output_bytes = (size_t)1024 << 10 };
    sw_check_request_init(&o->base);
    o->wargc = 1;
    wargv[0] = "grade";
    for (int i = 1; i < argc && rc == SW_EXIT_OK; i++) {
        const char *a = argv[i];
        int takes = a[0] == '-' && ((a[1] == '-' && strcmp(a, "--help") != 0 && strcmp(a, "--") != 0 &&
                    strcmp(a, "--no-sandbox") != 0 && strcmp(a, "--fresh") != 0 &&
                    strcmp(a, "--similarity") != 0) || strcmp(a, "-j") == 0);
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            fputs(grade_help, stdout);
            fputs(grade_help_more, stdout);
            return GRADE_HELP_SHOWN;
        }
        if (first_file || a[0] != '-') {
            o->files[o->nfiles++] = a;
            continue;
        }
        struct stat named;
        if (strcmp(a, "--") != 0 && lstat(a, &named) == 0) {
            /* a submission named like an option, from a shell's glob (a file
             * "--no-sandbox" must not turn the jail off for the class) */
            char shown[120];
            sw_escape(a, 60, shown, sizeof shown);
            rc = sw_cli_error("grade: '%s' is both an option and a file here: give the options before the "
                              "files, and a file whose name begins with '-' after --", shown);
            break;
        }
        if (strcmp(a, "--") == 0) {
            first_file = 1;
            continue;
        }
        if (takes && i + 1 >= argc) {
            rc = sw_cli_error("grade: %s needs a value; see 'stepwise grade --help'", a);
            break;
        }
        const char *val = takes ? argv[++i] : NULL;
        static const char *const for_worker[] = { "--assignment", "--cpu", "--wall", "--memory", "--output",
                                                  "--no-sandbox", "--plugin-timeout", "--rtol", "--atol",
                                                  "--tol", "--ignore" };
        for (size_t k = 0; k < sizeof for_worker / sizeof *for_worker; k++)
            if (strcmp(a, for_worker[k]) == 0) {
                wargv[o->wargc++] = (char *)a;
                if (val)
                    wargv[o->wargc++] = (char *)val;
            }
        double d;
        if (strcmp(a, "--assignment") == 0)
            o->assignment = val;
        else if (strcmp(a, "--roster") == 0)
            o->roster = val;
        else if (strcmp(a, "--fresh") == 0)
            o->fresh = 1;
        else if (strcmp(a, "--similarity") == 0)
            o->similarity = 1;
        else if (strcmp(a, "--feedback") == 0)
            o->feedback = val;
        else if (strcmp(a, "-j") == 0 || strcmp(a, "--jobs") == 0 || strncmp(a, "-j", 2) == 0) {
            rc = sw_cli_range(strncmp(a, "--", 2) == 0 ? a : "-j", val ? val : a + 2, 1, 256, "",
                              &d);
            if (rc == SW_EXIT_OK && d != (int)d)
                rc = sw_cli_error("grade: -j takes a whole number of submissions at once, 1 to 256");
            o->jobs = (int)d;
        }
        else if (strcmp(a, "--csv") == 0)
            o->csv = val;
        else if (strcmp(a, "--gradebook") == 0)
            o->gradebook = val;
        else if (strcmp(a, "--lms") == 0)
            o->lms = val;
        else if (strcmp(a, "--submission-metadata") == 0)
            o->metadata = val;
        else if (strcmp(a, "--results") == 0)
            o->results = val;
        else if (strcmp(a, "--gradescope") == 0)
            o->gradescope = val;
        else if (strcmp(a, "--cpu") == 0)
            rc = sw_cli_range("--cpu", val, 0.1, 3600, "seconds", &o->lim.cpu_seconds);
        else if (strcmp(a, "--wall") == 0)
            rc = sw_cli_range("--wall", val, 0.1, 86400, "seconds", &o->wall);
        else if (strcmp(a, "--memory") == 0) {
            rc = sw_cli_range("--memory", val, 64, 65536, "MiB", &d);
            o->lim.memory_bytes = (size_t)(d * 1048576);
        } else if (strcmp(a, "--output") == 0) {
            rc = sw_cli_range("--output", val, 4, 1048576, "KiB", &d);
            o->lim.output_bytes = (size_t)(d * 1024);
        } else if (strcmp(a, "--no-sandbox") == 0) {
            sw_jail_set_enabled(0);
        } else if (strcmp(a, "--plugin-timeout") == 0) {
            rc = sw_cli_range("--plugin-timeout", val, 0.01, 3600, "seconds", &d);
            if (rc == SW_EXIT_OK)
                sw_plugin_set_timeout(d);
        } else if (strcmp(a, "--rtol") == 0)
            rc = sw_cli_range("--rtol", val, 1e-16, 1, "", &o->base.rtol);
        else if (strcmp(a, "--atol") == 0)
            rc = sw_cli_range("--atol", val, 1e-300, 1e6, "", &o->base.atol);
        else if (strcmp(a, "--tol") == 0 || strcmp(a, "--ignore") == 0) {
            if (sw_coltol_parse(&o->base.coltols, val, a[2] == 'i', a, err, sizeof err) != SW_OK)
                rc = sw_cli_error("grade: %s", err);
        } else
            rc = sw_cli_error("grade: unknown option '%.40s'; see 'stepwise grade --help'", a);
    }
    return rc;
}

/* The submissions the command line names, into list, and every check that
 * comes before grading: the outputs' paths, the feedback directory, the
 * gradebook to update, the roster, the students' keys, a jail for
 * plugins. SW_EXIT_OK, or an exit status with the error printed. */
static int grade_gather(grade_opts *o, grade_list *list, const struct stat *asg_st)
{
    char err[SW_ERRLEN + SW_TRACE_PATH_MAX];
    int rc = SW_EXIT_OK;
    if (o->roster)
        rc = grade_roster_load(list, o->roster);
    if (rc == SW_EXIT_OK && o->metadata)
        rc = grade_read_submission_metadata(list, o->metadata);
    for (int i = 0; rc == SW_EXIT_OK && i < o->nfiles; i++)
        rc = grade_collect(list, o->files[i], asg_st);
    if (rc == SW_EXIT_OK && list->n + list->ignored == 0 && !o->gradescope)
        rc = sw_cli_error("grade: no submissions found (traces end in .trace or .csv, plugins in "
                          ".so or .c)");
    if (rc == SW_EXIT_OK && o->gradescope && o->results)
        rc = sw_cli_error("grade: --gradescope and --results are two forms of results.json; give "
                          "one");
    const char *const out_opts[] = { "--csv", o->gradescope ? "--gradescope" : "--results", "--gradebook", "--lms" };
    const char *const out_paths[] = { o->csv, o->gradescope ? o->gradescope : o->results, o->gradebook, o->lms };
    if (rc == SW_EXIT_OK)
        rc = grade_check_outputs(list, asg_st, out_opts, out_paths, 4);
    if (rc == SW_EXIT_OK && o->feedback)
        rc = grade_feedback_check(list, o->feedback);
    if (rc == SW_EXIT_OK)
        rc = grade_book_load(list, o->csv);
    if (rc == SW_EXIT_OK)
        rc = grade_roster_missing(list);
    if (rc == SW_EXIT_OK)
        rc = grade_student_keys_check(list);
    if (rc == SW_EXIT_OK)
        grade_mark_own_folders(list, o->gradescope != NULL);
    for (int i = 0; rc == SW_EXIT_OK && i < list->n; i++)
        if (list->items[i].plugin && sw_plugin_host_fd(err, sizeof err) < 0)
            rc = sw_cli_error("grade: %s", err); /* the grader's fault: never a row of the student's */
        else if (list->items[i].plugin && sw_sandbox_probe(err, sizeof err) != SW_OK)
            rc = sw_cli_error("grade: plugins are run isolated, and %s", err);
    return rc;
}

/* Grade the gathered list and write every output; the exit status. */
static int grade_run(grade_opts *o, grade_list *list, sw_homework *hw, char **wargv)
{
    char err[SW_ERRLEN + SW_TRACE_PATH_MAX];
    int rc = SW_EXIT_OK;
    /* the workers build their jails the way the probe found works here */
    if (sw_jail_enabled() && sw_jail_kind_now() == SW_JAIL_UID)
        setenv("STEPWISE_JAIL", "uid", 1);
    o->base.assignment = &hw->parts[0].a;
    if (!(o->wall > 0))
        o->wall = GRADE_WALL(o->lim.cpu_seconds);
    char build_dir[PATH_MAX];
    if (sw_tmpdir_make("grade", build_dir, sizeof build_dir, err, sizeof err) != SW_OK)
        return sw_cli_error("grade: %s", err);
    sw_signals_catch(); /* the sandbox's waits end on a caught signal too */
    grade_print_head(hw, list);
    double start = sw_sandbox_now();
    if (o->jobs == 0) {
        long cores = sysconf(_SC_NPROCESSORS_ONLN);
        o->jobs = cores < 1 ? 1 : cores > 256 ? 256 : (int)cores;
    }
    if (o->jobs > list->n)
        o->jobs = list->n > 0 ? list->n : 1;
    grade_job proto = { NULL, 0, build_dir, 0, &o->base, o->lim.output_bytes, list, o->similarity, &o->lim, o->wargc,
                        wargv, hw, "", 0 };
    sw_sandbox_adopt_orphans(); /* what a plugin leaves running comes back here */
    grade_all(list, &proto, o->wall, o->jobs);
    sw_sandbox_kill_orphans(); /* before any result is written */
    grade_clean_dir(build_dir, list->n);
    if (!sw_signal_caught)
        rc = grade_similar_run(list);
    if (sw_signal_caught) {
        sw_cli_note("grading interrupted; no gradebook written");
        sw_signals_reraise(sw_signal_caught);
        return SW_EXIT_USAGE;
    }
    double seconds = sw_sandbox_now() - start;
    if (rc == SW_EXIT_OK)
        rc = grade_finish(list, &o->lim, o->wall, seconds, o->csv, o->results);
    if (rc != SW_EXIT_USAGE && (o->gradebook || o->lms)) {
        int brc = grade_students_write(list, o->gradebook, o->lms);
        if (brc != SW_EXIT_OK)
            rc = brc;
    }
    if (o->gradescope) {
        int grc = grade_write_gradescope(list, hw, o->gradescope, seconds, sw_jail_enabled());
        if (grc != SW_EXIT_OK)
            rc = grc;
    }
    return rc;
}

/* The command; wargv (argc + 2 long) receives what a plugin's worker is
 * started with. */
static int grade_command(int argc, char **argv, char **wargv)
{
    grade_worker_args w;
    int wrc = grade_worker_mode(&argc, &argv, &w);
    if (wrc != SW_EXIT_OK)
        return wrc;
    static grade_opts o;
    memset(&o, 0, sizeof o);
    char err[SW_ERRLEN + SW_TRACE_PATH_MAX];
    if (!(o.files = calloc((size_t)argc + 1, sizeof *o.files)))
        return sw_cli_error("grade: out of memory");
    int rc = grade_parse(argc, argv, &o, wargv);
    if (rc == GRADE_HELP_SHOWN) {
        free(o.files);
        return SW_EXIT_OK;
    }
    if (rc == SW_EXIT_OK && !o.assignment)
        rc = sw_cli_error("grade needs --assignment A (an assignment file or a reference trace); "
                          "see 'stepwise grade --help'");
    if (rc == SW_EXIT_OK && o.nfiles == 0 && !w.path)
        rc = sw_cli_error("grade needs submissions: FILES... or a DIR");
    static sw_homework hw;
    struct stat asg_st;
    if (rc == SW_EXIT_OK && (sw_homework_read(&hw, o.assignment, NULL, err, sizeof err) != SW_OK ||
                             stat(o.assignment, &asg_st) != 0))
        rc = sw_cli_error("%s", err);
    if (rc == SW_EXIT_OK && !w.path && hw.secret_public && hw.nvarying > 0)
        sw_cli_warn_public_secret(o.assignment);
    if (w.path) {
        free(o.files);
        if (rc != SW_EXIT_OK)
            return rc;
        o.base.assignment = &hw.parts[0].a;
        sw_decimal_init();
        grade_job job = { w.path, 1, w.build, w.index, &o.base, o.lim.output_bytes, NULL, w.similarity, &o.lim, 0, NULL,
                          &hw, w.student, w.own_folder };
        return grade_worker(&job, 3, 3);
    }
    grade_list list = { 0 };
    list.hw = &hw;
    list.fresh = o.fresh;
    list.similarity = o.similarity;
    list.feedback = o.feedback;
    if (rc == SW_EXIT_OK)
        rc = grade_gather(&o, &list, &asg_st);
    free(o.files);
    if (rc == SW_EXIT_OK)
        rc = grade_run(&o, &list, &hw, wargv);
    grade_list_free(&list);
    return rc;
}

int sw_cmd_grade(int argc, char **argv)
{
    char **wargv = calloc((size_t)argc + 2, sizeof *wargv);
    if (!wargv)
        return sw_cli_error("grade: out of memory");
    int rc = grade_command(argc, argv, wargv);
    free(wargv);
    return rc;
}
