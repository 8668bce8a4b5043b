/* The check report, plain and JSON. Every number goes out in shortest
 * round-trip form; every name a plugin or a trace chose goes through the
 * JSON string escaper or was validated when loaded. */
#include "cli/check_report.h"

#include <errno.h>
#include <math.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/json.h"
#include "util/escape.h"

static const char *status_word(sw_verdict_status s)
{
    return s == SW_VERDICT_PASS ? "pass" : s == SW_VERDICT_FAIL ? "fail" : "error";
}

static const char *fault_word(sw_plugin_fault f)
{
    switch (f) {
    case SW_PF_EXIT: return "exit";
    case SW_PF_CRASH: return "crash";
    case SW_PF_OVERRUN_WORK: return "overrun_work";
    case SW_PF_OVERRUN_Y: return "overrun_y";
    case SW_PF_UNDERRUN: return "underrun";
    case SW_PF_ODE: return "ode_written";
    case SW_PF_TIMEOUT: return "timeout";
    case SW_PF_CANCELLED: return "interrupted";
    case SW_PF_START: return "start";
    case SW_PF_DISABLED: return "disabled";
    case SW_PF_FORGED: return "forged";
    case SW_PF_LIMIT: return "limit";
    case SW_PF_ALLOC: return "allocated";
    default: return "none";
    }
}

static void json_cell(FILE *out, int in, const char *key, const sw_check_cell *c, int have,
                      const char *column)
{
    static const char *const kinds[] = { "", "value", "missing_rows", "extra_rows" };
    sw_json_key(out, in, key, 0);
    if (!have) {
        fputs("null", out);
        return;
    }
    fputs("{", out);
    sw_json_key(out, in + 2, "kind", 1);
    sw_json_str(out, kinds[c->kind]);
    sw_json_key(out, in + 2, "line", 0);
    sw_json_long(out, c->line > 0 ? c->line : -1, 1);
    sw_json_key(out, in + 2, "step", 0);
    sw_json_long(out, c->step, 0);
    sw_json_key(out, in + 2, "t", 0);
    sw_json_num(out, c->t);
    sw_json_key(out, in + 2, "column", 0);
    sw_json_str(out, c->column >= 0 ? column : NULL);
    sw_json_key(out, in + 2, "expected", 0);
    sw_json_num(out, c->expected);
    sw_json_key(out, in + 2, "got", 0);
    sw_json_num(out, c->got);
    sw_json_key(out, in + 2, "abs_error", 0);
    sw_json_num(out, c->abs_err);
    sw_json_key(out, in + 2, "rel_error", 0);
    sw_json_num(out, c->rel_err);
    sw_json_key(out, in + 2, "tolerance_ratio", 0);
    sw_json_num(out, c->ratio);
    fprintf(out, "\n%*s}", in, "");
}

static void json_end(FILE *out, int in, const char *key, const sw_run_end *e, int numeric)
{
    sw_json_key(out, in, key, 0);
    int show = numeric ? e->blown && e->fault == SW_PF_NONE : e->fault != SW_PF_NONE;
    if (!show) {
        fputs("null", out);
        return;
    }
    fputs("{ ", out);
    if (!numeric) {
        fputs("\"kind\": ", out);
        sw_json_str(out, fault_word(e->fault));
        fputs(", ", out);
    }
    fprintf(out, "\"step\": %ld, \"t\": ", e->step);
    sw_json_num(out, e->t);
    fputs(numeric ? ", \"reason\": " : ", \"message\": ", out);
    sw_json_str(out, e->reason);
    fputs(" }", out);
}

