/* Private to `stepwise grade`: the submissions and their verdicts, and the
 * reports (table, CSV gradebook, Gradescope results.json). */
#ifndef SW_CLI_GRADE_H
#define SW_CLI_GRADE_H

#include <stdint.h>
#include <stdio.h>
#include <sys/types.h>

#include "grade/assignment.h"
#include "grade/homework.h"
#include "grade/points.h"
#include "grade/roster.h"
#include "grade/verdict.h"
#include "plugin/sandbox.h"
#include "trace/trace.h"

/* A row of a failing trace, for --similarity: its number and a digest of
 * its values. */
typedef struct grade_wrong_row {
    int64_t row;
    uint64_t hash;
} grade_wrong_row;

typedef struct grade_entry {
    char *path;
    char *rel;                           /* what the roster matches: the path below the
                                          * directory named, or the file as named */
    int plugin;
    int status;                          /* 0 pass, 1 fail, 2 error, GRADE_SKIPPED, GRADE_MISSING */
    long failing_step;                   /* -1: none */
    char student[SW_TRACE_STUDENT_MAX];  /* "# student:", else the file's base name */
    int who;                             /* --roster: the student, or SW_ROSTER_NONE/AMBIGUOUS */
    char owner[SW_TRACE_STUDENT_MAX];    /* --roster: who's name; "" when none */
    char owner_id[80];                   /* --roster: who's first id */
    char remarks[700];                   /* --roster: a claim not believed, no match */
    char similar[600];                   /* --similarity: the pairs this entry is in */
    grade_wrong_row *wrong;              /* --similarity, a failing trace: its rows from the
                                          * first failing step on */
    int nwrong;
    char notes[SW_TRACE_NOTES_MAX];
    char kind[24];                       /* the mistake's kind, when named */
    char message[1200];
    char *report;                        /* the plain report, or NULL */
    double seconds;
    sw_score score;                      /* the assignment's points, check by check */
    int part;                            /* a trace: the part it is for; -1 every part */
    long long mtime;                     /* the file's modification time (the "latest" rule) */
    int own_folder;                      /* a source in a folder of its student's alone: its
                                          * headers go with it (grade_mark_own_folders) */
} grade_entry;

/* The verdict of an entry that was not graded (not a submission, a link, a
 * FIFO, ...): counted everywhere with score 0, its reason in message. */
#define GRADE_SKIPPED 3
/* The verdict of a submission that ran out of a limit (CPU time, the wall
 * clock, a plugin's step time): not a wrong answer, scored 0. */
#define GRADE_LIMIT 4
/* The row of a roster student no submission matched (path ""). */
#define GRADE_MISSING 5

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
    /* What the options asked for (grade.c fills these before collecting). */
    sw_roster *roster;                   /* --roster (folders are then walked), or NULL */
    char *gs_metadata;                   /* a submission_metadata.yml found among them */
    int fresh;                           /* --fresh: an existing gradebook is replaced */
    const char *feedback;                /* --feedback DIR, or NULL */
    struct sw_csv_doc *old_book;         /* the --csv gradebook read back, or NULL */
    int similarity;                      /* --similarity */
    char similar_summary[200];           /* e.g. "2 similar pairs" for the summary */
    const sw_homework *hw;               /* the homework, with the teacher's preview values */
    char student_email[128];             /* --submission-metadata: whose submission this is */
    char *similar_table;                 /* the pairs, in words, printed after the rows */
} grade_list;

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
int grade_check_outputs(const grade_list *l, const struct stat *assign_st, const char *const *opts,
                        const char *const *paths, int n);
void grade_list_free(grade_list *l);
/* The table's heading, then one row per graded submission (on stdout, or
 * stderr when a report goes to stdout; names escaped). */
void grade_print_head(const sw_homework *h, const grade_list *l);
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
int grade_write_gradescope(const grade_list *l, const sw_homework *h, const char *path,
                           double seconds, int jailed);
