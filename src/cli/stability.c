/* `stepwise stability SCENE`: each method's largest stable step on a scene,
 * in theory (the truth module: every mode of the linearisation, along the
 * run) and measured (bisection on runs, src/measure/stability.c), side by side,
 * with the reason wherever they differ. `--markdown` prints the same as a
 * table; `stepwise stability --all --markdown` is docs/stability.md's. */
#include "cli/cli.h"

#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "measure/stability.h"
#include "sim/truth.h"
#include "util/num.h"

static const char usage_text[] =
    "usage: stepwise stability SCENE [--integrators LIST] [--set NAME=VALUE] [--plugin FILE]\n"
    "                            [--markdown]\n"
    "       stepwise stability --all [--markdown]\n"
    "\n"
    "Each fixed-step method's largest stable step on SCENE, two ways.\n"
    "\n"
    "Theory: the eigenvalues L of the scene's linearisation d f/d y, taken at 16 times\n"
    "along the true solution (the closed form, or a tight reference run), split into\n"
    "modes; the method's growth per step on a mode is the spectral radius of its own\n"
    "one-step map on that mode's test system, found by stepping it (so damping,\n"
    "Verlet's reused acceleration and plugins are all covered). The limit is the\n"
    "largest dt at which no mode grows. Modes that grow physically (an orbit's tidal\n"
    "stretching, a compressed spring's buckling) and modes an exact symmetry keeps at\n"
    "rest are left out. 'none': the method grows already at |L|*dt = 0.01.\n"
    "\n"
    "Measured: each probe runs the scene at one dt for 100 periods of the stiffest\n"
    "mode (at least 20 report times and 400 steps) and watches M, the energy of the\n"
    "motion (E - E_rest, normalised to 1 at the start; for a flow |y|^2). The step is\n"
    "unstable when the run blows up, when M passes 1000, when M's mean over a\n"
    "twentieth of the run passes a level or that many times its lowest such mean (3;\n"
    "30 for a symplectic method, times its first window's mean where that is above 1:\n"
    "its bounded swing near the limit; an orbit: 2, escape, at any step too) - growth\n"
    "a nonlinearity capped, energy that sank and came back - or when M's peaks climb\n"
    "(16 rises in 19 windows, or the latest peak above the first by more than the\n"
    "first window varied). Bisection between a stable and an unstable dt to 0.01%.\n"
    "Where the limit found lies above the theory's, it is probed again over 4 and 16\n"
    "times as long, and searched again below where a longer run grows. Where the two\n"
    "differ by more than 2%, a line says why.\n"
    "\n"
    "  --integrators LIST  comma-separated methods (default: all fixed-step ones that apply)\n"
    "  --set NAME=VALUE    change a scene parameter, e.g. --set c=0 (undamped spring)\n"
    "  --plugin FILE       load a student integrator (.so) and include it\n"
    "  --all               every scene where growth can be judged, default parameters\n"
    "  -j, --jobs N        with --all: scenes measured N at once, 1 to 64 (default: the\n"
    "                      online cores, at most 8); the report is the same for every N\n"
    "  --markdown          a Markdown table (docs/stability.md is made this way)\n"
    "\n"
    "Each probe runs for a fixed simulated time, so slow growth at small dt has as\n"
    "long to show as fast growth at large dt. Scenes with contact or births at step\n"
    "boundaries, and scenes whose energy has no floor (a projectile falls forever),\n"
    "get the theory only. Where a scene has a resting state, every probe also runs the\n"
    "same motion shrunk 1e4-fold towards it, so that growth cannot hide behind a\n"
    "nonlinearity that caps it (a spring flung through its anchor). docs/stability.md\n"
    "has the table for every scene.\n";

static void limit_text(double dt, int kind_none, int kind_unbounded, char *buf, size_t len)
{
    if (isnan(dt))
        snprintf(buf, len, "failed");
    else if (kind_unbounded)
        snprintf(buf, len, "unbounded");
    else if (kind_none)
        snprintf(buf, len, "none");
    else
        snprintf(buf, len, "%.5g", dt);
}

static void wdt_text(double stiff, double dt, int kind_none, int kind_unbounded, char *buf, size_t len)
{
    if (!(stiff > 0) || isnan(dt))
        snprintf(buf, len, "-");
    else if (kind_unbounded)
        snprintf(buf, len, ">= %.4g", stiff * dt);
    else if (kind_none)
        snprintf(buf, len, "< 0.01");
    else
        snprintf(buf, len, "%.4g", stiff * dt);
}

/* Refuse a report above the work budget before any run starts. */
/* What the report on sc would cost, in state evaluations. */
static double report_cost(const sw_scene *sc, const double *p, const sw_integrator *const *methods, int nmethods)
{
    sw_stability_config cfg;
    sw_stability_config_default(&cfg);
    return sw_stability_cost_sum(sc, p, methods, nmethods, &cfg);
}

