#!/bin/sh
# A plugin cannot earn the order point by telling the measuring runs from
# the run it is graded on (docs/grading.md, "What a measured figure stands
# on"). The order was once measured on a one-particle spring of its own,
# at dts of 0.16/2^k: a plugin that ran RK4 there and Euler on the graded
# chain failed its values and kept the order point. The cheaters of
# tests/data/cheat/ tell the runs apart by the particle count (dim.c), the
# initial state (start.c), the graded dt (dt.c), the run count (count.c),
# the step count (steps.c) and the time (late.c: RK4 for the first 64
# steps); none earns the order point, each for the
# reason the feedback names; nor the stability point, measured on a
# spring of its own only for a plugin whose order on its graded run is the
# method's. An honest RK4 and an honest Euler keep every point they earned,
# also where the graded run cannot show an order (the projectile): there
# the spring's order counts only where the graded values match.
. "$(dirname "$0")/lib.sh"
needs_jail
cheat="$ROOT/tests/data/cheat"
mkdir class
for f in dim start dt count steps late honest_rk4 honest_euler; do
    # one self-contained .c each, as a student hands it in
    { grep -q '"common.h"' "$cheat/$f.c" && cat "$cheat/common.h"; grep -v '"common.h"' "$cheat/$f.c"; } > class/$f.c
done
for m in rk4 euler; do
    cat > hw-$m.txt <<A
# stepwise assignment 1
# scene: chain
# param n: 3
# integrator: $m
# dt: 0.01
# steps: 100
# points x* y*: 7
# points order: 1
# points stability: 1
A
done
"$SW" grade --assignment hw-rk4.txt --csv rk4.csv --feedback fb class > rk4.out 2>&1
[ $? -le 1 ] || fail "grade exited $?: $(cat rk4.out)"
score() { grep "^$1,class/$1.c," "$2" | awk -F, '{ print $(NF-2) "/" $(NF-1) }'; }
[ "$(score honest_rk4 rk4.csv)" = 9/9 ] || fail "the honest RK4 lost points: $(cat fb/honest_rk4.txt)"
for c in dim start dt count steps late honest_euler; do
    [ "$(score $c rk4.csv)" = 0/9 ] || fail "$c scored $(score $c rk4.csv): $(grep -i order fb/$c.txt)"
    grep -q "order: 0 of 1" fb/$c.txt || fail "$c: no order line: $(cat fb/$c.txt)"
    grep -q "stability: 0 of 1" fb/$c.txt || fail "$c: no stability line: $(cat fb/$c.txt)"
done
# each for its own reason
grep -q "order: 0 of 1: measured order 0\.9" fb/dim.txt || fail "dim: $(grep 'order:' fb/dim.txt)"
# the stability limit is measured on a spring of its own (dim 4, which the
# dim cheater runs RK4 on): only for a plugin whose order on its graded
# run is the method's
grep -q "stability: 0 of 1: stability not measured: your order on the run checked (0\.9[0-9]*) is not rk4's (4)" \
    fb/dim.txt || fail "dim's stability: $(grep 'stability:' fb/dim.txt)"
grep -q "order: 0 of 1: measured order 0\.9" fb/start.txt || fail "start: $(grep 'order:' fb/start.txt)"
grep -q "is off the line of the finer steps" fb/dt.txt || fail "dt: $(grep 'order:' fb/dt.txt)"
grep -q "did not repeat its graded run" fb/count.txt || fail "count: $(grep 'order:' fb/count.txt)"
grep -q "order: 0 of 1: measured order" fb/steps.txt || fail "steps: $(grep 'order:' fb/steps.txt)"
# RK4 for the first 64 steps (t < 0.64), Euler after: what a sweep over
# part of the run reads counts only with matching values
grep -q "order: 0 of 1: order not measured: .*counts only where your values match the reference's" fb/late.txt \
    || fail "late: $(grep 'order:' fb/late.txt)"
# an honest Euler on an Euler homework keeps both
"$SW" grade --assignment hw-euler.txt --csv euler.csv class/honest_euler.c > euler.out 2>&1 \
    || fail "honest Euler on euler: $(cat euler.out)"
