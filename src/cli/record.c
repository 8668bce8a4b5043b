/* `stepwise record`: run a scene headless and stream a step trace to a file
 * (temporary name, renamed when complete) or to stdout. A blow-up is a
 * result: the trace ends at the diverged step and the exit status is 0. */
#include "cli/cli.h"

#include <getopt.h>
#include <string.h>

#include "plugin/plugin.h"
#include "trace/trace.h"
#include "grade/verdict.h"
#include "util/signals.h"

static const char record_help[] =
    "usage: stepwise record SCENE [--integrator NAME] [--dt H] [--steps N | --until T]\n"
    "                       [--set PARAM=VALUE]... [--every K] [--rtol R --atol A]\n"
    "                       [--events locate|step] [--plugin PATH.so]... [-o FILE]\n"
    "\n"
    "Runs SCENE headless and writes a step trace: CSV with metadata that regenerates\n"
    "the run (see docs/trace-format.md). A blow-up is a result, not an error: the\n"
    "trace ends at the step that diverged, says so in a '# diverged:' line and on\n"
    "stderr, and the exit status is 0.\n"
    "\n"
    "options:\n"
    "  -i, --integrator NAME  method (default: the scene's; 'stepwise list integrators')\n"
    "      --dt H             step size, in [1e-09, 1000] (default: the scene's)\n"
    "  -n, --steps N          run N steps, 1 to 10000000 (adaptive: accepted steps)\n"
    "  -u, --until T          run until time T, at most 10000000 steps of dt\n"
    "                         (default: the scene's report time, 'stepwise describe SCENE')\n"
    "  -s, --set PARAM=VALUE  set a scene parameter; repeatable\n"
    "  -k, --every K          record step 0, every K-th step and the last (default 1)\n"
    "      --rtol R           adaptive methods' relative tolerance (default 1e-06)\n"
    "      --atol A           adaptive methods' absolute tolerance (default 1e-09)\n"
    SW_CLI_EVENTS_HELP
    "      --plugin PATH.so   load a student integrator (docs/plugins.md); repeatable;\n"
    "                         without --integrator the last one loaded is used\n"
    "  -o, --output FILE      write to FILE instead of standard output; FILE appears only\n"
    "                         once the trace is complete\n"
    "  -h, --help             this help\n"
    "\n"
    "exit status: 0 trace written (a blow-up included), 1 a plugin failed (crashed, exited,\n"
    "looped, overran its vectors; the trace ends at that step), 2 bad input or a write error.\n";

static int bad_option(const char *cmd, int opt, char **argv)
{
    if (opt == ':')
        return sw_cli_error("%s: option '%s' needs a value; see 'stepwise %s --help'", cmd,
                            argv[optind - 1], cmd);
    return sw_cli_error("%s: unknown option '%s'; see 'stepwise %s --help'", cmd,
                        argv[optind - 1], cmd);
}

