/* `stepwise try my_method.c`: the student's self-check loop (after
 * rustlings). Builds the integrator with the documented flags, measures its
 * order and stability limit beside the claimed ones, checks it against a
 * reference method (naming the built-in method it does match when it
 * fails), then shows it live beside the reference. With --watch each run
 * happens in a child process and starts again whenever the file is saved. */
#include "cli/cli.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "app/app.h"
#include "cli/check_report.h"
#include "measure/measure.h"
#include "grade/verdict.h"
#include "plugin/plugin.h"
#include "plugin/plugin_build.h"
#include "util/escape.h"
#include "util/signals.h"

static const char try_help[] =
    "usage: stepwise try FILE.c|FILE.so [--reference NAME] [--scene SCENE] [--set PARAM=VALUE]...\n"
    "                    [--watch] [--no-play]\n"
    "\n"
    "Your integrator, tried the way rustlings tries an exercise: builds FILE.c with the\n"
    "flags docs/plugins.md gives, measures its order (errors on the run it checks as\n"
    "dt halves) and its stability limit, checks it value by value against a built-in\n"
    "method, and, on a terminal, runs it live beside that method (play with compare;\n"
    "q goes on). With --watch it starts again each time you save FILE.\n"
    "\n"
    "options:\n"
    "      --reference NAME   the method to match (default: by the order you claim:\n"
    "                         1 euler, 2 midpoint, 4 rk4; a name or label that says\n"
    "                         symplectic, verlet or leapfrog: 1 symplectic-euler,\n"
    "                         2 verlet, 4 yoshida4)\n"
    "      --scene SCENE      where to check and show it (default chain: it tells methods apart)\n"
    "  -s, --set PARAM=VALUE  a scene parameter; repeatable\n"
    "      --watch            run again whenever FILE changes (Ctrl-C stops)\n"
    "      --no-play          no live view, only the measurements and the check\n"
    "  -h, --help             this help\n"
    "\n"
    "exit status: 0 it matches the reference, 1 it does not, 2 it does not build or load.\n";

typedef struct try_args {
    const char *file, *reference, *scene;
    char file_shown[4 * 200 + 4]; /* file escaped, for the lines that name it */
    sw_run_opts o;
    int watch, play;
} try_args;

#define SYMPLECTIC (SW_EXPLICIT | SW_SYMPLECTIC | SW_NEEDS_SECOND_ORDER)

/* Whether the plugin's own words (its name or label) claim a symplectic
 * method (the ABI has no flags, and a symplectic Euler compared with
 * euler fails for being right): the words below, or the name of an
 * explicit symplectic built-in. */
static int claims_symplectic(const sw_integrator *m)
{
    static const char *const words[] = { "symplectic", "leapfrog", "stormer", "st\xc3\xb6rmer", "semi-implicit" };
    char said[256];
    snprintf(said, sizeof said, "%.120s %.120s", m->name ? m->name : "", m->label ? m->label : "");
    for (char *c = said; *c; c++)
        *c = (char)tolower((unsigned char)*c);
    for (size_t i = 0; i < sizeof words / sizeof words[0]; i++)
        if (strstr(said, words[i]))
            return 1;
    for (int i = 0; i < sw_integrator_count(); i++)
        if (sw_integrator_at(i)->flags == SYMPLECTIC && strstr(said, sw_integrator_at(i)->name))
            return 1;
    return 0;
}

/* The lecture's method a plugin of this order is compared with: the first
 * plain fixed-step explicit built-in (euler, midpoint, rk4: no other flag;
 * for a symplectic claim symplectic-euler, verlet, yoshida4) of at least
 * that order, else the highest-order one. */
static const sw_integrator *default_reference(const sw_integrator *plugin)
{
    unsigned want = claims_symplectic(plugin) ? SYMPLECTIC : SW_EXPLICIT;
    const sw_integrator *best = NULL;
    for (int i = 0; i < sw_integrator_count(); i++) {
        const sw_integrator *m = sw_integrator_at(i);
        if ((unsigned)m->flags != want)
            continue;
        if (m->order >= plugin->order)
            return m;
        if (!best || m->order > best->order)
            best = m;
    }
    return best;
}

