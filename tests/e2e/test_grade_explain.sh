#!/bin/sh
# The explaining checker names the mistake (each run fails first, then the
# message must name what happened), and the format details: --tol and
# --ignore, JSON numbers in shortest round-trip form with infinity as a
# string, a relative error meaningful near zero, the student's name carried.
set -u
SW=${STEPWISE:?set STEPWISE to the stepwise binary}
if ! why=$("$SW" autograder --probe 2>&1); then # as lib.sh's needs_jail
    echo "skip: $(basename "$0" .sh): no jail for plugins can be built here: $why"; exit 77
fi
root=$(cd "$(dirname "$0")/../.." && pwd)
json="$root/tests/e2e/json.awk"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
field() { grep "^$1=" fields | head -1 | sed "s/^$1=//"; }
# why FILE KIND REGEX [check options]: check fails, --json names KIND, the words match
why() {
    f=$1 kind=$2 words=$3; shift 3
    "$SW" check "$f" "$@" > out 2>err; rc=$?
    [ "$rc" -eq 1 ] || fail "$f: exit $rc, want 1: $(cat out err)"
    grep -Eq "  why: .*$words" out || fail "$f: no 'why' saying '$words': $(cat out)"
    "$SW" check "$f" --json "$@" > out 2>err
    awk -f "$json" out > fields || fail "$f: JSON does not parse"
    [ "$(field explanation.kind)" = "$kind" ] || fail "$f: explanation.kind $(field explanation.kind), want $kind"
}

# The double gyre under RK4 with its stages at the wrong times (awk, from docs/scenes.md).
cat > gyre.awk <<'AWK'
function f(t, S, D,    i, s, a, b, px, py, g, dg) {
    s = 0.25 * sin(0.6283185307179586 * t); a = s; b = 1 - 2 * s
    for (i = 0; i < N; i++) {
        px = S[2 * i]; py = S[2 * i + 1]; g = a * px * px + b * px; dg = 2 * a * px + b
        D[2 * i] = -PI * 0.1 * sin(PI * g) * cos(PI * py)
        D[2 * i + 1] = PI * 0.1 * cos(PI * g) * sin(PI * py) * dg
    }
}
BEGIN {
    PI = 3.14159265358979323846; N = 6; h = 0.1
    cols = 4; rows = 2
    for (i = 0; i < N; i++) { Y[2 * i] = 2 * ((i % cols) + 0.5) / cols; Y[2 * i + 1] = (int(i / cols) + 0.5) / rows }
    print "# stepwise trace 1\n# scene: gyre\n# param n: 6\n# integrator: rk4\n# dt: 0.1\n# steps: 40"
    printf "step,t"; for (i = 0; i < N; i++) printf ",x%d,y%d", i, i; print ""
    t = 0
    for (n = 0; n <= 40; n++) {
        printf "%d,%.17g", n, t; for (i = 0; i < 2 * N; i++) printf ",%.17g", Y[i]; print ""
        c2 = mistake == "at-t" ? 0 : 0.5; c4 = mistake == "at-t" ? 0 : 1; k3 = mistake == "k3" ? 1 : 0.5
        if (mistake == "inplace") { # y itself moved through the stages
            f(t, Y, K1); for (i = 0; i < 2 * N; i++) Y[i] = Y[i] + 0.5 * h * K1[i]
            f(t + 0.5 * h, Y, K2); for (i = 0; i < 2 * N; i++) Y[i] = Y[i] + 0.5 * h * K2[i]
            f(t + 0.5 * h, Y, K3); for (i = 0; i < 2 * N; i++) Y[i] = Y[i] + h * K3[i]
            f(t + h, Y, K4)
        } else {
            f(t, Y, K1); for (i = 0; i < 2 * N; i++) T[i] = Y[i] + 0.5 * h * K1[i]
            f(t + c2 * h, T, K2); for (i = 0; i < 2 * N; i++) T[i] = Y[i] + k3 * h * K2[i]
            f(t + c2 * h, T, K3); for (i = 0; i < 2 * N; i++) T[i] = Y[i] + h * K3[i]
            f(t + c4 * h, T, K4)
        }
        w1 = mistake == "weights" ? 2 : 1; w2 = mistake == "weights" ? 1 : 2
        for (i = 0; i < 2 * N; i++) Y[i] = Y[i] + h / 6 * (w1 * K1[i] + w2 * K2[i] + w2 * K3[i] + w1 * K4[i])
        t += h
    }
}
AWK
awk -v mistake=none -f gyre.awk > right.trace
"$SW" check right.trace > out 2>&1 || fail "the correct gyre fails: $(cat out)"
awk -v mistake=at-t -f gyre.awk > at-t.trace
why at-t.trace stage-time 'rk4 with every stage evaluated at the step.s start t.*changes with time'
awk -v mistake=k3 -f gyre.awk > k3.trace
why k3.trace k3-full-step 'rk4 with k3 taken at y \+ h\*k2 instead of y \+ h/2\*k2'
awk -v mistake=weights -f gyre.awk > weights.trace
why weights.trace rk4-weights 'rk4 with its weights swapped: h/6\*\(2\*k1 \+ k2 \+ k3 \+ 2\*k4\)'
awk -v mistake=inplace -f gyre.awk > inplace.trace
why inplace.trace rk4-in-place 'rk4 that moves y itself through its stages'

