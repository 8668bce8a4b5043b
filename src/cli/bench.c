/* `stepwise bench`: the work–precision report (error against cost for each
 * integrator on each scene that has an exact solution or a reference). The
 * engine benchmark is its own program (bench/, `make bench`). The numbers come from src/measure/bench.c;
 * this file parses, prints, and writes files whole or not at all (util/outfile). */
#include "cli/cli.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli/bench_jobs.h"
#include "engine/ode_fast.h"
#include "measure/bench.h"
#include "util/clock.h"
#include "util/names.h"
#include "util/outfile.h"
#include "util/signals.h"

static const char usage_text[] =
    "usage: stepwise bench [SCENE...] [--integrators LIST] [--csv FILE] [--svg FILE]\n"
    "                      [--set NAME=VALUE] [--quick] [--repeats N] [--jobs N] [--plugin FILE]\n"
    "                      [--events locate|step]\n"
    "\n"
    "Work-precision report: for each scene with an exact solution or a tight reference\n"
    "(rtol 1e-12, atol 1e-14, computed once per scene) and each integrator that applies,\n"
    "runs the scene to its report time over a geometric sweep of step sizes (from 8x the\n"
    "scene's dt, or twice the method's stability limit when the scene knows w, halving;\n"
    "adaptive methods sweep the tolerance 1e-2, 1e-3, ..., then their formula on fixed\n"
    "steps with the error control off, rows 'dt ... fixed') and records the largest absolute\n"
    "state error at 16 times spread to the report time (one time can be special: a whole\n"
    "number of periods), the derivative evaluations, the wall time (median of repeats)\n"
    "and blow-ups. A sweep goes on until 4 points agree and the error is below 1e-6 of\n"
    "the state, or 6 points agree.\n"
    "The observed order is the least-squares slope of log error against log dt (adaptive\n"
    "methods: of their fixed-step runs) over the points marked *: not blown up, before the error\n"
    "stops falling (a plateau: round-off, or the reference's accuracy), 10x above that\n"
    "floor and below 1e-2 of the state's size, contiguous down to the finest such point;\n"
    "at least 3 of them, errors and steps falling, steps spanning a factor 2, local\n"
    "slopes within 0.15 + 0.03 x order of each other, at most 0.3 above the method's order,\n"
    "else 'no order' and why (past the asymptotic range, not yet in it, or falling faster\n"
    "than the order can).\n"
    "With no SCENE, every scene that has a reference and every method that applies.\n"
    "docs/performance.md has the details and the figures.\n"
    "\n"
    "  --integrators LIST  comma-separated methods (default: all that apply)\n"
    "  --csv FILE          write every point as CSV (numbers in %.17g)\n"
    "  --svg FILE          write the log-log plots as SVG (open it in a browser)\n"
    "  --set NAME=VALUE    change a scene parameter (one SCENE only)\n"
    "  --quick             the small sweep the UI uses (6-8 step sizes, one run each)\n"
    "  --repeats N         timing repeats per point, 1..15 (default 3)\n"
    "  --jobs N            scenes measured side by side, 1..16 (default: one per core;\n"
    "                      1 with --plugin); only the times depend on it\n"
    "  --plugin FILE       load a student integrator (.so) and include it\n"
    "  --events MODE       locate: cut steps at contacts and crossings (every method keeps\n"
    "                      its order); step: meet them at step ends (default, first order)\n"
    "(The engine benchmark, ns per particle-step against hand-written loops, is\n"
    "`make bench` in the source tree.)\n";

/* Check an output path before the sweep (which may take minutes), creating
 * nothing: an interrupted sweep then leaves no file at all. */
static int out_check(const char *flag, const char *path)
{
    char err[SW_ERRLEN];
    switch (sw_outfile_check(path, err, sizeof err)) {
    case SW_OK:
        return SW_EXIT_OK;
    case SW_EINVAL:
        return sw_cli_error("%s '%.200s' is a directory (or an empty name); give the name of a file "
                            "to write", flag, path);
    default:
        return sw_cli_error("%s '%.200s': cannot create a file there (check the directory exists and is "
                            "writable): %s", flag, path, err);
    }
}

