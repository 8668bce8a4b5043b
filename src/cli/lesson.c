/* `stepwise lesson`: the menu of lessons with each one's progress, a lesson
 * run live beside its scene, and `--check` for teachers (no terminal). */
#include "cli/cli.h"

#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "app/progress.h"
#include "app/runner.h"
#include "cli/lesson_check.h"
#include "tui/loop.h"
#include "util/escape.h"
#include "util/signals.h"
#include "util/utf8.h"

static const char lesson_help[] =
    "usage: stepwise lesson [NAME|N]\n"
    "       stepwise lesson --next\n"
    "       stepwise lesson --check FILE...\n\n"
    "With no argument, opens the menu of lessons with your progress; NAME (a file\n"
    "name without .lesson, e.g. 02-euler) or N (its place in the menu) opens one,\n"
    "resuming where you left off. --next opens the first lesson not yet finished\n"
    "(lesson 1 on a first run; the menu once all are done). --check lints lesson files without a terminal:\n"
    "exit 0 when all are valid, 2 with FILE:LINE:COL: messages otherwise.\n"
    "Lessons are read from $STEPWISE_LESSONS, else the installed lessons directory.\n"
    "Progress is kept in $XDG_STATE_HOME/stepwise/progress (~/.local/state/...).\n";

static int lesson_key(void *ctx, sw_app *a, int key) { return sw_runner_key(ctx, a, key); }

static const sw_side *lesson_side(void *ctx, sw_app *a, int cols)
{
    sw_runner_update(ctx, a);
    return sw_runner_side(ctx, a, cols);
}

/* Run the lesson at path (*done: its pages completed when it ends). When it
 * cannot start: with why NULL the error is printed (exit 2); else it goes
 * into why (the menu shows it) and the status is SW_EXIT_USAGE with
 * nothing printed. */
static int run_lesson(const char *path, int page, char *why, size_t whylen, int *done)
{
    sw_runner *r = malloc(sizeof *r);
    sw_app a;
    char err[SW_LESSON_ERRLEN];
    if (!r)
        return sw_cli_error("out of memory");
    if (sw_runner_start(r, &a, path, page, err, sizeof err) != SW_OK) {
        free(r);
        if (!why)
            return sw_cli_error("%s", err);
        snprintf(why, whylen, "%s", err);
        return SW_EXIT_USAGE;
    }
    sw_play_hooks hooks = { .ctx = r, .key = lesson_key, .side = lesson_side };
    int rc = sw_cli_play(&a, &hooks);
    if (done)
        *done = r->done;
    sw_app_free(&a);
    if (rc == SW_EXIT_OK && r->save_error[0])
        rc = sw_cli_error("%s", r->save_error);
    sw_runner_free(r);
    free(r);
    return rc;
}

/* The command as the student typed it: "./stepwise" after `make run`,
 * "stepwise" once installed, so the line printed on leaving works as written. */
static const char *program(void)
{
    extern char *program_invocation_name; /* glibc: argv[0] */
    const char *p = program_invocation_name;
    return p && strchr(p, '/') && strlen(p) < 200 ? p : "stepwise";
}

/* One line on leaving: how to continue where the student stopped. */
static void say_how_to_continue(const sw_lesson_entry *e, int n, int k)
{
    int done = k >= 0 ? sw_progress_get(e[k].file) : 0;
    if (k >= 0 && done < e[k].npages) {
        printf("lesson %d continues at page %d of %d: %s lesson %d\n", k + 1, done + 1, e[k].npages, program(),
               k + 1);
        return;
    }
    int next = sw_progress_next(e, n, k >= 0 ? k + 1 : 0);
    if (next >= 0)
        printf("%snext: %s lesson %d (%s, page %d)\n", k >= 0 ? "lesson done; " : "", program(), next + 1,
               e[next].title, sw_progress_get(e[next].file) + 1);
    else
        printf("every lesson is done; %s lesson N opens one again\n", program());
}

/* Find a lesson by its number in the menu (1-based) or its name. */
static int find_lesson(const sw_lesson_entry *e, int n, const char *what)
{
    char *end;
    long k = strtol(what, &end, 10);
    if (*what && *end == '\0')
        return k >= 1 && k <= n ? (int)k - 1 : -1;
    for (int i = 0; i < n; i++) {
        size_t len = strlen(what);
        if (strcmp(e[i].file, what) == 0 ||
            (strncmp(e[i].file, what, len) == 0 && strcmp(e[i].file + len, ".lesson") == 0))
            return i;
    }
    return -1;
}

/* title cut to at most cols display cells on a character boundary and
 * padded with spaces to cols cells, into out. */
static void fit_title(char *out, size_t len, const char *title, size_t cols)
{
    size_t used, k = sw_utf8_fit(title, strlen(title), cols, &used);
    snprintf(out, len, "%.*s%*s", (int)k, title, (int)(cols - used), "");
}

/* The menu of lessons with each one's progress, until q or a signal. A
 * lesson that cannot be opened says why in the menu, which stays. */
