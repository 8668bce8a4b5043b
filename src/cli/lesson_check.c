/* The lesson linter: parses each file against the real catalog and reports
 * one line per file. Only this front end prints; the parser fills a buffer. */
#include "cli/lesson_check.h"

#include <stdarg.h>
#include <stdio.h>
#include <sys/stat.h>

#include "cli/cli.h"
#include "lesson/lesson.h"
#include "util/escape.h"

/* One line on stream: file names come from the command line or a
 * directory and may hold any byte, so the line is escaped whole. */
static void say(FILE *stream, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void say(FILE *stream, const char *fmt, ...)
{
    char line[SW_LESSON_ERRLEN + 600];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(line, sizeof line, fmt, ap);
    va_end(ap);
    sw_escape_message(line, sizeof line);
    fprintf(stream, "%s\n", line);
}

static int check_one(const char *path)
{
    sw_lesson lesson;
    char err[SW_LESSON_ERRLEN];
    if (sw_lesson_load(path, &lesson, err, sizeof err) != SW_OK) {
        say(stderr, "%s", err);
        return SW_EXIT_USAGE;
    }
    say(stdout, "%s: ok (%d page%s)", path, lesson.npages, lesson.npages == 1 ? "" : "s");
    sw_lesson_free(&lesson);
    return SW_EXIT_OK;
}

static int check_dir(const char *dir)
{
    sw_lesson_entry *list;
    int n;
    char err[SW_LESSON_ERRLEN];
    if (sw_lesson_list(dir, &list, &n, err, sizeof err) != SW_OK) {
        say(stderr, "%s", err);
        return SW_EXIT_USAGE;
    }
    int rc = SW_EXIT_OK;
    if (n == 0) {
        say(stderr, "%s: no *.lesson files in this directory", dir);
        rc = SW_EXIT_USAGE;
    }
    for (int i = 0; i < n; i++) {
        if (list[i].title) {
            say(stdout, "%s: ok (%d page%s)", list[i].path, list[i].npages, list[i].npages == 1 ? "" : "s");
        } else {
            say(stderr, "%s", list[i].error);
            rc = SW_EXIT_USAGE;
        }
    }
    sw_lesson_list_free(list, n);
    return rc;
}

int sw_cmd_lesson_check(int nfiles, char **files)
{
    if (nfiles < 1)
        return sw_cli_error("lesson --check needs FILE...: the lesson files (or directories of "
                            "*.lesson files) to check");
    int rc = SW_EXIT_OK;
    for (int i = 0; i < nfiles; i++) {
        struct stat st;
        int one = stat(files[i], &st) == 0 && S_ISDIR(st.st_mode) ? check_dir(files[i]) : check_one(files[i]);
        if (one != SW_EXIT_OK)
            rc = one;
    }
    fflush(stdout);
    return rc;
}
