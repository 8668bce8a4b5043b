#!/bin/sh
# docs/architecture.md's walk-through "Adding an integrator", done as the
# docs say in a scratch copy of the tree: Ralston's RK2 (k2 at 2h/3, weights
# 1/4 and 3/4), drawn in the stage view, so its step in engine/explicit.c,
# its prototype in engine/stepper.h, its row in builtins[] in
# engine/integrators.c, its script in engine/lecture.c and its extern in
# engine/lecture.h, and nothing else. The copy must then build with
# warnings as errors, and the new method show up with no further edit:
# in `list integrators`, in the stage view (its own script, k1 to y1, at
# 80x24), in the explainer (a trace made with it but headed midpoint is
# named as ralston's), in the stage view's unit check of every row, and
# the method-name test must still pass. A minute or two of building:
# full tier only (make test-full).
. "$(dirname "$0")/lib.sh"
. "$ROOT/tests/e2e/walkthrough.sh"
walkthrough_full integrator
walkthrough_copy

# 1. its step function in the family's file
cat >>"$copy/src/engine/explicit.c" <<'EOF'

/* Ralston's RK2: k1 = f(t, y), k2 = f(t + 2h/3, y + 2h/3 k1),
 * y1 = y + h (k1/4 + 3 k2/4). */
int sw_step_ralston(sw_stepper *s, sw_ode *ode, double *t, double *y, double h)
{
    int n = ode->dim;
    double *k1 = SW_WORK(s, 0), *k2 = SW_WORK(s, 1), *m = SW_WORK(s, 2);
    sw_ode_eval(ode, *t, y, k1);
    sw_axpy(n, m, y, 2.0 / 3.0 * h, k1);
    sw_ode_eval(ode, *t + 2.0 / 3.0 * h, m, k2);
    for (int i = 0; i < n; i++)
        y[i] += h * (0.25 * k1[i] + 0.75 * k2[i]);
    *t += h;
    return 0;
}
EOF
# 2. its prototype in engine/stepper.h
echo 'sw_step_fn sw_step_ralston; /* explicit.c */' >"$WORK/proto"
insert_before "$copy/src/engine/stepper.h" '^#endif' "$WORK/proto" || fail "no #endif in stepper.h"
# 3. its row in builtins[] (before the table's closing line)
cat >"$WORK/row" <<'EOF'
    { .name = "ralston", .label = "Ralston's RK2", .order = 2, .evals = 2, .flags = SW_EXPLICIT,
      .stability = 0.0, .work_vectors = 3, .step = sw_step_ralston,
      .summary = "y1 = y0 + h/4 (f(y0) + 3 f(y0 + 2h/3 f(y0)))", .lecture = &sw_lecture_ralston },
EOF
insert_in_table "$copy/src/engine/integrators.c" '^static const sw_integrator builtins\[\] = \{' "$WORK/row" ||
    fail "no builtins[] table closed by '};' in integrators.c"
# 4. its script in engine/lecture.c, 5. its extern in engine/lecture.h
cat >>"$copy/src/engine/lecture.c" <<'EOF'

const sw_stage_script sw_lecture_ralston = {
    .lines = { "k1 = f(t, y)", "k2 = f(t + 2h/3, y + 2h/3*k1)", "y = y + h/4*(k1 + 3*k2)", "t = t + h" },
    .views = { { .line = 0, .stage = 0, .shape = SW_STAGE_SLOPE, .label = "k1",
                 .caption = "k1: the slope at the start" },
               { .line = 1, .stage = 1, .shape = SW_STAGE_SLOPE, .label = "k2",
                 .caption = "k2: the slope two thirds of a step along k1" },
               { .line = 2, .stage = 0, .shape = SW_STAGE_SUM, .label = "y1",
                 .caption = "y1: the step on k1 and k2 weighted 1 and 3 over 4" } },
    .nviews = 3,
};
EOF
echo 'extern const sw_stage_script sw_lecture_ralston;' >"$WORK/ext"
insert_before "$copy/src/engine/lecture.h" '^#endif' "$WORK/ext" || fail "no #endif in lecture.h"

# It builds, warnings as errors (the program and the unit tests).
walkthrough_build stepwise build/check_stepwise
SWC=$copy/stepwise

# list
"$SWC" list integrators | grep -Eq '^ralston +order 2 +evals/step 2 +Ralston' ||
    fail "list integrators does not show ralston: $("$SWC" list integrators | tail -3)"

# the stage view's unit check of every row, and the method names
(cd "$copy" && CK_RUN_SUITE=stages CK_FORK=yes ./build/check_stepwise) >"$WORK/unit.log" 2>&1 ||
    { cat "$WORK/unit.log"; fail "the stage view's check of the rows fails with ralston"; }
STEPWISE=$SWC sh "$copy/tests/e2e/test_method_names.sh" >"$WORK/names.log" 2>&1 ||
    { cat "$WORK/names.log"; fail "the method-name test fails with ralston"; }

# the explainer: a nonlinear scene (on a linear one every two-stage RK2 is
# the same method), the trace headed midpoint, its numbers ralston's
(cd "$WORK" && "$SWC" record orbit -i midpoint --steps 20 -o ref.trace &&
    "$SWC" record orbit -i ralston --steps 20 -o sub.trace) 2>/dev/null || fail "record failed"
sed 's/^# integrator: ralston$/# integrator: midpoint/' "$WORK/sub.trace" >"$WORK/headed.trace"
out=$(cd "$WORK" && "$SWC" check headed.trace --assignment ref.trace)
printf '%s\n' "$out" | grep -q "why: your header says midpoint, but your numbers match ralston exactly: did you implement ralston (Ralston's RK2) instead of midpoint?" ||
    fail "the explainer does not name ralston: $out"

# the stage view at 80x24: ralston's own script, k1 to y1
tmux_start 80 24
type_cmd "$SWC play vortex --set n=1 -i ralston --dt 1"
wait_for 'vortex +ralston +dt=1 ' || fail "play -i ralston did not start"
keys k
wait_for '\[1 of 3: k next, Esc closes\]' || fail "k did not open ralston's stage view: $(screen)"
screen | grep -q '> k1 = f(t, y)' || fail "k1's line is not lit"
keys k
wait_for 'k2: the slope two thirds of a step along k1' || fail "k2 not shown: $(screen)"
screen | grep -q '> k2 = f(t + 2h/3, y + 2h/3\*k1)' || fail "k2's line is not lit"
keys k
wait_for '\[3 of 3: k closes' || fail "y1 not shown: $(screen)"
screen | grep -q '> y = y + h/4\*(k1 + 3\*k2)' || fail "the sum's line is not lit"
keys q
echo ok
