/* placeholder replaced below */
#include "cli/cli.h"
int sw_cmd_try(int argc, char **argv) { (void)argc; (void)argv; return sw_cli_error("try: not yet"); }
