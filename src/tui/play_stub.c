/* Placeholder until the play front end lands; replaced, not kept. */
#include "cli/cli.h"

int sw_cmd_play(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    return sw_cli_error("'play' is not built yet");
}
