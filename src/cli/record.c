/* Placeholder until the record front end lands; replaced, not kept. */
#include "cli/cli.h"

int sw_cmd_record(int argc, char **argv)
{
    (void)argc;
    (void)argv;
    return sw_cli_error("'record' is not built yet");
}
