#!/bin/sh
# docs/architecture.md's walk-through "Adding a force kind", done as the
# docs say in a scratch copy of the tree: a harmonic well, f = -k·m·(x - c),
# in its four files: its value in sw_force_kind (and SW_FORCE_KINDS) and
# its parameter in sw_force (include/stepwise/particles.h), its descriptor
# in engine/force_well.c (fields named), its extern in engine/forces.h and
# its line in engine/forces.c's switch. Nothing is silent: with the first
# three and not the switch's line, the build fails naming forces.c and the
# new kind. With all four it builds (warnings as errors: the program and
# the plugin host), and a program of the copy's library that adds the
# force with sw_particles_add_force gets from the engine the force, the
# energy and (through linearly implicit Euler's one Newton step, which asks
# the descriptor's Jacobian blocks: a wrong block gives another step) the
# step the formulas give.
# Full tier only (make test-full).
. "$(dirname "$0")/lib.sh"
. "$ROOT/tests/e2e/walkthrough.sh"
walkthrough_full "force kind"
walkthrough_copy

# 1. its value and its parameter in include/stepwise/particles.h
h=$copy/include/stepwise/particles.h
sed -i 's|^    SW_FORCE_SPH       /\*\(.*\)\*/$|    SW_FORCE_SPH,      /*\1*/\n    SW_FORCE_WELL      /* f = -k·m·(x - c): a harmonic well about (cx, cy) */|' "$h"
grep -q '^    SW_FORCE_WELL ' "$h" || fail "sw_force_kind does not end with SW_FORCE_SPH as the walk-through expects"
sed -i 's|^#define SW_FORCE_KINDS (SW_FORCE_SPH + 1)|#define SW_FORCE_KINDS (SW_FORCE_WELL + 1)|' "$h"
grep -q 'SW_FORCE_KINDS (SW_FORCE_WELL + 1)' "$h" || fail "no SW_FORCE_KINDS (the last kind + 1) in particles.h"
echo '    double well;         /* SW_FORCE_WELL: its stiffness k per unit mass, 1/s^2 */' >"$WORK/field"
insert_before "$h" '^    sw_spring \*springs;' "$WORK/field" || fail "no springs field in sw_force"

# 2. its descriptor in a file of its own
cat >"$copy/src/engine/force_well.c" <<'X'
/* A harmonic well: f = -k·m·(x - c) on every particle, about the point c
 * (the force kind walk-through of docs/architecture.md). */
#include "engine/forces.h"

#include <stdio.h>

static void well_add(const sw_particles *p, const sw_force *fo, const double *x, const double *v, double *f)
{
    (void)v;
    for (int i = 0; i < p->n; i++) {
        f[2 * i] -= fo->well * p->mass[i] * (x[2 * i] - fo->cx);
        f[2 * i + 1] -= fo->well * p->mass[i] * (x[2 * i + 1] - fo->cy);
    }
}

static void well_potential(const sw_particles *p, const sw_force *fo, const double *x, double *e)
{
    for (int i = 0; i < p->n; i++) {
        double dx = x[2 * i] - fo->cx, dy = x[2 * i + 1] - fo->cy;
        *e += 0.5 * fo->well * p->mass[i] * (dx * dx + dy * dy);
    }
}

static long well_pairs(const sw_particles *p, const sw_force *fo, int *reach)
{
    (void)p, (void)fo;
    *reach = 0;
    return 0;
}

static void well_blocks(const sw_particles *p, const sw_force *fo, const double *x, const double *v,
                        swp_blocks *out)
{
    (void)x, (void)v;
    for (int i = 0; i < p->n; i++) { /* d f / d x = -k m I */
        out->diag[8 * i] -= fo->well * p->mass[i];
        out->diag[8 * i + 3] -= fo->well * p->mass[i];
    }
}

static void well_values(const sw_force *fo, char *buf, size_t len)
{
    snprintf(buf, len, "k = %g, c = (%g, %g)", fo->well, fo->cx, fo->cy);
}

const swp_force_type swp_well = {
    .name = "well",
    .formula = "f = -k m (x - c)",
    .values = well_values,
    .add = well_add,
    .potential = well_potential,
    .term = "well potential",
    .term_formula = "1/2 k m |x - c|^2",
    .term_half = 1,
    .pairs = well_pairs,
    .blocks = well_blocks,
};
X
# 3. its extern in engine/forces.h
echo 'extern const swp_force_type swp_well;' >"$WORK/ext"
insert_before "$copy/src/engine/forces.h" '^/\* The descriptor of a kind' "$WORK/ext" ||
    fail "no 'The descriptor of a kind' comment in forces.h"

