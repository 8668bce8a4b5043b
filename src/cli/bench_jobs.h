/* `stepwise bench`'s scenes measured side by side: one worker thread per
 * core takes the next scene; the caller prints each report in order as
 * soon as it and those before it are done. Every number but the times is
 * the same whatever the number of workers (each scene's sweep is one
 * worker's, in a fixed order). */
#ifndef SW_CLI_BENCH_JOBS_H
#define SW_CLI_BENCH_JOBS_H

#include "measure/bench.h"

typedef struct sw_bench_jobs sw_bench_jobs;

typedef struct sw_bench_task {
    const sw_scene *scene;
    const double *p;              /* SW_MAX_PARAMS values */
    const sw_integrator *const *methods; /* NULL: every method that applies */
    int nmethods;
    const sw_bench_config *cfg;
    sw_events_mode events;
} sw_bench_task;

/* Start measuring task[i] into report[i] (i < n) on `workers` threads (at
 * most n; 0: none, each scene measured on the caller's thread when waited
 * for, as a plugin's host needs). NULL when out of memory or no thread
 * could start (err says). */
sw_bench_jobs *sw_bench_jobs_start(const sw_bench_task *task, sw_bench_report *report, int n, int workers,
                                   char *err, size_t errlen);
/* Wait until report i is done: SW_OK, or its status with err (the report
 * then freed). */
int sw_bench_jobs_wait(sw_bench_jobs *j, int i, char *err, size_t errlen);
/* Wait for every worker and free the jobs (not the reports). */
void sw_bench_jobs_free(sw_bench_jobs *j);

#endif
