#!/bin/sh
# Graded closeness (issue 36): "# points x* y*: 3 within 1e-9, 2 within
# 1e-6, 1 within 1e-3" pays by how close a trace's positions are, where
# the verdict alone is all or nothing at 1e-9. Traces made from a correct
# one by scaling every position by (1 + d) — d = 0, 2e-8, 5e-5, 0.1 — score
# 3, 2, 1 and 0 (each d is well inside its tier: |got - expected| / (1 +
# |expected|) <= d), and the feedback names the tier reached and how far
# the next one was missed.
. "$(dirname "$0")/lib.sh"
json="$ROOT/tests/e2e/json.awk"
cat > hw.txt <<'A'
# stepwise assignment 1
# kind: trace
# scene: chain
# param n: 4
# integrator: rk4
# dt: 0.005
# steps: 400
# points x* y*: 3 within 1e-9, 2 within 1e-6, 1 within 1e-3
# points vx* vy*: 1
A
"$SW" record chain --set n=4 -i rk4 --dt 0.005 --steps 400 -o exact.trace >/dev/null 2>&1 || fail "record"
# scale the x<i> and y<i> columns by (1 + d), keeping 17 digits
scale() { # D OUT
    awk -F, -v d="$1" 'BEGIN { OFS = "," }
        /^#/ { print; next }
        /^step/ { for (i = 1; i <= NF; i++) pos[i] = ($i ~ /^[xy][0-9]+$/); print; next }
        { for (i = 1; i <= NF; i++) if (pos[i]) $i = sprintf("%.17g", $i * (1 + d)); print }' exact.trace > "$2"
}
scale 2e-8 close.trace
scale 5e-5 near.trace
scale 0.1 far.trace
for f in exact close near far; do
    "$SW" grade --assignment hw.txt --gradescope "$f.json" "$f.trace" > "$f.out" 2>&1
    awk -f "$json" "$f.json" > "$f.flat" || fail "$f: results.json does not parse"
done
got() { grep '^tests\[0\]\.score=' "$1.flat" | cut -d= -f2; }
[ "$(got exact)" = 3 ] || fail "exact: $(got exact) points, want 3: $(grep 'tests\[0\]' exact.flat)"
[ "$(got close)" = 2 ] || fail "close: $(got close) points, want 2: $(grep 'tests\[0\]' close.flat)"
[ "$(got near)" = 1 ] || fail "near: $(got near) points, want 1: $(grep 'tests\[0\]' near.flat)"
[ "$(got far)" = 0 ] || fail "far: $(got far) points, want 0: $(grep 'tests\[0\]' far.flat)"
# the line docs/trace-format.md shows
grep -q "within 1e-06 of the reference (the largest difference 1.61e-08, as |got - expected| / (1 + |expected|)): 2 of 3 points; 'within 1e-09' (3 points) missed by a factor of 16.1" close.flat ||
    fail "close: the feedback does not name the tier and the miss: $(grep 'tests\[0\]\.output' close.flat)"
grep -q "beyond every tier, the widest 'within 0.001'" far.flat ||
    fail "far: $(grep 'tests\[0\]\.output' far.flat)"
# the velocities were not touched: their point is kept everywhere
for f in exact close near far; do
    grep -q '^tests\[1\]\.score=1$' "$f.flat" || fail "$f: the velocities' point: $(grep 'tests\[1\]' "$f.flat")"
done
echo ok
