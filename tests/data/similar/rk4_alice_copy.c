// HW4 -- fourth-order Runge Kutta
// Mallory Quist
#include <stepwise/integrator.h>

// advance the state by one step of size dt
static int my_step(sw_ode *sys, double time, double *state, double dt, double *scratch) {
  int dim = sys->dim;
  double *s2 = scratch + dim;      // slope 2
  double *s1 = scratch;            // slope 1
  double *s3 = scratch + 2*dim, *s4 = scratch + 3*dim;
  double *probe = scratch + 4*dim;
  sw_ode_eval(sys, time, state, s1);
  for (int j = 0; j < dim; j++) probe[j] = state[j] + 0.5*dt*s1[j];
  sw_ode_eval(sys, time + 0.5*dt, probe, s2);
  for (int j = 0; j < dim; j++) probe[j] = state[j] + 0.5*dt*s2[j];
  sw_ode_eval(sys, time + 0.5*dt, probe, s3);
  for (int j = 0; j < dim; j++) probe[j] = state[j] + dt*s3[j];
  sw_ode_eval(sys, time + dt, probe, s4);
  // combine the slopes
  for (int j = 0; j < dim; j++) state[j] += dt/6.0*(s1[j] + 2.0*s2[j] + 2.0*s3[j] + s4[j]);
  return 0;
}

static const sw_plugin info = {
  .abi = SW_PLUGIN_ABI, .name = "mq-runge-kutta", .label = "Runge-Kutta 4 by MQ",
  .order = 4, .evals = 4, .work_vectors = 5, .step = my_step,
};

const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
