/* The explaining checker: when a trace or a plugin's run fails, try the
 * usual mistakes on the first rows and name the one that matches (another
 * built-in method, dt doubled or halved, a stage at the wrong time, a
 * Verlet variant, single precision, too few printed digits, a missing or
 * duplicated row, a shifted time column, another parameter value, a wrong
 * initial state, a wrong energy formula, a column in other units). Works
 * on a bounded prefix of the rows, so its cost does not grow with the run. */
#ifndef SW_GRADE_EXPLAIN_H
#define SW_GRADE_EXPLAIN_H

#include <stddef.h>

#include "grade/check.h"
#include "trace/trace.h"

/* The run a trace should be: what the assignment (or the trace's own
 * metadata) describes. */
typedef struct sw_run_desc {
    const sw_scene *scene;
    double p[SW_MAX_PARAMS];
    const sw_integrator *method;
    double dt;
    sw_trace_spec spec;
    double rtol, atol;            /* the run's (rk45, implicit) tolerances */
} sw_run_desc;

typedef struct sw_explanation {
    char kind[24];      /* "method", "dt", "stage-time", "k3-full-step", "verlet-half-step",
                           "verlet-recomputed", "position-verlet", "single-precision",
                           "digits", "missing-row", "duplicate-row", "time-shift", "parameter",
                           "initial-state", "energy-formula", "energy", "units" */
    char message[480];  /* one sentence for the student */
    double agreement;   /* largest relative difference from the matching variant; NaN n/a */
} sw_explanation;

/* At most this many rows (and 2e6 values) of the trace are examined. */
#define SW_EXPLAIN_ROWS 400

/* Try the usual mistakes on the rows of the trace at path (grading
 * tolerances tol; arrays in the trace's column order) against want. 1 with
 * *out filled when one explains the rows, 0 when none does, or a negative
 * status when the trace cannot be read. */
int sw_explain(const char *path, const sw_run_desc *want, const sw_check_tol *tol,
               sw_explanation *out, char *err, size_t errlen);

/* The same for a run of method got (a plugin) with want's scene,
 * parameters, dt and spec, started afresh: its first rows are examined
 * (a run that fails part way is not explained). 1, 0 or a negative status
 * when the run cannot start. */
int sw_explain_run(const sw_integrator *got, const sw_run_desc *want, const sw_check_tol *tol,
                   sw_explanation *out, char *err, size_t errlen);

#endif
