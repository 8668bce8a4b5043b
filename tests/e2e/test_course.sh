#!/bin/sh
# e2e: long (run.sh starts it first)
# The worked example of docs/grading.md (issue 36): a course of 32 students
# (examples/course/roster.csv) with two homeworks. HW5, a plugin homework
# of three parts on two scenes (chain visible, gyre hidden, a longer chain
# shown after the due date) with a stiffness drawn per student; HW4, a trace
# homework of two parts with graded closeness and per-student values. The
# class has planted mistakes: a trace on the plugin homework, a classmate's
# trace, positions in cm, values close but not exact, an empty upload, a
# renamed re-upload (best on HW5, latest on HW4), a plugin right on one
# part only, a missing part, a student with nothing. The gradebook, the LMS
# CSV and each student's results.json (scores and tests) are compared with
# the expectation written below, byte for byte; a regrade of one student
# keeps every other row; the Gradescope bundle, run as Gradescope runs it
# (/autograder/source, a fresh submission/ and results/ each time), gives
# every student of HW5 the class run's score, its hidden part hidden (at
# the quick tier one student of each kind of submission, below).
. "$(dirname "$0")/lib.sh"
needs_jail
json="$ROOT/tests/e2e/json.awk"
course="$ROOT/examples/course"
cd "$WORK" || exit 1
cp "$course/hw5-rk4.txt" "$course/hw4-traces.txt" "$course/roster.csv" .
"$SW" handout --assignment hw4-traces.txt --roster roster.csv -o sheets4 > /dev/null 2>&1 || fail "handout hw4"
"$SW" handout --assignment hw5-rk4.txt --roster roster.csv -o sheets5 > /dev/null 2> warn5 || fail "handout hw5"
# the examples' secret is public: handing out (and grading) with it is warned of, once
[ "$(grep -c "warning: hw5-rk4.txt: its '# secret:' is the examples' words" warn5)" -eq 1 ] ||
    fail "no warning of the examples' secret: $(cat warn5)"
sed 's/^# secret: .*/# secret: a teacher'"'"'s own words/' hw5-rk4.txt > own.txt
"$SW" handout --assignment own.txt --roster roster.csv -o sheets-own > /dev/null 2> warn-own || fail "handout own"
grep -q "warning" warn-own && fail "a secret of the teacher's own is warned of: $(cat warn-own)"
[ "$(ls sheets4 | wc -l)" -eq 33 ] || fail "handout: not 32 sheets and an index: $(ls sheets4)"
grep -q "lighthouse\|replace these words" sheets4/* sheets5/* && fail "a sheet holds the course secret"
grep -q "gyre" sheets5/* && fail "a plugin homework's sheet shows its hidden part"
grep -q "per student" sheets4/* && fail "a sheet holds a range, not the student's value"

# name -> the folder a Moodle download gives it ("Full Name_ID_assignsubmission_file_")
folder() { # HW NAME
    id=$(awk -F, -v n="$2" '$1 == n { print $2 }' roster.csv)
    d="$1/$2_${id}_assignsubmission_file_"
    mkdir -p "$d"
    printf '%s\n' "$d"
}
sheet() { # DIR NAME: the student's sheet
    f=$(awk -F, -v n="$2" 'NR > 1 && $1 == n { print $3 }' "$1/handout.csv" | tr -d '\r')
    printf '%s/%s\n' "$1" "$f"
}
value() { # SHEET PARAM [N]: the N-th (default first) value of a parameter on a sheet
    sed -n "s/^# param $2: //p" "$1" | sed -n "${3:-1}p"
}
record_swing() { # SHEET OUT
    "$SW" record spring --set k="$(value "$1" k)" -i verlet --dt 0.01 --steps 200 -o "$2" > /dev/null 2>&1 ||
        fail "record swing for $1"
}
record_fall() { # SHEET OUT
    "$SW" record projectile --set drag="$(value "$1" drag)" -i rk4 --dt 0.05 --steps 40 -o "$2" > /dev/null 2>&1 ||
        fail "record fall for $1"
}
names=$(awk -F, 'NR > 1 { print $1 }' roster.csv)

# ---- HW4, traces -------------------------------------------------------------
mkdir hw4
printf '%s\n' "$names" | while IFS= read -r n; do
    case "$n" in
        "Grace Hopper"|"Emmy Noether"|"Henri Poincaré"|"Sofia Kovalevskaya"|"Carl Gauss"|\
        "Leonhard Euler"|"Joseph Lagrange"|"Pierre Laplace"|"Norbert Wiener") continue ;;
    esac
    d=$(folder hw4 "$n"); s=$(sheet sheets4 "$n")
    record_swing "$s" "$d/swing.trace"; record_fall "$s" "$d/fall.trace"
done
ada=$(folder hw4 "Ada Lovelace")
# Grace Hopper hands in Ada's traces as her own
d=$(folder hw4 "Grace Hopper"); cp "$ada/swing.trace" "$ada/fall.trace" "$d/"
# Emmy Noether writes positions in centimetres
d=$(folder hw4 "Emmy Noether"); s=$(sheet sheets4 "Emmy Noether")
record_swing "$s" m.trace; record_fall "$s" "$d/fall.trace"
awk -F, 'BEGIN { OFS = "," } /^#/ || /^step/ { print; next }
         { $3 = sprintf("%.17g", $3 * 100); $4 = sprintf("%.17g", $4 * 100); print }' m.trace > "$d/swing.trace"
# Henri Poincaré's values are close, not exact: 1e-7 relative on every value
d=$(folder hw4 "Henri Poincaré"); s=$(sheet sheets4 "Henri Poincaré")
record_swing "$s" h.trace; record_fall "$s" "$d/fall.trace"
awk -F, 'BEGIN { OFS = ","; CONVFMT = "%.17g"; OFMT = "%.17g" } /^#/ || /^step/ { print; next }
         { for (i = 3; i <= NF; i++) $i = sprintf("%.17g", $i * (1 + 1e-7)); print }' h.trace > "$d/swing.trace"
# Sofia Kovalevskaya uploads nothing (an empty folder)
folder hw4 "Sofia Kovalevskaya" > /dev/null
# Carl Gauss uploads a good swing, then a worse one named swing-v2 (latest counts)
d=$(folder hw4 "Carl Gauss"); s=$(sheet sheets4 "Carl Gauss")
record_swing "$s" "$d/swing.trace"; record_fall "$s" "$d/fall.trace"
touch -d '2026-01-01 10:00' "$d/swing.trace"
"$SW" record spring --set k="$(value "$s" k)" -i euler --dt 0.01 --steps 200 -o "$d/swing-v2.trace" > /dev/null 2>&1
touch -d '2026-01-02 10:00' "$d/swing-v2.trace"
# Leonhard Euler hands in a plugin on the trace homework
d=$(folder hw4 "Leonhard Euler"); sed "s/@NAME@/le/" "$ROOT/tests/hostile/honest-rk4.c" > "$d/rk4.c"
# Joseph Lagrange forgets the fall
d=$(folder hw4 "Joseph Lagrange"); record_swing "$(sheet sheets4 "Joseph Lagrange")" "$d/swing.trace"
# Pierre Laplace records with the teacher's preview values, not his own
d=$(folder hw4 "Pierre Laplace")
"$SW" record spring --set k=8 -i verlet --dt 0.01 --steps 200 -o "$d/swing.trace" > /dev/null 2>&1
record_fall "$(sheet sheets4 "Pierre Laplace")" "$d/fall.trace"
# Norbert Wiener uploads a file that is no trace (which part it is for cannot be told)
printf 'my answers are on paper\n' > "$(folder hw4 "Norbert Wiener")/homework.trace"

"$SW" grade --assignment hw4-traces.txt --roster roster.csv --csv files4.csv --gradebook book4.csv \
    --lms lms4.csv --similarity hw4 > out4 2>&1
[ $? -le 1 ] || fail "grade hw4: $(cat out4)"

# The expectation, written out: each student's points of 8 (4 a part: the
# header 1, the positions 3 within 1e-9, 2 within 1e-6, 1 within 1e-3).
cat > want-lms4.csv <<'EOF'
name,id,email,score,max
Ada Lovelace,1001,ada@uni.edu,8,8
Alan Turing,1002,alan@uni.edu,8,8
Grace Hopper,1003,grace@uni.edu,0,8
Emmy Noether,1004,emmy@uni.edu,5,8
Henri Poincaré,1005,henri@uni.edu,7,8
Sofia Kovalevskaya,1006,sofia@uni.edu,0,8
Carl Gauss,1007,carl@uni.edu,4,8
Leonhard Euler,1008,leonhard@uni.edu,0,8
Joseph Lagrange,1009,joseph@uni.edu,4,8
Pierre Laplace,1010,pierre@uni.edu,4,8
Katherine Johnson,1011,katherine@uni.edu,8,8
John von Neumann,1012,john@uni.edu,8,8
Mary Somerville,1013,mary@uni.edu,8,8
Srinivasa Ramanujan,1014,srinivasa@uni.edu,8,8
Hypatia Alexandria,1015,hypatia@uni.edu,8,8
Évariste Galois,1016,evariste@uni.edu,8,8
Sophie Germain,1017,sophie@uni.edu,8,8
Bernhard Riemann,1018,bernhard@uni.edu,8,8
Dorothy Vaughan,1019,dorothy@uni.edu,8,8
Karl Weierstrass,1020,karl@uni.edu,8,8
Maryam Mirzakhani,1021,maryam@uni.edu,8,8
Kurt Goedel,1022,kurt@uni.edu,8,8
Olga Ladyzhenskaya,1023,olga@uni.edu,8,8
David Hilbert,1024,david@uni.edu,8,8
Julia Robinson,1025,julia@uni.edu,8,8
Niels Abel,1026,niels@uni.edu,8,8
Cathleen Morawetz,1027,cathleen@uni.edu,8,8
Felix Klein,1028,felix@uni.edu,8,8
Ingrid Daubechies,1029,ingrid@uni.edu,8,8
George Boole,1030,george@uni.edu,8,8
Nalini Anantharaman,1031,nalini@uni.edu,8,8
Norbert Wiener,1032,norbert@uni.edu,0,8
EOF
tr -d '\r' < lms4.csv > got-lms4.csv
cmp -s got-lms4.csv want-lms4.csv || fail "HW4's LMS CSV is not the expectation: $(diff want-lms4.csv got-lms4.csv)"
# Every gradebook row's verdict, counted files and why, for the planted ones.
book4() { # NAME VERDICT COUNTED-PATTERN MESSAGE-PATTERN
    row=$(grep "^\"*$1" book4.csv)
    printf '%s\n' "$row" | grep -q ",$2," || fail "HW4 $1: not $2: $row"
    printf '%s\n' "$row" | grep -q -- "$3" || fail "HW4 $1: counted: $row"
    printf '%s\n' "$row" | grep -q -- "$4" || fail "HW4 $1: message: $row"
}
book4 "Grace Hopper" fail "swing.trace" "made for other parameters than yours (param k: "
grep "^Grace Hopper" book4.csv | grep -q "Ada" && fail "the copied trace's message names whose it was"
# ... but the teacher's --similarity pairs her files with Ada's: with values
# per student, byte-identical traces are a copy even when one is correct
grep "^Grace Hopper,.*swing.trace" files4.csv | grep -q "Ada Lovelace.*byte-identical files" ||
    fail "HW4: the copied traces are not paired: $(grep '^Grace Hopper' files4.csv)"
book4 "Emmy Noether" fail "swing.trace" "x0 is 100 times the reference at every step: positions in cm instead of m"
book4 "Henri Poincaré" fail "swing.trace" ""
book4 "Sofia Kovalevskaya" missing "" "no submission"
grep "^Henri Poincaré" book4.csv | grep -q "x0 = 1.50000015 in yours, 1.5 in the assignment's" ||
    fail "HW4 Henri Poincaré: $(grep '^Henri' book4.csv)"
grep "Henri Poincaré.*swing.trace" files4.csv | grep -q ',3,4,swing' || fail "HW4 Henri: not 3 of 4 on swing: $(grep Henri files4.csv)"
book4 "Carl Gauss" fail "swing-v2.trace" ""
grep "^Carl Gauss" book4.csv | grep -q ",swing-v2.trace.*hw4/Carl Gauss_1007_assignsubmission_file_/swing.trace," ||
    true # the older upload is in 'also' (checked below)
grep "^Carl Gauss" book4.csv | awk -F, '{ print $8 }' | grep -q "swing.trace" ||
    fail "HW4 Carl Gauss: the earlier upload is not listed as also graded: $(grep '^Carl Gauss' book4.csv)"
book4 "Leonhard Euler" fail "" "nothing of the kind this homework asks for: a trace"
book4 "Joseph Lagrange" fail "swing.trace" "no trace for part fall"
book4 "Pierre Laplace" fail "swing.trace" "made for other parameters"
book4 "Norbert Wiener" error "" "not a stepwise trace"
[ "$(awk -F, 'NR > 1 { print $5 }' book4.csv | sort -u | tr -d '\r')" = 8 ] || fail "HW4: not one max for every row"
[ "$(($(wc -l < book4.csv) - 1))" -eq 32 ] || fail "HW4: not one row per student: $(wc -l < book4.csv)"
# the cm trace: named as a unit mistake, in the files' rows
grep "Emmy Noether.*swing.trace" files4.csv | grep -q "100 times the reference" ||
    fail "HW4: positions in cm not named: $(grep 'Emmy Noether' files4.csv)"

# A regrade of one student keeps every other row of the gradebook as it was.
cp book4.csv before4.csv
d=$(folder hw4 "Joseph Lagrange"); record_fall "$(sheet sheets4 "Joseph Lagrange")" "$d/fall.trace"
"$SW" grade --assignment hw4-traces.txt --roster roster.csv --csv files4.csv --gradebook book4.csv \
    --lms lms4.csv "$d" > regrade4 2>&1
[ $? -le 1 ] || fail "regrade hw4: $(cat regrade4)"
grep -q "^Joseph Lagrange,1009,joseph@uni.edu,8,8,pass," book4.csv || fail "regrade: $(grep Lagrange book4.csv)"
grep -v "^Joseph Lagrange" before4.csv | sort > a; grep -v "^Joseph Lagrange" book4.csv | sort > b
cmp -s a b || fail "the regrade changed other rows: $(diff a b)"
grep -q "^Joseph Lagrange,1009,joseph@uni.edu,8,8" lms4.csv || fail "regrade: the LMS CSV: $(grep Lagrange lms4.csv)"
[ "$(($(wc -l < lms4.csv) - 1))" -eq 32 ] || fail "regrade: the LMS CSV lost rows: $(cat lms4.csv)"

# ---- HW5, plugins ------------------------------------------------------------
sed "s/@NAME@/student/" "$ROOT/tests/hostile/honest-rk4.c" > honest.c
cc -std=c11 -O2 -shared -fPIC -I"$ROOT/include" -o honest.so honest.c || fail "cannot build honest.so"
mkdir hw5
printf '%s\n' "$names" | while IFS= read -r n; do
    case "$n" in
        "Grace Hopper"|"Emmy Noether"|"Henri Poincaré"|"Sofia Kovalevskaya"|"Norbert Wiener") continue ;;
    esac
    d=$(folder hw5 "$n"); cp honest.so "$d/rk4.so"
done
cp honest.c "$(folder hw5 "Ada Lovelace")/rk4.c" && rm "$(folder hw5 "Ada Lovelace")/rk4.so"
# Grace Hopper: RK4 with every stage at t (right on the chains, wrong on the gyre)
cp "$course/rk4_at_t.c" "$(folder hw5 "Grace Hopper")/rk4.c"
# Emmy Noether: a draft (Euler) and, renamed, her final RK4 (the best counts)
d=$(folder hw5 "Emmy Noether"); cp "$ROOT/examples/euler_plugin.c" "$d/draft.c"; cp honest.so "$d/rk4_final.so"
# Henri Poincaré hands in a trace recorded with the settings
d=$(folder hw5 "Henri Poincaré"); s=$(sheet sheets5 "Henri Poincaré")
"$SW" record chain --set n=4 --set k="$(value "$s" k)" -i rk4 --dt 0.01 --steps 100 -o "$d/chain.trace" > /dev/null 2>&1
# Sofia Kovalevskaya uploads nothing; Norbert Wiener has no folder
folder hw5 "Sofia Kovalevskaya" > /dev/null
# John von Neumann's RK4 crashes on the gyre (8 values: 4 particles) and on
# nothing else: the hidden part's crash costs its own points only
sed -e "s/@NAME@/jvn/" -e 's/^{$/{ if (ode->dim == 8) abort();/' -e 's/#include <stepwise\/integrator.h>/#include <stdlib.h>\n#include <stepwise\/integrator.h>/' \
    "$ROOT/tests/hostile/honest-rk4.c" > "$(folder hw5 "John von Neumann")/rk4.c"
rm -f "$(folder hw5 "John von Neumann")/rk4.so"
grep -q "abort" "$(folder hw5 "John von Neumann")/rk4.c" || fail "the crashing plugin was not made"
# Carl Gauss hands in Euler
cp "$ROOT/examples/euler_plugin.c" "$(folder hw5 "Carl Gauss")/rk4.c"; rm -f "$(folder hw5 "Carl Gauss")/rk4.so"

"$SW" grade --assignment hw5-rk4.txt --roster roster.csv --csv files5.csv --gradebook book5.csv \
    --lms lms5.csv --feedback fb5 hw5 > out5 2>&1
[ $? -le 1 ] || fail "grade hw5: $(cat out5)"
# Points of 7: values 2 on each part, the order 1 on the chain.
{
    echo "name,id,email,score,max"
    awk -F, 'NR > 1 { s = 7
        if ($1 == "Grace Hopper" || $1 == "John von Neumann") s = 5
        if ($1 == "Henri Poincaré" || $1 == "Sofia Kovalevskaya" || $1 == "Carl Gauss" || $1 == "Norbert Wiener") s = 0
        print $1 "," $2 "," $3 "," s ",7" }' roster.csv
} > want-lms5.csv
tr -d '\r' < lms5.csv > got-lms5.csv
cmp -s got-lms5.csv want-lms5.csv || fail "HW5's LMS CSV is not the expectation: $(diff want-lms5.csv got-lms5.csv)"
grep "^Grace Hopper" book5.csv | grep -q "gyre:" || fail "HW5 Grace Hopper: the gyre is not named: $(grep Hopper book5.csv)"
# ... to the teacher; her feedback shows the chain and says the gyre was graded, nothing more
grep -q "== part chain ==" fb5/Grace_Hopper.txt && grep -q "the results of this part are not shown to you" fb5/Grace_Hopper.txt ||
    fail "HW5 Grace Hopper's feedback: $(cat fb5/Grace_Hopper.txt)"
grep -q "every stage evaluated\|rk4.c: fail\|first failing step" fb5/Grace_Hopper.txt &&
    fail "HW5 Grace Hopper's feedback tells how the hidden part went: $(cat fb5/Grace_Hopper.txt)"
grep "^Emmy Noether" book5.csv | grep -q ",7,7,pass,.*rk4_final.so,.*draft.c," ||
    fail "HW5 Emmy Noether: the best upload does not count: $(grep Noether book5.csv)"
# a teacher's slip: an output named like the roster is refused, the roster kept
cp roster.csv roster.bak
"$SW" grade --assignment hw5-rk4.txt --roster roster.csv --gradebook roster.csv hw5 > slip 2>&1; rc=$?
[ $rc -eq 2 ] && grep -q "is not what --gradebook writes" slip && cmp -s roster.csv roster.bak ||
    fail "--gradebook over the roster: exit $rc: $(cat slip)"
grep "^Henri Poincaré" book5.csv | grep -q "nothing of the kind this homework asks for: a plugin" ||
    fail "HW5 Henri Poincaré: $(grep Henri book5.csv)"

# ---- the bundle, as Gradescope runs it -----------------------------------
# Every student at the full tier; at the quick tier (SW_TEST_QUICK) each
# kind of submission once: the planted ones and one plain honest .so
# (Katherine Johnson's, whose first line is checked), the 22 other honest
# .so copies left to make test-full.
"$SW" autograder --assignment hw5-rk4.txt -o hw5.zip --source "$ROOT" > /dev/null 2>&1 || fail "autograder bundle"
gs=0
if [ -n "${SW_TEST_QUICK:-}" ]; then
    printf '%s\n' "Ada Lovelace" "Grace Hopper" "Emmy Noether" "Henri Poincaré" "Sofia Kovalevskaya" \
        "Carl Gauss" "Katherine Johnson" "John von Neumann" "Norbert Wiener" > names
else
    printf '%s\n' "$names" > names
fi
while IFS= read -r n; do
    r=$WORK/ag; rm -rf "$r"; mkdir -p "$r/source" "$r/submission"
    (cd "$r/source" && unzip -q "$WORK/hw5.zip") || fail "unzip"
    cp "$(folder hw5 "$n")"/* "$r/submission/" 2>/dev/null
    email=$(awk -F, -v n="$n" '$1 == n { print $3 }' roster.csv)
    printf '{"id": %d, "users": [{"email": "%s", "id": 7, "name": "%s"}]}\n' $gs "$email" "$n" \
        > "$r/submission_metadata.json"
    AUTOGRADER_ROOT=$r STEPWISE=$SW sh "$r/source/run_autograder" > "$r/stdout" 2>&1 || fail "run_autograder: $n"
    awk -f "$json" "$r/results/results.json" > flat || fail "$n: results.json does not parse"
    want=$(grep "^$n," want-lms5.csv | cut -d, -f4)
    grep -qx "score=$want" flat || fail "$n: the bundle's score is not the class run's $want: $(grep '^score=' flat)"
    # each test: its part's visibility
    awk -F= '/\.name=/ { split($1, a, "."); name[a[1]] = $2 } /\.visibility=/ { split($1, a, "."); vis[a[1]] = $2 }
             END { for (k in name) print name[k] "|" vis[k] }' flat | sort > tests
    printf '%s\n' "chain: order|visible" "chain: values: x* y*|visible" "gyre: values: x* y*|hidden" \
        "long-chain: values: x* y*|after_due_date" | sort > want-tests
    cmp -s tests want-tests || fail "$n: tests and visibility: $(cat tests)"
    grep '^output=' flat | grep -q "gyre: " &&
        fail "$n: the output tells how the hidden part went: $(grep '^output=' flat)"
    if [ "$n" = "Katherine Johnson" ]; then # the output's first line, as docs/grading.md quotes it
        grep -q '^output=.*: 3 of 3 points on the parts shown now; 2 of the 3 parts are graded now and shown later (or never)' flat ||
            fail "$n: the first line: $(grep '^output=' flat | cut -c1-300)"
    fi
    gs=$((gs + 1))
done < names
[ $gs -eq "$(wc -l < names)" ] && [ $gs -ge 9 ] || fail "the bundle ran $gs times for $(wc -l < names) students"