[ "$(score honest_euler euler.csv)" = 9/9 ] || fail "the honest Euler lost points: $(cat euler.out)"
# check and try measure as grade does: the dt cheater has no order there either
"$SW" check --plugin class/dt.c --reference rk4 --scene chain > check.out 2>&1
grep -q "is off the line of the finer steps" check.out || fail "check: $(cat check.out)"
"$SW" try class/dt.c --reference rk4 --no-play > try.out 2>&1
grep -q "order      claimed 4, not measured: no order: the error at the graded dt" try.out || fail "try: $(cat try.out)"
"$SW" try class/honest_rk4.c --no-play > try.out 2>&1 || fail "try honest: $(cat try.out)"
grep -q "order      claimed 4, measured \(3\.9\|4\.0\)" try.out || fail "try honest: $(cat try.out)"
# Where the graded run cannot show an order (RK4 on the projectile, a
# quadratic it integrates to round-off), the order is the spring's, and
# counts only where the graded values match: the honest RK4 keeps its
# points, and every cheater whose values fail earns none.
cat > hw-proj.txt <<A
# stepwise assignment 1
# scene: projectile
# integrator: rk4
# dt: 0.01
# steps: 100
# points x* y*: 7
# points order: 1
# points stability: 1
A
"$SW" grade --assignment hw-proj.txt --csv proj.csv --feedback fbp class > proj.out 2>&1
[ $? -le 1 ] || fail "grade (projectile) exited $?: $(cat proj.out)"
[ "$(score honest_rk4 proj.csv)" = 9/9 ] || fail "the honest RK4 lost points on the projectile: $(cat fbp/honest_rk4.txt)"
grep -q "order: 1 of 1" fbp/honest_rk4.txt || fail "projectile, honest: $(cat fbp/honest_rk4.txt)"
# (the dim cheater runs RK4 on every one-particle system: on the
# projectile, its graded run, it is RK4, and scores as one)
[ "$(score dim proj.csv)" = 9/9 ] || fail "dim, RK4 on the projectile, scored $(score dim proj.csv)"
for c in start dt count steps honest_euler; do
    [ "$(score $c proj.csv)" = 0/9 ] || fail "$c scored $(score $c proj.csv) on the projectile: $(grep -i order fbp/$c.txt)"
done
grep -q "the graded run cannot show an order (.*), and the spring's is believed only where the graded values match" \
    fbp/dt.txt || fail "projectile, dt: $(grep "order:" fbp/dt.txt)"
# Where even the assignment's run cannot tell its method from a lower
# order (the projectile without drag: the midpoint rule is exact under
# gravity alone), matching values prove no order either: nobody gets the
# order point, and every row says why, so the teacher can change the run.
# mid.c runs the midpoint rule there and RK4 on the spring.
mkdir classm
for f in mid honest_rk4; do
    { cat "$cheat/common.h"; grep -v '"common.h"' "$cheat/$f.c"; } > classm/$f.c
done
sed 's/^# scene: projectile$/# scene: projectile\n# param drag: 0/' hw-proj.txt > hw-proj0.txt
"$SW" grade --assignment hw-proj0.txt --csv proj0.csv --feedback fbm classm > proj0.out 2>&1
[ $? -le 1 ] || fail "grade (projectile, no drag) exited $?: $(cat proj0.out)"
for c in mid honest_rk4; do
    got=$(grep "^$c,classm/$c.c," proj0.csv | awk -F, '{ print $(NF-2) "/" $(NF-1) }')
    [ "$got" = 7/9 ] || fail "$c scored $got without drag: $(grep -i order fbm/$c.txt)"
    grep -q "order: 0 of 1: order not measured: on this run midpoint (order 2) ends within the tolerance of rk4 too" \
        fbm/$c.txt || fail "$c, no drag: $(grep 'order:' fbm/$c.txt)"
done
# `check` against the same homework says so too: a PASS with the points
# the grader would take off (QA: a PASS and exit 0 hid a lost point)
"$SW" check --plugin classm/honest_rk4.c --assignment hw-proj0.txt > check0.out 2>&1
grep -q "^PASS" check0.out && grep -q "^  points: 7 of 9, as the grader would give them:" check0.out &&
    grep -q "^    order: 0 of 1: order not measured: on this run midpoint (order 2) ends within the tolerance" check0.out ||
    fail "check does not show the lost order point: $(cat check0.out)"
echo "ok: no order point for a plugin that tells the measuring runs apart"
