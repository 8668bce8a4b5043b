/* Private to the truth module: the workspace that lets the live meter ask
 * for spectra, growths and limits again and again without allocating (a
 * buffer sized for one system; one stepper per mode for one method). */
#ifndef SW_SIM_TRUTH_WORK_H
#define SW_SIM_TRUTH_WORK_H

#include <stddef.h>

#include "engine/linear2.h"
#include "engine/stepper.h"
#include "sim/truth.h"

/* y' = J y for the 2x2 matrix J of one mode (engine/linear2.h): a flow
 * (order 1) with eigenvalues a ± ib, or a second-order system (x, v) with
 * J = [[0, 1], [A, B]] (roots λ, μ: B = λ + μ, A = -λμ). */
typedef sw_linear2 sw_test_system;

struct sw_truth_work {
    double *buf;          /* spectrum scratch, cap doubles */
    size_t cap;
    const sw_integrator *method;   /* the steppers' method, or NULL */
    int ready;            /* steppers initialised for it */
    sw_test_system ts[SW_TRUTH_MODES];
    sw_stepper st[SW_TRUTH_MODES];
};

/* Free the steppers (the method changed); the buffer stays. */
void sw_truth_work_drop_steppers(sw_truth_work *w);
/* At least n doubles of scratch (grown, never shrunk); NULL when out of memory. */
double *sw_truth_scratch(sw_truth_work *w, size_t n);

#endif