/* The JSON verdict object on out, at indent in. */
static void sw_check_json(FILE *out, const sw_verdict *v, int in)
{
    const sw_check_result *r = &v->res;
    fputs("{", out);
    sw_json_key(out, in + 2, "format", 1);
    sw_json_str(out, "stepwise check 1");
    sw_json_key(out, in + 2, "version", 0);
    sw_json_str(out, SW_VERSION);
    sw_json_key(out, in + 2, "status", 0);
    sw_json_str(out, status_word(v->status));
    sw_json_key(out, in + 2, "pass", 0);
    fputs(v->status == SW_VERDICT_PASS ? "true" : "false", out);
    sw_json_key(out, in + 2, "exit", 0);
    fprintf(out, "%d", (int)v->status);
    if (v->status == SW_VERDICT_ERROR) {
        sw_json_key(out, in + 2, "error", 0);
        sw_json_str(out, v->error);
        fprintf(out, "\n%*s}", in, "");
        return;
    }
    const char *strs[][2] = { { "trace", v->trace }, { "plugin", v->plugin[0] ? v->plugin : NULL },
                              { "against", v->against }, { "assignment", v->assignment },
                              { "reference", v->reference }, { "scene", v->scene },
                              { "integrator", v->method[0] ? v->method : NULL },
                              { "student", v->student[0] ? v->student : NULL },
                              { "notes", v->notes[0] ? v->notes : NULL } };
    for (size_t i = 0; i < sizeof strs / sizeof strs[0]; i++) {
        sw_json_key(out, in + 2, strs[i][0], 0);
        sw_json_str(out, strs[i][1]);
    }
    sw_json_key(out, in + 2, "dt", 0);
    if (isnan(v->dt))
        fputs("null", out);
    else
        sw_json_num(out, v->dt);
    sw_json_key(out, in + 2, "rtol", 0);
    sw_json_num(out, v->rtol);
    sw_json_key(out, in + 2, "atol", 0);
    sw_json_num(out, v->atol);
    sw_json_key(out, in + 2, "header_differences", 0);
    fputs("[", out);
    int kept = v->ndiffs < SW_VERDICT_DIFFS ? v->ndiffs : SW_VERDICT_DIFFS;
    for (int i = 0; i < kept; i++) {
        const sw_header_diff *d = &v->diffs[i];
        fprintf(out, "%s\n%*s{ \"what\": ", i ? "," : "", in + 4, "");
        sw_json_str(out, d->what);
        fputs(", \"got\": ", out);
        sw_json_str(out, d->got);
        fputs(", \"want\": ", out);
        sw_json_str(out, d->want);
        fputs(", \"line\": ", out);
        sw_json_long(out, d->line > 0 ? d->line : -1, 1);
        fputs(" }", out);
    }
    fprintf(out, kept ? "\n%*s]" : "]", in + 2, "");
    sw_json_key(out, in + 2, "comparable", 0);
    fputs(v->comparable ? "true" : "false", out);
    sw_json_key(out, in + 2, "warning", 0);
    sw_json_str(out, v->warning[0] ? v->warning : NULL);
    const char *counts[] = { "rows_expected", "rows_got", "rows_compared", "values_compared",
                             "values_failed" };
    long values[] = { r->rows_expected, r->rows_got, r->rows_compared, r->values_compared,
                      r->values_failed };
    sw_json_key(out, in + 2, "columns", 0);
    fprintf(out, "%d", v->ncols);
    for (int i = 0; i < 5; i++) {
        sw_json_key(out, in + 2, counts[i], 0);
        fprintf(out, "%ld", values[i]);
    }
    json_cell(out, in + 2, "first_failure", &r->first, r->have_first, v->first_column);
    json_cell(out, in + 2, "largest_error", &r->worst, r->have_worst, v->worst_column);
    sw_json_key(out, in + 2, "max_abs_error", 0);
    sw_json_num(out, r->max_abs);
    sw_json_key(out, in + 2, "max_rel_error", 0);
    sw_json_num(out, r->max_rel);
    json_end(out, in + 2, "reference_diverged", &v->ref_end, 1);
    json_end(out, in + 2, "plugin_diverged", &v->got_end, 1);
    json_end(out, in + 2, "plugin_failure", v->got_end.fault ? &v->got_end : &v->ref_end, 0);
    sw_json_key(out, in + 2, "explanation", 0);
    if (v->have_explanation) {
        fputs("{ \"kind\": ", out);
        sw_json_str(out, v->explanation.kind);
        fputs(", \"message\": ", out);
        sw_json_str(out, v->explanation.message);
        fputs(", \"agreement\": ", out);
        if (isnan(v->explanation.agreement))
            fputs("null", out);
        else
            sw_json_num(out, v->explanation.agreement);
        fputs(" }", out);
    } else
        fputs("null", out);
    sw_json_key(out, in + 2, "measured", 0);
    if (v->have_measure) {
        fprintf(out, "{ \"claimed_order\": %d, \"order\": ", v->claimed_order);
        if (isnan(v->order))
            fputs("null", out);
        else
            sw_json_num(out, v->order);
        fputs(", \"stability_omega_dt\": ", out);
        if (isnan(v->stability))
            fputs("null", out);
        else
            sw_json_num(out, v->stability);
        fprintf(out, ", \"claimed_evals\": %d, \"counted_evals\": ", v->claimed_evals);
        if (isnan(v->counted_evals))
            fputs("null", out);
        else
            sw_json_num(out, v->counted_evals);
        fputs(", \"note\": ", out);
        sw_json_str(out, v->measure_note[0] ? v->measure_note : NULL);
        fputs(" }", out);
    } else
        fputs("null", out);
    sw_json_key(out, in + 2, "failing_step", 0);
    sw_json_long(out, v->failing_step, 1);
    sw_json_key(out, in + 2, "message", 0);
    sw_json_str(out, v->message);
    fprintf(out, "\n%*s}", in, "");
}