# Nothing silent: without its line in the switch, the build names the switch.
(cd "$copy" && make WERROR=1 build/src/engine/forces.o) >"$WORK/half.log" 2>&1 &&
    fail "the tree built without the kind's line in forces.c's switch"
grep -q "forces.c.*SW_FORCE_WELL" "$WORK/half.log" ||
    { tail -10 "$WORK/half.log"; fail "the failed build does not name forces.c and SW_FORCE_WELL"; }

# 4. its line in the switch of engine/forces.c
echo '    case SW_FORCE_WELL: return &swp_well;' >"$WORK/case"
insert_before "$copy/src/engine/forces.c" '^    case SW_FORCE_SPH:' "$WORK/case" || fail "no SW_FORCE_SPH case in forces.c"

walkthrough_build stepwise build/stepwise-plugin-host

# A program of the copy's library: one particle of mass 2 at (3, -1), at
# rest, in a well of k = 4 about (1, 1).
cat >"$WORK/well.c" <<'X'
#include <math.h>
#include <stdio.h>
#include "stepwise/stepwise.h"
int main(void)
{
    sw_particles p;
    char err[256];
    if (sw_particles_init(&p, 1, 2.0, err, sizeof err) != SW_OK)
        return puts(err), 1;
    sw_force fo = { .kind = SW_FORCE_WELL, .well = 4, .cx = 1, .cy = 1 };
    if (sw_particles_add_force(&p, &fo) != SW_OK || sw_particles_finish(&p, err, sizeof err) != SW_OK)
        return puts("add_force refused the well"), 1;
    p.y[0] = 3, p.y[1] = -1, p.y[2] = 0, p.y[3] = 0;
    double dydt[4], y[4] = { 3, -1, 0, 0 }, t = 0;
    p.ode.deriv(p.ode.ctx, 0, p.y, dydt);
    printf("accel %.17g %.17g\n", dydt[2], dydt[3]);
    printf("energy %.17g\n", sw_particles_energy(&p, p.y));
    sw_stepper *s = sw_stepper_new(sw_integrator_find("linear-implicit-euler"), &p.ode, err, sizeof err);
    if (!s || sw_stepper_step(s, &p.ode, &t, y, 0.1) != SW_OK)
        return puts(err), 1;
    printf("backward %.17g %.17g\n", y[0], y[1]);
    sw_stepper_delete(s);
    sw_particles_free(&p);
    return 0;
}
X
(cd "$copy" && cc -std=c11 -Iinclude -Isrc "$WORK/well.c" build/libstepwise-tool.a -lseccomp -lm -ldl -o "$WORK/well") \
    >"$WORK/cc.log" 2>&1 || { cat "$WORK/cc.log"; fail "the program of the copy's library does not build"; }
"$WORK/well" >"$WORK/out" || fail "the program failed: $(cat "$WORK/out")"
# a = -k (x - c) = -4 (2, -2); E = 1/2 k m |x - c|^2 = 1/2 4 2 8; backward
# Euler from rest: (x1 - c)(1 + h^2 k) = x0 - c, so x1 = c + (2, -2)/1.04,
# which one Newton step reaches on this linear force when the Jacobian is
# right. Tolerances: the force and the energy take a few roundings (1e-15
# of their size); the step a linear solve's (1e-12 is far above it, and
# far below what a wrong block changes: h^2 k = 0.04 of the step).
awk '
    function near(got, want, tol) { return (got - want) <= tol * (1 + (want < 0 ? -want : want)) && (want - got) <= tol * (1 + (want < 0 ? -want : want)) }
    $1 == "accel" { ok += near($2, -8, 1e-15) && near($3, 8, 1e-15) }
    $1 == "energy" { ok += near($2, 32, 1e-15) }
    $1 == "backward" { ok += near($2, 1 + 2 / 1.04, 1e-12) && near($3, 1 - 2 / 1.04, 1e-12) }
    END { exit ok != 3 }' "$WORK/out" || fail "the well's force, energy or backward Euler step is off: $(cat "$WORK/out")"
echo "force walk-through: 4 files; the switch named when its line is missing; force, energy, Jacobian right"
