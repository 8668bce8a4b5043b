/* The integrator table and registry, and the stepper that runs one method
 * on one system. The methods themselves live one family per file
 * (explicit.c, implicit.c, rk45.c, dop853.c, rosenbrock.c, vern.c) and know nothing of particles: they see
 * an sw_ode. Invariant: a step allocates nothing — every vector it touches
 * was handed out by sw_stepper_init. */
#include "engine/stepper.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/lecture.h"
#include "engine/mistakes.h"
#include "stepwise/base.h"
#include "util/names.h"

/* Why a method's stages are not drawn, for its row (the stage view says
 * "stages: not drawn for NAME — " and this). */
static const char solves[] = "it solves an equation, see lesson 7";
static const char adapts[] = "it chooses its own steps, see lesson 9";

static const sw_integrator builtins[] = {
    { .name = "euler", .label = "explicit (forward) Euler", .order = 1, .evals = 1,
      .flags = SW_EXPLICIT, .stability = 0.0, .work_vectors = 1, .step = sw_step_euler,
      .summary = "y1 = y0 + h f(y0)",
      .lecture = &sw_lecture_euler, .compare = 2,
      .twin = "symplectic-euler",
      .twin_hint = "did you update v before x? (Euler moves x with the old v)" },
    { .name = "symplectic-euler", .label = "semi-implicit Euler", .order = 1, .evals = 1,
      .flags = SW_EXPLICIT | SW_SYMPLECTIC | SW_NEEDS_SECOND_ORDER, .stability = 2.0,
      .work_vectors = 1, .step = sw_step_symplectic_euler,
      .summary = "v1 = v0 + h a(x0, v0); x1 = x0 + h v1",
      .lecture = &sw_lecture_symplectic_euler, .compare = 5,
      .twin = "euler",
      .twin_hint = "did you move x with the old v? (symplectic Euler updates v first, "
                   "then x with the new v)" },
    { .name = "midpoint", .label = "explicit midpoint (RK2)", .order = 2, .evals = 2,
      .flags = SW_EXPLICIT, .stability = 0.0, .work_vectors = 2, .step = sw_step_midpoint,
      .summary = "y1 = y0 + h f(y0 + h/2 f(y0))",
      .lecture = &sw_lecture_midpoint, .mistakes = sw_mistakes_midpoint, .compare = 4 },
    { .name = "heun", .label = "Heun / explicit trapezoid (RK2)", .order = 2, .evals = 2,
      .flags = SW_EXPLICIT, .stability = 0.0, .work_vectors = 3, .step = sw_step_heun,
      .summary = "y1 = y0 + h/2 (f(y0) + f(y0 + h f(y0)))",
      .lecture = &sw_lecture_heun, .mistakes = sw_mistakes_heun },
    { .name = "rk4", .label = "classical Runge-Kutta", .order = 4, .evals = 4,
      .flags = SW_EXPLICIT, .stability = 2.0 * 1.4142135623730951, .work_vectors = 3,
      .step = sw_step_rk4, .summary = "y1 = y0 + h/6 (k1 + 2 k2 + 2 k3 + k4)",
      .lecture = &sw_lecture_rk4, .mistakes = sw_mistakes_rk4, .compare = 1 },
    { .name = "verlet", .label = "velocity Verlet (leapfrog)", .order = 2, .evals = 1,
      .flags = SW_EXPLICIT | SW_SYMPLECTIC | SW_NEEDS_SECOND_ORDER, .stability = 2.0,
      .work_vectors = 2, .step = sw_step_verlet,
      .summary = "v+ = v0 + h/2 a0; x1 = x0 + h v+; v1 = v+ + h/2 a1",
      .lecture = &sw_lecture_verlet, .mistakes = sw_mistakes_verlet, .compare = 3 },
    { .name = "implicit-euler", .label = "backward Euler (Newton to rounding, direct solve)",
      .order = 1, .evals = 1, .flags = SW_IMPLICIT | SW_NEWTON, .stability = INFINITY,
      .work_vectors = 6, .step = sw_step_implicit_euler,
      .summary = "y1 = y0 + h f(y1), solved by Newton's method", .no_lecture = solves,
      .compare = 6, .resting = 1 },
    { .name = "linear-implicit-euler", .label = "linearly implicit Euler (one Newton step)",
      .order = 1, .evals = 1, .flags = SW_IMPLICIT, .stability = INFINITY, .work_vectors = 2,
      .step = sw_step_linear_implicit_euler,
      .summary = "(I - h J(y0)) dy = h f(y0): Baraff-Witkin's large steps", .no_lecture = solves },
    { .name = "implicit-midpoint", .label = "implicit midpoint (Newton to rounding)", .order = 2,
      .evals = 2, .flags = SW_IMPLICIT | SW_SYMPLECTIC | SW_NEWTON, .stability = INFINITY,
      .work_vectors = 6, .step = sw_step_implicit_midpoint,
      .summary = "y1 = y0 + h f((y0 + y1)/2), solved by Newton's method", .no_lecture = solves },
    { .name = "rk45", .label = "Dormand-Prince 5(4), adaptive", .order = 5, .evals = 6,
      .flags = SW_EXPLICIT | SW_ADAPTIVE, .stability = 0.0, .work_vectors = 9, .step = sw_step_rk45,
      .summary = "adaptive: error estimate from an embedded 4th-order solution", .no_lecture = adapts },
    { .name = "dop853", .label = "Dormand-Prince 8(5,3), adaptive (Hairer)", .order = 8, .evals = 12,
      .flags = SW_EXPLICIT | SW_ADAPTIVE, .stability = 0.0, .work_vectors = SW_DOP853_VECTORS,
      .step = sw_step_dop853,
      .summary = "adaptive: error estimate from embedded 5th- and 3rd-order solutions",
      .no_lecture = adapts, .reference = 1 },
    /* Last, so that the keys of the methods before it (lessons name them)
     * keep their places. Stability: the first ω·h where the trace of the
     * one-step map on x'' = -ω²x, M = V(w1 z) V(w0 z) V(w1 z) with V(τ) =
     * [[1 - τ²/2, τ], [-τ(1 - τ²/4), 1 - τ²/2]], climbs back to +2: found by
     * bisection on the product at 30 digits (no root of |tr M| = 2 beyond it
     * up to ω·h = 4); tests/check_yoshida.c recomputes it. */
    { .name = "yoshida4", .label = "Yoshida 4th-order symplectic (2nd where a force reads v)", .order = 4,
      .evals = 3, .flags = SW_EXPLICIT | SW_SYMPLECTIC | SW_NEEDS_SECOND_ORDER,
      .stability = 1.5734019474345401, .work_vectors = 2, .step = sw_step_yoshida4,
      .summary = "verlet substeps of w1 h, w0 h, w1 h; w1 = 1/(2 - 2^(1/3)), w0 = -2^(1/3) w1",
      .no_lecture = "three Verlet steps in one, see verlet's" },
    /* x'' = f(x) only: refused where a force reads velocities (below). */
    { .name = "rkn", .label = "Runge-Kutta-Nystrom 6(4), adaptive (Dormand, El-Mikkawy, Prince)",
      .order = 6, .evals = 5,
      .flags = SW_EXPLICIT | SW_ADAPTIVE | SW_NEEDS_SECOND_ORDER | SW_POSITION_ONLY,
      .stability = 0.0, .work_vectors = 8, .step = sw_step_rkn,
      .summary = "adaptive: x'' = f(x) stepped directly, error from an embedded 4th-order solution",
      .no_lecture = adapts },
    /* Linearly implicit and L-stable: stable for every ω·h. Evaluations:
     * five stages, the derivative at the new state (FSAL) and one for
     * ∂f/∂t where the system does not say f ignores t (a flow field): 7,
     * the most, here; 6 on particle systems. Six solves with one matrix
     * (I - γh J). */
    { .name = "rodas4", .label = "Rosenbrock RODAS4 4(3), adaptive, L-stable (Hairer); 6 evals on particles",
      .order = 4,
      .evals = 7, .flags = SW_IMPLICIT | SW_ADAPTIVE, .stability = INFINITY, .work_vectors = 12,
      .step = sw_step_rodas4,
      .summary = "adaptive: (I - h/4 J) k_i = h/4 (f(y0 + sum a_ij k_j) + sum c_ij/h k_j), 6 stages",
      .no_lecture = solves },
    /* rkn's 12th-order sibling for tight tolerances: 16 stages and the
     * derivative at the new state (not FSAL), 17 evaluations a step. */
    { .name = "rkn12", .label = "Runge-Kutta-Nystrom 12(10), adaptive (Dormand, El-Mikkawy, Prince)",
      .order = 12, .evals = 17,
      .flags = SW_EXPLICIT | SW_ADAPTIVE | SW_NEEDS_SECOND_ORDER | SW_POSITION_ONLY,
      .stability = 0.0, .work_vectors = 21, .step = sw_step_rkn12,
      .summary = "adaptive: x'' = f(x) stepped directly at 12th order, error from an embedded "
                 "10th-order solution",
      .no_lecture = adapts },
    /* One body alone in one central field only (dop853_lc.c): 12 stages,
     * the first the last step's derivative at its end (13 on a step from
     * a state the last step did not leave); prepare makes the regularised
     * run it steps. */
    { .name = "dop853-lc", .label = "dop853 in Levi-Civita's variables: the Kepler problem regularised",
      .order = 8, .evals = 12,
      .flags = SW_EXPLICIT | SW_ADAPTIVE | SW_NEEDS_SECOND_ORDER | SW_ONE_BODY, .stability = 0.0,
      .work_vectors = 1, .step = sw_step_dop853_lc, .prepare = sw_dop853_lc_prepare,
      .summary = "adaptive: x = c + u^2, dt = |x - c| ds: the close pass taken in a clock that slows there",
      .no_lecture = adapts },
    /* Verner's efficient 8(7) and 9(8) pairs (vern.c): 12 and 15 stages
     * after the first, then the derivative at the new state, which the
     * next step reuses. */
    { .name = "vern8", .label = "Verner 8(7) \"most efficient\", adaptive", .order = 8, .evals = 13,
      .flags = SW_EXPLICIT | SW_ADAPTIVE, .stability = 0.0, .work_vectors = SW_V8_VECTORS,
      .step = sw_step_vern8,
      .summary = "adaptive: 13 stages, error estimate from an embedded 7th-order solution",
      .no_lecture = adapts },
    { .name = "vern9", .label = "Verner 9(8) \"most efficient\", adaptive", .order = 9, .evals = 16,
      .flags = SW_EXPLICIT | SW_ADAPTIVE, .stability = 0.0, .work_vectors = SW_V9_VECTORS,
      .step = sw_step_vern9,
      .summary = "adaptive: 16 stages, error estimate from an embedded 8th-order solution",
      .no_lecture = adapts },
};

