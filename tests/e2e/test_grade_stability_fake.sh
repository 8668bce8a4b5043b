#!/bin/sh
# The stability limit is measured on a spring of its own, a system a
# plugin can tell apart from its graded run, so it counts only where the
# graded values match (red team 3, F1). tests/data/cheat/stab.c runs the
# midpoint rule (verlet's order, 2) on the graded chain and velocity
# Verlet on the spring: it failed its values, kept the order point, and
# took the stability point with verlet's measured limit. Now it gets no
# stability point, with a note that says why; an honest Verlet keeps all
# of its points.
. "$(dirname "$0")/lib.sh"
needs_jail
mkdir class
cp "$ROOT/tests/data/cheat/stab.c" "$ROOT/tests/data/cheat/honest_verlet.c" class/
cat > hw.txt <<'A'
# stepwise assignment 1
# kind: plugin
# scene: chain
# integrator: verlet
# dt: 0.01
# steps: 200
# points x* y*: 2
# points order: 1
# points stability: 1
A
"$SW" grade --assignment hw.txt --csv g.csv --feedback fb class > g.out 2>&1
[ $? -le 1 ] || fail "grade: $(cat g.out)"
score() { grep "^$1,class/$1.c," g.csv | awk -F, '{ print $(NF-2) "/" $(NF-1) }'; }
[ "$(score honest_verlet)" = 4/4 ] || fail "the honest Verlet lost points: $(cat fb/honest_verlet.txt)"
grep -q "stability: 0 of 1: stability not measured: it is measured only where your values match the reference's" \
    fb/stab.txt || fail "the cheater's stability: $(cat fb/stab.txt)"
grep -q "order: 1 of 1" fb/stab.txt || fail "the cheater's order (midpoint's 2) is not believed: $(cat fb/stab.txt)"
[ "$(score stab)" = 1/4 ] || fail "the cheater scored $(score stab): $(cat fb/stab.txt)"
exit 0
