/* `stepwise check`: grade a trace against a reference regenerated from its
 * metadata, against another trace (--against), or grade a plugin integrator
 * against a built-in one (--plugin --reference --scene). Prints a plain
 * report, or JSON for autograders. Exit 0 pass, 1 mismatch, 2 unusable. */
#include "cli/cli.h"

#include <getopt.h>
#include <math.h>
#include <string.h>

#include "lab/check.h"
#include "lab/trace.h"

static const char check_help[] =
    "usage: stepwise check TRACE [--against REF] [--reference NAME] [--plugin PATH.so]...\n"
    "                      [--rtol R] [--atol A] [--json]\n"
    "       stepwise check --plugin PATH.so --reference NAME --scene SCENE\n"
    "                      [--integrator NAME] [--dt H] [--steps N | --until T]\n"
    "                      [--set PARAM=VALUE]... [--every K] [--rtol R] [--atol A] [--json]\n"
    "\n"
    "Compares a step trace with a reference, value by value: a value passes when\n"
    "|got - expected| <= atol + rtol*|expected|; equal nan or inf values pass. The\n"
    "reference is regenerated from TRACE's own metadata, or read from REF. The\n"
    "second form runs a plugin integrator and the built-in method NAME with the\n"
    "same settings and compares them. See docs/trace-format.md.\n"
    "\n"
    "options:\n"
    "      --against REF      compare with the trace REF instead of regenerating\n"
    "      --reference NAME   regenerate with integrator NAME instead of TRACE's own\n"
    "      --plugin PATH.so   load a student integrator (docs/plugins.md); repeatable\n"
    "      --scene SCENE      plugin form: the scene to run\n"
    "  -i, --integrator NAME  plugin form: the plugin's integrator (default: the last loaded)\n"
    "      --dt H             plugin form: step size (default: the scene's)\n"
    "  -n, --steps N          plugin form: run N steps, 1 to 10000000\n"
    "  -u, --until T          plugin form: run until T (default: the scene's report time)\n"
    "  -s, --set PARAM=VALUE  plugin form: set a scene parameter; repeatable\n"
    "  -k, --every K          plugin form: compare step 0, every K-th step and the last\n"
    "      --rtol R           relative tolerance (default 1e-09)\n"
    "      --atol A           absolute tolerance (default 1e-09)\n"
    "      --json             print a JSON report (fields in docs/trace-format.md)\n"
    "  -h, --help             this help\n"
    "\n"
    "exit status: 0 pass, 1 mismatch, 2 unusable input (one line on stderr naming\n"
    "file and line).\n";

/* ---- JSON ----------------------------------------------------------------- */

/* A JSON string: quotes, backslashes and control bytes escaped; valid UTF-8
 * passes through; any other byte becomes U+FFFD, so the output always parses. */
static void json_str(const char *s)
{
    if (!s) {
        fputs("null", stdout);
        return;
    }
    const unsigned char *p = (const unsigned char *)s;
    putchar('"');
    while (*p) {
        unsigned char c = *p;
        if (c == '"' || c == '\\') {
            printf("\\%c", c);
            p++;
        } else if (c < 0x20 || c == 0x7f) {
            printf("\\u%04x", c);
            p++;
        } else if (c < 0x80) {
            putchar(c);
            p++;
        } else {
            int len = c >= 0xf0 && c < 0xf5 ? 4 : c >= 0xe0 ? 3 : c >= 0xc2 && c < 0xe0 ? 2 : 0;
            int ok = len > 0;
            for (int i = 1; ok && i < len; i++)
                ok = (p[i] & 0xc0) == 0x80;
            if (ok) {
                fwrite(p, 1, (size_t)len, stdout);
                p += len;
            } else {
                fputs("\\ufffd", stdout);
                p++;
            }
        }
    }
    putchar('"');
}

/* JSON has no nan or inf: non-finite numbers are null. */
static void json_num(double v)
{
    if (isfinite(v))
        printf("%.17g", v);
    else
        fputs("null", stdout);
}

/* ---- the report ----------------------------------------------------------- */

