/* `list` and `describe`: what the catalog holds, in plain text. */
#include "cli/cli.h"

#include "engine/forces.h"
#include "sim/truth.h"
#include "util/escape.h"

#include <dirent.h>
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static int has_help(int argc, char **argv, const char *text)
{
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(text, stdout);
            return 1;
        }
    return 0;
}

static void list_scenes(void)
{
    for (int i = 0; i < sw_scene_count(); i++)
        printf("%-14s %s\n", sw_scene_at(i)->name, sw_scene_at(i)->summary);
}

static void list_integrators(void)
{
    for (int i = 0; i < sw_integrator_count(); i++) {
        const sw_integrator *m = sw_integrator_at(i);
        char evals[40];
        snprintf(evals, sizeof evals, "%s%d%s%s", (m->flags & SW_NEWTON) ? ">=" : "", m->evals,
                 (m->flags & SW_NEWTON) ? "+solves" : (m->flags & SW_IMPLICIT) ? "+solve" : "",
                 (m->flags & SW_PLUGIN) ? " (claimed)" : "");
        char label[4 * 100 + 4]; /* a plugin's is its author's text: escaped */
        sw_escape(m->label, 100, label, sizeof label);
        printf("%-22s order %-2d evals/step %-10s %s\n", m->name, m->order, evals, label);
    }
}

static int cmp_str(const void *a, const void *b)
{
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

static int list_lessons(void)
{
    const char *dir = sw_cli_lessons_dir();
    DIR *d = opendir(dir);
    if (!d)
        return sw_cli_error("no lessons directory at '%s' (set STEPWISE_LESSONS)", dir);
    char *names[256];
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) && n < 256) {
        size_t len = strlen(e->d_name);
        if (len > 7 && strcmp(e->d_name + len - 7, ".lesson") == 0)
            names[n++] = strdup(e->d_name);
    }
    closedir(d);
    qsort(names, (size_t)n, sizeof names[0], cmp_str);
    for (int i = 0; i < n; i++) {
        printf("%s\n", names[i]);
        free(names[i]);
    }
    return SW_EXIT_OK;
}

int sw_cmd_list(int argc, char **argv)
{
    if (has_help(argc, argv, "usage: stepwise list [scenes|integrators|lessons]\n\n"
                             "With no argument, lists scenes and integrators.\n"))
        return SW_EXIT_OK;
    if (argc > 2)
        return sw_cli_error("list takes at most one argument: scenes, integrators or lessons");
    const char *what = argc > 1 ? argv[1] : "";
    if (strcmp(what, "scenes") == 0)
        list_scenes();
    else if (strcmp(what, "integrators") == 0)
        list_integrators();
    else if (strcmp(what, "lessons") == 0)
        return list_lessons();
    else if (!*what) {
        printf("scenes:\n");
        list_scenes();
        printf("\nintegrators:\n");
        list_integrators();
    } else
        return sw_cli_error("cannot list '%.40s'; choose scenes, integrators or lessons", what);
    return SW_EXIT_OK;
}

static const char describe_help[] =
    "usage: stepwise describe SCENE [--full] [--set PARAM=VALUE]...\n\n"
    "Prints the scene's parameters (default, range, unit), its initial state, its\n"
    "defaults and what it teaches. --full prints every particle's initial state in\n"
    "full precision (%.17g); --set changes a parameter first. docs/scenes.md gives\n"
    "each scene's equations, forces and initial state as formulas.\n";

