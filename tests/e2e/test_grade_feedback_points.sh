#!/bin/sh
# --feedback tells each student their points check by check, on the parts
# shown now: a PASS report alone does not say that the order was missed or
# the stability limit not measured. A hidden part gives nothing away, its
# checks and points included; a reason every check shares is said once.
# A trace that could be matched to no part (unreadable) takes no part's
# points in its lines (QA: it listed the other part's checks as 0 under
# itself, beside the file that scored them).
. "$(dirname "$0")/lib.sh"
needs_jail
cat > hw.txt <<'A'
# stepwise assignment 1
# kind: plugin
# integrator: rk4
# steps: 50
# points x* y*: 2
# part line
# scene: chain
# param n: 3
# dt: 0.01
# points order: 1
# part swirl
# scene: gyre
# param n: 2
# dt: 0.05
# visibility: hidden
A
mkdir class
sed "s/@NAME@/honest/" "$ROOT/tests/hostile/honest-rk4.c" > class/honest.c
cp "$ROOT/examples/euler_plugin.c" class/euler.c
printf '#include <stepwise/integrator.h>\nint broken = ;\n' > class/broken.c
"$SW" grade --assignment hw.txt --feedback fb class > out 2>&1
[ $? -eq 1 ] || fail "grade: $(cat out)"
grep -qx "points: 3 of 3 on the parts shown now" fb/honest.txt || fail "honest: $(cat fb/honest.txt)"
grep -qx "  line: order: 1 of 1" fb/honest.txt || fail "honest: no order line: $(cat fb/honest.txt)"
grep -qx "points: 0 of 3 on the parts shown now" fb/euler.txt || fail "euler: $(cat fb/euler.txt)"
grep -q "^  line: values: x\* y\*: 0 of 2: .*did you implement euler" fb/euler.txt ||
    fail "euler: the values' line does not say why: $(cat fb/euler.txt)"
grep -q "^  line: order: 0 of 1: measured order [01]\.[0-9]*; the method.s is 4" fb/euler.txt || fail "euler: the order's line: $(cat fb/euler.txt)"
grep -q "swirl:" fb/*.txt && fail "a hidden part's checks reached the feedback: $(grep swirl: fb/*.txt)"
# the student's sheet says what the parts not on it are worth (student
# pass: a PASS on the sheet's parts read as the whole grade)
printf 'Name,ID,Email\nAda Lovelace,1,ada@uni.edu\n' > one.csv
"$SW" handout --assignment hw.txt --roster one.csv -o sheets > /dev/null 2>&1 || fail "handout"
grep -q "^# note: .*; 1 more part is graded, not shown here, for 2 of the 5 points$" sheets/Ada_Lovelace.txt ||
    fail "the sheet's note: $(head -3 sheets/Ada_Lovelace.txt)"
grep -q "^  line: order: 0 of 1: the same$" fb/broken.txt || fail "broken: the reason is not said once: $(cat fb/broken.txt)"

# two trace parts; one file scores the first, the other is unreadable
cat > tr.txt <<'A'
# stepwise assignment 1
# kind: trace
# integrator: rk4
# steps: 20
# points x* y*: 3
# part swing
# scene: spring
# dt: 0.01
# part fall
# scene: projectile
# dt: 0.05
A
printf 'Name,ID,Email\nAda Lovelace,1,ada@uni.edu\nBob Brown,2,bob@uni.edu\n' > roster.csv
mkdir -p "traces/Ada Lovelace"
"$SW" record spring -i rk4 --dt 0.01 --steps 20 -o "traces/Ada Lovelace/swing.trace" > /dev/null 2>&1 ||
    fail "record"
printf 'not a trace\001\002\n' > "traces/Ada Lovelace/fall.trace"
"$SW" grade --assignment tr.txt --roster roster.csv --feedback fbt --csv files.csv traces > out 2>&1
# a missing student's row is of no part (student pass: it named the first)
tr -d '\r' < files.csv | grep -q '^Bob Brown,,missing,.*,$' || fail "the missing row's part: $(grep Bob files.csv)"
f=fbt/Ada_Lovelace.txt
grep -A2 "== fall.trace: error ==" "$f" | grep -q "^points: none from this file: it could not be matched to a part" ||
    fail "an unreadable trace's points: $(cat "$f")"
grep -A3 "== fall.trace" "$f" | grep -q "swing:" && fail "the other part's checks under the unreadable file: $(cat "$f")"
grep -qx "points: 3 of 3" "$f" || fail "swing.trace's points: $(cat "$f")"
echo "ok: feedback gives the points on the parts shown"
