/* `stepwise check`: grade a trace against a reference regenerated from its
 * metadata or from an assignment, against another trace (--against), or
 * grade a plugin integrator against a built-in one. The check itself is
 * grade/verdict.c; this file parses options and prints the plain or JSON
 * report (cli/check_report.c). Exit 0 pass, 1 mismatch, 2 unusable input;
 * with --json every outcome, option errors included, is a JSON object. */
#include "cli/cli.h"

#include <getopt.h>
#include <math.h>
#include <string.h>

#include "cli/check_report.h"
#include "grade/homework.h"
#include "grade/verdict.h"
#include "plugin/jail.h"
#include "plugin/plugin_build.h"

static const char check_help[] =
    "usage: stepwise check TRACE [--assignment A | --against REF | --reference NAME]\n"
    "                      [--plugin PATH]... [--rtol R] [--atol A] [--tol COL=REL[,ABS]]...\n"
    "                      [--ignore COL]... [--no-explain] [--json]\n"
    "       stepwise check --plugin PATH (--assignment A | --reference NAME --scene SCENE\n"
    "                      [--integrator NAME] [--dt H] [--steps N | --until T]\n"
    "                      [--set PARAM=VALUE]... [--every K]) [--no-measure] [--json] ...\n"
    "\n"
    "Compares a step trace with a reference, value by value: a value passes when\n"
    "|got - expected| <= atol + rtol*|expected|; equal nan or inf values pass. The\n"
    "reference is regenerated from TRACE's own metadata, from an assignment (whose\n"
    "header differences are listed first), or read from REF. On a failure the usual\n"
    "mistakes are tried and the one that matches is named. The second form runs a\n"
    "plugin and a built-in method with the same settings, compares them, and puts the\n"
    "plugin's measured order and stability limit beside the claimed ones. A plugin\n"
    "runs in its own jailed process (the plugin host) with a watchdog; one that\n"
    "crashes, exits, loops, allocates or overruns its vectors fails, with the step.\n"
    "See docs/trace-format.md.\n"
    "\n"
    "options:\n"
    "      --assignment A     check against the run the assignment A describes (a small\n"
    "                         metadata file, or a reference trace whose header serves)\n"
    "      --against REF      compare with the trace REF instead of regenerating\n"
    "      --reference NAME   regenerate with integrator NAME instead of TRACE's own\n"
    "      --plugin PATH      load a student integrator, .so or .c (docs/plugins.md); repeatable\n"
    "      --scene SCENE      plugin form: the scene to run\n"
    "  -i, --integrator NAME  plugin form: the plugin's integrator (default: the last loaded)\n"
    "      --dt H             plugin form: step size (default: the scene's)\n"
    "  -n, --steps N          plugin form: run N steps, 1 to 10000000\n"
    "  -u, --until T          plugin form: run until T (default: the scene's report time)\n"
    "  -s, --set PARAM=VALUE  plugin form: set a scene parameter; repeatable\n"
    "  -k, --every K          plugin form: compare step 0, every K-th step and the last\n"
    "      --rtol R           relative tolerance (default 1e-09, or the assignment's)\n"
    "      --atol A           absolute tolerance (default 1e-09, or the assignment's)\n"
    "      --tol COL=REL[,ABS]  tolerance for one column (a prefix ending in '*' names\n"
    "                         several, e.g. vx*=1e-6); repeatable\n"
    "      --ignore COL       leave a column out of the comparison; repeatable\n"
    "      --no-explain       do not try the usual mistakes on a failure\n"
    "      --no-measure       plugin form: do not measure order and stability\n"
    "      --no-sandbox       plugin form: run the plugin without the jail, only in a\n"
    "                         disposable container (docs/sandbox.md)\n"
    "      --plugin-timeout S seconds of its own CPU time (or asleep) a plugin may take for one step (default 2)\n"
    "      --json             print a JSON report (fields in docs/trace-format.md)\n"
    "  -h, --help             this help\n"
    "\n"
    "exit status: 0 pass, 1 mismatch (or a failed plugin), 2 unusable input (one line\n"
    "on stderr naming file and line).\n";

enum { O_AGAINST = 256, O_REFERENCE, O_PLUGIN, O_SCENE, O_DT, O_RTOL, O_ATOL, O_JSON,
       O_ASSIGNMENT, O_TOL, O_IGNORE, O_NO_EXPLAIN, O_NO_MEASURE, O_TIMEOUT,
       O_NO_SANDBOX };

typedef struct check_args {
    sw_check_request req;
    const char *trace, *against, *reference, *integrator, *scene_name, *assignment;
    sw_run_opts o;
    int have_until, run_opts, json;
} check_args;

