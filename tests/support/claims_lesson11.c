/* Claims: lesson 11's figures (fire, explosion, water), each from the page's
 * own sim (its scene, parameters and Δt as the lesson sets them) or the
 * scene's defaults, through the library. */
#include "claims.h"

/* Parameter `name` of the sim on page `title`, and its Δt into *dt. */
static double page_param(const char *title, const char *name, double *dt)
{
    sw_runner r;
    sw_app a;
    cl_lesson_page(&r, &a, L11, title);
    const sw_system *sys = &a.sims[0].sys;
    int i = sw_scene_param_index(sys->scene, name);
    ck_assert_msg(i >= 0, "no parameter %s on page %s", name, title);
    double v = sys->p[i];
    if (dt)
        *dt = a.sims[0].dt;
    cl_page_free(&r, &a);
    return v;
}

#define P_LIFE "Particles with a life"
#define P_FAST "Fast cooling limits the step"
#define P_DEATH "A death inside a step"
#define P_BANG "An explosion"
#define P_WATER "Water: the sound sets the step"

static double births(void) { return page_param(P_LIFE, "rate", NULL); }
static double life(void) { return page_param(P_LIFE, "life", NULL); }
/* 300 + (1200 - 300) e^(-kappa·1 s) at the page's kappa. */
static double after_1s(void) { return 300 + 900 * exp(-page_param(P_LIFE, "kappa", NULL)); }
static double times_faster(void) { return page_param(P_FAST, "kappa", NULL) / page_param(P_LIFE, "kappa", NULL); }
static double kappa_fast(void) { return page_param(P_FAST, "kappa", NULL); }
static double fast_dt(void)
{
    double dt;
    page_param(P_FAST, "kappa", &dt);
    return dt;
}
/* Euler's factor on the excess at kappa = 0: one step of the page's method
 * on body 0's temperature, θ1/θ0 (the 1 in 1 - kappa·Δt). */
static double one(void)
{
    sw_sim s;
    cl_sim_init(&s, "fire", "kappa=0", "euler", fast_dt());
    int n = s.sys.n;
    double th0 = s.sys.y[2 * n + 2 * (n / 2)];
    sw_sim_step(&s);
    double f = s.sys.y[2 * n + 2 * (n / 2)] / th0;
    sw_sim_free(&s);
    return f;
}
static double euler_factor(void)
{
    double dt, k = page_param(P_FAST, "kappa", &dt);
    return 1 - k * dt;
}
static double euler_limit(void) { return cl_limit0("fire", "kappa=20", "euler"); }
static double motion_limit(void) { return cl_limit0("fire", "kappa=0", "euler"); }
static double drag(void) { return page_param(P_FAST, "drag", NULL); }
static double death_life(void) { return page_param(P_DEATH, "life", NULL); }
/* When the first flame is first seen dead on the page's sim (events stepped over). */
static double death_stepped(void)
{
    sw_runner r;
    sw_app a;
    cl_lesson_page(&r, &a, L11, P_DEATH);
    sw_sim *s = &a.sims[0];
    ck_assert_int_eq(s->events, SW_EVENTS_STEP);
    int n = s->sys.n;
    while (s->t < 2 && s->sys.y[2 * n + 2 * (n / 2) + 1] != 0)
        sw_sim_step(s);
    double t = s->t;
    cl_page_free(&r, &a);
    return t;
}
/* The fragments' mean temperature just after the burst, K. */
static double burst_mean(void)
{
    sw_runner r;
    sw_app a;
    cl_lesson_page(&r, &a, L11, P_BANG);
    sw_sim *s = &a.sims[0];
    double t0 = s->sys.p[sw_scene_param_index(s->sys.scene, "t0")];
    sw_sim_run_until(s, t0 + s->dt);
    int n = s->sys.n, m = n / 2;
    double sum = 0;
    for (int i = 0; i < m; i++)
        sum += 300 + s->sys.y[2 * n + 2 * (m + i)] * exp(s->sys.p[sw_scene_param_index(s->sys.scene, "kappa")] *
                                                         (s->t - t0)); /* at the burst */
    cl_page_free(&r, &a);
    return sum / m;
}
static double restitution(void) { return page_param(P_BANG, "e", NULL); }
static double sound(void) { return sqrt(page_param(P_WATER, "k", NULL)); }
/* symplectic Euler's limit on the page's water, in ms. */
static double water_limit_ms(void) { return 1000 * cl_limit0("water", NULL, "symplectic-euler"); }
static double water_dt_ms(void)
{
    double dt;
    page_param(P_WATER, "k", &dt);
    return 1000 * dt;
}
static double water_limit(void) { return cl_limit0("water", NULL, "symplectic-euler"); }
/* Euler's limit on the page's water: over nu/c² (c² = k), and in ms. */
static double euler_water_ms(void) { return 1000 * cl_limit0("water", NULL, "euler"); }
static double euler_water_c(void)
{
    return cl_limit0("water", NULL, "euler") * page_param(P_WATER, "k", NULL) / page_param(P_WATER, "nu", NULL);
}

