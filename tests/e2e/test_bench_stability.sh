#!/bin/sh
# `stepwise stability`: on the undamped spring with k = m = 1 (w = 1), the
# printed limits, theory and measured, are verlet 2 and rk4 2 sqrt 2 within
# 1%, euler 'none' and implicit-euler 'unbounded'; rk45 is skipped with a
# reason. Scenes where growth cannot be measured get the theory alone.
. "$(dirname "$0")/lib.sh"
out=$("$SW" stability spring --set k=1 --set m=1 --set c=0 \
      --integrators euler,verlet,rk4,implicit-euler,rk45) || fail "stability exited $?"
echo "$out" | grep -q 'stiffest mode at the start: |L| = 1 rad/s' || fail "no |L| line: $out"
echo "$out" | awk '$1 == "verlet" { v = $2; vm = $4 } $1 == "rk4" { r = $2; rm = $4 }
    END { if (!(v > 1.98 && v < 2.02 && r > 2.8 && r < 2.857 && vm > 1.98 && vm < 2.02 &&
                rm > 2.8 && rm < 2.857)) { print v, r, vm, rm; exit 1 } }' \
    || fail "limits off: $out"
echo "$out" | grep -Eq '^  euler +none +< 0.01 +none' || fail "euler not none: $out"
echo "$out" | grep -Eq '^  implicit-euler +unbounded +[^ ]+ +[^ ]+ +unbounded' || fail "implicit-euler not unbounded: $out"
echo "$out" | grep -Eq '^  rk45 +skipped: rk45 chooses its own steps' || fail "rk45 not skipped: $out"
# the table reads at 80 columns (issue 37: stiff-spring's rows were 94 and
# its notes 217): what a measurement saw goes under its row, wrapped
out=$("$SW" stability stiff-spring --integrators symplectic-euler,implicit-midpoint) || fail "stiff-spring exited $?"
wide=$(echo "$out" | awk '{ n = length($0) } n > 80 { print n ": " $0 }')
[ -z "$wide" ] || fail "stability stiff-spring prints lines past 80 columns: $wide"
echo "$out" | grep -Eq '^ +\(energy x1000 at dt = 0\.0199' || fail "symplectic-euler's note is not under its row: $out"
# rk4 on the default (damped) spring fails below its linear limit: what it
# saw is said once, in the reason (it was printed twice)
out=$("$SW" stability spring --integrators rk4) || fail "stability spring rk4 exited $?"
[ "$(echo "$out" | grep -c 'energy raised at dt')" -eq 1 ] || fail "rk4's failing step not said once: $out"
echo "$out" | grep -q 'differ: rk4 fails below the linear limit' || fail "rk4's reason is missing: $out"
out=$("$SW" stability bounce --integrators euler) || fail "stability bounce exited $?"
echo "$out" | grep -q 'theory only: bounce changes its state at step boundaries' || fail "bounce: $out"
echo "stability: ok"