typedef struct report {
    int json;
    const char *trace;          /* path of the checked trace; NULL in the plugin form */
    const char *plugin;         /* the plugin integrator's name in the plugin form */
    const char *against;        /* path of REF, or NULL */
    const char *scene;
    const char *method;         /* the reference's integrator; NULL for --against */
    double dt;
    double rtol, atol;
    const sw_system *sys;       /* gives column names */
    const sw_sim *ref_sim;      /* the regenerated reference, or NULL */
    const sw_sim *got_sim;      /* the plugin's run, or NULL */
    char what[300];             /* "trace.csv" or "plugin my-euler" */
    char reference[400];        /* what the reference is, in words */
} report;

static void column_name(const report *rp, int c, char *buf, size_t len)
{
    if (c < 0)
        snprintf(buf, len, "(row)");
    else
        sw_trace_colname(rp->sys, c, buf, len);
}

/* With --json, an error object for an unusable input whose one line is
 * already on stderr (printed by a shared helper). */
static int json_error(const report *rp, const char *msg)
{
    if (rp->json) {
        fputs("{\n  \"format\": \"stepwise check 1\",\n  \"version\": ", stdout);
        json_str(SW_VERSION);
        fputs(",\n  \"status\": \"error\",\n  \"pass\": false,\n  \"exit\": 2,\n  \"error\": ", stdout);
        json_str(msg);
        fputs("\n}\n", stdout);
    }
    return SW_EXIT_USAGE;
}

/* An unusable input: one line on stderr and, with --json, an error object. */
static int report_error(const report *rp, const char *msg)
{
    sw_cli_error("%s", msg);
    return json_error(rp, msg);
}

static void json_cell(const report *rp, const char *key, const sw_check_cell *c, int have)
{
    printf(",\n  \"%s\": ", key);
    if (!have) {
        fputs("null", stdout);
        return;
    }
    static const char *const kinds[] = { "", "value", "missing_rows", "extra_rows" };
    char name[32];
    column_name(rp, c->column, name, sizeof name);
    fputs("{\n    \"kind\": ", stdout);
    json_str(kinds[c->kind]);
    fputs(",\n    \"line\": ", stdout);
    if (c->line > 0)
        printf("%ld", c->line);
    else
        fputs("null", stdout);
    printf(",\n    \"step\": %ld,\n    \"t\": ", c->step);
    json_num(c->t);
    fputs(",\n    \"column\": ", stdout);
    json_str(c->column >= 0 ? name : NULL);
    fputs(",\n    \"expected\": ", stdout);
    json_num(c->expected);
    fputs(",\n    \"got\": ", stdout);
    json_num(c->got);
    fputs(",\n    \"abs_error\": ", stdout);
    json_num(c->abs_err);
    fputs(",\n    \"rel_error\": ", stdout);
    json_num(c->rel_err);
    fputs(",\n    \"tolerance_ratio\": ", stdout);
    json_num(c->ratio);
    fputs("\n  }", stdout);
}

static void json_blowup(const char *key, const sw_sim *s)
{
    printf(",\n  \"%s\": ", key);
    if (!s || !s->blown) {
        fputs("null", stdout);
        return;
    }
    printf("{ \"step\": %ld, \"t\": ", s->blow_step);
    json_num(s->blow_time);
    fputs(", \"reason\": ", stdout);
    json_str(s->blow_reason);
    fputs(" }", stdout);
}

