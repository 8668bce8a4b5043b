/* One check, start to verdict, without printing: what `check` reports and
 * what `grade` records per submission. A trace is compared with a
 * regenerated reference (its own metadata, an assignment, or --reference),
 * with another trace, or a plugin run with a built-in one; on a failure the
 * usual mistakes are tried; a plugin that crashes, loops or overruns is a
 * failure with the step, never a pass. */
#ifndef SW_GRADE_VERDICT_H
#define SW_GRADE_VERDICT_H

#include <stddef.h>

#include "grade/assignment.h"
#include "grade/check.h"
#include "grade/explain.h"
#include "grade/points.h"
#include "plugin/plugin.h"

#define SW_VERDICT_DIFFS 16
/* Budget for regenerating a run: state components x derivative evaluations
 * (docs/trace-format.md, "Limits"; about 10 to 60 s of computing). */
#define SW_CHECK_WORK_BUDGET 2e10

/* Budget for writing a trace: values (rows x columns), each formatted with
 * %.17g (about 1e8 values a minute, 2 GB of text). */
#define SW_RECORD_VALUE_BUDGET 1e8

typedef enum sw_verdict_status { SW_VERDICT_PASS = 0, SW_VERDICT_FAIL = 1, SW_VERDICT_ERROR = 2 } sw_verdict_status;

/* What to check. Exactly one of trace and plugin_form. */
typedef struct sw_check_request {
    const char *trace;                 /* the trace file, or NULL */
    const char *against;               /* compare with this trace instead */
    const sw_assignment *assignment;   /* compare with the run it describes */
    const sw_integrator *reference;    /* regenerate with this method (--reference) */
    /* The plugin form: run `plugin` and `reference` with these settings. */
    const sw_integrator *plugin;
    const sw_scene *scene;
    double p[SW_MAX_PARAMS];
    double dt;
    sw_trace_spec spec;
    /* Tolerances: the defaults (or the assignment's), overridden by the
     * options when given (rtol/atol > 0), then per-column options. */
    double rtol, atol;
    sw_coltols coltols;
    int explain;                       /* try the usual mistakes on a failure */
    int measure;                       /* plugin form: measure order and stability */
} sw_check_request;

typedef struct sw_run_end {
    int blown;
    long step;
    double t;
    char reason[SW_ERRLEN];
    sw_plugin_fault fault;             /* a plugin failure, not a numerical blow-up */
} sw_run_end;

typedef struct sw_verdict {
    sw_verdict_status status;
    char error[SW_ERRLEN + SW_TRACE_PATH_MAX]; /* ERROR: "FILE:LINE: what" */
    const char *trace, *against, *assignment;
    char plugin[64];                   /* the plugin's name in the plugin form */
    char scene[32];
    char method[64];                   /* the reference's integrator ("" with --against) */
    char reference[400];               /* what the reference is, in words */
    double dt, rtol, atol;
    char student[SW_TRACE_STUDENT_MAX], notes[SW_TRACE_NOTES_MAX];
    sw_header_diff diffs[SW_VERDICT_DIFFS];
    int ndiffs;                        /* may exceed SW_VERDICT_DIFFS: only that many kept */
    int comparable;                    /* the numbers could be compared */
    int ncols;
    sw_check_result res;
    char first[600], worst[600];       /* res.first and res.worst in words */
    char first_column[32], worst_column[32];
    sw_run_end ref_end, got_end;       /* the regenerated reference, the plugin's run */
    int have_explanation;
    sw_explanation explanation;
    int have_measure;                  /* plugin form */
    int claimed_order;
    int claimed_evals;                 /* plugin form: what its sw_plugin_info said per step */
    double counted_evals;              /* ... and what its host counted per step in the graded run (NaN: none) */
    double order;                      /* NaN: not measured (measure_note says why) */
    int order_on_spring;               /* measured on the undamped spring: the graded run shows none */
    int measure_shown;                 /* the caller printed order and stability itself (try) */
    double stability;                  /* ω·dt limit on the undamped spring; NaN: none */
    int stability_kind;
    double ref_stability;              /* the method's own, measured the same way; NaN: not */
    int stability_decided;             /* an assignment's stability point, decided without a figure
                                        * (sw_measure_stability_match; measure_note says how) */
    int stability_given;               /* ... and given */
    char measure_note[600];
    long failing_step;                 /* the first failing step; -1 none */
    int limit;                         /* the plugin ran out of a resource limit */
    char warning[160];                 /* e.g. extra columns ignored; "" none */
    sw_score score;                    /* the assignment's points, check by check */
    char message[1600];                /* the verdict in one line */
} sw_verdict;

/* Fill req's defaults: tolerances unset (0), explain on, every 1. */
void sw_check_request_init(sw_check_request *req);
/* Run the check. Always fills v (v->status says the verdict); returns
 * v->status. */
sw_verdict_status sw_check_run(const sw_check_request *req, sw_verdict *v);
/* Estimate a run's work (state components x derivative evaluations) and
 * refuse it above SW_CHECK_WORK_BUDGET with a message naming the numbers. */
int sw_check_budget(const sw_scene *sc, const double *p, const sw_integrator *m, double dt,
                    const sw_trace_spec *spec, double *work, char *err, size_t errlen);

/* Estimate the values a recording writes (rows x columns) and refuse it
 * above SW_RECORD_VALUE_BUDGET with a message naming the numbers. */
int sw_record_budget(const sw_scene *sc, const double *p, double dt, const sw_trace_spec *spec,
                     char *err, size_t errlen);

#endif