static int menu(sw_lesson_entry *e, int n)
{
    char err[SW_ERRLEN], note[SW_LESSON_ERRLEN + 80] = "", (*text)[400] = malloc((size_t)n * sizeof *text);
    const char **lines = malloc((size_t)n * sizeof *lines);
    int sel = 0, rc = SW_EXIT_OK;
    if (!text || !lines) {
        free(text);
        free(lines);
        return sw_cli_error("out of memory");
    }
    int first = sw_progress_next(e, n, 0), last = -1;
    sel = first >= 0 ? first : 0; /* start on the first lesson not finished */
    for (;;) {
        for (int i = 0; i < n; i++) {
            int done = sw_progress_get(e[i].file);
            char prog[32];
            if (!e[i].title)
                snprintf(prog, sizeof prog, "(broken)");
            else if (done >= e[i].npages)
                snprintf(prog, sizeof prog, "done \xe2\x9c\x93");
            else
                snprintf(prog, sizeof prog, "%d/%d pages", done, e[i].npages);
            char title[300];
            fit_title(title, sizeof title, e[i].title ? e[i].title : e[i].file, 52);
            snprintf(text[i], sizeof text[i], "%2d. %s %s", i + 1, title, prog);
            sw_escape_message(text[i], sizeof text[i]);
            lines[i] = text[i];
        }
        sw_escape_message(note, sizeof note);
        int chosen = sw_tui_menu("stepwise: numerical integration of particle systems", lines, n, &sel,
                                 note, err, sizeof err);
        note[0] = '\0';
        if (chosen == -3) {
            rc = sw_cli_error("%s", err);
            break;
        }
        if (chosen == -2) {
            rc = sw_signals_status();
            break;
        }
        if (chosen == -1) {
            say_how_to_continue(e, n, last >= 0 && sw_progress_get(e[last].file) < e[last].npages ? last : -1);
            break;
        }
        if (!e[chosen].title) {
            snprintf(note, sizeof note, "cannot open this lesson: %s", e[chosen].error);
            continue;
        }
        char why[SW_LESSON_ERRLEN] = "";
        int done = 0;
        rc = run_lesson(e[chosen].path, -1, why, sizeof why, &done);
        last = chosen;
        if (done >= e[chosen].npages) { /* finished: the cursor moves on to the next one not done */
            int next = sw_progress_next(e, n, chosen + 1);
            sel = next >= 0 ? next : chosen;
        }
        if (why[0]) {
            snprintf(note, sizeof note, "cannot open this lesson: %s", why);
            rc = SW_EXIT_OK;
            continue;
        }
        if (rc != SW_EXIT_OK)
            break;
    }
    free(text);
    free(lines);
    return rc;
}

int sw_cmd_lesson(int argc, char **argv)
{
    static const struct option opts[] = {
        { "check", no_argument, NULL, 'c' }, { "next", no_argument, NULL, 'n' },
        { "help", no_argument, NULL, 'h' }, { NULL, 0, NULL, 0 },
    };
    int check = 0, next = 0;
    optind = 1;
    opterr = 0;
    for (int c; (c = getopt_long(argc, argv, "h", opts, NULL)) != -1;) {
        if (c == 'c')
            check = 1;
        else if (c == 'n')
            next = 1;
        else if (c == 'h') {
            fputs(lesson_help, stdout);
            return SW_EXIT_OK;
        } else
            return sw_cli_error("lesson: unknown option '%s'; see 'stepwise lesson --help'", argv[optind - 1]);
    }
    if (check) {
        if (optind >= argc)
            return sw_cli_error("lesson --check needs at least one lesson file");
        return sw_cmd_lesson_check(argc - optind, argv + optind);
    }
    if (argc - optind > 1)
        return sw_cli_error("lesson takes one lesson name or number; see 'stepwise list lessons'");
    if (next && optind < argc)
        return sw_cli_error("lesson --next takes no lesson name or number: it picks the next unfinished one");
    const char *dir = sw_cli_lessons_dir();
    sw_lesson_entry *e;
    int n;
    char err[SW_LESSON_ERRLEN];
    if (sw_lesson_list(dir, &e, &n, err, sizeof err) != SW_OK)
        return sw_cli_error("%s (set STEPWISE_LESSONS to the lessons directory)", err);
    if (n == 0) {
        sw_lesson_list_free(e, n);
        return sw_cli_error("no lessons in %s (set STEPWISE_LESSONS to the lessons directory)", dir);
    }
    int rc, k = -1;
    char why[SW_ERRLEN];
    if (optind < argc && (k = find_lesson(e, n, argv[optind])) < 0)
        rc = sw_cli_error("no lesson '%.60s' in %s; choose 1..%d or a name from 'stepwise list lessons'",
                          argv[optind], dir, n);
    else if (k >= 0 && !e[k].title)
        rc = sw_cli_error("%s", e[k].error);
    else if (sw_progress_check(why, sizeof why) != SW_OK)
        rc = sw_cli_error("%s; progress could not be saved (set XDG_STATE_HOME to a writable directory)", why);
    else {
        if (next) /* the first unfinished lesson; every one finished: the menu */
            k = sw_progress_next(e, n, 0);
        char unreadable[SW_ERRLEN + 400];
        if (sw_progress_readable(unreadable, sizeof unreadable) != SW_OK)
            sw_cli_note("warning: %s; lessons start from their first page and progress is not "
                        "saved over it", unreadable);
        if (!isatty(STDOUT_FILENO) || !isatty(STDIN_FILENO))
            rc = sw_cli_error("lessons need a terminal; to lint lesson files use 'stepwise lesson "
                              "--check FILE...'");
        else
        if (k >= 0) {
            rc = run_lesson(e[k].path, -1, NULL, 0, NULL);
            if (rc == SW_EXIT_OK)
                say_how_to_continue(e, n, k);
        } else
            rc = menu(e, n);
    }
    sw_lesson_list_free(e, n);
    return rc;
}