/* Remove dir and all that grading built in it (n: the submissions). */
void grade_clean_dir(const char *dir, int n);
/* The submissions directory that the resolved directory real is in or
 * under, or NULL (grade_out.c). */
const char *grade_inside_submissions(const grade_list *l, const char *real);
/* The student a row is about: the roster's name, else "# student:", else
 * the file's name without directory and extension. */
void grade_student_of(const grade_entry *e, char *buf, size_t len);
/* text as every report to a student or a teacher shows it: each line
 * through the message rule (util/escape.h; a file's name, a "# student:"
 * line or a report may hold controls, escape sequences or bidirectional
 * overrides), its newlines kept. Caller frees; NULL when out of memory. */
char *grade_text_shown(const char *text);
const char *grade_verdict_word(int status);
/* A row's points and their maximum, as every report counts them: the
 * checks it was scored on, else 0 of the homework's points. */
void grade_points_of(const grade_list *l, const grade_entry *e, double *score, double *max);

/* --roster (grade_roster.c): read the roster (and Gradescope's metadata
 * when the submissions hold it), match every row to a student, check each
 * graded file's "# student:" line, add a row for every student nobody's
 * submission matched. Each returns SW_EXIT_OK or SW_EXIT_USAGE, printed. */
int grade_roster_load(grade_list *l, const char *path);
void grade_roster_claim(const grade_list *l, grade_entry *e);
int grade_roster_missing(grade_list *l);
/* Gradescope's submission_metadata.json: its first user's e-mail into
 * l->student_email. SW_EXIT_OK or SW_EXIT_USAGE, printed. */
int grade_read_submission_metadata(grade_list *l, const char *path);
/* Whose values a submission is graded with: --submission-metadata's
 * student, else its roster student's e-mail, else "". */
const char *grade_student_key(const grade_list *l, const grade_entry *e);
/* A homework with per-student values needs to know each student's e-mail:
 * from --submission-metadata, or a --roster with an email column. */
int grade_student_keys_check(const grade_list *l);

/* The counted submissions of one student (grade_count.c): per part, the
 * entry whose checks count (best score, or the latest file, by the
 * homework's rule), among entries of the kind it asks for; -1 none. */
typedef struct grade_counted {
    int entry[SW_PARTS_MAX];
    double score, max;                   /* the sum over parts; max the homework's */
    int status;                          /* pass when every part's counted entry passed */
    int close_times;                     /* count: latest, and a file that scored otherwise was
                                          * modified within GRADE_CLOSE_SECONDS of the counted
                                          * one: which is later is a guess (copied files) */
} grade_counted;
#define GRADE_CLOSE_SECONDS 2
void grade_count(const grade_list *l, const int *entries, int n, grade_counted *out);
/* --gradebook and --lms (grade_students.c): one row per student. */
int grade_students_write(const grade_list *l, const char *gradebook, const char *lms);

/* --csv over an existing gradebook (grade_book.c): read it back before
 * grading (refused unless its columns are this version's or a prefix of
 * them) and, when writing, keep its rows but those regraded. */
int grade_book_load(grade_list *l, const char *csv);
void grade_book_write(FILE *f, const grade_list *l, char *said, size_t saidlen);
/* Whether the gradebook read back has a row of the student named name. */
int grade_book_has_student(const grade_list *l, const char *name);

/* --similarity (grade_similar.c): compare the graded plugin sources and
 * traces; fill each entry's similar and the list's table of pairs. */
int grade_similar_run(grade_list *l);

/* --feedback DIR (grade_feedback.c): check DIR before grading; write one
 * report per student at the end, each whole. */
int grade_feedback_check(const grade_list *l, const char *dir);
int grade_feedback_write(const grade_list *l, const char *dir);
/* A student's name as a file name: letters, digits, '.', '-', '_', its
 * Latin letters folded as the roster folds them (Poincaré: Poincare). */
void grade_safe_name(const char *name, char *out, size_t len);
/* names[n] = base, or base-2, base-3, ... when names[0..n) has it (in any
 * case): one file each for students whose names fold alike. */
void grade_name_unique(char (*names)[112], int n, const char *base);