/* An unusable input: one line on stderr and, with --json, an error object. */
static int fail_usage(const check_args *a, const char *fmt, const char *detail)
{
    char msg[SW_ERRLEN + SW_TRACE_PATH_MAX];
    snprintf(msg, sizeof msg, fmt, detail ? detail : "");
    sw_cli_error("%s", msg);
    if (a->json)
        sw_check_print_error(msg);
    return SW_EXIT_USAGE;
}

/* A helper already printed its line on stderr: with --json, say where. */
static int failed_helper(const check_args *a, const char *what)
{
    if (a->json)
        sw_check_print_error(what);
    return SW_EXIT_USAGE;
}

/* The part's points, check by check, as the grader gives them: a PASS
 * may lose one (an order not measured), a FAIL keep all (a column the
 * points do not read). */
static void print_points(const sw_verdict *v)
{
    const char *tail = v->status != SW_VERDICT_PASS && !(v->score.score < v->score.max)
                           ? ", as the grader would give them (the difference above is in values they do not "
                             "read):"
                           : ", as the grader would give them:";
    sw_score_print(stdout, &v->score, "  ", tail);
}

static int plugin_form(check_args *a)
{
    sw_check_request *req = &a->req;
    if (a->integrator) {
        if (sw_cli_integrator(a->integrator, &req->plugin) != SW_EXIT_OK)
            return failed_helper(a, "check: --integrator names no integrator (see stderr)");
    } else
        req->plugin = sw_integrator_at(sw_integrator_count() - 1);
    if (!(req->plugin->flags & SW_PLUGIN))
        return fail_usage(a, "check: '%s' is a built-in method; the plugin form grades a plugin's "
                          "integrator (give --plugin PATH)", req->plugin->name);
    if (a->assignment)
        return SW_EXIT_OK;
    if (!a->reference)
        return fail_usage(a, "check: the plugin form needs --reference NAME, the built-in method "
                          "to grade against (e.g. --reference euler), or --assignment A%s", NULL);
    if (sw_cli_scene(a->scene_name, &a->o.scene) != SW_EXIT_OK)
        return failed_helper(a, "check: --scene names no scene (see stderr)");
    a->o.method = req->reference;
    if (sw_cli_finish_opts(&a->o) != SW_EXIT_OK)
        return failed_helper(a, "check: bad --set (see stderr)");
    if (a->req.spec.steps == 0 && !a->have_until)
        a->req.spec.until = a->o.scene->duration;
    char err[SW_ERRLEN];
    if (sw_trace_spec_check(&req->spec, a->o.dt, err, sizeof err) != SW_OK)
        return fail_usage(a, "check: %s", err);
    req->scene = a->o.scene;
    memcpy(req->p, a->o.p, sizeof req->p);
    req->dt = a->o.dt;
    return SW_EXIT_OK;
}

static int bad_option(const check_args *a, int opt, char **argv)
{
    char msg[200];
    if (opt == ':')
        snprintf(msg, sizeof msg, "check: option '%.60s' needs a value; see 'stepwise check --help'",
                 argv[optind - 1]);
    else
        snprintf(msg, sizeof msg, "check: unknown option '%.60s'; see 'stepwise check --help'",
                 argv[optind - 1]);
    return fail_usage(a, "%s", msg);
}

