/* Trace checking for homework: compare a trace (or a run) with a reference,
 * row by row and column by column, numdiff-style: a value passes when
 * |got - expected| <= atol + rtol·|expected|. Rows come from a file or from
 * a running sim, streamed; nothing holds a whole trace. */
#ifndef SW_GRADE_CHECK_H
#define SW_GRADE_CHECK_H

#include <stddef.h>

#include "trace/trace.h"

/* Default tolerances (measured; see docs/trace-format.md, "Tolerances"). */
#define SW_CHECK_RTOL 1e-9
#define SW_CHECK_ATOL 1e-9

/* Where rows come from: a trace file (reader, header already read) or a run
 * (sim at step 0, recorded by spec). */
typedef struct sw_row_source {
    sw_trace_reader *reader;
    sw_sim *sim;
    sw_trace_spec spec;
    int started;
} sw_row_source;

/* Next row into row (ncols values): 1, 0 at the end, or a negative status
 * with err filled. *line is the file line of the row (0 for a run). */
int sw_row_next(sw_row_source *src, double *row, long *line, char *err, size_t errlen);

/* Whether got matches expected: equal non-finite values (NaN and NaN, inf
 * and inf of one sign) pass; a finite value never matches a non-finite one.
 * Fills the absolute error, the relative error |got - expected| / max(|expected|,
 * atol/rtol) (relative to the value, or near zero to the scale below which
 * atol dominates, so it stays meaningful where values cross zero; when rtol
 * is 0 it is relative to |expected|), and the ratio to the tolerance
 * (<= 1 passes); any of them may be infinite. */
int sw_check_value(double expected, double got, double rtol, double atol,
                   double *abs_err, double *rel_err, double *ratio);

typedef enum sw_check_kind {
    SW_CHECK_VALUE = 1,    /* a value outside the tolerance */
    SW_CHECK_MISSING,      /* the trace ends before the reference */
    SW_CHECK_EXTRA         /* the trace goes on after the reference ends */
} sw_check_kind;

/* One compared value (or, for MISSING / EXTRA, the first row concerned). */
typedef struct sw_check_cell {
    sw_check_kind kind;
    long line;             /* line in the checked trace; 0 when it is a run */
    long step;
    double t;
    int column;            /* column index; -1 for MISSING / EXTRA */
    double expected, got;
    double abs_err, rel_err, ratio;
} sw_check_cell;

/* Tolerances per column: column c passes |got - expected| <= atol[c] +
 * rtol[c]·|expected|; ignore[c] non-zero leaves it out. NULL arrays mean the
 * defaults for every column. Column 0 (step) always matches exactly. */
typedef struct sw_check_tol {
    double rtol, atol;          /* the defaults */
    const double *col_rtol;     /* ncols, or NULL */
    const double *col_atol;     /* ncols, or NULL */
    const unsigned char *ignore; /* ncols, or NULL */
    long *col_failed;           /* ncols, or NULL: failures per column (zeroed by the caller) */
    sw_check_cell *col_first;   /* ncols, or NULL: each column's first failure */
    double *col_worst;          /* ncols, or NULL: each column's largest |got - expected| /
                                 * (1 + |expected|), the least tolerance (rtol = atol) it passes
                                 * (inf where a non-finite value differs; zeroed by the caller) */
} sw_check_tol;

typedef struct sw_check_result {
    int pass;
    long rows_expected, rows_got, rows_compared;
    long values_compared, values_failed;
    int have_first, have_worst;
    sw_check_cell first;   /* the first failure */
    sw_check_cell worst;   /* the value with the largest error relative to its tolerance */
    double max_abs, max_rel;  /* over all compared values except the step column */
    long last_step_expected, last_step_got;
} sw_check_result;

/* Compare every row of got with expected (both ncols wide). 0 with res
 * filled (res->pass says the verdict), or a negative status when a source
 * is unusable (err names file and line). */
int sw_check_compare(sw_row_source *expected, sw_row_source *got, int ncols, double rtol,
                     double atol, sw_check_result *res, char *err, size_t errlen);
/* The same with per-column tolerances and exclusions. */
int sw_check_compare_tol(sw_row_source *expected, sw_row_source *got, int ncols,
                         const sw_check_tol *tol, sw_check_result *res, char *err, size_t errlen);

#endif
