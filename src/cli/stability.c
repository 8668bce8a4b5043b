/* Placeholder until the stability front end lands; replaced, not kept. */
#include "cli/cli.h"

int sw_cmd_stability(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    return sw_cli_error("'stability' is not built yet");
}