typedef int write_fn(FILE *out, const sw_bench_report *const *reports, int nreports, char *err,
                     size_t errlen);

/* Write one output file whole (util/outfile.h); signals are caught around
 * it, so an interrupted write removes its temporary and then dies of the
 * signal. 0 or 1 with the error printed. */
static int out_write(const char *flag, const char *path, write_fn *write, const sw_bench_report *const *done,
                     int ndone)
{
    char err[SW_ERRLEN];
    sw_outfile out;
    if (sw_outfile_open(&out, path, err, sizeof err) != SW_OK) {
        sw_cli_error("%s: %s", flag, err);
        return SW_EXIT_FAIL;
    }
    int rc = write(out.f, done, ndone, err, sizeof err);
    if (sw_signal_caught) {
        sw_outfile_abort(&out);
        sw_signals_reraise(sw_signal_caught);
    }
    if (rc == SW_OK)
        rc = sw_outfile_commit(&out, err, sizeof err);
    else
        sw_outfile_abort(&out);
    if (rc != SW_OK) {
        sw_cli_error("%s '%s': %s", flag, path, err);
        return SW_EXIT_FAIL;
    }
    return SW_EXIT_OK;
}

/* Split a comma-separated --integrators list into methods; prints what is allowed. */
static int parse_methods(char *list, const sw_integrator **out, int *n)
{
    *n = 0;
    for (char *save = NULL, *name = strtok_r(list, ",", &save); name; name = strtok_r(NULL, ",", &save)) {
        if (*n == SW_BENCH_MAX_METHODS)
            return sw_cli_error("--integrators: at most %d methods", SW_BENCH_MAX_METHODS);
        if (sw_cli_integrator(name, &out[*n]) != SW_EXIT_OK)
            return SW_EXIT_USAGE;
        for (int i = 0; i < *n; i++)
            if (out[i] == out[*n])
                return sw_cli_error("--integrators: '%.40s' is listed twice", name);
        (*n)++;
    }
    if (*n == 0)
        return sw_cli_error("--integrators wants a comma-separated list of methods, e.g. euler,rk4");
    return SW_EXIT_OK;
}

static void print_time(char *buf, size_t len, double s)
{
    if (s < 1e-3)
        snprintf(buf, len, "%.3g us", s * 1e6);
    else if (s < 1.0)
        snprintf(buf, len, "%.3g ms", s * 1e3);
    else
        snprintf(buf, len, "%.3g s", s);
}

static const char *stop_note(int stop)
{
    switch (stop) {
    case SW_BENCH_STOP_FLOOR: return "; stopped at round-off";
    case SW_BENCH_STOP_BUDGET: return "; finer steps over the work budget";
    case SW_BENCH_STOP_DT_MIN: return "; next step below the smallest dt";
    default: return "";
    }
}

/* A symplectic composition's order above 2 holds where the forces read
 * positions alone: where drag or damping reads velocities, each Verlet
 * substep's velocity predictor errs at second order and the composition
 * does not cancel it (yoshida4: 2, tests/check_yoshida.c). */
static void print_velocity_note(const sw_bench_report *r, const sw_system *sys)
{
    if (sw_ode_position_only(sys->ode))
        return;
    for (int i = 0; i < r->nseries; i++) {
        const sw_integrator *m = r->series[i].method;
        if ((m->flags & SW_SYMPLECTIC) && !(m->flags & SW_PLUGIN) && m->order > 2)
            printf("   %s: order %d where forces read positions alone; here a force reads\n"
                   "   velocities (drag or damping), and its order is 2\n", m->name, m->order);
    }
}

/* Under the orders: what the scene's events do to them (its own sentence)
 * when the runs stepped over them, or that they were located; and what
 * velocity-dependent forces do to a symplectic composition's. */
