/* `stepwise lesson`: the menu of lessons with each one's progress, a lesson
 * run live beside its scene, and `--check` for teachers (no terminal). */
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "app/runner.h"
#include "cli/cli.h"
#include "cli/lesson_check.h"
#include "tui/play.h"
#include "tui/term.h"

static const char lesson_help[] =
    "usage: stepwise lesson [NAME|N]\n"
    "       stepwise lesson --check FILE...\n\n"
    "With no argument, opens the menu of lessons with your progress; NAME (a file\n"
    "name without .lesson, e.g. 02-euler) or N (its place in the menu) opens one,\n"
    "resuming where you left off. --check lints lesson files without a terminal:\n"
    "exit 0 when all are valid, 2 with FILE:LINE:COL: messages otherwise.\n"
    "Lessons are read from $STEPWISE_LESSONS, else the installed lessons directory.\n"
    "Progress is kept in $XDG_STATE_HOME/stepwise/progress (~/.local/state/...).\n";

static int lesson_key(void *ctx, sw_app *a, int key) { return sw_runner_key(ctx, a, key); }

static const sw_side *lesson_side(void *ctx, sw_app *a, int cols)
{
    sw_runner_update(ctx, a);
    return sw_runner_side(ctx, a, cols);
}

static int run_lesson(const char *path, int page)
{
    sw_runner *r = malloc(sizeof *r);
    sw_app a;
    char err[SW_LESSON_ERRLEN];
    if (!r)
        return sw_cli_error("out of memory");
    if (sw_runner_start(r, &a, path, page, err, sizeof err) != SW_OK) {
        free(r);
        return sw_cli_error("%s", err);
    }
    sw_play_hooks hooks = { .ctx = r, .key = lesson_key, .side = lesson_side };
    int rc = sw_play_loop(&a, &hooks);
    sw_app_free(&a);
    sw_runner_free(r);
    free(r);
    return rc;
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

/* The menu, drawn straight onto a screen grid: arrows or digits, Enter opens. */
static int menu(sw_lesson_entry *e, int n)
{
    char err[SW_ERRLEN];
    int sel = 0;
    for (int i = 0; i < n; i++)
        if (sw_progress_get(e[i].file) < e[i].npages) {
            sel = i; /* start on the first lesson not finished */
            break;
        }
    for (;;) {
        if (sw_term_start(err, sizeof err) != SW_OK)
            return sw_cli_error("%s", err);
        int cols, rows, chosen = -1;
        sw_screen scr = { 0 };
        while (chosen < 0 && !sw_term_signal) {
            sw_term_size(&cols, &rows);
            if (scr.cols != cols || scr.rows != rows) {
                sw_screen_free(&scr);
                if (sw_screen_init(&scr, cols < 1 ? 1 : cols, rows < 1 ? 1 : rows, err, sizeof err) != SW_OK)
                    return sw_cli_error("%s", err);
            }
            sw_screen_clear(&scr);
            sw_screen_text(&scr, 0, 2, cols - 2, SW_STYLE_TITLE, "stepwise: numerical integration of particle systems");
            sw_screen_text(&scr, 1, 2, cols - 2, SW_STYLE_DIM, "Up/Down or a number to choose, Enter to open, q to quit");
            for (int i = 0; i < n && 3 + i < rows - 1; i++) {
                char line[400];
                int done = sw_progress_get(e[i].file);
                char prog[32];
                if (!e[i].title)
                    snprintf(prog, sizeof prog, "(broken)");
                else if (done >= e[i].npages)
                    snprintf(prog, sizeof prog, "done \xe2\x9c\x93");
                else
                    snprintf(prog, sizeof prog, "%d/%d pages", done, e[i].npages);
                snprintf(line, sizeof line, "%s %2d. %-52.52s %s", i == sel ? ">" : " ", i + 1,
                         e[i].title ? e[i].title : e[i].file, prog);
                sw_screen_text(&scr, 3 + i, 2, cols - 2, i == sel ? SW_STYLE_MAIN : SW_STYLE_TEXT, line);
            }
            sw_term_paint(&scr);
            int key = sw_term_key(500);
            if (key == 'q' || key == SW_KEY_ESC) {
                sw_screen_free(&scr);
                sw_term_stop();
                return SW_EXIT_OK;
            }
            if (key == SW_KEY_UP && sel > 0)
                sel--;
            else if (key == SW_KEY_DOWN && sel + 1 < n)
                sel++;
            else if (key >= '1' && key <= '9' && key - '1' < n)
                sel = key - '1';
            else if (key == '\r' || key == '\n' || key == SW_KEY_RIGHT)
                chosen = sel;
        }
        sw_screen_free(&scr);
        if (sw_term_signal) {
            sw_term_stop();
            return sw_term_signal_status();
        }
        if (!e[chosen].title) {
            sw_term_stop();
            return sw_cli_error("%s", e[chosen].error);
        }
        int rc = run_lesson(e[chosen].path, -1);
        if (rc != SW_EXIT_OK)
            return rc;
    }
}

int sw_cmd_lesson(int argc, char **argv)
{
    static const struct option opts[] = {
        { "check", no_argument, NULL, 'c' }, { "help", no_argument, NULL, 'h' }, { NULL, 0, NULL, 0 },
    };
    int check = 0;
    optind = 1;
    opterr = 0;
    for (int c; (c = getopt_long(argc, argv, "h", opts, NULL)) != -1;) {
        if (c == 'c')
            check = 1;
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
    if (optind < argc && (k = find_lesson(e, n, argv[optind])) < 0)
        rc = sw_cli_error("no lesson '%.60s' in %s; choose 1..%d or a name from 'stepwise list lessons'",
                          argv[optind], dir, n);
    else if (k >= 0 && !e[k].title)
        rc = sw_cli_error("%s", e[k].error);
    else if (!isatty(STDOUT_FILENO) || !isatty(STDIN_FILENO))
        rc = sw_cli_error("lessons need a terminal; to lint lesson files use 'stepwise lesson --check FILE...'");
    else
        rc = k >= 0 ? run_lesson(e[k].path, -1) : menu(e, n);
    sw_lesson_list_free(e, n);
    return rc;
}
