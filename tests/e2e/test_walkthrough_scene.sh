#!/bin/sh
# docs/architecture.md's walk-through "Adding a scene", done as the docs
# say in a scratch copy of the tree: a ball dropped from a height (exact
# solution y = h - g t²/2) in its three files: scenes/drop.c, its extern in
# scenes/scenes.h, its line in catalog[] in scenes/catalog.c. It builds
# (warnings as errors: the program, the unit tests, the plugin host) and
# shows up with no further edit in `list scenes`, `describe` and a
# recorded, checked trace. Nothing silent: what the docs ask beside the
# code is named by the tests, each until it is done — the docs test
# (tests/check_docs.c) names the missing section of docs/scenes.md, and
# the trace hash test names each of the new scene's rows not pinned.
# Full tier only (make test-full).
. "$(dirname "$0")/lib.sh"
. "$ROOT/tests/e2e/walkthrough.sh"
walkthrough_full scene
walkthrough_copy

# 1. scenes/drop.c
cat >"$copy/src/scenes/drop.c" <<'X'
/* drop: one ball let go at rest from a height under gravity (the scene
 * walk-through of docs/architecture.md); exact: y = h - g t^2/2. */
#include <math.h>

#include "scenes/scenes.h"
#include "stepwise/stepwise.h"

enum { DR_G, DR_H, DR_M };
static const sw_param drop_params[] = {
    { "g", 9.81, 0.0, 100.0, 0, "m/s^2", "gravity, pointing down" },
    { "h", 10.0, 0.0, 1000.0, 0, "m", "the height it is let go from" },
    { "m", 1.0, 0.001, 1000.0, 0, "kg", "mass of the ball" },
};

static int drop_build(sw_system *sys, char *err, size_t errlen)
{
    const double *p = sys->p;
    int rc = sw_scene_particles(sys, 1, p[DR_M], err, errlen);
    if (rc != SW_OK)
        return rc;
    sw_particles_add_gravity(&sys->particles, 0.0, -p[DR_G]);
    sys->y[1] = p[DR_H];
    return SW_OK;
}

static int drop_exact(const sw_system *sys, double t, double *y)
{
    const double *p = sys->p;
    y[0] = 0;
    y[1] = p[DR_H] - 0.5 * p[DR_G] * t * t;
    y[2] = 0;
    y[3] = -p[DR_G] * t;
    return 0;
}

static sw_view drop_view(const sw_system *sys)
{
    double h = sys->p[DR_H];
    return (sw_view){ -0.6 * h - 1, 0.6 * h + 1, -0.1 * h - 1, 1.1 * h + 1 };
}

const sw_scene sw_scene_drop = {
    .name = "drop",
    .kind = SW_SYS_PARTICLES,
    .summary = "one ball let go from a height; closed-form exact solution",
    .teaches = "Euler lands late: it uses the velocity at the start of each step.",
    .params = drop_params,
    .nparams = SW_NPARAMS(drop_params),
    .dt = 0.05,
    .integrator = "euler",
    .duration = 1.0,
    .build = drop_build,
    .exact = drop_exact,
    .energy = sw_scene_particle_energy,
    .reference = 1,
    .view = drop_view,
};
X
# 2. its extern in scenes/scenes.h
echo 'extern const sw_scene sw_scene_drop;' >"$WORK/ext"
insert_before "$copy/src/scenes/scenes.h" '^/\* Set sys up as a flow' "$WORK/ext" ||
    fail "no 'Set sys up as a flow' comment after the externs in scenes.h"
# 3. its line in catalog[]
echo '    &sw_scene_drop,' >"$WORK/row"
insert_in_table "$copy/src/scenes/catalog.c" '^static const sw_scene \*const catalog\[\] = \{' "$WORK/row" ||
    fail "no catalog[] table closed by '};' in catalog.c"

walkthrough_build stepwise build/check_stepwise build/stepwise-plugin-host
SWC=$copy/stepwise

"$SWC" list scenes | grep -q '^drop ' || fail "list scenes does not show drop: $("$SWC" list scenes | tail -3)"
"$SWC" describe drop >"$WORK/describe" 2>&1 || fail "describe drop failed: $(cat "$WORK/describe")"
grep -q 'the height it is let go from' "$WORK/describe" || fail "describe drop lacks its parameters: $(cat "$WORK/describe")"
(cd "$WORK" && "$SWC" record drop -i rk4 --steps 20 -o drop.trace && "$SWC" check drop.trace) >"$WORK/rc.log" 2>&1 ||
    fail "a drop trace does not record and check: $(cat "$WORK/rc.log")"

# Named, not silent: the section docs/scenes.md lacks ...
(cd "$copy" && CK_RUN_SUITE=docs CK_FORK=yes ./build/check_stepwise) >"$WORK/docs.log" 2>&1 &&
    fail "the docs test passed without a '## drop' section in docs/scenes.md"
grep -q "docs/scenes.md has no section '## drop'" "$WORK/docs.log" ||
    { cat "$WORK/docs.log"; fail "the docs test does not name the missing section"; }
# ... and passes once it is written (the section the walk-through asks for)
printf '\n## drop\n\nOne ball of mass m let go at rest from (0, h) under gravity g: it starts at\ny = h and falls, y(t) = h - g t²/2.\n' >>"$copy/docs/scenes.md"
(cd "$copy" && CK_RUN_SUITE=docs CK_FORK=yes ./build/check_stepwise) >"$WORK/docs.log" 2>&1 ||
    { cat "$WORK/docs.log"; fail "the docs test fails with drop's section written"; }

# ... and the rows the pinned trace hashes lack, each by name
(cd "$copy" && STEPWISE=$SWC sh tests/e2e/test_trace_hashes.sh) >"$WORK/hash.log" 2>&1 &&
    fail "the trace hash test passed with drop's rows not pinned"
n=$("$SWC" list integrators | wc -l)
[ "$(grep -c '^FAIL: not pinned: drop ' "$WORK/hash.log")" -eq "$n" ] ||
    { cat "$WORK/hash.log"; fail "the hash test does not name each of drop's $n rows"; }
[ "$(grep -c '^FAIL: not pinned: ' "$WORK/hash.log")" -eq "$n" ] ||
    { cat "$WORK/hash.log"; fail "the hash test names rows other than drop's"; }
echo "scene walk-through: 3 files; the docs section and $n trace rows named until done"