int sw_cmd_describe(int argc, char **argv)
{
    if (has_help(argc, argv, describe_help))
        return SW_EXIT_OK;
    sw_run_opts o;
    memset(&o, 0, sizeof o);
    int full = 0;
    const char *name = NULL;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--full") == 0)
            full = 1;
        else if (strcmp(argv[i], "--set") == 0 || strcmp(argv[i], "-s") == 0) {
            if (i + 1 >= argc)
                return sw_cli_error("describe: --set needs PARAM=VALUE");
            if (sw_cli_add_set(&o, argv[++i]) != SW_EXIT_OK)
                return SW_EXIT_USAGE;
        } else if (argv[i][0] == '-')
            return sw_cli_error("describe: unknown option '%.40s'; options: --full, --set", argv[i]);
        else if (name)
            return sw_cli_error("describe takes one scene name; see 'stepwise list scenes'");
        else
            name = argv[i];
    }
    if (!name)
        return sw_cli_error("describe takes one scene name; see 'stepwise list scenes'");
    const sw_scene *sc;
    if (sw_cli_scene(name, &sc) != SW_EXIT_OK)
        return SW_EXIT_USAGE;
    o.scene = sc;
    if (sw_cli_finish_opts(&o) != SW_EXIT_OK)
        return SW_EXIT_USAGE;
    printf("%s — %s\n\nteaches: %s\n\nparameters (change with --set NAME=VALUE):\n", sc->name,
           sc->summary, sc->teaches);
    for (int i = 0; i < sc->nparams; i++) {
        const sw_param *p = &sc->params[i];
        char range[64];
        snprintf(range, sizeof range, "[%g, %g]%s", p->min, p->max, p->integer ? " whole" : "");
        printf("  %-8s = %-10g %-22s %-8s %s\n", p->name, o.p[i], range, p->unit, p->help);
    }
    printf("\ndefaults: integrator %s, dt %g, report time %g\n", sc->integrator, sw_scene_dt(sc, o.p), sc->duration);
    sw_system sys;
    char err[SW_ERRLEN], why[SW_ERRLEN];
    if (sw_system_build(&sys, sc, o.p, err, sizeof err) != SW_OK)
        return sw_cli_error("%s", err);
    sw_truth_source src = sw_truth_source_of(&sys, why, sizeof why);
    printf("truth: %s%s%s\n", src == SW_TRUTH_EXACT ? "the exact solution" : src == SW_TRUTH_REFERENCE
           ? "a tight reference run" : "none", *why ? " - " : "", why);
    printf("knows:%s", sc->energy ? " energy;" : "");
    if (sc->drift)
        printf(" %s;", sc->drift_name);
    sw_spectrum sp;
    if (sw_truth_spectrum(&sys, 0.0, sys.y, &sp) == 0 && sp.largest > 0)
        printf(" stiffest mode |L| = %g rad/s at the start;", sp.largest);
    printf("\n");
    for (int k = 0; sys.kind == SW_SYS_PARTICLES && k < sys.particles.nforces; k++) {
        const sw_force *fo = &sys.particles.forces[k];
        const swp_force_type *type = swp_force_type_of(fo->kind);
        char values[128];
        type->values(fo, values, sizeof values);
        printf("%s %s: %s (%s)\n", k ? "      " : "forces:", type->name, type->formula, values);
    }
    printf("\ninitial state%s:\n", full ? " (every particle, %.17g)" : "");
    int shown = full ? sys.n : sys.n < 5 ? sys.n : 5;
    for (int i = 0; i < shown; i++) {
        if (full) {
            printf("  particle %d: x = (%.17g, %.17g)", i, sys.y[2 * i], sys.y[2 * i + 1]);
            if (sys.kind == SW_SYS_PARTICLES)
                printf("  v = (%.17g, %.17g)", sys.y[2 * sys.n + 2 * i], sys.y[2 * sys.n + 2 * i + 1]);
        } else {
            printf("  particle %d: x = (%g, %g)", i, sys.y[2 * i], sys.y[2 * i + 1]);
            if (sys.kind == SW_SYS_PARTICLES)
                printf("  v = (%g, %g)", sys.y[2 * sys.n + 2 * i], sys.y[2 * sys.n + 2 * i + 1]);
        }
        printf("\n");
    }
    if (sys.n > shown)
        printf("  ... and %d more ('stepwise describe %s --full' lists them all)\n", sys.n - shown,
               sc->name);
    printf("  %s system, state dimension %d; docs/scenes.md has the equations\n",
           sys.kind == SW_SYS_FLOW ? "first-order (flow)" : "second-order (masses)", sys.ode->dim);
    sw_system_free(&sys);
    return SW_EXIT_OK; /* main.c reports output that did not reach its destination */
}