/* Where try's report goes: stdout, or on a terminal a buffer printed
 * wrapped to its width once the report is whole (try_once). */
static FILE *rep;

/* The figures the check measured, as grade measures them: the order on
 * the run checked (on the spring where that run shows none), the
 * stability limit on the spring. */
static void print_measure(const sw_verdict *v, const sw_integrator *ref)
{
    char why[SW_ERRLEN];
    if (!isnan(v->order))
        fprintf(rep, "  order      claimed %d, measured %.2f  (%s: %d)%s\n", v->claimed_order, v->order, ref->name,
               ref->order, v->order_on_spring ? " on the undamped spring: the run checked shows none" : "");
    else
        fprintf(rep, "  order      claimed %d, not measured: %s\n", v->claimed_order,
               v->measure_note + strlen("order not measured: "));
    if (isnan(v->order))
        return;
    if (isnan(v->stability)) {
        fprintf(rep, "  stability  not measured: %s\n", v->measure_note + strlen("stability not measured: "));
        return;
    }
    /* the reference's figure measured the same way, as grade compares them */
    double rwdt;
    int rkind;
    char rshown[64];
    if (sw_measure_stability_as_plugin(ref, &rwdt, &rkind, why, sizeof why) != SW_OK)
        snprintf(rshown, sizeof rshown, "not measured");
    else
        snprintf(rshown, sizeof rshown, rkind == 1 ? "none" : rkind == 2 ? "unbounded" : "%.4g", rwdt);
    if (v->stability_kind == 1)
        fprintf(rep, "  stability  none: grows even at w*dt = 0.01 on the undamped spring (%s: %s)\n",
               ref->name, rshown);
    else if (v->stability_kind == 2)
        fprintf(rep, "  stability  unbounded on the undamped spring (%s: %s)\n", ref->name, rshown);
    else
        fprintf(rep, "  stability  largest stable w*dt %.4g on the undamped spring (%s: %s, measured the same "
               "way)\n", v->stability, ref->name, rshown);
}

/* When the plugin fails its check: the built-in method it matches, if any. */
static void name_match(const sw_check_request *base)
{
    for (int i = 0; i < sw_integrator_count(); i++) {
        const sw_integrator *m = sw_integrator_at(i);
        if (m == base->reference || (m->flags & (SW_PLUGIN | SW_ADAPTIVE)))
            continue;
        sw_check_request req = *base;
        req.reference = m;
        req.measure = 0;
        static sw_verdict v;
        if (sw_check_run(&req, &v) == SW_VERDICT_PASS) {
            fprintf(rep, "  your numbers match %s (%s) instead\n", m->name, m->label);
            return;
        }
    }
}

/* The chain's forces do not read t, so a step that evaluates its stages
 * at the wrong times passes there (student pass: only a hidden part
 * caught it): the same check on the double gyre, whose field swings with
 * time, at its own step and length. The check's status. */
static int check_in_time(const sw_check_request *base)
{
    const sw_scene *sc = sw_scene_find("gyre");
    if (!sc)
        return SW_VERDICT_PASS;
    sw_check_request req = *base;
    req.scene = sc;
    sw_scene_defaults(sc, req.p);
    req.dt = sc->dt;
    req.spec.until = sc->duration;
    req.measure = 0;
    static sw_verdict v;
    sw_check_run(&req, &v);
    if (v.status == SW_VERDICT_PASS) {
        fprintf(rep, "  time       PASS on gyre too, whose field changes with t: your stages' times are %s's\n",
               base->reference->name);
        return SW_VERDICT_PASS;
    }
    fprintf(rep, "  time       on gyre, whose field changes with t (the chain's forces do not read it): ");
    sw_check_print_plain(rep, &v);
    return (int)v.status;
}

/* A plugin's printf goes nowhere (its host drops it): say so, once, where
 * it printed, so that a student debugging with printf is not left
 * wondering. */