static int within_budget(const sw_scene *sc, const double *p, const sw_integrator *const *methods, int nmethods)
{
    double cost = report_cost(sc, p, methods, nmethods);
    if (cost <= SW_WORK_REPORT)
        return 1;
    sw_cli_error("stability on %s would cost about %.2g state evaluations (%d method%s), over the budget of "
                 "%.0e; use fewer particles or pick methods with --integrators", sc->name, cost, nmethods,
                 nmethods == 1 ? "" : "s", SW_WORK_REPORT);
    return 0;
}

/* One scene: a row per method. Returns 0, or 1 when a run failed to start. */
static int report(const sw_scene *sc, const double *p, const sw_integrator *const *methods, int nmethods,
                  int markdown)
{
    sw_stability_config cfg;
    sw_stability_config_default(&cfg);
    char err[SW_ERRLEN];
    int status = 0;
    if (markdown) {
        printf("\n### %s (", sc->name);
        for (int i = 0; i < sc->nparams; i++)
            printf("%s%s=%g", i ? " " : "", sc->params[i].name, p[i]);
        char why[SW_ERRLEN];
        printf(")\n\n");
        if (!sw_stability_measurable(sc, p, why, sizeof why))
            printf("Theory only: %s.\n\n", why);
        printf("| method | theory dt | theory \\|L\\|dt | measured dt | measured \\|L\\|dt | agree |\n"
               "| --- | --- | --- | --- | --- | --- |\n");
    } else {
        printf("stability on %s (", sc->name);
        for (int i = 0; i < sc->nparams; i++)
            printf("%s%s=%g", i ? " " : "", sc->params[i].name, p[i]);
        printf(")\n('stepwise stability --help' gives the criteria)\n");
        sw_system sys;
        sw_spectrum sp;
        if (sw_system_build(&sys, sc, p, err, sizeof err) == SW_OK) {
            if (sw_truth_spectrum(&sys, 0.0, sys.y, &sp) == 0 && sp.largest > 0)
                printf("stiffest mode at the start: |L| = %.6g rad/s%s\n", sp.largest,
                       sp.complete ? "" : " (by power iteration: the stiffest mode only)");
            sw_system_free(&sys);
        }
        char why[SW_ERRLEN];
        if (!sw_stability_measurable(sc, p, why, sizeof why))
            printf("theory only: %s\n", why);
        printf("\n");
        printf("  %-22s %-12s %-10s %-34s %-10s\n", "method", "theory dt", "|L|*dt", "measured dt",
               "|L|*dt");
    }
    for (int i = 0; i < nmethods; i++) {
        const sw_integrator *m = methods[i];
        sw_stability_result r;
        int rc = sw_stability_find(sc, p, m, &cfg, &r, err, sizeof err);
        if (rc == SW_EINVAL) {
            if (!markdown)
                printf("  %-22s skipped: %s\n", m->name, err);
            continue;
        }
        if (rc != SW_OK) {
            sw_cli_note("%s: %s", m->name, err);
            status = 1;
            continue;
        }
        char th[32], thw[32], me[96] = "-", mew[32] = "-";
        int t_none = !r.theory_unbounded && r.theory == 0;
        limit_text(r.theory, t_none, r.theory_unbounded, th, sizeof th);
        wdt_text(r.stiff, r.theory, t_none, r.theory_unbounded, thw, sizeof thw);
        if (r.measured) {
            limit_text(r.dt, r.kind == SW_STAB_NONE, r.kind == SW_STAB_UNBOUNDED, me, sizeof me);
            wdt_text(r.stiff, r.dt, r.kind == SW_STAB_NONE, r.kind == SW_STAB_UNBOUNDED, mew, sizeof mew);
        }
        if (r.measured && r.kind == SW_STAB_LIMIT && !markdown) {
            size_t n = strlen(me);
            snprintf(me + n, sizeof me - n, " (%s at %.5g)", sw_stability_verdict_text(r.fail.verdict), r.dt_unstable);
        }
        if (markdown)
            printf("| %s | %s | %s | %s | %s | %s |\n", m->name, th, thw, me, mew,
                   r.agree ? "yes" : !r.measured ? "theory only" : r.why);
        else {
            printf("  %-22s %-12s %-10s %-34s %-10s\n", m->name, th, thw, me, mew);
            if (r.measured && !r.agree)
                printf("  %-22s differ: %s\n", "", r.why);
            if (r.fail.verdict == SW_PROBE_BLOWN)
                printf("  %-22s (at dt = %.6g: %s)\n", "", r.fail.dt, r.fail.reason);
        }
        fflush(stdout);
    }
    return status;
}