# Rows and the time column.
"$SW" record spring --steps 60 -o a.trace 2>/dev/null
sed '/^0,/d' a.trace > no-step0.trace
why no-step0.trace missing-row 'no row for step 0 \(the initial state\)'
sed '/^23,/d' a.trace > gap.trace
why gap.trace missing-row 'no row for step 23 \(line 40 holds step 24\)'
awk -F, '/^23,/ { print } { print }' a.trace > twice.trace
why twice.trace duplicate-row 'step 23 appears twice \(lines 40 and 41\)'
awk -F, -v OFS=, '/^[0-9]/ { $2 = sprintf("%.17g", ($1 + 1) * 0.02) } { print }' a.trace > ahead.trace
why ahead.trace time-shift 't column is one step ahead'

# --tol and --ignore: the energy 1e-7 off fails by default, passes with its own tolerance or ignored.
awk -F, -v OFS=, '/^[0-9]/ { $7 = sprintf("%.17g", $7 * (1 + 1e-7)) } { print }' a.trace > e.trace
"$SW" check e.trace > out 2>&1 && fail "a 1e-7 energy error passes the default tolerance"
grep -q 'column energy' out || fail "the energy column is not named: $(cat out)"
"$SW" check e.trace --tol energy=1e-6 > out 2>&1 || fail "--tol energy=1e-6 does not accept it: $(cat out)"
"$SW" check e.trace --ignore energy > out 2>&1 || fail "--ignore energy does not accept it: $(cat out)"
grep -q ' 366 values' out || fail "--ignore energy still compares it: $(cat out)"

# JSON: shortest numbers, infinity as a string, relative error near zero, the student.
sed 's/^# version:/# student: Ada\n# version:/' a.trace > s.trace
"$SW" check s.trace --json > out 2>err || fail "s.trace: $(cat err)"
grep -q '"rtol": 1e-09,' out && grep -q '"dt": 0.02,' out || fail "numbers not shortest: $(grep -E 'rtol|"dt"' out)"
awk -f "$json" out > fields || fail "not JSON"
[ "$(field student)" = "Ada" ] || fail "student: $(field student)"
# y0 and vy0 are 0 throughout and x0 crosses rest: max_rel_error stays a relative error, not inf
"$SW" record chain --steps 100 -o c.trace 2>/dev/null
"$SW" check c.trace --json > out
awk -f "$json" out > fields
awk -v r="$(field max_rel_error)" 'BEGIN { exit !(r >= 0 && r < 1e-12) }' || fail "max_rel_error $(field max_rel_error) on an exact pass"
awk -F, -v OFS=, '/^5,/ { $3 = "inf" } { print }' a.trace > inf.trace
"$SW" check inf.trace --json > out
awk -f "$json" out > fields || fail "an infinite error breaks the JSON"
[ "$(field first_failure.got)" = "inf" ] && [ "$(field first_failure.tolerance_ratio)" = "inf" ] \
    || fail "infinity: got $(field first_failure.got), ratio $(field first_failure.tolerance_ratio)"
grep -q 'null' out && grep -q '"first_failure": null' out && fail "null for a number"
grep -Eq '"(got|tolerance_ratio|abs_error|rel_error)": null' out && fail "null for infinity: $(cat out)"