static void print_printed(const sw_integrator *m, const char *shown)
{
    long long n = sw_plugin_printed(m);
    if (n <= 0)
        return;
    char size[32];
    if (n < 10240)
        snprintf(size, sizeof size, "%lld byte%s", n, n == 1 ? "" : "s");
    else
        snprintf(size, sizeof size, "%.0f KiB", (double)n / 1024);
    fprintf(rep,
            "  output     your plugin printed %s (printf, fprintf), which stepwise drops: a plugin's "
            "output is never shown. To see your numbers step by step, record a trace: stepwise record "
            "chain --plugin %s --steps 3\n",
            size, shown);
}

/* One run: build, measure, check, play. Returns the exit status. */
static int try_once(try_args *a)
{
    sw_build_warnings warn = { 0 };
    if (sw_cli_plugin("", a->file, &warn) != SW_EXIT_OK)
        return SW_EXIT_USAGE;
    const sw_integrator *m = sw_integrator_at(sw_integrator_count() - 1), *ref;
    if (a->reference) {
        if (sw_cli_integrator(a->reference, &ref) != SW_EXIT_OK)
            return SW_EXIT_USAGE;
    } else
        ref = default_reference(m);
    if (sw_cli_scene(a->scene ? a->scene : "chain", &a->o.scene) != SW_EXIT_OK)
        return SW_EXIT_USAGE;
    a->o.method = ref;
    if (sw_cli_finish_opts(&a->o) != SW_EXIT_OK)
        return SW_EXIT_USAGE;
    char label[4 * 100 + 4]; /* the plugin's own text: escaped, as every label shown */
    sw_escape(m->label, 100, label, sizeof label);
    printf("%s: %s (%s), %d work vector%s\n", a->file_shown, m->name, label, m->work_vectors,
           m->work_vectors == 1 ? "" : "s");
    fflush(stdout); /* at once: the measuring runs take a moment */
    char *text = NULL;
    size_t text_len = 0;
    int width = sw_cli_terminal_width(stdout);
    rep = width ? open_memstream(&text, &text_len) : NULL;
    if (!rep)
        rep = stdout;
    if (warn.count)
        fprintf(rep, "  build      %d compiler warning%s (often a bug: read them); the first: %s\n", warn.count,
                warn.count == 1 ? "" : "s", warn.first);
    fflush(rep);
    sw_check_request req;
    sw_check_request_init(&req);
    req.plugin = m;
    req.reference = ref;
    req.scene = a->o.scene;
    memcpy(req.p, a->o.p, sizeof req.p);
    req.dt = a->o.dt;
    req.spec.until = a->o.scene->duration;
    req.measure = 1; /* on the run checked, as grade measures */
    static sw_verdict v;
    sw_check_run(&req, &v); /* a plugin that crashes is named with its step */
    if (v.have_measure)
        print_measure(&v, ref);
    v.measure_shown = 1; /* above, beside the reference's: not again in the check's lines */
    fprintf(rep, "  check      ");
    sw_check_print_plain(rep, &v);
    if (v.status == SW_VERDICT_FAIL && !v.got_end.fault && !v.have_explanation) /* else said in its why: */
        name_match(&req);
    int status = (int)v.status;
    if (!a->scene && v.status == SW_VERDICT_PASS && !(ref->flags & SW_NEEDS_SECOND_ORDER))
        status = check_in_time(&req);
    print_printed(m, a->file_shown);
    if (rep != stdout) {
        fclose(rep);
        sw_cli_report_wrapped(stdout, text ? text : "", width);
        free(text);
    }
    rep = stdout;
    fflush(stdout);
    if (!a->play || !isatty(STDIN_FILENO) || !isatty(STDOUT_FILENO) || v.got_end.fault)
        return status;
    sw_app app;
    char err[SW_ERRLEN];
    if (sw_app_init(&app, a->o.scene, a->o.p, m, a->o.dt, err, sizeof err) != SW_OK)
        return sw_cli_error("%s", err);
    sw_app_set_compare(&app, 1, ref, NULL);
    snprintf(app.message, sizeof app.message, "%s (yellow) beside %s: q when you have seen enough",
             m->name, ref->name);
    int rc = sw_cli_play(&app, NULL);
    sw_app_free(&app);
    return rc != SW_EXIT_OK ? rc : status;
}

