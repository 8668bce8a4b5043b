/* The water scene's CFL limit measured and in theory, for check_water.c
 * and the claims (docs/scenes.md, 'water'). */
#ifndef SW_TESTS_WATER_CFL_H
#define SW_TESTS_WATER_CFL_H

/* Theory's largest stable step for method on a column of 100 particles at
 * rest (the truth module on the scene's spectrum at the start) into
 * *theory, and the measured one (the step where the column first blows
 * up within 1 s, bisected to 1 %: runs away, or moves faster than 5 m/s)
 * into *measured. */
void water_cfl(const char *method, double *theory, double *measured);
/* measured / theory. */
double water_cfl_ratio(const char *method);

#endif
