/* The water scene's CFL limit measured and in theory, for check_water.c
 * and the claims (docs/scenes.md, 'water'). */
#ifndef SW_TESTS_WATER_CFL_H
#define SW_TESTS_WATER_CFL_H

/* Theory's largest stable step for method on a column of 100 particles at
 * rest with sets ("NAME=VALUE ...", or NULL) on top: the truth module on
 * the scene's spectrum at the start (0: the method grows at every step). */
double water_cfl_theory(const char *sets, const char *method);
/* The theory's limit into *theory, and the measured one (the step where the
 * column first blows up within `horizon` seconds, bisected to 1 %: runs
 * away, or moves faster than 5 m/s) into *measured. */
void water_cfl_at(const char *sets, const char *method, double horizon, double *theory, double *measured);
/* water_cfl_at with the scene's parameters and a horizon of 1 s. */
void water_cfl(const char *method, double *theory, double *measured);
/* measured / theory (water_cfl). */
double water_cfl_ratio(const char *method);

#endif
