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
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "measure/stability.h"
#include "sim/truth.h"
#include "util/num.h"
#include "util/wrap.h"

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
    "its bounded swing near the limit; an orbit: 2, escape, or E >= 0 held for a\n"
    "whole revolution) - growth a nonlinearity capped, energy that sank and came\n"
    "back - or when M's peaks climb (16 rises in 19 windows, or the latest peak\n"
    "above the first by more than the first window varied). Bisection between a\n"
    "stable and an unstable dt to 0.01%.\n"
    "Where the limit found lies above the theory's, it is probed again over 4 and 16\n"
    "times as long, and searched again below where a longer run grows. Where the two\n"
    "differ by more than 2%, a line says why.\n"
    "\n"
    "  --integrators LIST  comma-separated methods (default: all fixed-step ones that apply)\n"
    "  --set NAME=VALUE    change a scene parameter, e.g. --set c=0 (undamped spring)\n"
    "  --plugin FILE       load a student integrator (.so) and include it\n"
    "  --all               every scene where growth can be judged, default parameters\n"
    "  -j, --jobs N        with --all: N measurements at once (a method on a measured\n"
    "                      scene, or a theory-only scene), 1 to 64 (default: the\n"
    "                      online cores, at most 8); the same report for every N\n"
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
static double report_cost(const sw_scene *sc, const double *p, const sw_integrator *const *methods, int nmethods,
                          double *each)
{
    sw_stability_config cfg;
    sw_stability_config_default(&cfg);
    return sw_stability_cost_sum(sc, p, methods, nmethods, &cfg, each);
}

static int within_budget(const sw_scene *sc, const double *p, const sw_integrator *const *methods, int nmethods)
{
    double cost = report_cost(sc, p, methods, nmethods, NULL);
    if (cost <= SW_WORK_REPORT)
        return 1;
    sw_cli_error("stability on %s would cost about %.2g state evaluations (%d method%s), over the budget of "
                 "%.0e; use fewer particles or pick methods with --integrators", sc->name, cost, nmethods,
                 nmethods == 1 ? "" : "s", SW_WORK_REPORT);
    return 0;
}

/* One scene's heading: its parameters, what the report can say, the
 * table's header. */
static void report_head(const sw_scene *sc, const double *p, int markdown)
{
    char err[SW_ERRLEN];
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
        printf("  %-22s %-10s %-9s %-10s %s\n", "method", "theory dt", "|L|*dt", "measured", "|L|*dt");
    }
}

/* A note under a row of the table, indented to the method's column end
 * and wrapped so that no line passes 80 columns. */
static void note_line(void *ctx, int lead, const char *text, size_t len)
{
    (void)ctx;
    printf("  %-22s %*s%.*s\n", "", lead, "", (int)len, text);
}

static void note_lines(const char *text)
{
    sw_wrap_paragraph(text, 80 - 25, note_line, NULL);
}

/* The rows of methods[lo..hi) on one scene. Returns 0, or 1 when a run
 * failed to start. */
static int report_rows(const sw_scene *sc, const double *p, const sw_integrator *const *methods, int lo, int hi,
                       int markdown)
{
    sw_stability_config cfg;
    sw_stability_config_default(&cfg);
    char err[SW_ERRLEN];
    int status = 0;
    for (int i = lo; i < hi; i++) {
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
        if (markdown)
            printf("| %s | %s | %s | %s | %s | %s |\n", m->name, th, thw, me, mew,
                   r.agree ? "yes" : !r.measured ? "theory only" : r.why);
        else {
            /* 66 columns a row; what the measurement saw goes under it,
             * wrapped to 80 columns, so the table reads at 80 */
            printf("  %-22s %-10s %-9s %-10s %s\n", m->name, th, thw, me, mew);
            char note[1024];
            if (r.measured && r.kind == SW_STAB_LIMIT) {
                snprintf(note, sizeof note, "(%s at dt = %.5g)", sw_stability_verdict_text(r.fail.verdict),
                         r.dt_unstable);
                /* once: where theory and measurement differ, the reason
                 * under it may name the failing step already */
                if (r.agree || !strstr(r.why, sw_stability_verdict_text(r.fail.verdict)))
                    note_lines(note);
            }
            if (r.measured && !r.agree) {
                snprintf(note, sizeof note, "differ: %s", r.why);
                note_lines(note);
            }
            if (r.fail.verdict == SW_PROBE_BLOWN) {
                snprintf(note, sizeof note, "(at dt = %.6g: %s)", r.fail.dt, r.fail.reason);
                note_lines(note);
            }
        }
        fflush(stdout);
    }
    return status;
}