static void print_events(const sw_bench_report *r)
{
    sw_system sys;
    char err[SW_ERRLEN];
    if (sw_system_build(&sys, r->scene, r->p, err, sizeof err) != SW_OK)
        return;
    print_velocity_note(r, &sys);
    const char *breaks = sw_system_events_break(&sys);
    if (breaks && r->events == SW_EVENTS_STEP) {
        /* the sentence in lines of at most 78 columns */
        const char *lead = "   not smooth: ";
        size_t col = 0;
        fputs(lead, stdout);
        col = strlen(lead);
        for (const char *w = breaks; *w;) {
            size_t len = strcspn(w, " ");
            if (col > strlen(lead) && col + 1 + len > 78) {
                printf("\n%*s", (int)strlen(lead), "");
                col = strlen(lead);
            } else if (col > strlen(lead)) {
                putchar(' ');
                col++;
            }
            printf("%.*s", (int)len, w);
            col += len;
            w += len;
            w += strspn(w, " ");
        }
        putchar('\n');
    }
    else if (sw_system_event_count(&sys) > 0 && r->events == SW_EVENTS_LOCATE)
        printf("   events located: steps end at each contact or crossing (--events locate)\n");
    sw_system_free(&sys);
}

/* "no order: why" in lines of at most 78 columns, the stop note unless the
 * reason already says the error reached its floor. */
static void print_no_order(const sw_bench_series *s)
{
    char line[256];
    snprintf(line, sizeof line, "no order: %s%s", sw_bench_no_order_text(s),
             s->no_order == SW_BENCH_ORDER_PAST ? "" : stop_note(s->stop));
    printf("   %-18s ", s->method->name);
    int indent = 22, col = indent;
    for (const char *w = line; *w;) {
        int len = (int)strcspn(w, " ");
        if (col > indent && col + 1 + len > 78) {
            printf("\n%*s", indent, "");
            col = indent;
        } else if (col > indent) {
            putchar(' ');
            col++;
        }
        printf("%.*s", len, w);
        col += len;
        w += len;
        w += strspn(w, " ");
    }
    putchar('\n');
}