#define NBUILTIN ((int)(sizeof builtins / sizeof builtins[0]))
_Static_assert(NBUILTIN + SW_REGISTERED_MAX <= SW_METHODS_MAX,
               "a row too many: the built-ins and SW_REGISTERED_MAX plugins must fit SW_METHODS_MAX "
               "(stepwise/integrator.h), and the UI then needs a pick key for each (SW_PICK_KEYS, lesson/controls.h)");
static sw_integrator extra[SW_REGISTERED_MAX];
static char extra_disabled[SW_REGISTERED_MAX][SW_ERRLEN]; /* non-empty: why it is refused */
static int nextra;

int sw_integrator_count(void) { return NBUILTIN + nextra; }

const sw_integrator *sw_integrator_at(int index)
{
    if (index < 0 || index >= NBUILTIN + nextra)
        return NULL;
    return index < NBUILTIN ? &builtins[index] : &extra[index - NBUILTIN];
}

static const char *name_at(const void *ctx, int i)
{
    (void)ctx;
    return sw_integrator_at(i)->name;
}

size_t sw_integrator_names(char *buf, size_t len)
{
    return sw_names_join(buf, len, name_at, NULL, sw_integrator_count());
}

const sw_integrator *sw_integrator_find(const char *name)
{
    for (int i = 0; i < sw_integrator_count(); i++)
        if (strcmp(sw_integrator_at(i)->name, name) == 0)
            return sw_integrator_at(i);
    return NULL;
}