/* What a submission's child sends back: this, then report_len bytes, then
 * nwrong grade_wrong_row (--similarity). */
typedef struct grade_record {
    int status;
    long failing_step;
    char student[SW_TRACE_STUDENT_MAX];
    char notes[SW_TRACE_NOTES_MAX];
    char kind[24];
    char message[1200];
    sw_score score;
    int part;                /* a trace's part; -1 a plugin's, every part */
    unsigned report_len;
    unsigned nwrong;
} grade_record;

typedef struct grade_job {
    const char *path;
    int plugin;
    const char *build_dir;
    int index;
    const sw_check_request *base;
    size_t report_max;
    grade_list *list;        /* the class so far: wiped in the worker */
    int similarity;          /* send a failing trace's wrong rows */
    const sw_limits *lim;    /* the submission's: this worker and its plugin's processes together */
    int argc;                /* the command's arguments (argv[0] "grade"), from which a plugin's */
    char **argv;             /* worker starts again as a new program; NULL: it is that program */
    const sw_homework *hw;   /* the homework, with the teacher's preview values */
    const char *student_key; /* whose values this submission is graded with ("" unknown) */
    int own_folder;          /* the entry's own_folder */
} grade_job;

/* `stepwise grade --worker INDEX BUILD_DIR PATH SIMILARITY OWN_FOLDER STUDENT ARGS...`: the
 * worker of one plugin, as a new program (grade_worker.c starts it): so
 * that nothing of the class the grader had read (roster, gradebook, the
 * other submissions, in live or in freed memory) is in the process the
 * plugin runs from. ARGS are the grade command's own. */
#define GRADE_WORKER_FLAG "--worker"

/* A header's row: built with the sources beside it, or not (a folder of
 * several students' sources; grade_mark_own_folders may find it is one
 * student's after all). */
#define GRADE_HEADER_BUILT "not graded on its own: a header, built with the .c beside it (a source and its " \
                           "headers are one submission)"
#define GRADE_HEADER_SHARED "not a submission: a .h file, and not built with a .c either: its folder holds "

/* Mark each plugin source whose folder holds no other student's source:
 * in Gradescope's one submission (one_student) every one; else where the
 * roster matched it and every other source beside it to one student (an
 * LMS download's folder). Without a roster a folder's files are the
 * students' own by name, so a folder of two sources is shared. A header
 * beside a source so marked is built with it (its row says so). */
void grade_mark_own_folders(grade_list *l, int one_student);
/* Whether e is a plugin's C source (a .c, not a .so). */
int grade_is_source(const grade_entry *e);

/* Those arguments after GRADE_WORKER_FLAG (start_clean in grade_worker.c
 * writes them). */
typedef struct grade_worker_args {
    const char *build, *path, *student; /* path NULL: not a worker */
    int index, similarity, own_folder;
} grade_worker_args;

/* grade_worker.c: the worker's arguments taken off the front of *argc,
 * *argv into w when the command is a worker's (w->path NULL when not);
 * SW_EXIT_OK, or SW_EXIT_USAGE with the error printed where the flag is
 * there but the command is not grade's own start of a worker. */
int grade_worker_mode(int *argc, char ***argv, grade_worker_args *w);

/* grade_worker.c: a submission's worker, the child that checks it (an
 * sw_child_fn, ctx a grade_job) and sends back a grade_record. */
int grade_worker(void *ctx, int in, int out);
/* Every check of the assignment at 0 points, for a submission that could
 * not be checked, with why. */
void grade_zero_score(sw_score *s, const sw_homework *h, int plugin, const char *why);

/* The grader's CPU budget for one submission's worker (its own work:
 * the reference, the comparison, the measurements, the explainer), from
 * the submission's --cpu, as its measuring runs' host gets it
 * (plugin.h, via verdict.h); and the default wall-clock guard. */
#define GRADE_WORKER_CPU(cpu) SW_GRADER_CPU(cpu)
#define GRADE_WALL(cpu) (4 * (cpu) + 20)

#endif