static void print_report(const sw_bench_report *r, const char *skipped)
{
    const sw_scene *sc = r->scene;
    printf("== %s: ", sc->name);
    if (r->source == SW_BENCH_EXACT)
        printf("largest error at %d times to t = %g, against the exact solution\n", SW_BENCH_SAMPLES,
               r->t_report);
    else
        printf("largest error at %d times to t = %g, against a %s reference (rtol %g, atol %g, %ld "
               "evaluations; its own error <= %.1e)\n", SW_BENCH_SAMPLES, r->t_report,
               sw_truth_reference_method()->name, SW_TRUTH_RTOL, SW_TRUTH_ATOL, r->ref_evals, r->ref_error);
    printf("   parameters:");
    for (int i = 0; i < sc->nparams; i++)
        printf(" %s=%g", sc->params[i].name, r->p[i]);
    if (r->omega > 0)
        printf("; stiffest frequency w = %.4g rad/s", r->omega);
    printf("; state size %.3g\n", r->scale);
    if (skipped[0])
        printf("   not run here: %s\n", skipped);
    printf("\n   %-18s %-16s %-22s %10s %10s  %s\n", "method", "step", "error", "evals", "time", "fit");
    for (int i = 0; i < r->nseries; i++) {
        const sw_bench_series *s = &r->series[i];
        if (s->npoints == 0)
            printf("   %-18s (no run: the coarsest step is already over the work budget)\n", s->method->name);
        for (int j = 0; j < s->npoints + s->nfixed; j++) {
            /* an adaptive method's controlled runs, then its fixed steps */
            const sw_bench_point *pt = j < s->npoints ? &s->points[j] : &s->fixed[j - s->npoints];
            char step[32], err[40], t[24];
            if (pt->rtol > 0)
                snprintf(step, sizeof step, "rtol %.0e", pt->rtol);
            else if (j >= s->npoints)
                snprintf(step, sizeof step, "dt %.4g fixed", pt->dt);
            else
                snprintf(step, sizeof step, "dt %.4g", pt->dt);
            if (pt->blown)
                snprintf(err, sizeof err, "blown up at t = %.3g", pt->blow_time);
            else
                snprintf(err, sizeof err, "%.3e", pt->error);
            print_time(t, sizeof t, pt->seconds);
            printf("   %-18s %-16s %-22s %10ld %10s  %s\n", j == 0 ? s->method->name : "", step, err,
                   pt->evals, t, pt->in_fit ? "*" : "");
        }
    }
    printf("\n   observed order (slope of log error against log dt over the * points; adaptive methods:\n"
           "   their formula on fixed steps, error control off):\n");
    for (int i = 0; i < r->nseries; i++) {
        const sw_bench_series *s = &r->series[i];
        if (isfinite(s->order))
            printf("   %-18s %5.2f  (%d%s points, local slopes %.2f to %.2f; theory %d%s)\n",
                   s->method->name, s->order, s->nfit, s->method->flags & SW_ADAPTIVE ? " fixed-step" : "",
                   s->slope_min, s->slope_max, s->method->order, stop_note(s->stop));
        else
            print_no_order(s);
    }
    print_events(r);
    printf("\n   cheapest measured run to reach each error level:\n");
    static const double levels[] = { 1e-2, 1e-4, 1e-6, 1e-8 };
    for (int k = 0; k < 4; k++) {
        int jt, je;
        int it = sw_bench_cheapest(r, levels[k], 0, &jt), ie = sw_bench_cheapest(r, levels[k], 1, &je);
        if (it < 0) {
            printf("   %.0e  no method reached it in this sweep\n", levels[k]);
            continue;
        }
        char t[24];
        const sw_bench_point *pt = &r->series[it].points[jt], *pe = &r->series[ie].points[je];
        print_time(t, sizeof t, pt->seconds);
        printf("   %.0e  by time: %-17s (%s, %ld evals)   by evaluations: %-17s (%ld evals)\n",
               levels[k], r->series[it].method->name, t, pt->evals, r->series[ie].method->name,
               pe->evals);
    }
    enum { W = 76, H = 22 };
    static char plot[(W + 1) * H + 1];
    for (int axis = 0; axis < 2; axis++)
        if (sw_bench_plot(r, axis ? SW_BENCH_X_EVALS : SW_BENCH_X_TIME, plot, W, H) == SW_OK)
            printf("\n%s", plot);
    printf("\n");
    fflush(stdout);
}

static const char *method_name_at(const void *ctx, int i)
{
    return ((const sw_integrator *const *)ctx)[i]->name;
}

/* Methods of `wanted` (all when n == 0) that cannot step this scene, by name. */
static void list_inapplicable(const sw_scene *sc, const double *p, const sw_integrator *const *wanted,
                              int n, char *buf, size_t len)
{
    sw_system sys;
    char err[SW_ERRLEN];
    buf[0] = '\0';
    if (sw_system_build(&sys, sc, p, err, sizeof err) != SW_OK)
        return;
    const sw_integrator *refused[SW_BENCH_MAX_METHODS + 64];
    int nrefused = 0, count = n ? n : sw_integrator_count();
    unsigned why = 0; /* the kinds refused: implicit, x'' = f(x) only, one body only */
    const char *one_body = ""; /* the method refused for wanting one body alone (named in the reason) */
    for (int i = 0; i < count && nrefused < (int)(sizeof refused / sizeof refused[0]); i++) {
        const sw_integrator *m = n ? wanted[i] : sw_integrator_at(i);
        if (sw_integrator_accepts(m, sys.ode, err, sizeof err) != SW_OK) {
            refused[nrefused++] = m;
            why |= m->flags & (SW_IMPLICIT | SW_ONE_BODY) ? m->flags & (SW_IMPLICIT | SW_ONE_BODY) : SW_POSITION_ONLY;
            if (m->flags & SW_ONE_BODY)
                one_body = m->name;
        }
    }
    size_t used = sw_names_join(buf, len, method_name_at, refused, nrefused);
    if (used > 0 && used < len && sys.kind == SW_SYS_FLOW)
        snprintf(buf + used, len - used, " (a flow field has no masses, or no Jacobian for implicit methods)");
    else if (used > 0 && used < len)
        snprintf(buf + used, len - used, " (%s%s%s%s%s%s)", why & SW_IMPLICIT ? "no Jacobian at this size" : "",
                 why & SW_IMPLICIT && why & ~SW_IMPLICIT ? "; " : "",
                 why & SW_POSITION_ONLY ? "a force reads velocities: x'' = f(x) only" : "",
                 why & SW_POSITION_ONLY && why & SW_ONE_BODY ? "; " : "", one_body,
                 why & SW_ONE_BODY ? ": one body alone in one central field" : "");
    sw_system_free(&sys);
}

