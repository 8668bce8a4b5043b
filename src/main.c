/* stepwise: the command line. Dispatches subcommands to the front ends in
 * src/cli/; with no arguments it opens the lesson menu. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli/cli.h"
#include "util/names.h"

static const struct command {
    const char *name;
    int (*run)(int argc, char **argv);
    const char *summary;
} commands[] = {
    { "lesson", sw_cmd_lesson, "open the lesson menu, a lesson, or lint lesson files" },
    { "play", sw_cmd_play, "run a scene live in the terminal" },
    { "record", sw_cmd_record, "run a scene headless and write a step trace" },
    { "check", sw_cmd_check, "compare a trace with a reference (homework grading)" },
    { "grade", sw_cmd_grade, "grade a class: every submission against an assignment" },
    { "handout", sw_cmd_handout, "write each student's own assignment sheet (per-student parameters)" },
    { "autograder", sw_cmd_autograder, "write Gradescope's autograder bundle for an assignment" },
    { "try", sw_cmd_try, "build your integrator, measure it, check it and watch it live" },
    { "list", sw_cmd_list, "list scenes, integrators or lessons" },
    { "describe", sw_cmd_describe, "show a scene's parameters and what it teaches" },
    { "bench", sw_cmd_bench, "work-precision report: error against cost for each method" },
    { "stability", sw_cmd_stability, "find each method's largest stable step on a scene" },
};

#define NCOMMANDS ((int)(sizeof commands / sizeof commands[0]))

static const char *command_at(const void *ctx, int i)
{
    (void)ctx;
    return commands[i].name;
}

static void usage(FILE *out)
{
    fprintf(out, "usage: stepwise [COMMAND] [OPTIONS]\n\n"
                 "Numerical integration of particle systems, taught in a terminal.\n"
                 "With no command, opens the lesson menu.\n\ncommands:\n");
    for (int i = 0; i < NCOMMANDS; i++)
        fprintf(out, "  %-10s %s\n", commands[i].name, commands[i].summary);
    fprintf(out, "\n'stepwise COMMAND --help' describes a command; 'man stepwise' has the rest.\n"
                 "options:\n  -h, --help     this help\n  -V, --version  print the version\n");
}

/* The jail's switches (docs/sandbox.md), refused when misspelt: a grader
 * that meant the container's jail must not silently get another. */
static int check_env(void)
{
    const char *jail = getenv("STEPWISE_JAIL"), *box = getenv("STEPWISE_SANDBOX");
    if (jail && jail[0] && strcmp(jail, "uid") != 0 && strcmp(jail, "ns") != 0)
        return sw_cli_error("STEPWISE_JAIL='%.20s' is not a jail: give uid (a user of its own, as root, "
                            "where user namespaces are refused) or ns (namespaces), or leave it unset", jail);
    if (box && box[0] && strcmp(box, "off") != 0 && strcmp(box, "on") != 0)
        return sw_cli_error("STEPWISE_SANDBOX='%.20s': give off (no jail, a teacher's choice) or on, or leave "
                            "it unset", box);
    return SW_EXIT_OK;
}

int main(int argc, char **argv)
{
    if (check_env() != SW_EXIT_OK)
        return SW_EXIT_USAGE;
    if (argc < 2) {
        char *lesson_argv[] = { "lesson", NULL };
        return sw_cmd_lesson(1, lesson_argv);
    }
    const char *cmd = argv[1];
    if (strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0 || strcmp(cmd, "help") == 0) {
        usage(stdout);
        return sw_cli_flush_stdout();
    }
    if (strcmp(cmd, "--version") == 0 || strcmp(cmd, "-V") == 0) {
        printf("stepwise %s\n", SW_VERSION);
        return sw_cli_flush_stdout();
    }
    for (int i = 0; i < NCOMMANDS; i++)
        if (strcmp(cmd, commands[i].name) == 0) {
            int rc = commands[i].run(argc - 1, argv + 1);
            /* Output that did not reach its destination is an error, whatever
             * the command (unless it has already failed and said why). */
            if (rc == SW_EXIT_USAGE) {
                fflush(stdout);
                return rc;
            }
            return sw_cli_flush_stdout() != SW_EXIT_OK ? SW_EXIT_USAGE : rc;
        }
    if (cmd[0] == '-')
        sw_cli_error("unknown option '%.40s'; try 'stepwise --help'", cmd);
    else {
        char names[256];
        sw_names_join(names, sizeof names, command_at, NULL, NCOMMANDS);
        sw_cli_error("unknown command '%.40s'; commands: %s", cmd, names);
    }
    return SW_EXIT_USAGE;
}
