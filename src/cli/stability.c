/* `stepwise stability SCENE`: each method's largest stable step on a scene,
 * found by bisection (src/lab/stability.c), printed beside w·dt and the
 * theoretical limit on an undamped oscillator. */
#include "cli/cli.h"

#include <math.h>
#include <string.h>

#include "lab/stability.h"

static const char usage_text[] =
    "usage: stepwise stability SCENE [--integrators LIST] [--set NAME=VALUE] [--plugin FILE]\n"
    "\n"
    "Finds each method's largest stable step on SCENE by bisection, and where the scene\n"
    "knows its stiffest frequency w, prints w*dt beside the theoretical limit on an\n"
    "undamped oscillator x'' = -w^2 x (euler, midpoint, heun: none; symplectic-euler and\n"
    "verlet: 2; rk4: 2*sqrt(2); implicit methods: unbounded).\n"
    "\n"
    "Criterion. Each probe runs the scene at one dt, and a twin started 1e-7 (relative)\n"
    "ahead along its path (y0 + e f(y0)), for a fixed simulated time: 100 periods 2*pi/w\n"
    "(100 report times when w is unknown), at least 10 report times, and at least 400\n"
    "steps. It watches M, the scene's energy (for a flow without one, half the squared\n"
    "state norm), and D, the squared distance between the twins. The step is unstable\n"
    "when either sim blows up; when M rises above its start by more than 1e4 |M(0)|;\n"
    "when D grows past 1e8 times its start (a growing mode that the scene's\n"
    "nonlinearity has capped still drives the twins apart); when M grows steadily (the\n"
    "run cut into 20 windows, M's peak rises from one window to the next at least 16\n"
    "times in 19); or when M's peak over the last tenth of the run stands above the\n"
    "first tenth's by more than the first tenth varied. A bounded oscillation has window\n"
    "peaks that rise and fall at random and decay lowers them, so damped and decaying\n"
    "runs are stable (a run whose D has decayed below 1e-24 of its start stops early,\n"
    "stable); growth, however slow, raises them window after window. A fixed simulated\n"
    "time (not a fixed number of steps) is what lets the slow growth of euler, midpoint\n"
    "and heun at small dt show: they are reported 'none' when they grow even at\n"
    "w*dt = 0.01. A method still stable at w*dt = 1000 (dt = 1000 at most) is\n"
    "'unbounded'. Between a stable and an unstable dt the search bisects to 0.01%.\n"
    "rk45 and dop853 choose their own steps and are skipped. Scenes with contact or\n"
    "births at step boundaries (bounce, fireworks) are refused: nearby runs split at\n"
    "every step.\n"
    "docs/performance.md has the details and the figures.\n"
    "\n"
    "  --integrators LIST  comma-separated methods (default: all that apply)\n"
    "  --set NAME=VALUE    change a scene parameter, e.g. --set c=0 (undamped spring)\n"
    "  --plugin FILE       load a student integrator (.so) and include it\n";

static const char *verdict_text(int verdict)
{
    switch (verdict) {
    case SW_PROBE_BLOWN: return "blew up";
    case SW_PROBE_BOUND: return "energy bound";
    case SW_PROBE_TWIN: return "twins split";
    case SW_PROBE_TREND: return "grew";
    default: return "stable";
    }
}