# The scene, not the method: a wrong initial bead, an energy with the wrong sign.
"$SW" record chain --set n=6 --set c=1 --steps 40 -o chain.trace 2>/dev/null
awk -F, -v OFS=, '/^0,/ { $12 = "0.5" } { print }' chain.trace > bead.trace
why bead.trace initial-state "particle 2 starts with y2 = 0.5 in yours, 0 in the assignment's; docs/scenes.md, 'chain'"
awk -F, -v OFS=, '/^0,/ { $12 = "0.5"; $16 = "0" } { print }' chain.trace > pluck.trace
why pluck.trace initial-state "particle 2 starts with y2 = 0.5 in yours, 0 in the assignment's, and particle 3 with y3 = 0 in yours: particle 2's and particle 3's values are exchanged \(an index off by one\?\)"
"$SW" record spring --set g=9.81 --set k=25 --steps 50 -o sp.trace 2>/dev/null
awk -F, -v OFS=, '/^[0-9]/ { r = sqrt($3 * $3 + $4 * $4) - 1
    $7 = sprintf("%.17g", 0.5 * ($5 * $5 + $6 * $6) - 0.5 * 25 * r * r + 9.81 * $4) } { print }' sp.trace > sign.trace
why sign.trace energy-formula 'energy column is kinetic energy plus gravity potential minus spring potential.*the spring potential has the wrong sign'
# Positions printed in cm: a unit, not a wrong initial state ("x0 = 150 in yours, 1.5").
awk -F, -v OFS=, '/^[0-9]/ { $3 = sprintf("%.17g", 100 * $3); $4 = sprintf("%.17g", 100 * $4) } { print }' sp.trace > cm.trace
why cm.trace units 'x0 and y0 are 100 times the reference at every step: positions in cm instead of m\?'

# Plugins get the same "why" as traces: on a damped chain set as verlet.
cat > damped.txt <<'A'
# stepwise assignment 1
# scene: chain
# param n: 5
# param c: 1.5
# param g: 9.81
# integrator: verlet
# dt: 0.01
# steps: 100
A
# vplugin FILE NAME A1_VELOCITY: Verlet recomputing a0 every step, a1 at the given velocity
vplugin() {
    cat > "$1" <<C
#include <stepwise/integrator.h>
static int step(sw_ode *ode, double t, double *y, double h, double *work)
{
    int n = ode->dim, half = n / 2;
    double *a = work, *yt = work + n;
    sw_ode_eval(ode, t, y, a);
    for (int i = 0; i < half; i++) {
        double vh = y[half + i] + 0.5 * h * a[half + i];
        yt[half + i] = $3;
        y[i] += h * vh;
        yt[i] = y[i];
        y[half + i] = vh;
    }
    sw_ode_eval(ode, t + h, yt, a);
    for (int i = 0; i < half; i++)
        y[half + i] += 0.5 * h * a[half + i];
    return 0;
}
static const sw_plugin info = { .abi = SW_PLUGIN_ABI, .name = "$2", .label = "Verlet ($2)",
    .order = 2, .evals = 2, .work_vectors = 2, .step = step };
const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
C
}
vplugin textbook.c textbook vh
vplugin recompute.c recompute 'y[half + i] + h * a[half + i]'
pwhy() { # FILE KIND REGEX: the plugin fails on damped.txt, the why line and JSON kind
    "$SW" check --plugin "$1" --assignment damped.txt > out 2>err; rc=$?
    [ "$rc" -eq 1 ] || fail "$1: exit $rc, want 1: $(cat out err)"
    grep -Eq "  why: .*$3" out || fail "$1: no 'why' saying '$3': $(cat out)"
    "$SW" check --plugin "$1" --assignment damped.txt --json > out 2>err
    awk -f "$json" out > fields || fail "$1: JSON does not parse"
    [ "$(field explanation.kind)" = "$2" ] || fail "$1: explanation.kind $(field explanation.kind), want $2"
}
pwhy textbook.c verlet-half-step 'recomputes a0 = a\(x, v\) every step and takes a1 at the half-step velocity'
pwhy recompute.c verlet-recomputed 'recomputes a0 = a\(x, v\) at the start of every step'
pwhy "$root/examples/euler_plugin.c" method 'your numbers match euler exactly: did you implement euler'
# Without velocity-dependent forces recomputing is verlet: a pass, no why.
sed -e 's/chain/orbit/' -e '/param/d' damped.txt > orbit.txt
"$SW" check --plugin recompute.c --assignment orbit.txt > out 2>&1 || fail "recompute.c fails the orbit: $(cat out)"
grep -q 'why:' out && fail "a passing plugin gets a why: $(cat out)"
echo "ok"
