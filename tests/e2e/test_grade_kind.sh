#!/bin/sh
# An assignment's kind (issue 36): "# kind: plugin" grades plugins only and
# "# kind: trace" traces only. The other kind of upload scores 0 with one
# line saying what the homework asks for, out of the same max as every
# row, and is never the file a Gradescope submission counts: a trace made
# with `stepwise record` beside a plugin that does not compile scores 0,
# not the trace's points. An empty upload is told the kind asked for only.
# "# submit: source" takes a plugin's .c only (a .so is not graded).
. "$(dirname "$0")/lib.sh"
needs_jail
json="$ROOT/tests/e2e/json.awk"
base='# stepwise assignment 1
# scene: chain
# param n: 4
# integrator: rk4
# dt: 0.005
# steps: 400
# points x* y*: 4
# points vx* vy*: 1'
{ echo "$base" | head -1; echo "# kind: plugin"; echo "$base" | tail -n +2; } > plugin-hw.txt
{ echo "$base" | head -1; echo "# kind: trace"; echo "$base" | tail -n +2; } > trace-hw.txt
{ echo "$base" | head -1; echo "# kind: spreadsheet"; echo "$base" | tail -n +2; } > bad-hw.txt
"$SW" record chain --set n=4 -i rk4 --dt 0.005 --steps 400 -o good.trace >/dev/null 2>&1 || fail "record"
sed "s/@NAME@/honest/" "$ROOT/tests/hostile/honest-rk4.c" > honest.c
printf '#include <stepwise/integrator.h>\nint broken = ;\n' > broken.c

# an unknown kind is refused with what is allowed
"$SW" grade --assignment bad-hw.txt good.trace > out 2>&1; rc=$?
[ $rc -eq 2 ] && grep -q "'kind' is trace or plugin" out || fail "bad kind: exit $rc: $(cat out)"

# grade: each kind where it belongs
mkdir class
cp good.trace honest.c class/
"$SW" grade --assignment plugin-hw.txt --csv p.csv class > out 2>&1
grep -q "good.trace,fail,,\"this homework asks for a plugin (.c, .so), not a trace: not graded\"" p.csv ||
    fail "plugin homework: the trace's row: $(cat p.csv)"
grep -q "honest.c,pass," p.csv || fail "plugin homework: the plugin's row: $(cat p.csv)"
maxes=$(awk -F, 'NR > 1 { print $(NF - 1) }' p.csv | sort -u | tr -d '\r')
[ "$maxes" = 5 ] || fail "plugin homework: not one max for every row: $maxes"
"$SW" grade --assignment trace-hw.txt --csv t.csv class > out 2>&1
grep -q "honest.c,fail,,\"this homework asks for a trace (.trace, .csv), not a plugin: not graded\"" t.csv ||
    fail "trace homework: the plugin's row: $(cat t.csv)"
grep -q "good.trace,pass," t.csv || fail "trace homework: the trace's row: $(cat t.csv)"

# check refuses the other kind, saying what to give
"$SW" check good.trace --assignment plugin-hw.txt > out 2>&1; rc=$?
[ $rc -eq 2 ] && grep -q "asks for a plugin (.c, .so), not a trace: give --plugin FILE" out ||
    fail "check, trace on a plugin homework: exit $rc: $(cat out)"

# Gradescope: a recorded trace beside a plugin that does not compile is 0
mkdir sub
cp good.trace broken.c sub/
"$SW" grade --assignment plugin-hw.txt --gradescope r.json sub > out 2>&1
awk -f "$json" r.json > flat || fail "results.json does not parse"
grep -qx "score=0" flat || fail "the trace was counted on a plugin homework: $(grep '^score=\|^output=' flat)"
grep -q "^output=.*0 of 5 points for broken.c" flat || fail "the counted file is not the plugin: $(grep '^output=' flat)"
# an empty upload is told the kind asked for, and only that
mkdir empty
"$SW" grade --assignment plugin-hw.txt --gradescope e.json empty > out 2>&1
awk -f "$json" e.json > flat || fail "results.json (empty) does not parse"
grep -q "^output=.*upload a plugin (.c, .so)" flat || fail "empty upload: $(grep '^output=' flat)"
grep -q "^output=.*trace" flat && fail "empty upload on a plugin homework is told about traces: $(grep '^output=' flat)"

# "# submit: source": a plugin only as its C source; a compiled .so (which
# can carry any code, stepwise's own methods linked in) is not graded, in
# grade, check and the Gradescope count, with one line saying what to give
{ echo "$base" | head -1; echo "# kind: plugin"; echo "# submit: source"; echo "$base" | tail -n +2; } > src-hw.txt
{ echo "$base" | head -1; echo "# submit: binary"; echo "$base" | tail -n +2; } > bad-submit.txt
"$SW" grade --assignment bad-submit.txt good.trace > out 2>&1; rc=$?
[ $rc -eq 2 ] && grep -q "'submit' is source (a plugin's .c only) or source or compiled" out ||
    fail "bad submit: exit $rc: $(cat out)"
cc -shared -fPIC -I"$ROOT/include" -o honest.so honest.c || fail "cc honest.so"
# (the .so under a name of its own: honest.so beside honest.c would be
# its build, not graded, test_grade_build_beside.sh)
mkdir src-class
cp honest.c src-class/
cp honest.so src-class/built.so
"$SW" grade --assignment src-hw.txt --csv s.csv src-class > out 2>&1
grep -q "built.so,fail,,\"this homework asks for a plugin's C source (.c), not a compiled plugin (.so): hand in the .c it was built from: not graded\"" s.csv ||
    fail "source homework: the .so's row: $(cat s.csv)"
grep -q "honest.c,pass," s.csv || fail "source homework: the .c's row: $(cat s.csv)"
"$SW" grade --assignment plugin-hw.txt --csv both.csv src-class > out 2>&1
grep -q "built.so,pass," both.csv || fail "plugin homework: the .so's row: $(cat both.csv)"
"$SW" check --assignment src-hw.txt --plugin ./honest.so > out 2>&1; rc=$?
[ $rc -eq 2 ] && grep -q "not a compiled plugin (.so): hand in the .c" out ||
    fail "check, .so on a source homework: exit $rc: $(cat out)"
mkdir so-only
cp honest.so so-only/
"$SW" grade --assignment src-hw.txt --gradescope so.json so-only > out 2>&1
awk -f "$json" so.json > flat || fail "results.json (.so only) does not parse"
grep -qx "score=0" flat || fail "a .so was counted on a source homework: $(grep '^score=\|^output=' flat)"

# Gradescope with a roster: a roster student without a file is no file
# the submission left out (no "Not graded: : no submission matched ...")
printf 'name,email\nAda One,ada@example.edu\nBen Two,ben@example.edu\n' > roster.csv
"$SW" grade --assignment plugin-hw.txt --roster roster.csv --gradescope ro.json src-class > out 2>&1
awk -f "$json" ro.json > flat || fail "results.json (roster) does not parse"
grep -q "Not graded: :" flat && fail "Gradescope output names a roster row as a file: $(grep '^output=' flat)"
grep -q "^output=.*honest.c" flat || fail "Gradescope with a roster: $(grep '^output=' flat)"
echo ok
