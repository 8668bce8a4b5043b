/* Placeholder until the lesson front end lands; replaced, not kept. */
#include "cli/cli.h"

int sw_cmd_lesson(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    return sw_cli_error("'lesson' is not built yet");
}
