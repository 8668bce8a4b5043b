/* The water scene's dam break against Martin & Moyce (1952), for
 * check_water.c and the claims (docs/scenes.md, 'water'). */
#ifndef SW_TESTS_WATER_DAM_H
#define SW_TESTS_WATER_DAM_H

/* The measurements compared: Martin & Moyce's points for n² = 2 (a column
 * a wide and 2a high), T = t·√(2g/a) and Z = z/a. */
#define WATER_DAM_POINTS 5
extern const double water_dam_T[WATER_DAM_POINTS], water_dam_Z[WATER_DAM_POINTS];

/* Water's own kinematic viscosity, m²/s. */
#define WATER_NU 1e-6

/* The dam (shape 0, a = 0.6 m) of about n particles with viscosity nu
 * under symplectic Euler at Δt = 0.4 ms: the front z/a at each measured T
 * into Z (WATER_DAM_POINTS values), and the least and the largest of
 * Z/Z_measured - 1 into *lo and *hi. */
void water_dam_front(int n, double nu, double *Z, double *lo, double *hi);

#endif
