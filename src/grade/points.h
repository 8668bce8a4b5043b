/* Partial credit: the checks an assignment gives points for ("# points
 * header: 1", "# points x* y*: 3", "# points energy: 1", "# points order:
 * 1") and a submission's score on each, with the words that say why. A
 * check scores all its points or none, or for columns the points of the
 * closest tier it reaches; the score is the sum. */
#ifndef SW_GRADE_POINTS_H
#define SW_GRADE_POINTS_H

#include <stddef.h>
#include <stdio.h>

#include "grade/check.h"
#include "trace/trace.h"

/* A measured order is the method's when within this of it (the order
 * point; and the stability limit, measured on the spring, is measured only
 * for a plugin whose order on its graded run is the method's). */
#define SW_POINTS_ORDER_MARGIN 0.5
/* A stability limit counts as the method's within this fraction of it. */
#define SW_POINTS_STABILITY_MARGIN 0.05

#define SW_POINTS_MAX 12
#define SW_POINTS_LIMIT 1000.0    /* the most one check may give */

typedef enum sw_points_kind {
    SW_POINTS_HEADER = 1,         /* the header states the assignment's run */
    SW_POINTS_COLUMNS,            /* every value of these columns within tolerance */
    SW_POINTS_ORDER,              /* a plugin's measured order is the method's */
    SW_POINTS_STABILITY           /* a plugin's measured stability limit is the method's */
} sw_points_kind;

/* Graded closeness: at most this many tiers on a columns line. */
#define SW_TIERS_MAX 4

/* One "# points WHAT: N" line; a columns line may give tiers instead,
 * "N1 within T1, N2 within T2, ...": N1 points when every value of the
 * columns is within T1 (|got - expected| <= T1 + T1·|expected|), else N2
 * within T2, and so on (tolerances widening, points not growing). */
typedef struct sw_points {
    sw_points_kind kind;
    char what[48];                /* "header", "x* y*", "energy", "order", "stability" */
    double points;                /* the most it gives (the first tier's) */
    long line;                    /* the assignment's line; 0 for the defaults */
    int ntiers;                   /* 0: all or nothing at the assignment's tolerance */
    double tier_points[SW_TIERS_MAX], tier_within[SW_TIERS_MAX];
} sw_points;

typedef struct sw_points_set {
    sw_points items[SW_POINTS_MAX];
    int n;
} sw_points_set;

/* Parse "# points WHAT: VALUE" (what without the "points " prefix) into
 * set; where ("FILE:LINE") names it in errors. WHAT is header, order,
 * stability, or column names and prefixes ending in '*' separated by
 * spaces; VALUE a number in [0, SW_POINTS_LIMIT], or for columns tiers
 * "N within T, ..." (T in (0, 1]). 0 or SW_EINVAL. */
int sw_points_parse(sw_points_set *set, const char *what, const char *value, long line,
                    const char *where, char *err, size_t errlen);
/* Every group's columns exist in sys and no column is in two groups; an
 * empty set becomes the defaults (header 1, every column 1). 0 or
 * SW_EINVAL with err naming the line. */
int sw_points_resolve(sw_points_set *set, const sw_system *sys, const char *path, char *err,
                      size_t errlen);
/* Whether column name c of the group p (SW_POINTS_COLUMNS) is one of its. */
int sw_points_has_column(const sw_points *p, const char *column);

/* The checks of a submission over every part of a homework. */
#define SW_SCORE_CHECKS 32

/* One check's result, as Gradescope lists a test. */
typedef struct sw_score_check {
    char name[64];                /* "header"; "gyre: order" in a homework of parts */
    double score, max;
    char output[600];             /* why, in the explainer's words */
    int visibility;               /* the part's (grade/homework.h, sw_visibility) */
    int part;                     /* the part's index */
} sw_score_check;

typedef struct sw_score {
    sw_score_check checks[SW_SCORE_CHECKS];
    int n;
    double score, max;
} sw_score;

/* What the scorer knows of a check that ran (the verdict's facts). */
typedef struct sw_score_facts {
    int is_plugin;
    int usable;                   /* 0: the file could not be checked (error) */
    const char *error;            /* why, when not usable */
    int ndiffs;                   /* header differences */
    const char *header_words;     /* them in words */
    int comparable;               /* the numbers were compared */
    const char *fault;            /* a plugin failure on either side, or NULL */
    int fault_is_limit;
    int rows_differ;              /* missing or extra rows */
    const char *rows_words;
    const sw_system *sys;         /* the columns */
    const long *col_failed;       /* ncols failures per column */
    const sw_check_cell *col_first; /* ncols: the first failure of each column */
    const double *col_worst;      /* ncols, or NULL: each column's largest |got - expected| / (1 + |expected|) */
    const char *explanation;      /* the explainer's sentence, or NULL */
    double order, expected_order; /* NaN: not measured */
    double stability, expected_stability;
    int stability_decided;        /* the stability point decided without a figure (the note says */
    int stability_given;          /* how), and whether it is given */
    const char *measure_note;
} sw_score_facts;

/* Score the facts f on the checks of set into s. */
void sw_points_score(const sw_points_set *set, const sw_score_facts *f, sw_score *s);
/* Add the checks of part to into, each named "PART: check" (part "" keeps
 * the names) with the part's visibility; the sums too. Checks beyond
 * SW_SCORE_CHECKS are dropped (a homework is read with at most that many). */
void sw_score_append(sw_score *into, const sw_score *part, const char *name, int visibility,
                     int index);
/* s as a student reads it: "points: G of M" and TAIL after indent, then a
 * line a check, two spaces further in ("order: 1 of 2"), with why where it
 * lost some (a reason said just before is "the same"). Nothing when s has
 * no checks. */
void sw_score_print(FILE *f, const sw_score *s, const char *indent, const char *tail);

#endif