/* Parse one option; SW_EXIT_OK or the exit status of a failure. */
static int take_option(check_args *a, int opt, const char **plugins, int *nplugins, char **argv)
{
    sw_check_request *req = &a->req;
    char err[SW_ERRLEN];
    int rc = SW_EXIT_OK;
    switch (opt) {
    case O_AGAINST: a->against = optarg; break;
    case O_REFERENCE: a->reference = optarg; break;
    case O_ASSIGNMENT: a->assignment = optarg; break;
    case O_PLUGIN:
        if (*nplugins == 8)
            return fail_usage(a, "check: at most 8 --plugin options%s", NULL);
        plugins[(*nplugins)++] = optarg;
        break;
    case O_SCENE: a->scene_name = optarg; break;
    case 'i': a->integrator = optarg; a->run_opts = 1; break;
    case O_DT: rc = sw_cli_dt("--dt", optarg, &a->o.dt); a->run_opts = 1; break;
    case 'n':
        rc = sw_cli_long("--steps", optarg, 1, SW_TRACE_MAX_STEPS, &req->spec.steps);
        a->run_opts = 1;
        break;
    case 'u':
        rc = sw_cli_positive("--until", optarg, &req->spec.until);
        a->have_until = a->run_opts = 1;
        break;
    case 's': rc = sw_cli_add_set(&a->o, optarg); a->run_opts = 1; break;
    case 'k':
        rc = sw_cli_long("--every", optarg, 1, SW_TRACE_MAX_STEPS, &req->spec.every);
        a->run_opts = 1;
        break;
    case O_RTOL: rc = sw_cli_positive("--rtol", optarg, &req->rtol); break;
    case O_ATOL: rc = sw_cli_positive("--atol", optarg, &req->atol); break;
    case O_TOL:
    case O_IGNORE:
        if (sw_coltol_parse(&req->coltols, optarg, opt == O_IGNORE, opt == O_TOL ? "--tol" : "--ignore",
                            err, sizeof err) != SW_OK)
            return fail_usage(a, "check: %s", err);
        break;
    case O_NO_EXPLAIN: req->explain = 0; break;
    case O_NO_MEASURE: req->measure = 0; break;
    case O_NO_SANDBOX: sw_jail_set_enabled(0); break;
    case O_TIMEOUT: {
        double s;
        rc = sw_cli_positive("--plugin-timeout", optarg, &s);
        if (rc == SW_EXIT_OK)
            sw_plugin_set_timeout(s);
        break;
    }
    case O_JSON: break;
    case 'h': fputs(check_help, stdout); return -1;
    default: return bad_option(a, opt, argv);
    }
    return rc == SW_EXIT_OK ? rc : failed_helper(a, "check: a bad option value (see stderr)");
}

