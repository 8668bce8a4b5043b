/* Private to `stepwise grade`: the submissions and their verdicts, and the
 * reports (table, CSV gradebook, Gradescope results.json). */
#ifndef SW_CLI_GRADE_H
#define SW_CLI_GRADE_H

#include <sys/types.h>

#include "grade/assignment.h"
#include "grade/points.h"
#include "plugin/sandbox.h"
#include "trace/trace.h"

typedef struct grade_entry {
    char *path;
    int plugin;
    int status;                          /* 0 pass, 1 fail, 2 error, GRADE_SKIPPED */
    long failing_step;                   /* -1: none */
    char student[SW_TRACE_STUDENT_MAX];  /* "# student:", else the file's base name */
    char notes[SW_TRACE_NOTES_MAX];
    char kind[24];                       /* the mistake's kind, when named */
    char message[1200];
    char *report;                        /* the plain report, or NULL */
    double seconds;
    sw_score score;                      /* the assignment's points, check by check */
} grade_entry;

/* The verdict of an entry that was not graded (not a submission, a link, a
 * FIFO, ...): counted everywhere with score 0, its reason in message. */
#define GRADE_SKIPPED 3
/* The verdict of a submission that ran out of a limit (CPU time, the wall
 * clock, a plugin's step time): not a wrong answer, scored 0. */
#define GRADE_LIMIT 4

/* A file or directory named for grading, by identity (grade_collect.c), so
 * no output can be written over or among the submissions. */
typedef struct grade_place {
    dev_t dev;
    ino_t ino;
    char *real;                          /* a directory's resolved path; NULL for a file */
} grade_place;

typedef struct grade_list {
    grade_entry *items;
    int n, cap;
    int ignored;                         /* entries not graded: refused[0..ignored) */
    grade_entry *refused;                /* each with status GRADE_SKIPPED and its reason */
    int refused_cap;
    grade_place *places;                 /* every submission, refused entry and directory */
    int nplaces, places_cap;
} grade_list;

int grade_list_add(grade_list *l, const char *path, int plugin);
/* Add the submission FILE, or every entry of the directory DIR (sorted by
 * path): regular files named .trace, .csv, .so or .c to grade; anything
 * else (a link, a FIFO, a device, a subdirectory, a hidden or unknown file,
 * the assignment itself) to refused, with its reason. SW_EXIT_OK, or
 * SW_EXIT_USAGE with the error printed (grade_collect.c). */
struct stat;
int grade_collect(grade_list *list, const char *arg, const struct stat *assign_st);
/* Check the --csv and --results paths before any grading: writable, not
 * the assignment, a submission or a file among them; standard output sends
 * the table to stderr. SW_EXIT_OK, or SW_EXIT_USAGE with one line printed. */
int grade_check_outputs(const grade_list *l, const struct stat *assign_st, const char *csv,
                        const char *results);
void grade_list_free(grade_list *l);
/* The table's heading, then one row per graded submission (on stdout, or
 * stderr when a report goes to stdout; names escaped). */
void grade_print_head(const sw_assignment *a, int n, int ignored);
void grade_print_row(grade_entry *e);
/* The entries not graded, the totals; the CSV gradebook and results.json
 * when asked (each written whole through a temporary file renamed into
 * place, or straight to stdout, a pipe or a device). Returns the exit status. */
int grade_finish(const grade_list *l, const sw_limits *lim, double wall, double seconds,
                 const char *csv, const char *results);
/* Gradescope's results.json for one submission (its container's): the
 * checks of each graded file as tests, the best file's total as the score,
 * whole or not at all. jailed says how plugins ran. SW_EXIT_OK or
 * SW_EXIT_USAGE (grade_gs.c). */
int grade_write_gradescope(const grade_list *l, const sw_assignment *a, const char *path,
                           double seconds, int jailed);
/* Remove dir and all that grading built in it (n: the submissions). */
void grade_clean_dir(const char *dir, int n);

#endif
