#!/bin/sh
# Event location from the outside: --events takes locate or step (anything
# else: one line naming both, exit 2); a located run's trace says so in one
# header line (a step-mode trace has none), regenerates bit for bit and is
# checked in its own mode; two traces of different modes are not compared;
# bench names what breaks the order; the x key toggles the mode in play.
. "$(dirname "$0")/lib.sh"

for cmd in record play bench; do
    out=$("$STEPWISE" $cmd bounce --events foo 2>&1 >/dev/null); rc=$?
    [ $rc -eq 2 ] || fail "$cmd --events foo: exit $rc, expected 2"
    [ "$(printf '%s\n' "$out" | wc -l)" -eq 1 ] || fail "$cmd --events foo: not one line: $out"
    echo "$out" | grep -q "allowed: locate, step" || fail "$cmd --events foo: does not name what is allowed: $out"
done

"$STEPWISE" record bounce -i rk4 --until 2 -o step.csv 2>/dev/null || fail "record step mode"
"$STEPWISE" record bounce -i rk4 --until 2 --events step -o step2.csv 2>/dev/null || fail "record --events step"
"$STEPWISE" record bounce -i rk4 --until 2 --events locate -o loc.csv 2>/dev/null || fail "record --events locate"
"$STEPWISE" record bounce -i rk4 --until 2 --events locate -o loc2.csv 2>/dev/null || fail "record --events locate again"
grep -q '^# events' step.csv && fail "a step-mode trace has an events line"
cmp -s step.csv step2.csv || fail "--events step differs from the default"
grep -qx '# events: locate' loc.csv || fail "a located trace lacks '# events: locate'"
cmp -s loc.csv loc2.csv || fail "two located runs differ"
cmp -s loc.csv step.csv && fail "located and stepped traces are the same"

"$STEPWISE" check loc.csv >/dev/null || fail "a located trace does not pass check against its own regeneration"
out=$("$STEPWISE" check step.csv --against loc.csv 2>&1); rc=$?
[ $rc -eq 2 ] || fail "check --against across modes: exit $rc, expected 2"
echo "$out" | grep -q "recorded with events step and loc.csv with events locate" ||
    fail "check --against across modes does not say why: $out"
printf '# stepwise assignment 1\n# scene: bounce\n# integrator: rk4\n# dt: 0.01\n# until: 2\n# events: locate\n' >as.txt
out=$("$STEPWISE" check step.csv --assignment as.txt 2>&1); rc=$?
[ $rc -eq 1 ] || fail "a step-mode trace against a located assignment: exit $rc, expected 1"
echo "$out" | grep -q "events: yours step" || fail "the header difference does not name events: $out"
"$STEPWISE" check loc.csv --assignment as.txt >/dev/null || fail "a located trace fails its located assignment"

# bench: stepped over, the scene's sentence; located, the order.
out=$("$STEPWISE" bench spring --set stretch=1.5 --set c=0 --integrators rk4 --quick 2>&1)
echo "$out" | grep -q "the force jumps where the mass passes its anchor" || fail "bench does not say what breaks the order: $out"
out=$("$STEPWISE" bench spring --set stretch=1.5 --set c=0 --integrators rk4 --events locate --repeats 1 2>&1)
echo "$out" | grep -Eq "rk4 +(3\.[7-9]|4\.[0-3])" || fail "bench --events locate: rk4 not fourth order: $out"

# play: x toggles, the status line says so.
tmux_start
type_cmd "$STEPWISE play bounce"
wait_for 'bounce +verlet .*ev(ents)? step' || fail "the status line does not show the events mode"
keys x
wait_for 'events located' || fail "x did not locate events"
wait_for 'ev(ents)? loc' || fail "the status line does not show locate"
keys x
wait_for 'events stepped over' || fail "x did not go back to step"
keys q
wait_for 'PROMPT\$ *$' || fail "q did not quit"
echo ok
