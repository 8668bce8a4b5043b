/* Placeholder until the bench front end lands; replaced, not kept. */
#include "cli/cli.h"

int sw_cmd_bench(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    return sw_cli_error("'bench' is not built yet");
}