void sw_check_print_error(const char *msg)
{
    fputs("{\n  \"format\": \"stepwise check 1\",\n  \"version\": ", stdout);
    sw_json_str(stdout, SW_VERSION);
    fputs(",\n  \"status\": \"error\",\n  \"pass\": false,\n  \"exit\": 2,\n  \"error\": ", stdout);
    sw_json_str(stdout, msg);
    fputs("\n}\n", stdout);
    fflush(stdout);
}

static void print_measure(FILE *out, const sw_verdict *v)
{
    if (!v->have_measure)
        return;
    /* counted by the plugin's host, where the step does not write */
    if (!isnan(v->counted_evals)) {
        fprintf(out, "  evaluations: claimed %d per step, counted %.4g per step", v->claimed_evals,
                v->counted_evals);
        /* a method that keeps its last evaluation (Verlet's a1) makes one
         * more on its first step: a few hundredths over a run, not more */
        if (v->counted_evals < v->claimed_evals - 1e-9)
            fprintf(out, " (fewer than claimed: does your step evaluate the derivative at every stage?)");
        else if (v->counted_evals > v->claimed_evals + 0.05)
            fprintf(out, " (more than claimed: set .evals to what a step costs)");
        else if (v->counted_evals > v->claimed_evals + 1e-9)
            fprintf(out, " (the extra is the first step's: a step that keeps its last evaluation starts "
                    "without one)");
        fputc('\n', out);
    }
    if (v->measure_shown)
        return;
    if (isnan(v->order)) {
        fprintf(out, "  %s (claimed order %d)\n", v->measure_note, v->claimed_order);
        return;
    }
    if (v->order_on_spring)
        fprintf(out, "  order: claimed %d, measured %.2f (on the undamped spring: the run checked cannot show an "
                "order, and its values match)\n", v->claimed_order, v->order);
    else
        fprintf(out, "  order: claimed %d, measured %.2f (on the run checked: %s from dt = %g, dt halved until "
                "the local slopes agree)\n", v->claimed_order, v->order, v->scene, v->dt);
    if (isnan(v->stability))
        fprintf(out, "  %s\n", v->measure_note); /* "stability not measured: why" */
    else if (isinf(v->stability))
        fprintf(out, "  stability: measured unbounded on the undamped spring (stable at every dt probed)\n");
    else if (v->stability == 0)
        fprintf(out, "  stability: measured none (grows even at w*dt = 0.01)\n");
    else if (isnan(v->ref_stability) || isinf(v->ref_stability))
        fprintf(out, "  stability: largest stable w*dt measured %.4g on the undamped spring\n", v->stability);
    else if (v->ref_stability == 0)
        fprintf(out, "  stability: largest stable w*dt measured %.4g on the undamped spring (%s: none, "
                "measured the same way)\n", v->stability, v->method);
    else
        fprintf(out, "  stability: largest stable w*dt measured %.4g on the undamped spring (%s: %.4g, "
                "measured the same way)\n", v->stability, v->method, v->ref_stability);
}


/* A run that ended: "diverged" where the state ran away, "stopped" where
 * the plugin's step refused (returned non-zero). */