/* One scene of --all at its defaults: its report, or a line saying it is
 * over the budget. cost: report_cost's, when the caller has it, else NAN.
 * 1 when report() found a disagreement. */
static int all_one(const sw_scene *sc, const sw_integrator *const *methods, int nmethods, int markdown,
                   double cost)
{
    double p[SW_MAX_PARAMS];
    char why[SW_ERRLEN];
    sw_scene_fill(sc, NULL, p);
    /* (theory only is cheap: no probe runs) */
    if (sw_stability_measurable(sc, p, why, sizeof why) &&
        (cost = isnan(cost) ? report_cost(sc, p, methods, nmethods) : cost) > SW_WORK_REPORT) {
        int has_n = sw_scene_param_index(sc, "n") >= 0;
        printf(markdown ? "\n### %s\n\nNot measured: it would cost about %.2g state evaluations, "
                          "over the budget of %.0e%s%s%s.\n"
                        : "stability on %s: not measured: it would cost about %.2g state evaluations, "
                          "over the budget of %.0e%s%s%s\n",
               sc->name, cost, SW_WORK_REPORT, has_n ? " (fewer particles measure: stepwise stability " : "",
               has_n ? sc->name : "", has_n ? " --set n=10)" : "");
        return 0;
    }
    return report(sc, p, methods, nmethods, markdown);
}

/* --all: the scenes measured `jobs` at once, each in a child process that
 * writes its report to a temporary file; the reports are printed in the
 * catalog's order, so the output is the same bytes for every jobs (each
 * scene's measurement depends on nothing but the scene). 1 when a report
 * found a disagreement, 2 when a child failed (said on stderr). */
static int all_scenes(const sw_integrator *const *methods, int nmethods, int markdown, int jobs)
{
    int n = sw_scene_count(), status = 0;
    FILE *out[64];
    pid_t pid[64];
    int code[64];
    if (jobs <= 1 || n > 64) {
        for (int i = 0; i < n; i++)
            status |= all_one(sw_scene_at(i), methods, nmethods, markdown, NAN);
        return status;
    }
    /* the costliest first (longest-first scheduling): the last to finish
     * is then a short one */
    int order[64];
    double cost[64];
    for (int i = 0; i < n; i++) {
        double p[SW_MAX_PARAMS];
        sw_scene_fill(sw_scene_at(i), NULL, p);
        cost[i] = report_cost(sw_scene_at(i), p, methods, nmethods);
        order[i] = i;
        for (int j = i; j > 0 && cost[order[j]] > cost[order[j - 1]]; j--) {
            int t = order[j];
            order[j] = order[j - 1];
            order[j - 1] = t;
        }
    }
    fflush(stdout);
    int next = 0, running = 0;
    for (int i = 0; i < n; i++)
        out[i] = NULL;
    while (next < n || running > 0) {
        if (next < n && running < jobs) {
            int i = order[next++];
            pid[i] = -1;
            code[i] = 2;
            if (!(out[i] = tmpfile())) {
                sw_cli_note("stability: no temporary file for %s: %s", sw_scene_at(i)->name, strerror(errno));
                continue;
            }
            pid[i] = fork();
            if (pid[i] == 0) {
                prctl(PR_SET_PDEATHSIG, SIGKILL); /* never outlives the report */
                int rc = dup2(fileno(out[i]), STDOUT_FILENO) < 0 ? 2
                         : all_one(sw_scene_at(i), methods, nmethods, markdown, cost[i]);
                _exit(fflush(stdout) == 0 ? rc : 2);
            }
            if (pid[i] < 0)
                sw_cli_note("stability: could not start the measurement of %s: %s", sw_scene_at(i)->name,
                            strerror(errno));
            else
                running++;
            continue;
        }
        int wst;
        pid_t done = wait(&wst);
        if (done < 0) {
            if (errno == EINTR)
                continue;
            break;
        }
        for (int k = 0; k < next; k++)
            if (pid[order[k]] == done) {
                int i = order[k];
                code[i] = WIFEXITED(wst) ? WEXITSTATUS(wst) : 2;
                running--;
            }
    }
    for (int i = 0; i < n; i++) {
        if (out[i] && code[i] != 2) {
            rewind(out[i]);
            char buf[4096];
            for (size_t got; (got = fread(buf, 1, sizeof buf, out[i])) > 0;)
                fwrite(buf, 1, got, stdout);
        } else
            sw_cli_note("stability: the measurement of %s failed", sw_scene_at(i)->name);
        if (out[i])
            fclose(out[i]);
        status |= code[i] == 1 ? 1 : code[i] ? 2 : 0;
    }
    return status;
}

