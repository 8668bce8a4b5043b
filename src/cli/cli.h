/* The command-line front ends: one function per subcommand, each taking its
 * own argv (argv[0] is the command name) and returning the exit status:
 * 0 success, 1 a failed check, 2 bad input. Only this layer prints (the
 * TUI paints). */
#ifndef SW_CLI_CLI_H
#define SW_CLI_CLI_H

#include <stdio.h>

#include "stepwise/base.h"
#include "stepwise/scene.h"
#include "stepwise/sim.h"

int sw_cmd_list(int argc, char **argv);
int sw_cmd_describe(int argc, char **argv);
int sw_cmd_record(int argc, char **argv);
int sw_cmd_check(int argc, char **argv);
int sw_cmd_play(int argc, char **argv);
int sw_cmd_lesson(int argc, char **argv);
int sw_cmd_bench(int argc, char **argv);
int sw_cmd_stability(int argc, char **argv);

/* Exit statuses. */
enum { SW_EXIT_OK = 0, SW_EXIT_FAIL = 1, SW_EXIT_USAGE = 2 };

/* Print "stepwise: <message>" on stderr, escaped to one line of printable
 * text (util/escape.h); returns SW_EXIT_USAGE. */
int sw_cli_error(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
/* The same for a line that is not an error (a notice, a report's verdict). */
void sw_cli_note(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
/* The warning for a homework that keeps the examples' '# secret:' words. */
void sw_cli_warn_public_secret(const char *assignment);

/* Settings shared by record, play, check and the lab: what to run and how. */
typedef struct sw_run_opts {
    const sw_scene *scene;
    double p[SW_MAX_PARAMS];
    const sw_integrator *method;  /* NULL: the scene's default */
    double dt;                    /* 0: the scene's default */
    double rtol, atol;            /* rk45 tolerances */
    sw_events_mode events;        /* --events (default step) */
    const char *sets[64];         /* --set assignments, applied once the scene is known */
    int nsets;
} sw_run_opts;

/* Look up a scene / an integrator by name; on failure print what is allowed
 * and return SW_EXIT_USAGE. */
int sw_cli_scene(const char *name, const sw_scene **out);
int sw_cli_integrator(const char *name, const sw_integrator **out);
/* Parse a step size in [SW_DT_MIN, SW_DT_MAX] for flag `flag`. */
int sw_cli_dt(const char *flag, const char *text, double *out);
/* Parse a positive finite double for flag `flag`. */
int sw_cli_positive(const char *flag, const char *text, double *out);
/* Parse a finite number in [min, max] for flag `flag`; the message names the
 * range and its unit ("seconds", "" for none). */
int sw_cli_range(const char *flag, const char *text, double min, double max, const char *unit,
                 double *out);
/* Parse a run tolerance (rtol, atol) in [SW_TRACE_TOL_MIN, 1] for flag `flag`. */
int sw_cli_tolerance(const char *flag, const char *text, double *out);
/* Parse --events: "locate" or "step"; else print what is allowed and return SW_EXIT_USAGE. */
int sw_cli_events(const char *text, sw_events_mode *out);
/* The help line every command with --events shows. */
#define SW_CLI_EVENTS_HELP \
    "      --events MODE      locate: cut steps at contacts and crossings (every method keeps\n" \
    "                         its order); step: meet them at step ends (default, first order)\n"
/* text (lines) to `to`, each line wider than width broken between words
 * and going on under its own text (report_wrap.c); width < 40: as is. */
void sw_cli_report_wrapped(FILE *to, const char *text, int width);
/* The width of the terminal f writes to; 0 when it is not one. */
int sw_cli_terminal_width(FILE *f);
/* Parse a whole number in [min, max] for flag `flag`. */
int sw_cli_long(const char *flag, const char *text, long min, long max, long *out);
/* Queue a --set assignment; checked by sw_cli_finish_opts. */
int sw_cli_add_set(sw_run_opts *o, const char *assignment);
/* Load a plugin's shared object (or C source, built first) and register
 * its integrator; the plugin runs in child processes (plugin/plugin.h).
 * flag: what the user typed before the path ("--plugin"), which starts
 * each error message, or "" where the path was the command's argument.
 * A source's compiler warnings into warn (may be NULL; a .so has none). */
struct sw_build_warnings;
int sw_cli_plugin(const char *flag, const char *path, struct sw_build_warnings *warn);
int sw_cmd_grade(int argc, char **argv);
/* Gradescope's autograder bundle for an assignment (cli/autograder.c). */
int sw_cmd_autograder(int argc, char **argv);
int sw_cmd_handout(int argc, char **argv);
int sw_cmd_try(int argc, char **argv);
/* Once the scene is known: defaults, --set values, default method and dt. */
int sw_cli_finish_opts(sw_run_opts *o);
/* Initialise a sim from options; prints the error and returns SW_EXIT_USAGE on failure. */
int sw_cli_sim(sw_sim *s, const sw_run_opts *o);

/* Flush standard output: 0, or 2 with "cannot write standard output: why"
 * on stderr (a full disk, a closed pipe). Every command's output ends here. */
int sw_cli_flush_stdout(void);

/* The live terminal UI for an app (hooks NULL: play); the exit status:
 * 0, 128 + a signal's number, or 2 with the error printed. */
struct sw_app;
struct sw_play_hooks;
int sw_cli_play(struct sw_app *a, const struct sw_play_hooks *hooks);

/* Where the lesson files are: $STEPWISE_LESSONS, ./lessons, or the install dir. */
const char *sw_cli_lessons_dir(void);

#endif
