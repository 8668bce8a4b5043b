/* The engine benchmark (`make bench`, `stepwise bench --engine`): throughput
 * of every integrator against hand-written loops, frame cost, peak memory and
 * allocations counted in the step loops. Prints its tables on stdout. */
#ifndef SW_CLI_BENCH_ENGINE_H
#define SW_CLI_BENCH_ENGINE_H

/* argv as given to `bench` (argv[0] is the command name); returns the exit status. */
int sw_bench_engine_main(int argc, char **argv);

#endif