int sw_cmd_stability(int argc, char **argv)
{
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(usage_text, stdout);
            return SW_EXIT_OK;
        }
    sw_run_opts opts;
    memset(&opts, 0, sizeof opts);
    const char *plugins[8];
    char *methods_arg = NULL;
    int nplugins = 0, all = 0, markdown = 0, jobs = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        int takes = strcmp(a, "--integrators") == 0 || strcmp(a, "--set") == 0 ||
                    strcmp(a, "--plugin") == 0 || strcmp(a, "--jobs") == 0 || strcmp(a, "-j") == 0;
        if (takes && i + 1 >= argc)
            return sw_cli_error("%s needs a value; see 'stepwise stability --help'", a);
        if (strcmp(a, "--integrators") == 0)
            methods_arg = argv[++i];
        else if (strcmp(a, "--set") == 0) {
            if (sw_cli_add_set(&opts, argv[++i]) != SW_EXIT_OK)
                return SW_EXIT_USAGE;
        } else if (strcmp(a, "--plugin") == 0) {
            if (nplugins == 8)
                return sw_cli_error("at most 8 --plugin options");
            plugins[nplugins++] = argv[++i];
        } else if (strcmp(a, "--jobs") == 0 || strcmp(a, "-j") == 0) {
            long j;
            if (sw_parse_long(argv[++i], 1, 64, &j) != SW_OK)
                return sw_cli_error("%s '%.40s' is not allowed: it takes a whole number of scenes measured at "
                                    "once, 1 to 64", a, argv[i]);
            jobs = (int)j;
        } else if (strcmp(a, "--all") == 0)
            all = 1;
        else if (strcmp(a, "--markdown") == 0)
            markdown = 1;
        else if (a[0] == '-')
            return sw_cli_error("stability: unknown option '%.40s'; options: --integrators, --set, "
                                "--plugin, --all, --jobs, --markdown, --help", a);
        else if (opts.scene)
            return sw_cli_error("stability takes one SCENE (got '%.40s' and '%.40s')",
                                opts.scene->name, a);
        else if (sw_cli_scene(a, &opts.scene) != SW_EXIT_OK)
            return SW_EXIT_USAGE;
    }
    if (jobs && !all)
        return sw_cli_error("--jobs is for --all: one scene is measured in one process");
    if (!jobs) {
        long cores = sysconf(_SC_NPROCESSORS_ONLN);
        jobs = cores < 1 ? 1 : cores > 8 ? 8 : (int)cores;
    }
    if (all && (opts.scene || opts.nsets))
        return sw_cli_error("stability --all takes no SCENE and no --set: it reports every scene at "
                            "its defaults");
    if (!all && !opts.scene)
        return sw_cli_error("stability needs a SCENE (or --all); see 'stepwise list scenes'");
    if (opts.scene && sw_cli_finish_opts(&opts) != SW_EXIT_OK)
        return SW_EXIT_USAGE;
    for (int i = 0; i < nplugins; i++)
        if (sw_cli_plugin(plugins[i]) != SW_EXIT_OK)
            return SW_EXIT_USAGE;
    const sw_integrator *methods[32];
    int nmethods = 0;
    if (methods_arg) {
        for (char *save = NULL, *name = strtok_r(methods_arg, ",", &save); name;
             name = strtok_r(NULL, ",", &save)) {
            if (nmethods == 32)
                return sw_cli_error("--integrators: at most 32 methods");
            if (sw_cli_integrator(name, &methods[nmethods]) != SW_EXIT_OK)
                return SW_EXIT_USAGE;
            nmethods++;
        }
        if (nmethods == 0)
            return sw_cli_error("--integrators wants a comma-separated list of methods, e.g. verlet,rk4");
    } else {
        for (int i = 0; i < sw_integrator_count() && nmethods < 32; i++)
            if (!(sw_integrator_at(i)->flags & SW_ADAPTIVE))
                methods[nmethods++] = sw_integrator_at(i);
    }
    int status = SW_EXIT_OK;
    if (!all) {
        /* Check the parameters by building the scene once, before any run. */
        sw_system sys;
        char err[SW_ERRLEN];
        if (sw_system_build(&sys, opts.scene, opts.p, err, sizeof err) != SW_OK)
            return sw_cli_error("%s", err);
        sw_system_free(&sys);
        if (!within_budget(opts.scene, opts.p, methods, nmethods))
            return SW_EXIT_USAGE;
        if (report(opts.scene, opts.p, methods, nmethods, markdown))
            status = SW_EXIT_FAIL;
    } else if (all_scenes(methods, nmethods, markdown, jobs))
        status = SW_EXIT_FAIL;
    return fflush(stdout) == 0 ? status : sw_cli_error("stability: could not write the report");
}