int sw_integrator_register(const sw_integrator *method, char *err, size_t errlen)
{
    if (sw_integrator_find(method->name)) {
        snprintf(err, errlen, "an integrator named '%s' already exists", method->name);
        return SW_EINVAL;
    }
    if (nextra == SW_REGISTERED_MAX) {
        snprintf(err, errlen, "at most %d plugin integrators can be loaded", SW_REGISTERED_MAX);
        return SW_EINVAL;
    }
    extra[nextra++] = *method;
    return SW_OK;
}

void sw_integrator_disable(const sw_integrator *m, const char *why)
{
    for (int i = 0; i < nextra; i++)
        if (m == &extra[i])
            snprintf(extra_disabled[i], sizeof extra_disabled[i], "%s", why && *why ? why : "disabled");
}

/* "euler, midpoint, ... or dop853": the built-in methods a first-order
 * system can use, from the table. */
static void first_order_names(char *buf, size_t len)
{
    int n = 0, last = -1;
    for (int i = 0; i < NBUILTIN; i++)
        if (!(builtins[i].flags & SW_NEEDS_SECOND_ORDER))
            last = i;
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < NBUILTIN && used < len; i++) {
        if (builtins[i].flags & SW_NEEDS_SECOND_ORDER)
            continue;
        int w = snprintf(buf + used, len - used, "%s%s", n == 0 ? "" : i == last ? " or " : ", ",
                         builtins[i].name);
        used += w > 0 ? (size_t)w : 0;
        n++;
    }
}