static void print_json(const report *rp, const sw_check_result *res, const char *message)
{
    fputs("{\n  \"format\": \"stepwise check 1\",\n  \"version\": ", stdout);
    json_str(SW_VERSION);
    printf(",\n  \"status\": \"%s\",\n  \"pass\": %s,\n  \"exit\": %d", res->pass ? "pass" : "fail",
           res->pass ? "true" : "false", res->pass ? SW_EXIT_OK : SW_EXIT_FAIL);
    fputs(",\n  \"trace\": ", stdout);
    json_str(rp->trace);
    fputs(",\n  \"plugin\": ", stdout);
    json_str(rp->plugin);
    fputs(",\n  \"against\": ", stdout);
    json_str(rp->against);
    fputs(",\n  \"reference\": ", stdout);
    json_str(rp->reference);
    fputs(",\n  \"scene\": ", stdout);
    json_str(rp->scene);
    fputs(",\n  \"integrator\": ", stdout);
    json_str(rp->method);
    fputs(",\n  \"dt\": ", stdout);
    json_num(rp->dt);
    fputs(",\n  \"rtol\": ", stdout);
    json_num(rp->rtol);
    fputs(",\n  \"atol\": ", stdout);
    json_num(rp->atol);
    printf(",\n  \"columns\": %d,\n  \"rows_expected\": %ld,\n  \"rows_got\": %ld,\n"
           "  \"rows_compared\": %ld,\n  \"values_compared\": %ld,\n  \"values_failed\": %ld",
           sw_trace_ncols(rp->sys), res->rows_expected, res->rows_got, res->rows_compared,
           res->values_compared, res->values_failed);
    json_cell(rp, "first_failure", &res->first, res->have_first);
    json_cell(rp, "largest_error", &res->worst, res->have_worst);
    fputs(",\n  \"max_abs_error\": ", stdout);
    json_num(res->max_abs);
    fputs(",\n  \"max_rel_error\": ", stdout);
    json_num(res->max_rel);
    json_blowup("reference_diverged", rp->ref_sim);
    json_blowup("plugin_diverged", rp->got_sim);
    fputs(",\n  \"message\": ", stdout);
    json_str(message);
    fputs("\n}\n", stdout);
}

/* One compared value in words. */
static void describe_cell(const report *rp, const sw_check_cell *c, char *buf, size_t len)
{
    char name[32], where[40] = "";
    column_name(rp, c->column, name, sizeof name);
    if (c->line > 0)
        snprintf(where, sizeof where, " (line %ld)", c->line);
    snprintf(buf, len, "step %ld, t = %g, column %s%s: expected %.17g, got %.17g "
             "(relative error %.3g)", c->step, c->t, name, where, c->expected, c->got, c->rel_err);
}

static int print_report(const report *rp, const sw_check_result *res)
{
    char first[600] = "", worst[600] = "", message[1400];
    if (res->have_first) {
        const sw_check_cell *c = &res->first;
        if (c->kind == SW_CHECK_VALUE)
            describe_cell(rp, c, first, sizeof first);
        else if (c->kind == SW_CHECK_MISSING)
            snprintf(first, sizeof first, "the %s ends after step %ld with %ld rows; the reference "
                     "goes on to step %ld (%ld rows)", rp->trace ? "trace" : "plugin run",
                     res->last_step_got, res->rows_got, res->last_step_expected, res->rows_expected);
        else
        {
            char where[40] = "";
            if (c->line > 0)
                snprintf(where, sizeof where, " on line %ld", c->line);
            snprintf(first, sizeof first, "the %s goes on past the reference's last step %ld: "
                     "step %ld%s; %ld rows against the reference's %ld",
                     rp->trace ? "trace" : "plugin run", res->last_step_expected, c->step, where,
                     res->rows_got, res->rows_expected);
        }
    }
    if (res->have_worst)
        describe_cell(rp, &res->worst, worst, sizeof worst);
    if (res->pass)
        snprintf(message, sizeof message, "PASS: %s matches %s: %ld rows, %ld values within "
                 "|got - expected| <= %g + %g*|expected|", rp->what, rp->reference,
                 res->rows_compared, res->values_compared, rp->atol, rp->rtol);
    else
        snprintf(message, sizeof message, "FAIL: %s differs from %s; first failure: %s",
                 rp->what, rp->reference, first);
    if (rp->json) {
        print_json(rp, res, message);
        return res->pass ? SW_EXIT_OK : SW_EXIT_FAIL;
    }
    if (res->pass)
        printf("PASS: %s matches %s\n  %ld rows, %ld values within |got - expected| <= %g + "
               "%g*|expected|\n", rp->what, rp->reference, res->rows_compared,
               res->values_compared, rp->atol, rp->rtol);
    else {
        printf("FAIL: %s differs from %s\n  first failure: %s\n", rp->what, rp->reference, first);
        if (res->values_failed > 0)
            printf("  %ld of %ld values are outside |got - expected| <= %g + %g*|expected|\n",
                   res->values_failed, res->values_compared, rp->atol, rp->rtol);
        else
            printf("  the %ld values compared are all within |got - expected| <= %g + "
                   "%g*|expected|\n", res->values_compared, rp->atol, rp->rtol);
    }
    if (res->have_worst)
        printf("  largest error: %s\n", worst);
    else if (res->rows_compared > 0)
        printf("  largest error: none; every compared value matches exactly\n");
    const sw_sim *sims[2] = { rp->ref_sim, rp->got_sim };
    const char *who[2] = { "the reference", "the plugin" };
    for (int i = 0; i < 2; i++)
        if (sims[i] && sims[i]->blown)
            printf("  %s diverged at step %ld (t = %g): %s\n", who[i], sims[i]->blow_step,
                   sims[i]->blow_time, sims[i]->blow_reason);
    return res->pass ? SW_EXIT_OK : SW_EXIT_FAIL;
}

