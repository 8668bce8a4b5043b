/* A homework: the assignment file as a course uses it. Several parts, each
 * a run of its own (an sw_assignment) under the keys they share, each with
 * a visibility (Gradescope's four); parameters that differ per student,
 * drawn from the student's e-mail and a course secret; which submission
 * counts. A file without parts is one part named "" that is visible, so
 * every assignment written before parts is a homework as it is.
 *
 *     # stepwise assignment 1
 *     # kind: plugin
 *     # secret: any words the students never see
 *     # scene: chain
 *     # param k: 8..12 per student          (values on the ends' decimal grid)
 *     # integrator: rk4
 *     # part chain
 *     # part gyre
 *     # scene: gyre
 *     # param speed: one of 0.5, 1, 2
 *     # visibility: hidden
 *
 * A part's lines replace the shared lines with the same key. */
#ifndef SW_GRADE_HOMEWORK_H
#define SW_GRADE_HOMEWORK_H

#include <stddef.h>
#include <stdio.h>

#include "grade/assignment.h"

#define SW_PARTS_MAX 8
#define SW_PART_NAME_MAX 32
#define SW_VARYING_MAX 16
#define SW_VARYING_LIST_MAX 16
#define SW_HOMEWORK_LINES 512      /* metadata lines an assignment file may have */

typedef enum sw_visibility {
    SW_VIS_VISIBLE = 0, SW_VIS_HIDDEN, SW_VIS_AFTER_DUE_DATE, SW_VIS_AFTER_PUBLISHED
} sw_visibility;

/* Gradescope's word for v: "visible", "hidden", "after_due_date",
 * "after_published". */
const char *sw_visibility_name(sw_visibility v);
/* When a student sees a part of visibility v, in words for a message. */
const char *sw_visibility_words(sw_visibility v);

/* Which of a student's submissions counts: the best-scoring, or the last
 * one handed in ("# count: best" or "latest"; best when not said). */
typedef enum sw_count_rule { SW_COUNT_BEST = 0, SW_COUNT_LATEST } sw_count_rule;

typedef struct sw_part {
    char name[SW_PART_NAME_MAX];   /* "" in a homework without parts */
    sw_visibility visibility;
    long line;                     /* its "# part" line; 0 without parts */
    sw_assignment a;
} sw_part;

/* A parameter drawn per student: "LO..HI per student" (values on the
 * finer of the two ends' decimal grids: 8..12 gives whole numbers, 0.50..2
 * hundredths) or "one of V1, V2, ...". */
typedef struct sw_varying {
    char param[SW_TRACE_NAME_MAX];
    int part;                      /* -1: a shared line, every part */
    long line;
    int nlist;                     /* > 0: a list */
    double list[SW_VARYING_LIST_MAX];
    long long lo, count;           /* a range: lo·10^-digits, count grid values */
    int digits;
    double value;                  /* this student's */
} sw_varying;

/* The words of the examples' '# secret:' line: public, so a homework that
 * keeps them lets anyone draw every student's values (a warning). */
#define SW_EXAMPLE_SECRET "replace these words with your own, and keep them from students"

typedef struct sw_homework {
    char path[SW_TRACE_PATH_MAX];
    char title[128];
    sw_assign_kind kind;
    sw_count_rule rule;
    sw_part parts[SW_PARTS_MAX];
    int nparts;
    sw_varying varying[SW_VARYING_MAX];
    int nvarying;
    char student[128];             /* whose values: an e-mail; "" the teacher's preview */
    double max;                    /* the points of every part together, for the kind asked
                                    * for (a homework of either kind: a trace's) */
    double max_of[2];              /* ... for a trace [0] and for a plugin [1] */
    /* private: the file's metadata lines, as read once */
    char *text;
    long nlines;
    char *line_text[SW_HOMEWORK_LINES];
    int line_part[SW_HOMEWORK_LINES];  /* -1 shared, else the part; -2 not metadata */
    unsigned char secret_set;
    unsigned char secret_public;   /* it is the examples' words (SW_EXAMPLE_SECRET) */
    unsigned long long key[2];     /* from "# secret:" */
} sw_homework;

/* Read an assignment file (or a reference trace) as a homework, with the
 * per-student values of student (an e-mail, folded to lower case; NULL or
 * "" for the teacher's preview: each range's low end, each list's first).
 * 0 or an error "FILE:LINE: what". sw_homework_free after either. */
int sw_homework_read(sw_homework *h, const char *path, const char *student, char *err,
                     size_t errlen);
void sw_homework_free(sw_homework *h);

/* The part a trace is for: the one its file is named after (the base name,
 * or a word of it, e.g. "chain.trace", "hw4-gyre.csv"), else the only
 * part with its scene (and, among several, the one whose parameters it
 * states). -1 when none; why then says what the parts are. */
int sw_homework_part_of_trace(const sw_homework *h, const char *file, const sw_trace_meta *m,
                              char *why, size_t whylen);
/* Whether param (of part) is drawn per student. */
int sw_homework_varies(const sw_homework *h, int part, const char *param);
/* Parts of visibility other than visible. */
int sw_homework_hidden_parts(const sw_homework *h);

/* Write the student's own assignment sheet to f: the file with this
 * student's values in place of the ranges, without the secret, and, for a
 * plugin homework, without the parts that are not visible (a note says
 * how many). A valid assignment for `check` and `try`. */
int sw_homework_write_sheet(const sw_homework *h, FILE *f, const char *who);

/* The key of a student for per-student values: their e-mail, trimmed and
 * in lower case, into out. */
void sw_homework_student_key(const char *email, char *out, size_t outlen);

#endif
