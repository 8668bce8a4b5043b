/* The lesson linter: parses each file against the real catalog and reports
 * one line per file. Only this front end prints; the parser fills a buffer. */
#include "cli/lesson_check.h"

#include <stdio.h>
#include <sys/stat.h>

#include "cli/cli.h"
#include "lesson/lesson.h"

static int check_one(const char *path)
{
    sw_lesson lesson;
    char err[SW_LESSON_ERRLEN];
    if (sw_lesson_load(path, &lesson, err, sizeof err) != SW_OK) {
        fprintf(stderr, "%s\n", err);
        return SW_EXIT_USAGE;
    }
    printf("%s: ok (%d page%s)\n", path, lesson.npages, lesson.npages == 1 ? "" : "s");
    sw_lesson_free(&lesson);
    return SW_EXIT_OK;
}

static int check_dir(const char *dir)
{
    sw_lesson_entry *list;
    int n;
    char err[SW_LESSON_ERRLEN];
    if (sw_lesson_list(dir, &list, &n, err, sizeof err) != SW_OK) {
        fprintf(stderr, "%s\n", err);
        return SW_EXIT_USAGE;
    }
    int rc = SW_EXIT_OK;
    if (n == 0) {
        fprintf(stderr, "%s: no *.lesson files in this directory\n", dir);
        rc = SW_EXIT_USAGE;
    }
    for (int i = 0; i < n; i++) {
        if (list[i].title) {
            printf("%s: ok (%d page%s)\n", list[i].path, list[i].npages, list[i].npages == 1 ? "" : "s");
        } else {
            fprintf(stderr, "%s\n", list[i].error);
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