const claim sw_claims_l[] = {
    { L11, "born at the source {60} times a second", births, EXACT, 0, R_COUNT, NULL },
    { L11, "die below 350 K or at age {2.5} s", life, EXACT, 0, R_COUNT, NULL },
    { L11, "@answer a) {631} K | Yes: T = 300 + 900·e^(−1)", after_1s, ROUNDED, 0, R_ROUND, NULL },
    { L11, "Now the flames cool {20} times faster", times_faster, EXACT, 0, "the page's kappa over the first page's", NULL },
    { L11, "the cooling is {20} times faster", times_faster, EXACT, 0, "the page's kappa over the first page's", NULL },
    { L11, "excess by {1} − kappa·Δt each step", one, EXACT, 0, "Euler's factor on the excess with the cooling off: exactly 1", NULL },
    { L11, "each step: at Δt = {0.16} that is", fast_dt, EXACT, 0, "the page's Δt", NULL },
    { L11, "at Δt = 0.16 that is {−2.2}", euler_factor, ROUNDED, 0, "1 - kappa·Δt at the page's settings", NULL },
    { L11, "Δt < 2/{20}", kappa_fast, EXACT, 0, "the page's kappa", NULL },
    { L11, "@answer a) {0.1} s | Yes:", euler_limit, REL, 1e-9, "Euler's limit on the page's spectrum", NULL },
    { L11, "the motion alone (drag {1} per second)", drag, EXACT, 0, "the page's drag", NULL },
    { L11, "would allow a step of {2} s", motion_limit, REL, 1e-9, "Euler's limit with the cooling off", NULL },
    { L11, "each living {0.55} s", death_life, EXACT, 0, "the page's life", NULL },
    { L11, "@answer b) At {0.6} s | Yes:", death_stepped, ABS, 1e-9, "the page's run, events stepped over", NULL },
    { L11, "a temperature of about {1500} K", burst_mean, ABS, 50, "\"about\": the fragments' mean at the burst, 0.8 to 1.2 of 1200 K above ambient", NULL },
    { L11, "keeping half their speed at each bounce (e = {0.5})", restitution, EXACT, 0, "the page's e", NULL },
    { L11, "at c = √k = {20} m/s here", sound, EXACT, 0, R_COUNT, NULL },
    { L11, "At Δt = {4} ms the meter says the stiffest mode grows", water_limit_ms, ATMOST, 0,
      "symplectic Euler's limit in theory is below the page's step", NULL },
    { L11, "At Δt = {4} ms the meter", water_dt_ms, EXACT, 0, "the page's Δt", NULL },
    { L11, "until dt is {0.001} or less", water_limit, ATLEAST, 0, "the goal's step is within the theory's limit", NULL },
    { L11, "gives it a limit ({4.2}·nu/c²", euler_water_c, ROUNDED, 0, R_ROUND, NULL },
    { L11, "·nu/c², {0.52} ms here)", euler_water_ms, ROUNDED, 0, R_ROUND, NULL },
};
const size_t sw_claims_l_n = sizeof sw_claims_l / sizeof sw_claims_l[0];