int sw_cmd_check(int argc, char **argv)
{
    static const struct option longopts[] = {
        { "against", required_argument, NULL, O_AGAINST },
        { "reference", required_argument, NULL, O_REFERENCE },
        { "assignment", required_argument, NULL, O_ASSIGNMENT },
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
        { "tol", required_argument, NULL, O_TOL },
        { "ignore", required_argument, NULL, O_IGNORE },
        { "no-explain", no_argument, NULL, O_NO_EXPLAIN },
        { "no-measure", no_argument, NULL, O_NO_MEASURE },
        { "no-sandbox", no_argument, NULL, O_NO_SANDBOX },
        { "plugin-timeout", required_argument, NULL, O_TIMEOUT },
        { "json", no_argument, NULL, O_JSON },
        { "help", no_argument, NULL, 'h' },
        { NULL, 0, NULL, 0 },
    };
    check_args a;
    memset(&a, 0, sizeof a);
    sw_check_request_init(&a.req);
    a.req.measure = 1;
    /* --json anywhere makes every outcome JSON, option errors before it too. */
    for (int i = 1; i < argc && strcmp(argv[i], "--") != 0; i++)
        a.json |= strcmp(argv[i], "--json") == 0;
    const char *plugins[8];
    int nplugins = 0, opt;
    opterr = 0;
    optind = 1;
    while ((opt = getopt_long(argc, argv, ":i:n:u:s:k:h", longopts, NULL)) != -1) {
        int rc = take_option(&a, opt, plugins, &nplugins, argv);
        if (rc != SW_EXIT_OK)
            return rc < 0 ? SW_EXIT_OK : rc;
    }
    int npos = argc - optind;
    if (npos > 1)
        return fail_usage(&a, "check takes one trace file (got %s more); to grade many, use "
                          "'stepwise grade'", argv[optind + 1]);
    a.trace = npos == 1 ? argv[optind] : NULL;
    int plugin_run = !a.trace && (a.scene_name || (a.assignment && nplugins > 0));
    if (a.trace && a.scene_name)
        return fail_usage(&a, "check: give a TRACE or --scene (the plugin form), not both%s", NULL);
    if (!a.trace && !plugin_run)
        return fail_usage(&a, "check needs a trace file, or --plugin PATH with --assignment A or "
                          "--reference NAME --scene SCENE; see 'stepwise check --help'%s", NULL);
    if ((a.trace || a.assignment) && a.run_opts)
        return fail_usage(&a, "check: --integrator, --dt, --steps, --until, --set and --every "
                          "belong to the plugin form with --scene; a trace's metadata or the "
                          "assignment sets them%s", NULL);
    if ((a.against != NULL) + (a.reference != NULL && a.trace) + (a.assignment != NULL) > 1)
        return fail_usage(&a, "check: --against, --reference and --assignment exclude each other "
                          "for a trace%s", NULL);
    if (a.req.spec.steps > 0 && a.have_until)
        return fail_usage(&a, "check: give --steps or --until, not both%s", NULL);
    if (plugin_run && nplugins == 0)
        return fail_usage(&a, "check: the --scene form grades a plugin: give --plugin PATH%s", NULL);
    for (int i = 0; i < nplugins; i++) {
        sw_build_warnings warn = { 0 };
        if (sw_cli_plugin("--plugin", plugins[i], &warn) != SW_EXIT_OK)
            return failed_helper(&a, "check: the plugin could not be loaded (see stderr)");
        if (warn.count && !a.json) /* as try and grade's feedback say them */
            printf("note: the compiler warned %d time%s (nothing is taken off; a warning is often a bug); "
                   "the first: %s\n", warn.count, warn.count == 1 ? "" : "s", warn.first);
    }
    if (a.reference && sw_cli_integrator(a.reference, &a.req.reference) != SW_EXIT_OK)
        return failed_helper(&a, "check: --reference names no integrator (see stderr)");
    static sw_homework hw;
    char err[SW_ERRLEN + SW_TRACE_PATH_MAX];
    int first = 0, last = 1; /* the parts to check */
    if (a.assignment) {
        if (sw_homework_read(&hw, a.assignment, NULL, err, sizeof err) != SW_OK) {
            sw_homework_free(&hw);
            return fail_usage(&a, "%s", err);
        }
        sw_homework_free(&hw);
        a.req.assignment = &hw.parts[0].a;
        char why[200], msg[300];
        if (!sw_assignment_kind_ok(&hw.parts[0].a, plugin_run, NULL, why, sizeof why)) {
            snprintf(msg, sizeof msg, "%s: %s", why, plugin_run ? "give the trace you recorded"
                     : hw.parts[0].a.source_only ? "give --plugin FILE (your .c)"
                                                 : "give --plugin FILE (your .c or .so)");
            return fail_usage(&a, "check: %s", msg);
        }
        for (int i = 0; plugin_run && i < nplugins; i++)
            if (!sw_assignment_kind_ok(&hw.parts[0].a, 1, plugins[i], why, sizeof why))
                return fail_usage(&a, "check: %s", why);
        last = hw.nparts;
        if (a.trace) {
            sw_trace_reader r;
            if (sw_trace_read_open(&r, a.trace, err, sizeof err) == SW_OK) {
                first = sw_homework_part_of_trace(&hw, a.trace, &r.meta, err, sizeof err);
                sw_trace_read_close(&r);
                if (first < 0)
                    return fail_usage(&a, "check: %s", err);
                last = first + 1;
            }
        }
    }
    if (plugin_run) {
        int rc = plugin_form(&a);
        if (rc != SW_EXIT_OK)
            return rc;
    }
    a.req.trace = a.trace;
    a.req.against = a.against;
    static sw_verdict v;
    int rc = SW_EXIT_OK, shown = 0, hidden = 0, by[SW_VIS_AFTER_PUBLISHED + 1] = { 0 };
    if (hw.nvarying > 0 && !a.json)
        printf("note: %s draws parameters per student; checked with the first value of each "
               "(your own are on your assignment sheet, 'stepwise handout')\n", a.assignment);
    for (int p = first; p < last; p++) {
        if (a.assignment && hw.parts[p].visibility != SW_VIS_VISIBLE) {
            hidden++;
            by[hw.parts[p].visibility]++;
            continue;
        }
        if (a.assignment)
            a.req.assignment = &hw.parts[p].a;
        if (a.assignment && hw.nparts > 1 && !a.json)
            printf("%s== part %s ==\n", shown ? "\n" : "", hw.parts[p].name);
        if (a.json)
            fputs(shown ? ",\n" : hw.nparts > 1 ? "[\n" : "", stdout);
        sw_check_run(&a.req, &v);
        int one = sw_check_print(&v, a.json);
        if (a.assignment && !a.json && v.status != SW_VERDICT_ERROR)
            print_points(&v);
        if (one > rc)
            rc = one;
        shown++;
    }
    if (a.json && hw.nparts > 1)
        fputs(shown ? "\n]\n" : "[]\n", stdout);
    if (hidden && !a.json)
    {
        printf("%s%d %spart%s of this homework %s graded by the teacher's grader only:", shown ? "\n" : "",
               hidden, shown ? "more " : "", hidden == 1 ? "" : "s", hidden == 1 ? "is" : "are");
        for (int k = SW_VIS_HIDDEN, said = 0; k <= SW_VIS_AFTER_PUBLISHED; k++)
            if (by[k])
                printf("%s %d %s", said++ ? "," : "", by[k], sw_visibility_words((sw_visibility)k));
        printf(".\n");
    }
    return rc;
}