int sw_integrator_accepts(const sw_integrator *m, const sw_ode *ode, char *err, size_t errlen)
{
    for (int i = 0; i < nextra; i++)
        if (m == &extra[i] && extra_disabled[i][0]) {
            snprintf(err, errlen, "'%s' is disabled: %s", m->name, extra_disabled[i]);
            return SW_EINVAL;
        }
    if ((m->flags & SW_NEEDS_SECOND_ORDER) && ode->order != 2) {
        char fit[512];
        first_order_names(fit, sizeof fit);
        snprintf(err, errlen,
                 "'%s' updates velocities and positions separately and needs a system with "
                 "masses; this is a first-order flow field (use %s)", m->name, fit);
        return SW_EINVAL;
    }
    if ((m->flags & SW_POSITION_ONLY) && !sw_ode_position_only(ode)) {
        snprintf(err, errlen, "'%s' solves x'' = f(x) and needs forces that ignore velocities; this system "
                 "has drag or damped springs (set them to 0, or use dop853 or rk45)", m->name);
        return SW_EINVAL;
    }
    sw_central1 field;
    if ((m->flags & SW_ONE_BODY) && !sw_ode_central1(ode, &field)) {
        snprintf(err, errlen, "'%s' steps one body alone in one central field (the orbit scene) in "
                 "regularised variables; this system is not that (use dop853)", m->name);
        return SW_EINVAL;
    }
    if ((m->flags & SW_IMPLICIT) && !ode->solve && ode->dim > SW_DENSE_MAX) {
        snprintf(err, errlen, "'%s' needs a Jacobian this system does not provide "
                 "(dimension %d is above the dense fallback's %d)", m->name, ode->dim, SW_DENSE_MAX);
        return SW_EINVAL;
    }
    return SW_OK;
}

int sw_stepper_init(sw_stepper *s, const sw_integrator *m, const sw_ode *ode, char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    int rc = sw_integrator_accepts(m, ode, err, errlen);
    if (rc != SW_OK)
        return rc;
    s->method = m;
    s->dim = ode->dim;
    s->rtol = SW_RTOL_DEFAULT;
    s->atol = SW_ATOL_DEFAULT;
    size_t len = (size_t)(m->work_vectors > 0 ? m->work_vectors : 1) * (size_t)ode->dim;
    s->work = calloc(len, sizeof *s->work);
    if ((m->flags & SW_IMPLICIT) && !ode->solve) {
        size_t d = (size_t)ode->dim;
        s->dense = calloc(d * d + 3 * d, sizeof *s->dense);
        if (!s->dense) {
            free(s->work);
            s->work = NULL;
        }
    }
    if (!s->work) {
        snprintf(err, errlen, "out of memory for %s workspace (%d doubles)", m->name, ode->dim);
        return SW_ENOMEM;
    }
    if (m->prepare) {
        rc = m->prepare(s, ode, err, errlen);
        if (rc != SW_OK) {
            sw_stepper_free(s);
            return rc;
        }
    }
    if ((m->flags & SW_IMPLICIT) && ode->prepare) {
        rc = ode->prepare(ode->ctx, err, errlen);
        if (rc != SW_OK) {
            sw_stepper_free(s);
            return rc;
        }
    }
    return SW_OK;
}

void sw_stepper_free(sw_stepper *s)
{
    if (s->release)
        s->release(s);
    s->release = NULL;
    free(s->work);
    free(s->dense);
    s->work = s->dense = NULL;
}

void sw_stepper_touch(sw_stepper *s) { s->have_cache = 0; }

int sw_stepper_memory_save(const sw_stepper *s, double *out)
{
    return s->method->step == sw_step_dop853_lc ? sw_dop853_lc_save(s, out) : 0;
}

void sw_stepper_memory_load(sw_stepper *s, const double *in, int n, double t, const double *y)
{
    if (n > 0 && s->method->step == sw_step_dop853_lc)
        sw_dop853_lc_load(s, in, n, t, y);
}

sw_stepper *sw_stepper_new(const sw_integrator *m, const sw_ode *ode, char *err, size_t errlen)
{
    if (!m || !ode || !ode->deriv || ode->dim < 1 || (ode->order != 1 && ode->order != 2) ||
        (ode->order == 2 && ode->dim % 2)) {
        snprintf(err, errlen, "a stepper needs a method and an ode with a derivative, dim >= 1 and "
                 "order 1 or 2 (order 2: an even dim, y = [x | v])");
        return NULL;
    }
    sw_stepper *s = malloc(sizeof *s);
    if (!s) {
        snprintf(err, errlen, "out of memory for a stepper");
        return NULL;
    }
    if (sw_stepper_init(s, m, ode, err, errlen) != SW_OK) {
        free(s);
        return NULL;
    }
    return s;
}

void sw_stepper_delete(sw_stepper *s)
{
    if (!s)
        return;
    sw_stepper_free(s);
    free(s);
}

int sw_stepper_step(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    s->checked = 0;
    s->why = NULL;
    return s->method->step(s, ode, t, y, h);
}

