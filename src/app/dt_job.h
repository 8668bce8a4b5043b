/* The Δt change's measurement (app/dt_error.h) on a worker thread, so that
 * the picture keeps moving while the runs to the report time are made
 * (issue 41: 140 ms on the vortex at n = 1e5). The job owns a copy of its
 * inputs and, while it runs, the scene's measurement cache; both come back
 * when it is polled done or cancelled. */
#ifndef SW_APP_DT_JOB_H
#define SW_APP_DT_JOB_H

#include <stddef.h>

#include "app/dt_error.h"

typedef struct sw_dt_job sw_dt_job;

/* Start measuring in (copied), with the cache *c moved into the job (*c is
 * left empty until it comes back); on this thread, done before it returns,
 * when on_caller is set. NULL when out of memory or no thread could start
 * (err says which; *c untouched). */
sw_dt_job *sw_dt_job_start(const sw_dt_in *in, sw_dt_cache *c, int on_caller, char *err, size_t errlen);
/* 0 while it runs; 1 when done: *out is its result, the cache is back in
 * *c (which must be empty) and the job is freed. */
int sw_dt_job_poll(sw_dt_job *j, sw_dt_result *out, sw_dt_cache *c);
/* Wait for it to end (sw_dt_job_poll then answers 1). */
void sw_dt_job_wait(sw_dt_job *j);
/* Ask it to stop at its next sample time, wait, and free it; the cache
 * comes back into *c (empty), or is freed when c is NULL. j may be NULL. */
void sw_dt_job_cancel(sw_dt_job *j, sw_dt_cache *c);

#endif