/* One scene: a row per method. Returns 0, or 1 when a run failed to start. */
static int report(const sw_scene *sc, const double *p, const sw_integrator *const *methods, int nmethods,
                  int markdown)
{
    report_head(sc, p, markdown);
    return report_rows(sc, p, methods, 0, nmethods, markdown);
}

/* Rows lo..hi of one scene of --all at its defaults, the heading with row 0:
 * its report, or (all its rows at once) a line saying it is over the
 * budget. cost: report_cost's, when the caller has it, else NAN. 1 when a
 * run failed to start. */
static int all_one(const sw_scene *sc, const sw_integrator *const *methods, int lo, int hi, int markdown,
                   double cost)
{
    double p[SW_MAX_PARAMS];
    char why[SW_ERRLEN];
    sw_scene_fill(sc, NULL, p);
    if (lo > 0)
        return report_rows(sc, p, methods, lo, hi, markdown);
    /* (theory only is cheap: no probe runs) */
    if (sw_stability_measurable(sc, p, why, sizeof why) &&
        (cost = isnan(cost) ? report_cost(sc, p, methods, hi, NULL) : cost) > SW_WORK_REPORT) {
        int has_n = sw_scene_param_index(sc, "n") >= 0;
        printf(markdown ? "\n### %s\n\nNot measured: it would cost about %.2g state evaluations, "
                          "over the budget of %.0e%s%s%s.\n"
                        : "stability on %s: not measured: it would cost about %.2g state evaluations, "
                          "over the budget of %.0e%s%s%s\n",
               sc->name, cost, SW_WORK_REPORT, has_n ? " (fewer particles measure: stepwise stability " : "",
               has_n ? sc->name : "", has_n ? " --set n=10)" : "");
        return 0;
    }
    return report(sc, p, methods, hi, markdown);
}

/* A piece of --all: rows lo..hi of one scene, measured in a child process
 * that writes them to a temporary file, read back when it is done. */
typedef struct piece {
    int scene, lo, hi;
    const char *method; /* its one method's name, or NULL: the whole scene */
    double cost;       /* this piece's estimate: the order only */
    double scene_cost; /* the scene's: its budget */
    int state;         /* 0 waiting, 1 running, 2 done */
    pid_t pid;
    int code;          /* the child's exit status; 2 when it failed */
    FILE *tmp;
    char *text;        /* what it printed */
    size_t len;
} piece;

/* The pieces, in the report's order. A measured scene is a piece per
 * method (its probes are its cost, so two cores share the chain's ten
 * methods); a theory-only scene is one piece, since its methods share one
 * reference run (the gyre's 400 points: most of its time), and so is a
 * scene over the budget (one line). NULL when out of memory. */
static piece *plan(const sw_integrator *const *methods, int nmethods, int *count)
{
    int n = sw_scene_count(), k = 0;
    piece *pc = calloc((size_t)n * (size_t)nmethods + 1, sizeof *pc);
    for (int i = 0; pc && i < n; i++) {
        const sw_scene *sc = sw_scene_at(i);
        double p[SW_MAX_PARAMS], each[32];
        char why[SW_ERRLEN];
        sw_scene_fill(sc, NULL, p);
        double cost = report_cost(sc, p, methods, nmethods, each);
        int split = sw_stability_measurable(sc, p, why, sizeof why) && cost <= SW_WORK_REPORT;
        for (int j = 0; j < (split ? nmethods : 1); j++)
            pc[k++] = (piece){ .scene = i, .lo = split ? j : 0, .hi = split ? j + 1 : nmethods,
                               .method = split ? methods[j]->name : NULL, .cost = split ? each[j] : cost,
                               .scene_cost = cost, .code = 2 };
    }
    *count = k;
    return pc;
}

