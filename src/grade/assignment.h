/* Assignments: what a teacher set (scene, parameters, integrator or "any
 * of" several, dt, the run's length, grading tolerances), as a small file
 * in the trace metadata format; a reference trace's header serves as one.
 * A trace is checked against the run the assignment describes, after its
 * header's differences from the assignment are listed by name and value. */
#ifndef SW_GRADE_ASSIGNMENT_H
#define SW_GRADE_ASSIGNMENT_H

#include <stddef.h>

#include "grade/check.h"
#include "grade/points.h"
#include "trace/trace.h"
#include "util/num.h" /* sw_fmt_shortest, which assignments' messages use */

#define SW_ASSIGN_METHODS 8
#define SW_COLTOL_MAX 64

/* A per-column tolerance or exclusion: COL is a column name, or a prefix
 * ending in '*' ("vx*" is every vx<i>). */
typedef struct sw_coltol {
    char column[32];
    double rtol, atol;
    int ignore;
    char where[64];      /* "FILE:LINE" or the option, for messages */
} sw_coltol;

/* Per-column tolerances and exclusions, from an assignment and options. */
typedef struct sw_coltols {
    sw_coltol cols[SW_COLTOL_MAX];
    int n;
} sw_coltols;

/* What a homework asks students to hand in ("# kind: trace" or "plugin");
 * ANY when the assignment does not say. */
typedef enum sw_assign_kind { SW_KIND_ANY = 0, SW_KIND_TRACE, SW_KIND_PLUGIN } sw_assign_kind;

typedef struct sw_assignment {
    char path[SW_TRACE_PATH_MAX];
    sw_trace_meta meta;                       /* scene, parameters, dt, run, rk45 tolerances */
    const sw_integrator *methods[SW_ASSIGN_METHODS]; /* the integrator, or any of these */
    int nmethods;
    double rtol, atol;                        /* grading tolerances */
    sw_coltols coltols;
    sw_points_set points;                     /* "# points" lines, or the defaults */
    char title[128];
    sw_assign_kind kind;
    /* "# submit: source": a plugin only as C source (.c), which the grader
     * compiles and the similarity check reads; a compiled .so, which can
     * carry any code (stepwise's own methods linked in among it), is not
     * graded. 0 ("source or compiled", the default): either. */
    int source_only;
} sw_assignment;

/* Whether a submission (a plugin, or a trace; path, where known, names a
 * plugin's form by its ending: .c or .so) is of the kind a asks for; when
 * not, why says what it asks for, in one clause. */
int sw_assignment_kind_ok(const sw_assignment *a, int is_plugin, const char *path, char *why, size_t whylen);
/* What to upload, for a message: "a trace (.trace, .csv)", "a plugin (.c,
 * .so)", "a plugin's C source (.c)" or both kinds. */
const char *sw_assignment_wanted(const sw_assignment *a);

/* Read an assignment file (or a trace, whose header serves). 0 or an error
 * "FILE:LINE: what". */
int sw_assignment_read(sw_assignment *a, const char *path, char *err, size_t errlen);
/* The same with each metadata line through filter (grade/homework.c). */
int sw_assignment_read_filtered(sw_assignment *a, const char *path, sw_trace_meta_filter filter,
                                void *ctx, char *err, size_t errlen);

/* Parse "COL=REL[,ABS]" (or "REL[,ABS]" for the key form: col NULL) into t;
 * where names the source for messages. 0 or SW_EINVAL. */
int sw_coltol_parse(sw_coltols *t, const char *text, int ignore, const char *where, char *err,
                    size_t errlen);
/* Resolve against a system's columns into ncols-long arrays (defaults rtol,
 * atol); a name that matches no column is an error. 0 or SW_EINVAL. */
int sw_coltol_resolve(const sw_coltols *t, const sw_system *sys, double rtol, double atol,
                      double *col_rtol, double *col_atol, unsigned char *ignore, char *err,
                      size_t errlen);

/* One way a trace's header differs from the assignment. */
typedef struct sw_header_diff {
    char what[48];       /* "dt", "param k", "integrator", ... */
    char got[96];        /* the trace's value */
    char want[160];      /* the assignment's */
    long line;           /* the trace's line (0: not stated, the default) */
} sw_header_diff;

/* Every difference between a trace's metadata m and the assignment, in
 * header order, up to max; returns how many. The same run written another
 * way is no difference: "until: T" for "steps: N" when a fixed-step method
 * takes N steps of dt to reach T (|T - N dt| <= 1e-9 dt), and the reverse. A different scene or a
 * different column count makes the numbers incomparable: *comparable 0. */
int sw_assignment_diff(const sw_assignment *a, const sw_trace_meta *m, const sw_system *trace_sys,
                       sw_header_diff *out, int max, int *comparable);
/* The method to regenerate with: the trace's when the assignment allows
 * it, else the assignment's first. */
const sw_integrator *sw_assignment_method(const sw_assignment *a, const sw_trace_meta *m);
/* Initialise a sim for the assignment's run under method mth. 0 or error. */
int sw_assignment_sim(const sw_assignment *a, const sw_integrator *mth, sw_sim *s, char *err,
                      size_t errlen);


#endif
