/* Claims: how far back the rewind keys go (sim/history.c), in the README,
 * the man page and docs/architecture.md: measured on the histories the
 * app would build. */
#include "claims.h"
#include "sim/history.h"

#define ARCH "docs/architecture.md"

/* The history a sim of scene (with sets) under method m gets: what `what`
 * asks of it (0 cap, 1 stride, 2 budget in MiB, 3 span (cap - 1) · stride). */
static double history_of(const char *scene, const char *sets, const char *m, int what)
{
    sw_sim s;
    sw_history h;
    cl_sim_init(&s, scene, sets, m, sw_scene_find(scene)->dt);
    sw_history_init(&h, &s);
    double v = what == 0 ? h.cap : what == 1 ? h.stride : what == 2 ? h.budget / 1048576.0
                                                                   : (double)(h.cap - 1) * h.stride;
    sw_history_free(&h);
    sw_sim_free(&s);
    return v;
}

static double small_cap(void) { return history_of("spring", NULL, "rk4", 0); }
static double small_budget_mib(void) { return history_of("spring", NULL, "rk4", 2); }

/* The chain at n = 100000: the same stride under its own method (verlet,
 * which keeps an FSAL derivative) and rk4 (which does not); NaN if not. */
static double chain_stride(void)
{
    double a = history_of("chain", "n=100000", "verlet", 1), b = history_of("chain", "n=100000", "rk4", 1);
    return a == b ? a : NAN;
}

/* The fewest snapshots (with room for an FSAL derivative) kept every step:
 * the vortex's n bisected to the last size whose history under rk45 has
 * stride 1, and its cap there. */
static double fewest_every_step(void)
{
    char sets[32];
    int lo = 100, hi = 100000; /* stride 1 at lo, above 1 at hi */
    while (hi - lo > 1) {
        int mid = lo + (hi - lo) / 2;
        snprintf(sets, sizeof sets, "n=%d", mid);
        *(history_of("vortex", sets, "rk45", 1) == 1 ? &lo : &hi) = mid;
    }
    snprintf(sets, sizeof sets, "n=%d", lo);
    return history_of("vortex", sets, "rk45", 0);
}

/* The least span of a striding history, over vortex sizes from just past
 * stride 1 to 300000 points, under rk45 and rk4. */
static double least_span(void)
{
    static const char *const sizes[] = { "n=8200", "n=9000", "n=12000", "n=20000", "n=33000", "n=50000",
                                         "n=100000", "n=150000", "n=300000" };
    double least = INFINITY;
    for (size_t i = 0; i < sizeof sizes / sizeof sizes[0]; i++)
        for (int m = 0; m < 2; m++) {
            const char *method = m ? "rk4" : "rk45";
            if (history_of("vortex", sizes[i], method, 1) > 1)
                least = fmin(least, history_of("vortex", sizes[i], method, 3));
        }
    return least;
}

const claim sw_claims_w[] = {
    { README, "(the last {4096} states are kept; a system too large", small_cap, EXACT, 0, R_COUNT, NULL },
    { README, "checkpoint every few steps, every {64} for the chain at n = 100000", chain_stride, EXACT, 0,
      "the stride the chain's history takes at that size, the same under verlet and rk4", NULL },
    { MAN, "through the last {4096} states", small_cap, EXACT, 0, R_COUNT, NULL },
    { ARCH, "at most {4096} states in 16 MiB", small_cap, EXACT, 0, R_COUNT, NULL },
    { ARCH, "at most 4096 states in {16} MiB", small_budget_mib, EXACT, 0, "the budget of a small system's history",
      NULL },
    { ARCH, "with room for fewer than {64} (counting", fewest_every_step, EXACT, 0,
      "the cap at the largest vortex that still keeps every step", NULL },
    { ARCH, "the ring spanning {64} steps or more", least_span, ATLEAST, 0,
      "the least span measured over vortex sizes that stride", NULL },
};
const size_t sw_claims_w_n = sizeof sw_claims_w / sizeof sw_claims_w[0];
