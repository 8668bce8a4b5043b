/* Private to `stepwise grade`: the submissions and their verdicts, and the
 * reports (table, CSV gradebook, Gradescope results.json). */
#ifndef SW_CLI_GRADE_H
#define SW_CLI_GRADE_H

#include "grade/assignment.h"
#include "plugin/sandbox.h"
#include "trace/trace.h"

typedef struct grade_entry {
    char *path;
    int plugin;
    int status;                          /* 0 pass, 1 fail, 2 error */
    long failing_step;                   /* -1: none */
    char student[SW_TRACE_STUDENT_MAX];  /* "# student:", else the file's base name */
    char notes[SW_TRACE_NOTES_MAX];
    char kind[24];                       /* the mistake's kind, when named */
    char message[1200];
    char *report;                        /* the plain report, or NULL */
    double seconds;
} grade_entry;

typedef struct grade_list {
    grade_entry *items;
    int n, cap;
    int ignored;                         /* files in a directory that are no submission */
} grade_list;

int grade_list_add(grade_list *l, const char *path, int plugin);
/* Add the submission FILE, or the submissions in the directory DIR (sorted
 * by path; the file assign_st describes left out). SW_EXIT_OK, or
 * SW_EXIT_USAGE with the error printed (grade_collect.c). */
struct stat;
int grade_collect(grade_list *list, const char *arg, const struct stat *assign_st);
void grade_list_free(grade_list *l);
/* The table's heading, then one row per graded submission. */
void grade_print_head(const sw_assignment *a, int n, int ignored);
void grade_print_row(grade_entry *e);
/* The totals; the CSV gradebook and results.json when asked (each written
 * whole through a temporary file). Returns the exit status. */
int grade_finish(const grade_list *l, const sw_limits *lim, double wall, double seconds,
                 const char *csv, const char *results);
/* Remove what grading built in dir (sN.so, sN.log for N < n), then dir. */
void grade_clean_dir(const char *dir, int n);

#endif