int sw_cmd_record(int argc, char **argv)
{
    static const struct option longopts[] = {
        { "integrator", required_argument, NULL, 'i' },
        { "dt", required_argument, NULL, 'd' },
        { "steps", required_argument, NULL, 'n' },
        { "until", required_argument, NULL, 'u' },
        { "set", required_argument, NULL, 's' },
        { "every", required_argument, NULL, 'k' },
        { "rtol", required_argument, NULL, 'r' },
        { "atol", required_argument, NULL, 'a' },
        { "plugin", required_argument, NULL, 'p' },
        { "events", required_argument, NULL, 'e' },
        { "output", required_argument, NULL, 'o' },
        { "help", no_argument, NULL, 'h' },
        { NULL, 0, NULL, 0 },
    };
    sw_run_opts o;
    memset(&o, 0, sizeof o);
    sw_trace_spec spec = { .steps = 0, .until = 0, .every = 1 };
    const char *integrator = NULL, *output = NULL, *plugins[8];
    int nplugins = 0, have_until = 0, opt;
    opterr = 0;
    optind = 1;
    while ((opt = getopt_long(argc, argv, ":i:n:u:s:k:o:h", longopts, NULL)) != -1) {
        int rc = SW_EXIT_OK;
        switch (opt) {
        case 'i': integrator = optarg; break;
        case 'd': rc = sw_cli_dt("--dt", optarg, &o.dt); break;
        case 'n': rc = sw_cli_long("--steps", optarg, 1, SW_TRACE_MAX_STEPS, &spec.steps); break;
        case 'u': rc = sw_cli_positive("--until", optarg, &spec.until); have_until = 1; break;
        case 's': rc = sw_cli_add_set(&o, optarg); break;
        case 'k': rc = sw_cli_long("--every", optarg, 1, SW_TRACE_MAX_STEPS, &spec.every); break;
        case 'r': rc = sw_cli_tolerance("--rtol", optarg, &o.rtol); break;
        case 'a': rc = sw_cli_tolerance("--atol", optarg, &o.atol); break;
        case 'o': output = optarg; break;
        case 'e': rc = sw_cli_events(optarg, &o.events); break;
        case 'p':
            if (nplugins == 8)
                return sw_cli_error("record: at most 8 --plugin options");
            plugins[nplugins++] = optarg;
            break;
        case 'h': fputs(record_help, stdout); return SW_EXIT_OK;
        default: return bad_option("record", opt, argv);
        }
        if (rc != SW_EXIT_OK)
            return rc;
    }
    if (optind != argc - 1)
        return sw_cli_error("record takes one scene name (got %d arguments); see 'stepwise list "
                            "scenes' and 'stepwise record --help'", argc - optind);
    if (spec.steps > 0 && have_until)
        return sw_cli_error("record: give --steps or --until, not both");
    if (sw_cli_scene(argv[optind], &o.scene) != SW_EXIT_OK)
        return SW_EXIT_USAGE;
    for (int i = 0; i < nplugins; i++)
        if (sw_cli_plugin("--plugin", plugins[i], NULL) != SW_EXIT_OK)
            return SW_EXIT_USAGE;
    if (integrator && sw_cli_integrator(integrator, &o.method) != SW_EXIT_OK)
        return SW_EXIT_USAGE;
    if (!integrator && nplugins > 0)
        o.method = sw_integrator_at(sw_integrator_count() - 1);
    if (sw_cli_finish_opts(&o) != SW_EXIT_OK)
        return SW_EXIT_USAGE;
    if (spec.steps == 0 && !have_until)
        spec.until = o.scene->duration;

    char err[SW_ERRLEN];
    if (sw_trace_spec_check(&spec, o.dt, err, sizeof err) != SW_OK)
        return sw_cli_error("record: %s", err);
    /* Refused before anything is written, even to standard output. */
    double work;
    if (sw_check_budget(o.scene, o.p, o.method, o.dt, &spec, &work, err, sizeof err) != SW_OK)
        return sw_cli_error("record: %s", err);
    if (sw_record_budget(o.scene, o.p, o.dt, &spec, err, sizeof err) != SW_OK)
        return sw_cli_error("record: %s", err);
    sw_sim sim;
    if (sw_cli_sim(&sim, &o) != SW_EXIT_OK)
        return SW_EXIT_USAGE;
    sw_trace_writer w;
    if (sw_trace_open(&w, output, err, sizeof err) != SW_OK) {
        sw_sim_free(&sim);
        return sw_cli_error("record: %s", err);
    }
    sw_signals_catch();
    int rc = sw_trace_begin(&w, &sim, &spec, err, sizeof err);
    while (rc == SW_OK && !sw_trace_done(&sim, &spec) && !sw_signal_caught) {
        rc = sw_trace_step(&sim, &spec, err, sizeof err);
        if (rc == SW_OK)
            rc = sw_trace_observe(&w, &sim, err, sizeof err);
    }
    if (sw_signal_caught) {
        sw_trace_abort(&w);
        sw_cli_note("record interrupted at step %ld; %s", sim.steps,
                w.to_stdout ? "the trace on standard output is incomplete" : "no trace written");
        sw_sim_free(&sim);
        sw_signals_reraise(sw_signal_caught);
        return SW_EXIT_USAGE;
    }
    if (rc == SW_OK)
        rc = sw_trace_commit(&w, &sim, err, sizeof err);
    else
        sw_trace_abort(&w);
    if (rc != SW_OK) {
        sw_sim_free(&sim);
        return sw_cli_error("record: %s%s", err, output ? "; no trace written" : "");
    }
    if (sim.blown && sw_plugin_failed(&sim) != SW_PF_NONE) {
        /* Not a numerical result: the plugin is broken. The trace shows how far it got. */
        sw_cli_note("%s (plugin) failed on %s: %s (t = %g); the trace ends there",
                sim.method->name, o.scene->name, sim.blow_reason, sim.blow_time);
        sw_sim_free(&sim);
        return SW_EXIT_FAIL;
    }
    if (sim.blown)
        sw_cli_note("%s under %s%s %s at step %ld (t = %g): %s; the trace "
                "ends there", o.scene->name, sim.method->name,
                (sim.method->flags & SW_PLUGIN) ? " (plugin)" : "",
                sw_sim_refused(sim.blow_reason) ? "stopped" : "diverged",
                sim.blow_step, sim.blow_time, sim.blow_reason);
    else if (output && strcmp(output, "-") != 0)
        sw_cli_note("wrote %ld rows (steps 0 to %ld, t = 0 to %g) to %s",
                w.rows, sim.steps, sim.t, output);
    sw_sim_free(&sim);
    return SW_EXIT_OK;
}