static int mtime_of(const char *path, struct timespec *t)
{
    struct stat st;
    if (stat(path, &st) != 0)
        return -1;
    *t = st.st_mtim;
    return 0;
}

/* --watch: each run in a child, started again when the file changes. */
static int watch(try_args *a)
{
    sw_signals_catch();
    struct timespec seen;
    int status = SW_EXIT_USAGE;
    while (!sw_signal_caught) {
        if (mtime_of(a->file, &seen) != 0)
            return sw_cli_error("try: cannot read '%.200s': %s", a->file, strerror(errno));
        fflush(NULL);
        pid_t pid = fork();
        if (pid < 0)
            return sw_cli_error("try: cannot start a run: %s", strerror(errno));
        if (pid == 0) {
            sw_signals_default();
            exit(try_once(a));
        }
        int wstatus, done = 0, changed = 0;
        while (!sw_signal_caught && !done) {
            struct timespec now, pause = { 0, 300000000 };
            nanosleep(&pause, NULL);
            done = waitpid(pid, &wstatus, WNOHANG) == pid;
            changed = mtime_of(a->file, &now) == 0 &&
                      (now.tv_sec != seen.tv_sec || now.tv_nsec != seen.tv_nsec);
            if (changed && !done) {
                kill(pid, SIGTERM); /* the live view restores the terminal and ends */
                for (int i = 0; i < 50 && !done; i++) {
                    nanosleep(&pause, NULL);
                    done = waitpid(pid, &wstatus, WNOHANG) == pid;
                }
                if (!done) {
                    kill(pid, SIGKILL);
                    waitpid(pid, &wstatus, 0);
                }
                done = 1;
            }
        }
        if (!done) {
            kill(pid, SIGTERM);
            waitpid(pid, &wstatus, 0);
            break;
        }
        status = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : SW_EXIT_USAGE;
        if (!changed) {
            printf("\nwatching %s: save it to try again (Ctrl-C stops)\n", a->file_shown);
            fflush(stdout);
            struct timespec now, pause = { 0, 300000000 };
            while (!sw_signal_caught && (mtime_of(a->file, &now) != 0 ||
                             (now.tv_sec == seen.tv_sec && now.tv_nsec == seen.tv_nsec)))
                nanosleep(&pause, NULL);
        }
        if (!sw_signal_caught)
            printf("\n%s changed: trying again\n", a->file_shown);
    }
    return status;
}

int sw_cmd_try(int argc, char **argv)
{
    try_args a;
    memset(&a, 0, sizeof a);
    a.play = 1;
    for (int i = 1; i < argc; i++) {
        const char *s = argv[i];
        int takes = strcmp(s, "--reference") == 0 || strcmp(s, "--scene") == 0 ||
                    strcmp(s, "--set") == 0 || strcmp(s, "-s") == 0;
        if (strcmp(s, "--help") == 0 || strcmp(s, "-h") == 0) {
            fputs(try_help, stdout);
            return SW_EXIT_OK;
        }
        if (takes && i + 1 >= argc)
            return sw_cli_error("try: %s needs a value; see 'stepwise try --help'", s);
        if (strcmp(s, "--reference") == 0)
            a.reference = argv[++i];
        else if (strcmp(s, "--scene") == 0)
            a.scene = argv[++i];
        else if (strcmp(s, "--set") == 0 || strcmp(s, "-s") == 0) {
            if (sw_cli_add_set(&a.o, argv[++i]) != SW_EXIT_OK)
                return SW_EXIT_USAGE;
        } else if (strcmp(s, "--watch") == 0)
            a.watch = 1;
        else if (strcmp(s, "--no-play") == 0)
            a.play = 0;
        else if (s[0] == '-')
            return sw_cli_error("try: unknown option '%.40s'; see 'stepwise try --help'", s);
        else if (a.file)
            return sw_cli_error("try takes one file (got '%.60s' and '%.60s')", a.file, s);
        else
            a.file = s;
    }
    if (!a.file)
        return sw_cli_error("try needs your integrator: stepwise try my_method.c (start from "
                            "examples/euler_plugin.c)");
    sw_escape(a.file, 200, a.file_shown, sizeof a.file_shown);
    return a.watch ? watch(&a) : try_once(&a);
}
