#!/bin/sh
# `stepwise bench`: the work-precision report on spring with three methods
# (the quick sweep): the table, the fitted orders near theory, the cheapest
# method per error level, both ASCII plots; the CSV it writes (one row per
# point, every error read back as a number or nan) and the SVG (well formed
# enough for xmllint when it is installed, one series group per method per
# panel). Timing is never checked: it varies from run to run.
. "$(dirname "$0")/lib.sh"

"$SW" bench spring --set k=1 --set m=1 --set c=0 --integrators euler,midpoint,rk4 \
    --csv "$dir/points.csv" --svg "$dir/plot.svg" >"$dir/out" 2>"$dir/err" \
    || fail "bench exited $?: $(cat "$dir/err")"
[ -s "$dir/err" ] && fail "unexpected stderr: $(cat "$dir/err")"
out="$dir/out"
grep -q '^== spring: largest error at 16 times to t = 10, against the exact solution' "$out" || fail "no scene header"
for m in euler midpoint rk4; do
    grep -q "^   $m " "$out" || fail "no rows for $m"
done
grep -q 'symplectic-euler' "$out" && fail "a method outside --integrators was run"
# Observed orders within 0.3 of theory (1, 2, 4).
awk '/observed order/ { on = 1; next }
     on && $1 == "euler"    { e = $2 } on && $1 == "midpoint" { m = $2 } on && $1 == "rk4" { r = $2 }
     END { if (e < 0.7 || e > 1.3 || m < 1.7 || m > 2.3 || r < 3.7 || r > 4.3) { print e, m, r; exit 1 } }' \
    "$out" || fail "orders off: $(grep -A4 'observed order' "$out")"
grep -q 'cheapest measured run' "$out" || fail "no cheapest-method table"
grep -Eq '^   1e-0[2468] ' "$out" || fail "no error levels"
grep -q 'largest error against wall time' "$out" || fail "no plot against time"
grep -q 'largest error against derivative evaluations' "$out" || fail "no plot against evaluations"
grep -q '1=euler  3=midpoint  5=rk4' "$out" || fail "no plot legend"

# CSV: header, 16 columns on every row, errors numeric or nan, methods as asked.
csv="$dir/points.csv"
head -1 "$csv" | grep -q '^scene,method,dt,rtol,h,error,evals,solves,steps,seconds,repeats,blown,blow_time,in_fit,order,reference$' \
    || fail "bad CSV header: $(head -1 "$csv")"
awk -F, 'NR > 1 { rows++
    if (NF != 16) { print "fields", NF; exit 1 }
    if ($1 != "spring" || ($2 != "euler" && $2 != "midpoint" && $2 != "rk4")) { print "row", $0; exit 1 }
    if ($6 != "nan" && $6 !~ /^[0-9.e+-]+$/) { print "error", $6; exit 1 }
    if ($12 == 1 && $6 != "nan") { print "blown with an error", $0; exit 1 }
    seen[$2] = 1 }
    END { if (rows < 15 || length(seen) != 3) { print "rows", rows; exit 1 } }' "$csv" \
    || fail "bad CSV rows"

# SVG: an XML document with an svg root, 2 panels, 2 x and 2 y axes, and
# one series group per method per panel.
svg="$dir/plot.svg"
head -1 "$svg" | grep -q '^<?xml' || fail "SVG does not start with an XML declaration"
grep -q '^<svg xmlns="http://www.w3.org/2000/svg"' "$svg" || fail "no svg root"
tail -1 "$svg" | grep -q '^</svg>$' || fail "SVG not closed"
[ "$(grep -c 'class="panel"' "$svg")" -eq 2 ] || fail "panels"
[ "$(grep -c 'data-axis="x"' "$svg")" -eq 2 ] || fail "x axes"
[ "$(grep -c 'data-axis="y"' "$svg")" -eq 2 ] || fail "y axes"
for m in euler midpoint rk4; do
    [ "$(grep -c "class=\"series\" data-method=\"$m\"" "$svg")" -eq 2 ] || fail "series for $m"
done
if command -v xmllint >/dev/null 2>&1; then
    xmllint --noout "$svg" || fail "xmllint rejects the SVG"
fi
# Scenes measured side by side (--jobs): every number but the seconds is
# the same as one at a time, and the reports come in the order asked.
"$STEPWISE" bench spring chain orbit --quick --jobs 1 --csv "$dir/j1.csv" > "$dir/j1.txt" || fail "--jobs 1"
"$STEPWISE" bench spring chain orbit --quick --jobs 3 --csv "$dir/j3.csv" > "$dir/j3.txt" || fail "--jobs 3"
cut -d, -f1-9,11- "$dir/j1.csv" > "$dir/j1.cut"
cut -d, -f1-9,11- "$dir/j3.csv" > "$dir/j3.cut"
cmp -s "$dir/j1.cut" "$dir/j3.cut" || fail "--jobs 3 measured other numbers than --jobs 1: $(diff "$dir/j1.cut" "$dir/j3.cut" | head -3)"
[ "$(cut -d, -f1 "$dir/j3.csv" | uniq | tr '\n' ' ')" = "scene spring chain orbit " ] ||
    fail "--jobs 3: scenes out of order: $(cut -d, -f1 "$dir/j3.csv" | uniq | tr '\n' ' ')"
"$STEPWISE" bench spring --jobs 0 > /dev/null 2> "$dir/j0.err"
rc=$?
[ "$rc" -eq 2 ] || fail "--jobs 0 exited $rc, not 2"
grep -q -- "--jobs" "$dir/j0.err" || fail "--jobs 0: the message does not name --jobs: $(cat "$dir/j0.err")"
# yoshida4's order is 4 where forces read positions alone, 2 where drag or
# damping reads velocities: the report says so under its orders there (the
# damped default spring), and not on the undamped one.
"$STEPWISE" bench spring --quick --integrators yoshida4 > "$dir/y_damped.txt" || fail "bench yoshida4 damped"
"$STEPWISE" bench spring --set c=0 --quick --integrators yoshida4 > "$dir/y_undamped.txt" || fail "bench yoshida4"
grep -A2 '^   yoshida4 .*theory 4' "$dir/y_damped.txt" | grep -q 'and its order is 2' ||
    fail "damped spring: no note that yoshida4's order is 2: $(grep -A3 'observed order' "$dir/y_damped.txt")"
grep -q 'its order is 2' "$dir/y_undamped.txt" && fail "undamped spring: the velocity note printed"
echo "bench report: ok"