/* ---- the three forms ------------------------------------------------------ */

typedef struct check_args {
    const char *trace, *against, *reference, *integrator;
    const char *scene_name;
    sw_run_opts o;
    sw_trace_spec spec;
    int have_until, run_opts;   /* run_opts: a plugin-form option was given */
} check_args;

/* Compare TRACE with a regenerated reference or with REF. */
static int check_trace(report *rp, const check_args *a)
{
    char err[SW_ERRLEN + SW_TRACE_PATH_MAX];
    sw_trace_reader got, ref;
    sw_sim sim;
    int have_ref = 0, have_sim = 0, status;
    sw_row_source src_e = { 0 }, src_g = { 0 };
    rp->trace = a->trace;
    snprintf(rp->what, sizeof rp->what, "%s", a->trace);
    if (sw_trace_read_open(&got, a->trace, err, sizeof err) != SW_OK)
        return report_error(rp, err);
    rp->sys = &got.sys;
    rp->scene = got.meta.scene->name;
    rp->dt = got.meta.dt;
    if (a->against) {
        rp->against = a->against;
        rp->dt = NAN;
        snprintf(rp->reference, sizeof rp->reference, "the trace %s", a->against);
        if (sw_trace_read_open(&ref, a->against, err, sizeof err) != SW_OK) {
            status = report_error(rp, err);
            goto done;
        }
        have_ref = 1;
        if (ref.meta.scene != got.meta.scene || ref.ncols != got.ncols) {
            snprintf(err, sizeof err, "%s:%ld: a '%s' trace with %d columns cannot be compared "
                     "with %s, a '%s' trace with %d columns", a->trace, got.meta.scene_line,
                     got.meta.scene->name, got.ncols, a->against, ref.meta.scene->name, ref.ncols);
            status = report_error(rp, err);
            goto done;
        }
        if (sw_trace_read_header(&ref, err, sizeof err) != SW_OK) {
            status = report_error(rp, err);
            goto done;
        }
        src_e.reader = &ref;
    } else {
        const sw_integrator *m = NULL;
        if (a->reference && sw_cli_integrator(a->reference, &m) != SW_EXIT_OK) {
            status = json_error(rp, "--reference names no integrator (see stderr)");
            goto done;
        }
        if (sw_trace_meta_sim(&got, &sim, m, err, sizeof err) != SW_OK) {
            status = report_error(rp, err);
            goto done;
        }
        have_sim = 1;
        rp->ref_sim = &sim;
        rp->method = sim.method->name;
        snprintf(rp->reference, sizeof rp->reference, "%s on %s, regenerated from the trace's "
                 "metadata%s", sim.method->name, rp->scene, m ? " with --reference" : "");
        src_e.sim = &sim;
        src_e.spec = got.meta.spec;
    }
    if (sw_trace_read_header(&got, err, sizeof err) != SW_OK) {
        status = report_error(rp, err);
        goto done;
    }
    src_g.reader = &got;
    sw_check_result res;
    if (sw_check_compare(&src_e, &src_g, got.ncols, rp->rtol, rp->atol, &res, err, sizeof err) != SW_OK)
        status = report_error(rp, err);
    else
        status = print_report(rp, &res);
done:
    if (have_sim)
        sw_sim_free(&sim);
    if (have_ref)
        sw_trace_read_close(&ref);
    sw_trace_read_close(&got);
    return status;
}