static void start(piece *q, const sw_integrator *const *methods, int markdown)
{
    q->state = 2; /* unless it starts */
    if (!(q->tmp = tmpfile())) {
        sw_cli_note("stability: no temporary file for %s: %s", sw_scene_at(q->scene)->name, strerror(errno));
        return;
    }
    fflush(stdout); /* nothing of the parent's repeated by the child */
    q->pid = fork();
    if (q->pid == 0) {
        prctl(PR_SET_PDEATHSIG, SIGKILL); /* never outlives the report */
        int rc = dup2(fileno(q->tmp), STDOUT_FILENO) < 0
                     ? 2 : all_one(sw_scene_at(q->scene), methods, q->lo, q->hi, markdown, q->scene_cost);
        _exit(fflush(stdout) == 0 ? rc : 2);
    }
    if (q->pid < 0)
        sw_cli_note("stability: could not start the measurement of %s: %s", sw_scene_at(q->scene)->name,
                    strerror(errno));
    else
        q->state = 1;
}

/* A child is done: its exit status, and its report read back. */
static void collect(piece *q, int wst)
{
    q->state = 2;
    q->code = WIFEXITED(wst) ? WEXITSTATUS(wst) : 2;
    size_t cap = 0;
    rewind(q->tmp);
    for (char buf[4096];;) {
        size_t got = fread(buf, 1, sizeof buf, q->tmp);
        if (got == 0)
            break;
        if (q->len + got > cap) {
            char *t = realloc(q->text, cap = 2 * (q->len + got));
            if (!t) {
                q->code = 2;
                break;
            }
            q->text = t;
        }
        memcpy(q->text + q->len, buf, got);
        q->len += got;
    }
    if (ferror(q->tmp))
        q->code = 2;
}

/* Print the pieces from `shown` on that are done, in order; the next not
 * yet done stops it. Returns the new `shown`. */
static int show(piece *pc, int count, int shown, int *status)
{
    for (; shown < count && pc[shown].state == 2; shown++) {
        piece *q = &pc[shown];
        if (q->code != 2)
            fwrite(q->text, 1, q->len, stdout);
        else
            sw_cli_note("stability: the measurement of %s%s%s failed", sw_scene_at(q->scene)->name,
                        q->method ? " with " : "", q->method ? q->method : "");
        *status |= q->code == 1 ? 1 : q->code ? 2 : 0;
        if (q->tmp)
            fclose(q->tmp);
        free(q->text);
        q->tmp = NULL;
        q->text = NULL;
    }
    fflush(stdout);
    return shown;
}

/* --all: the scenes measured `jobs` pieces at once, the costliest first
 * (longest-first scheduling: the last to finish is then a short one); the
 * report is printed in the catalog's order as its pieces finish, so it is
 * the same bytes for every jobs (each row depends on nothing but its scene
 * and method). 1 when a report found a disagreement, 2 when a child failed
 * (said on stderr). */
static int all_scenes(const sw_integrator *const *methods, int nmethods, int markdown, int jobs)
{
    int status = 0, count = 0;
    if (jobs <= 1) {
        for (int i = 0; i < sw_scene_count(); i++)
            status |= all_one(sw_scene_at(i), methods, 0, nmethods, markdown, NAN);
        return status;
    }
    piece *pc = plan(methods, nmethods, &count);
    int *order = pc ? malloc((size_t)count * sizeof *order + 1) : NULL;
    if (!order) {
        free(pc);
        sw_cli_note("stability: out of memory planning the report");
        return 2;
    }
    for (int i = 0; i < count; i++) {
        order[i] = i;
        for (int j = i; j > 0 && pc[order[j]].cost > pc[order[j - 1]].cost; j--) {
            int t = order[j];
            order[j] = order[j - 1];
            order[j - 1] = t;
        }
    }
    int next = 0, running = 0, shown = 0;
    while (next < count || running > 0) {
        if (next < count && running < jobs) {
            piece *q = &pc[order[next++]];
            start(q, methods, markdown);
            running += q->state == 1;
            shown = show(pc, count, shown, &status);
            continue;
        }
        int wst;
        pid_t done = wait(&wst);
        if (done < 0) {
            if (errno == EINTR)
                continue;
            break;
        }
        for (int k = 0; k < count; k++)
            if (pc[k].state == 1 && pc[k].pid == done) {
                collect(&pc[k], wst);
                running--;
            }
        shown = show(pc, count, shown, &status);
    }
    for (int k = shown; k < count; k++)
        pc[k].state = 2; /* (wait failed: none left to wait for) */
    show(pc, count, shown, &status);
    free(order);
    free(pc);
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
                return sw_cli_error("%s '%.40s' is not allowed: it takes a whole number of measurements at "
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
        if (sw_cli_plugin("--plugin", plugins[i], NULL) != SW_EXIT_OK)
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