static void theory_text(const sw_integrator *m, char *buf, size_t len)
{
    double th = m->stability;
    if (isnan(th))
        snprintf(buf, len, "unknown");
    else if (th == 0)
        snprintf(buf, len, "none");
    else if (isinf(th))
        snprintf(buf, len, "unbounded");
    else if (fabs(th - 2.0 * sqrt(2.0)) < 1e-12)
        snprintf(buf, len, "2.828 (2 sqrt 2)");
    else
        snprintf(buf, len, "%.4g", th);
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
    int nplugins = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        int takes = strcmp(a, "--integrators") == 0 || strcmp(a, "--set") == 0 ||
                    strcmp(a, "--plugin") == 0;
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
        } else if (a[0] == '-')
            return sw_cli_error("stability: unknown option '%.40s'; options: --integrators, --set, "
                                "--plugin, --help", a);
        else if (opts.scene)
            return sw_cli_error("stability takes one SCENE (got '%.40s' and '%.40s')",
                                opts.scene->name, a);
        else if (sw_cli_scene(a, &opts.scene) != SW_EXIT_OK)
            return SW_EXIT_USAGE;
    }
    if (!opts.scene)
        return sw_cli_error("stability needs a SCENE; see 'stepwise list scenes'");
    char why[SW_ERRLEN];
    if (!sw_stability_applicable(opts.scene, why, sizeof why))
        return sw_cli_error("%s", why);
    if (sw_cli_finish_opts(&opts) != SW_EXIT_OK)
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
        for (int i = 0; i < sw_integrator_count() && i < 32; i++)
            methods[nmethods++] = sw_integrator_at(i);
    }
    /* Check the parameters by building the scene once, before any run. */
    sw_system sys;
    char err[SW_ERRLEN];
    if (sw_system_build(&sys, opts.scene, opts.p, err, sizeof err) != SW_OK)
        return sw_cli_error("%s", err);
    double omega = opts.scene->omega_max ? opts.scene->omega_max(&sys) : NAN;
    sw_system_free(&sys);

    const sw_scene *sc = opts.scene;
    printf("stability on %s (", sc->name);
    for (int i = 0; i < sc->nparams; i++)
        printf("%s%s=%g", i ? " " : "", sc->params[i].name, opts.p[i]);
    printf(")\n");
    double probe_time = fmax(omega > 0 ? 100 * 6.283185307179586 / omega : 100 * sc->duration,
                             10 * sc->duration);
    if (omega > 0)
        printf("stiffest frequency w = %.6g rad/s; ", omega);
    else
        printf("no stiffest frequency known; ");
    printf("growth judged on %s and a twin run over %.4g s per probe\n",
           sc->energy ? "the energy" : "half the squared state norm", probe_time);
    printf("('stepwise stability --help' gives the criterion)\n\n");
    printf("  %-18s %-34s %-10s %-17s %s\n", "method", "largest stable dt", "w*dt",
           "theory w*dt", "probes");
    sw_stability_config cfg;
    sw_stability_config_default(&cfg);
    int status = SW_EXIT_OK;
    for (int i = 0; i < nmethods; i++) {
        const sw_integrator *m = methods[i];
        sw_stability_result res;
        char theory[32], found[80], wdt[24];
        theory_text(m, theory, sizeof theory);
        int rc = sw_stability_find(sc, opts.p, m, &cfg, &res, err, sizeof err);
        if (rc == SW_EINVAL) {
            printf("  %-18s skipped: %s\n", m->name, err);
            continue;
        }
        if (rc != SW_OK) {
            fprintf(stderr, "stepwise: %s: %s\n", m->name, err);
            status = SW_EXIT_FAIL;
            continue;
        }
        double shown = res.dt;
        switch (res.kind) {
        case SW_STAB_NONE:
            snprintf(found, sizeof found, "none (%s at dt = %.3g)", verdict_text(res.fail.verdict),
                     res.dt);
            break;
        case SW_STAB_UNBOUNDED:
            snprintf(found, sizeof found, "unbounded (stable at dt = %.3g)", res.dt);
            break;
        default:
            snprintf(found, sizeof found, "%.6g (%s at %.6g)", res.dt,
                     verdict_text(res.fail.verdict), res.dt_unstable);
        }
        if (omega > 0)
            snprintf(wdt, sizeof wdt, "%s%.5g", res.kind == SW_STAB_UNBOUNDED ? ">= " :
                     res.kind == SW_STAB_NONE ? "< " : "", omega * shown);
        else
            snprintf(wdt, sizeof wdt, "-");
        printf("  %-18s %-34s %-10s %-17s %d\n", m->name, found, wdt, theory, res.probes);
        if (res.fail.verdict == SW_PROBE_BLOWN)
            printf("  %-18s (at dt = %.6g: %s)\n", "", res.fail.dt, res.fail.reason);
        fflush(stdout);
    }
    return status;
}