/* Run a plugin and a built-in method with the same settings and compare. */
static int check_plugin(report *rp, check_args *a)
{
    char err[SW_ERRLEN];
    const sw_integrator *plugin = NULL, *ref = NULL;
    if (!a->reference)
        return report_error(rp, "check: the plugin form needs --reference NAME, the built-in "
                            "method to grade against (e.g. --reference euler)");
    if (sw_cli_scene(a->scene_name, &a->o.scene) != SW_EXIT_OK)
        return json_error(rp, "check: --scene names no scene (see stderr)");
    if (a->integrator) {
        if (sw_cli_integrator(a->integrator, &plugin) != SW_EXIT_OK)
            return json_error(rp, "check: --integrator names no integrator (see stderr)");
    } else
        plugin = sw_integrator_at(sw_integrator_count() - 1);
    if (!(plugin->flags & SW_PLUGIN)) {
        snprintf(err, sizeof err, "check: '%s' is a built-in method; the plugin form grades a "
                 "plugin's integrator (give --plugin PATH.so)", plugin->name);
        return report_error(rp, err);
    }
    if (sw_cli_integrator(a->reference, &ref) != SW_EXIT_OK)
        return json_error(rp, "check: --reference names no integrator (see stderr)");
    a->o.method = ref;
    if (sw_cli_finish_opts(&a->o) != SW_EXIT_OK)
        return json_error(rp, "check: bad --set (see stderr)");
    if (a->spec.steps == 0 && !a->have_until)
        a->spec.until = a->o.scene->duration;
    if (sw_trace_spec_check(&a->spec, a->o.dt, err, sizeof err) != SW_OK) {
        char msg[SW_ERRLEN + 16];
        snprintf(msg, sizeof msg, "check: %s", err);
        return report_error(rp, msg);
    }
    sw_sim ref_sim, got_sim;
    if (sw_cli_sim(&ref_sim, &a->o) != SW_EXIT_OK)
        return json_error(rp, "check: the reference run could not start (see stderr)");
    a->o.method = plugin;
    if (sw_cli_sim(&got_sim, &a->o) != SW_EXIT_OK) {
        sw_sim_free(&ref_sim);
        return json_error(rp, "check: the plugin run could not start (see stderr)");
    }
    rp->plugin = plugin->name;
    rp->scene = a->o.scene->name;
    rp->method = ref->name;
    rp->dt = a->o.dt;
    rp->sys = &ref_sim.sys;
    rp->ref_sim = &ref_sim;
    rp->got_sim = &got_sim;
    snprintf(rp->what, sizeof rp->what, "plugin %s on %s", plugin->name, rp->scene);
    snprintf(rp->reference, sizeof rp->reference, "%s on %s with the same settings", ref->name,
             rp->scene);
    sw_row_source src_e = { .sim = &ref_sim, .spec = a->spec };
    sw_row_source src_g = { .sim = &got_sim, .spec = a->spec };
    sw_check_result res;
    int status;
    if (sw_check_compare(&src_e, &src_g, sw_trace_ncols(&ref_sim.sys), rp->rtol, rp->atol, &res,
                         err, sizeof err) != SW_OK) {
        char msg[SW_ERRLEN + 16];
        snprintf(msg, sizeof msg, "check: %s", err);
        status = report_error(rp, msg);
    } else
        status = print_report(rp, &res);
    sw_sim_free(&got_sim);
    sw_sim_free(&ref_sim);
    return status;
}

static int bad_option(int opt, char **argv)
{
    if (opt == ':')
        return sw_cli_error("check: option '%s' needs a value; see 'stepwise check --help'",
                            argv[optind - 1]);
    return sw_cli_error("check: unknown option '%s'; see 'stepwise check --help'", argv[optind - 1]);
}