static const char *ended_how(const char *reason)
{
    return sw_sim_refused(reason) ? "stopped" : "diverged";
}
void sw_check_print_plain(FILE *out, const sw_verdict *v)
{
    const sw_check_result *r = &v->res;
    char what[400], shown[300];
    sw_escape(v->trace ? v->trace : v->plugin, 200, shown, sizeof shown); /* a file's name, a plugin's */
    if (v->trace)
        snprintf(what, sizeof what, "%s", shown);
    else
        snprintf(what, sizeof what, "plugin %s on %s", shown, v->scene);
    if (v->status == SW_VERDICT_PASS)
        fprintf(out, "PASS: %s matches %s\n  %ld rows, %ld values within |got - expected| <= %g + "
               "%g*|expected|\n", what, v->reference, r->rows_compared, r->values_compared,
               v->atol, v->rtol);
    else
        fprintf(out, "FAIL: %s differs from %s\n", what, v->reference);
    char esc[400], got[200];
    if (v->student[0]) {
        sw_escape(v->student, 120, esc, sizeof esc);
        fprintf(out, "  student: %s\n", esc);
    }
    if (v->warning[0]) {
        sw_escape(v->warning, 160, esc, sizeof esc);
        fprintf(out, "  warning: %s\n", esc);
    }
    int kept = v->ndiffs < SW_VERDICT_DIFFS ? v->ndiffs : SW_VERDICT_DIFFS;
    if (v->ndiffs)
        fprintf(out, "  header differs from the assignment in %d place%s:\n", v->ndiffs, v->ndiffs == 1 ? "" : "s");
    for (int i = 0; i < kept; i++) {
        const sw_header_diff *d = &v->diffs[i];
        char line[32] = "";
        if (d->line > 0)
            snprintf(line, sizeof line, " (line %ld)", d->line);
        else
            snprintf(line, sizeof line, " (not stated: the default)");
        sw_escape(d->got, 80, got, sizeof got);
        fprintf(out, "    %s: yours %s%s, the assignment's %s\n", d->what, got, line, d->want);
    }
    if (!v->comparable)
        fprintf(out, "  the numbers were not compared: the trace has other columns than the assignment's run\n");
    const sw_run_end *pf = v->got_end.fault ? &v->got_end : v->ref_end.fault ? &v->ref_end : NULL;
    if (pf) { /* the values after a broken plugin's last step say nothing more */
        fprintf(out, "  %s\n", pf->reason);
        print_measure(out, v);
        return;
    }
    /* a run that stopped before the reference's: its rows end there, and
     * the step column is the first to differ (said below, in words) */
    int stopped = v->got_end.blown && !v->ref_end.blown && strcmp(v->first_column, "step") == 0;
    if (v->status != SW_VERDICT_PASS && v->first[0] && !stopped)
        fprintf(out, "  first failure: %s\n", v->first);
    if (v->status != SW_VERDICT_PASS && r->rows_compared > 0) {
        if (r->values_failed > 0)
            fprintf(out, "  %ld of %ld values are outside |got - expected| <= %g + %g*|expected|\n",
                   r->values_failed, r->values_compared, v->atol, v->rtol);
        else
            fprintf(out, "  the %ld values compared are all within |got - expected| <= %g + "
                   "%g*|expected|\n", r->values_compared, v->atol, v->rtol);
    }
    if (v->have_explanation)
        fprintf(out, "  why: %s\n", v->explanation.message);
    if (r->have_worst)
        fprintf(out, "  largest error: %s\n", v->worst);
    else if (r->rows_compared > 0)
        fprintf(out, "  largest error: none; every compared value matches exactly\n");
    if (v->ref_end.blown && !v->ref_end.fault)
        fprintf(out, "  the reference diverged at step %ld (t = %g): %s\n", v->ref_end.step, v->ref_end.t,
               v->ref_end.reason);
    if (v->got_end.blown && !v->got_end.fault)
        fprintf(out, "  the plugin %s at step %ld (t = %g): %s\n", ended_how(v->got_end.reason), v->got_end.step,
                v->got_end.t, v->got_end.reason);
    print_measure(out, v);
}

int sw_check_print(const sw_verdict *v, int json)
{
    if (v->status == SW_VERDICT_ERROR)
        sw_cli_error("%s", v->error);
    if (json) {
        if (v->status == SW_VERDICT_ERROR)
            sw_check_print_error(v->error);
        else {
            sw_check_json(stdout, v, 0);
            fputc('\n', stdout);
        }
    } else if (v->status != SW_VERDICT_ERROR)
        sw_check_print_plain(stdout, v);
    errno = 0;
    if (fflush(stdout) != 0 || ferror(stdout))
        return sw_cli_error("cannot write the report to standard output: %s",
                            errno ? strerror(errno) : "write error");
    return (int)v->status;
}
