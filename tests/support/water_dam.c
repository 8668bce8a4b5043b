/* The water scene's dam break against Martin & Moyce's measurements. The
 * front is the largest x of a particle of the fluid's body (at least three
 * others within h), not of the spray thrown ahead of it. */
#include "water_dam.h"

#include <check.h>
#include <math.h>
#include <stdio.h>

#include "stepwise/stepwise.h"

/* J. C. Martin and W. J. Moyce, "An experimental study of the collapse of
 * liquid columns on a rigid horizontal plane", Phil. Trans. R. Soc. Lond.
 * A 244 (1952) 312-324, figure 3: n² = 2, a = 1.125 in. As transcribed in
 * PySPH, pysph/examples/db_exp_data.py (mm_data_1, get_martin_moyce_1),
 * github.com/pypr/pysph at commit 483e4449f50719350fc2857e8163ea3aae637cc7.
 * The first five points: Z up to 3.7, while the scene's front is still
 * short of its far wall at Z = 3 m / a = 5 (the experiment's plane ran
 * on; at the sixth, T = 3.598, a fine run's front is at the wall). */
const double water_dam_T[WATER_DAM_POINTS] = { 0.849, 1.212, 1.602, 2.283, 2.950 };
const double water_dam_Z[WATER_DAM_POINTS] = { 1.245, 1.443, 1.884, 2.689, 3.728 };

#define DAM_A 0.6 /* the dam's width, m (water.c's shape 0: a × 2a) */

/* The largest x of a particle with at least three others within h. */
static double body_front(const sw_sim *s, double h)
{
    int n = s->sys.n;
    const double *x = s->sys.y;
    double front = 0;
    for (int i = 0; i < n; i++) {
        if (!(x[2 * i] > front))
            continue;
        int near = 0;
        for (int j = 0; j < n && near < 3; j++) {
            double dx = x[2 * i] - x[2 * j], dy = x[2 * i + 1] - x[2 * j + 1];
            near += j != i && dx * dx + dy * dy < h * h;
        }
        if (near >= 3)
            front = x[2 * i];
    }
    return front;
}

void water_dam_front(int n, double nu, double *Z, double *lo, double *hi)
{
    const sw_scene *sc = sw_scene_find("water");
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN], set[32];
    sw_scene_defaults(sc, p);
    snprintf(set, sizeof set, "n=%d", n);
    ck_assert(sw_scene_set(sc, p, set, err, sizeof err) == SW_OK);
    snprintf(set, sizeof set, "nu=%.17g", nu);
    ck_assert(sw_scene_set(sc, p, set, err, sizeof err) == SW_OK);
    ck_assert(sw_scene_set(sc, p, "shape=0", err, sizeof err) == SW_OK);
    sw_sim s;
    ck_assert_msg(sw_sim_init(&s, sc, p, sw_integrator_find("symplectic-euler"), 0.0004, err, sizeof err) == SW_OK,
                  "%s", err);
    double h = 0;
    for (int k = 0; k < s.sys.particles.nforces; k++)
        if (s.sys.particles.forces[k].kind == SW_FORCE_SPH)
            h = s.sys.particles.forces[k].h;
    ck_assert(h > 0);
    double g = p[sw_scene_param_index(sc, "g")], rate = sqrt(2 * g / DAM_A);
    *lo = INFINITY, *hi = -INFINITY;
    for (int k = 0; k < WATER_DAM_POINTS; k++) {
        sw_sim_run_until(&s, water_dam_T[k] / rate);
        ck_assert(!s.blown);
        Z[k] = body_front(&s, h) / DAM_A;
        *lo = fmin(*lo, Z[k] / water_dam_Z[k] - 1);
        *hi = fmax(*hi, Z[k] / water_dam_Z[k] - 1);
    }
    sw_sim_free(&s);
}