int sw_cmd_check(int argc, char **argv)
{
    enum { O_AGAINST = 256, O_REFERENCE, O_PLUGIN, O_SCENE, O_DT, O_RTOL, O_ATOL, O_JSON };
    static const struct option longopts[] = {
        { "against", required_argument, NULL, O_AGAINST },
        { "reference", required_argument, NULL, O_REFERENCE },
        { "plugin", required_argument, NULL, O_PLUGIN },
        { "scene", required_argument, NULL, O_SCENE },
        { "integrator", required_argument, NULL, 'i' },
        { "dt", required_argument, NULL, O_DT },
        { "steps", required_argument, NULL, 'n' },
        { "until", required_argument, NULL, 'u' },
        { "set", required_argument, NULL, 's' },
        { "every", required_argument, NULL, 'k' },
        { "rtol", required_argument, NULL, O_RTOL },
        { "atol", required_argument, NULL, O_ATOL },
        { "json", no_argument, NULL, O_JSON },
        { "help", no_argument, NULL, 'h' },
        { NULL, 0, NULL, 0 },
    };
    check_args a;
    memset(&a, 0, sizeof a);
    a.spec.every = 1;
    report rp;
    memset(&rp, 0, sizeof rp);
    rp.rtol = SW_CHECK_RTOL;
    rp.atol = SW_CHECK_ATOL;
    rp.dt = NAN;
    const char *plugins[8];
    int nplugins = 0, opt;
    opterr = 0;
    optind = 1;
    while ((opt = getopt_long(argc, argv, ":i:n:u:s:k:h", longopts, NULL)) != -1) {
        int rc = SW_EXIT_OK;
        switch (opt) {
        case O_AGAINST: a.against = optarg; break;
        case O_REFERENCE: a.reference = optarg; break;
        case O_PLUGIN:
            if (nplugins == 8)
                return sw_cli_error("check: at most 8 --plugin options");
            plugins[nplugins++] = optarg;
            break;
        case O_SCENE: a.scene_name = optarg; break;
        case 'i': a.integrator = optarg; a.run_opts = 1; break;
        case O_DT: rc = sw_cli_dt("--dt", optarg, &a.o.dt); a.run_opts = 1; break;
        case 'n':
            rc = sw_cli_long("--steps", optarg, 1, SW_TRACE_MAX_STEPS, &a.spec.steps);
            a.run_opts = 1;
            break;
        case 'u':
            rc = sw_cli_positive("--until", optarg, &a.spec.until);
            a.have_until = a.run_opts = 1;
            break;
        case 's': rc = sw_cli_add_set(&a.o, optarg); a.run_opts = 1; break;
        case 'k':
            rc = sw_cli_long("--every", optarg, 1, SW_TRACE_MAX_STEPS, &a.spec.every);
            a.run_opts = 1;
            break;
        case O_RTOL: rc = sw_cli_positive("--rtol", optarg, &rp.rtol); break;
        case O_ATOL: rc = sw_cli_positive("--atol", optarg, &rp.atol); break;
        case O_JSON: rp.json = 1; break;
        case 'h': fputs(check_help, stdout); return SW_EXIT_OK;
        default: return bad_option(opt, argv);
        }
        if (rc != SW_EXIT_OK)
            return rc;
    }
    int npos = argc - optind;
    if (npos > 1)
        return report_error(&rp, "check takes one trace file; see 'stepwise check --help'");
    a.trace = npos == 1 ? argv[optind] : NULL;
    if (a.trace && a.scene_name)
        return report_error(&rp, "check: give a TRACE or --scene (the plugin form), not both");
    if (!a.trace && !a.scene_name)
        return report_error(&rp, "check needs a trace file, or --plugin PATH.so --reference NAME "
                            "--scene SCENE; see 'stepwise check --help'");
    if (a.trace && a.run_opts)
        return report_error(&rp, "check: --integrator, --dt, --steps, --until, --set and --every "
                            "belong to the plugin form (--scene); a trace's metadata sets them");
    if (a.against && a.reference)
        return report_error(&rp, "check: --against REF and --reference NAME exclude each other");
    if (a.spec.steps > 0 && a.have_until)
        return report_error(&rp, "check: give --steps or --until, not both");
    if (!a.trace && nplugins == 0)
        return report_error(&rp, "check: the --scene form grades a plugin: give --plugin PATH.so");
    for (int i = 0; i < nplugins; i++)
        if (sw_cli_plugin(plugins[i]) != SW_EXIT_OK)
            return json_error(&rp, "check: the plugin could not be loaded (see stderr)");
    return a.trace ? check_trace(&rp, &a) : check_plugin(&rp, &a);
}
