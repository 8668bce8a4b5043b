/* CPU past the limit: three threads burn CPU during the first steps (each
 * step under the 2 s step watchdog) until the process has used @CPU@ s
 * (the grader's --cpu) plus half a second. The numbers are rk4's from the
 * start; if the process is not stopped by then it has used more CPU than
 * allowed and keeps handing in the right answer (a pass); stopped, it
 * fails. If it could not get that much CPU in 20 steps (a machine too busy
 * to tell), it hands in NaN: the test notes an inconclusive result. So a
 * pass always means the limit was not enforced.
 * Graded with generous watchdogs (--wall 40, a 10 s step watchdog): on a
 * busy machine the default ones could stop it first. */
#define EVIL_FAMILY "cpu-hog"
#define EVIL_EXPENSIVE
#define EVIL_CUSTOM_STEP
#include "evil.h"
#include <pthread.h>
#include <stdatomic.h>

static atomic_int burning;

static void *burn(void *arg)
{
    (void)arg;
    volatile double x = 1;
    while (atomic_load(&burning))
        for (int i = 0; i < 100000; i++)
            x = x * 1.0000001 + 1e-9;
    return NULL;
}

static double cpu_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void evil_attack(void) {}

static int evil_step(sw_ode *ode, double t, double *y, double h, double *work)
{
    static int graded, step, inconclusive;
    static pthread_t th[3];
    double goal = atof("@CPU@") + 0.5;
    if (t == 0 && evil_graded_run(ode, t, y, h, work)) {
        graded = 1;
        atomic_store(&burning, 1);
        for (int i = 0; i < 3; i++)
            pthread_create(&th[i], NULL, burn, NULL);
    }
    if (graded && atomic_load(&burning)) {
        double start = evil_now();
        while (evil_now() - start < 1.5 && cpu_seconds() < goal)
            evil_sleep(0.01);
        step++;
        if (cpu_seconds() >= goal || step >= 20) {
            atomic_store(&burning, 0);
            for (int i = 0; i < 3; i++)
                pthread_join(th[i], NULL);
            if (cpu_seconds() < goal)
                inconclusive = 1;
            else
                evil_mark("cpu", NULL);
        }
    }
    if (inconclusive) { /* the test reads "nan" in the row as "inconclusive" */
        for (int i = 0; i < ode->dim; i++)
            y[i] = NAN;
        return 0;
    }
    if (!graded)
        return evil_euler(ode, t, y, h, work);
    return evil_rk4(ode, t, y, h, work);
}