int sw_cmd_bench(int argc, char **argv)
{
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(usage_text, stdout);
            return SW_EXIT_OK;
        }
    }
    const char *scene_names[64], *plugins[8], *csv_path = NULL, *svg_path = NULL;
    char *methods_arg = NULL;
    int nscenes = 0, nplugins = 0, quick = 0;
    long repeats = 3, jobs_n = sysconf(_SC_NPROCESSORS_ONLN);
    if (jobs_n < 1)
        jobs_n = 1;
    sw_run_opts opts;
    memset(&opts, 0, sizeof opts);
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        int takes = strcmp(a, "--integrators") == 0 || strcmp(a, "--csv") == 0 ||
                    strcmp(a, "--svg") == 0 || strcmp(a, "--set") == 0 ||
                    strcmp(a, "--repeats") == 0 || strcmp(a, "--plugin") == 0 ||
                    strcmp(a, "--events") == 0 || strcmp(a, "--jobs") == 0;
        if (takes && i + 1 >= argc)
            return sw_cli_error("%s needs a value; see 'stepwise bench --help'", a);
        if (strcmp(a, "--integrators") == 0)
            methods_arg = argv[++i];
        else if (strcmp(a, "--csv") == 0)
            csv_path = argv[++i];
        else if (strcmp(a, "--svg") == 0)
            svg_path = argv[++i];
        else if (strcmp(a, "--set") == 0) {
            if (sw_cli_add_set(&opts, argv[++i]) != SW_EXIT_OK)
                return SW_EXIT_USAGE;
        } else if (strcmp(a, "--repeats") == 0) {
            if (sw_cli_long("--repeats", argv[++i], 1, 15, &repeats) != SW_EXIT_OK)
                return SW_EXIT_USAGE;
        } else if (strcmp(a, "--jobs") == 0) {
            if (sw_cli_long("--jobs", argv[++i], 1, 16, &jobs_n) != SW_EXIT_OK)
                return SW_EXIT_USAGE;
        } else if (strcmp(a, "--plugin") == 0) {
            if (nplugins == 8)
                return sw_cli_error("at most 8 --plugin options");
            plugins[nplugins++] = argv[++i];
        } else if (strcmp(a, "--events") == 0) {
            if (sw_cli_events(argv[++i], &opts.events) != SW_EXIT_OK)
                return SW_EXIT_USAGE;
        } else if (strcmp(a, "--quick") == 0)
            quick = 1;
        else if (a[0] == '-')
            return sw_cli_error("bench: unknown option '%.40s'; options: --integrators, --csv, --svg, "
                                "--set, --quick, --repeats, --jobs, --plugin, --events, --help", a);
        else {
            const sw_scene *sc;
            if (sw_cli_scene(a, &sc) != SW_EXIT_OK)
                return SW_EXIT_USAGE;
            if (nscenes == 64)
                return sw_cli_error("bench: at most 64 scenes");
            scene_names[nscenes++] = a;
        }
    }
    if (opts.nsets > 0 && nscenes != 1)
        return sw_cli_error("--set changes one scene's parameters: name exactly one SCENE with it");
    for (int i = 0; i < nplugins; i++)
        if (sw_cli_plugin("--plugin", plugins[i], NULL) != SW_EXIT_OK)
            return SW_EXIT_USAGE;
    const sw_integrator *methods[SW_BENCH_MAX_METHODS];
    int nmethods = 0;
    if (methods_arg && parse_methods(methods_arg, methods, &nmethods) != SW_EXIT_OK)
        return SW_EXIT_USAGE;

    /* The scenes: as named (with --set checked now), or every measurable one. */
    const sw_scene *scenes[64];
    double params[64][SW_MAX_PARAMS];
    char notes[2048] = "";
    size_t notes_used = 0;
    int n = 0;
    for (int i = 0; i < (nscenes ? nscenes : sw_scene_count()); i++) {
        const sw_scene *sc = nscenes ? sw_scene_find(scene_names[i]) : sw_scene_at(i);
        opts.scene = sc;
        if (sw_cli_finish_opts(&opts) != SW_EXIT_OK)
            return SW_EXIT_USAGE;
        char why[SW_ERRLEN];
        if (!sw_bench_measurable(sc, opts.p, why, sizeof why)) {
            if (notes_used < sizeof notes)
                notes_used += (size_t)snprintf(notes + notes_used, sizeof notes - notes_used,
                                               "%s%s", notes_used ? "; " : "", why);
            continue;
        }
        scenes[n] = sc;
        memcpy(params[n], opts.p, sizeof params[n]);
        n++;
    }
    if (n == 0)
        return sw_cli_error("bench: nothing to measure: %s", notes);
    if ((csv_path && out_check("--csv", csv_path) != SW_EXIT_OK) ||
        (svg_path && out_check("--svg", svg_path) != SW_EXIT_OK))
        return SW_EXIT_USAGE;

    sw_bench_config cfg;
    if (quick)
        sw_bench_config_quick(&cfg);
    else
        sw_bench_config_default(&cfg);
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], "--repeats") == 0)
            cfg.repeats = (int)repeats;
    sw_bench_report *reports = calloc((size_t)n, sizeof *reports);
    const sw_bench_report **done = calloc((size_t)n, sizeof *done);
    if (!reports || !done) {
        free(reports);
        free(done);
        sw_cli_note("out of memory for %d reports", n);
        return SW_EXIT_FAIL;
    }
    if (notes[0])
        printf("skipped: %s\n\n", notes);
    int ndone = 0, status = SW_EXIT_OK;
    double t0 = sw_clock_now();
    sw_bench_task task[64];
    for (int i = 0; i < n; i++)
        task[i] = (sw_bench_task){ .scene = scenes[i], .p = params[i], .methods = nmethods ? methods : NULL,
                                   .nmethods = nmethods, .cfg = &cfg, .events = opts.events };
    /* a plugin's host answers one thread: with one loaded, no workers */
    char err[SW_ERRLEN];
    sw_bench_jobs *jobs = sw_bench_jobs_start(task, reports, n, nplugins ? 0 : (int)jobs_n, err, sizeof err);
    if (!jobs) {
        sw_cli_note("%s", err);
        free(reports);
        free(done);
        return SW_EXIT_FAIL;
    }
    for (int i = 0; i < n; i++) {
        char skipped[512];
        sw_bench_report *r = &reports[i];
        if (sw_bench_jobs_wait(jobs, i, err, sizeof err) != SW_OK) {
            sw_cli_note("%s", err);
            status = SW_EXIT_FAIL;
            continue;
        }
        list_inapplicable(scenes[i], params[i], methods, nmethods, skipped, sizeof skipped);
        print_report(r, skipped);
        fflush(stdout);
        done[ndone++] = r;
    }
    sw_bench_jobs_free(jobs);
    printf("bench: %d scene%s in %.1f s\n", ndone, ndone == 1 ? "" : "s", sw_clock_now() - t0);
    sw_signals_catch();
    if (csv_path && out_write("--csv", csv_path, sw_bench_write_csv, done, ndone) != SW_EXIT_OK)
        status = SW_EXIT_FAIL;
    if (svg_path && out_write("--svg", svg_path, sw_bench_write_svg, done, ndone) != SW_EXIT_OK)
        status = SW_EXIT_FAIL;
    sw_signals_default();
    if (sw_signal_caught)
        sw_signals_reraise(sw_signal_caught);
    for (int i = 0; i < n; i++)
        sw_bench_free(&reports[i]);
    free(reports);
    free(done);
    return status;
}
