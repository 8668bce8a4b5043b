/* Placeholder until the check front end lands; replaced, not kept. */
#include "cli/cli.h"

int sw_cmd_check(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    return sw_cli_error("'check' is not built yet");
}
