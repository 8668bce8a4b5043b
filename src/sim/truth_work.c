/* The truth module's workspace: a scratch buffer and one stepper per mode,
 * kept so the live meter asks again and again without allocating. The
 * spectrum (truth_spectrum.c) and the growth (truth_growth.c) both use it;
 * it calls neither. */
#include "sim/truth_work.h"

#include <stdlib.h>

sw_truth_work *sw_truth_work_new(void) { return calloc(1, sizeof(sw_truth_work)); }

void sw_truth_work_drop_steppers(sw_truth_work *w)
{
    for (int k = 0; k < w->ready; k++)
        sw_stepper_free(&w->st[k]);
    w->ready = 0;
    w->method = NULL;
}

void sw_truth_work_free(sw_truth_work *w)
{
    if (!w)
        return;
    sw_truth_work_drop_steppers(w);
    free(w->buf);
    free(w);
}

double *sw_truth_scratch(sw_truth_work *w, size_t n)
{
    if (n > w->cap) {
        double *b = realloc(w->buf, n * sizeof *b);
        if (!b)
            return NULL;
        w->buf = b;
        w->cap = n;
    }
    return w->buf;
}
