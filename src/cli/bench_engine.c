/* TEMPORARY while the engine benchmark is written. */
#include "cli/bench_engine.h"
#include "cli/cli.h"
int sw_bench_engine_main(int argc, char **argv) { (void)argc; (void)argv; return sw_cli_error("engine benchmark: in progress"); }
