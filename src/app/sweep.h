/* The work-precision sweep behind `w`, run on a worker thread so that the
 * picture keeps moving while every method is measured (issue 41: the sweep
 * stopped the picture for up to a second at n = 1e5). The worker owns its
 * report until it is done; the app reads it only after sw_sweep_poll says
 * so. A sweep that would step a student's plugin runs on the caller's
 * thread instead: a plugin's host answers one thread. */
#ifndef SW_APP_SWEEP_H
#define SW_APP_SWEEP_H

#include <stddef.h>

#include "measure/bench.h"

typedef struct sw_sweep sw_sweep;

/* Start measuring scene sc at parameters p (NULL: the defaults) within budget state
 * evaluations. NULL when out of memory or no thread could start (err says
 * which). */
sw_sweep *sw_sweep_start(const sw_scene *sc, const double *p, double budget, char *err, size_t errlen);
/* 0 while it runs; 1 when done: then *report is the sweep (the caller owns
 * it, to sw_bench_free and free) or NULL with why set; the job is freed. */
int sw_sweep_poll(sw_sweep *s, sw_bench_report **report, char *why, size_t whylen);
/* 1 when a sweep started now would run on the caller's thread (a plugin is
 * loaded), holding the picture until it is done. */
int sw_sweep_inline(void);
/* Wait for it to end (sw_sweep_poll then answers 1). */
void sw_sweep_wait(sw_sweep *s);
/* Ask it to stop at its next sample, wait, and free it and its report. */
void sw_sweep_cancel(sw_sweep *s);

#endif
