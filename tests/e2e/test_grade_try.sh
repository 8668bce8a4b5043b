#!/bin/sh
# stepwise try: builds the student's C file, measures its order and stability
# limit beside the claimed ones, checks it against the reference for its
# order, names the method it matches when it fails, and with --watch runs
# again when the file is saved; Ctrl-C ends the watch with nothing left running.
set -u
SW=${STEPWISE:?set STEPWISE to the stepwise binary}
if ! why=$("$SW" autograder --probe 2>&1); then # as lib.sh's needs_jail
    echo "skip: $(basename "$0" .sh): no jail for plugins can be built here: $why"; exit 77
fi
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/tests/e2e/wait.sh"
dir=$(mktemp -d)
trap 'kill "$pid" 2>/dev/null; rm -rf "$dir"' EXIT
pid=""
cd "$dir" || exit 1
fail() { echo "FAIL: $*"; cat log 2>/dev/null | tail -20; exit 1; }

cp "$root/examples/euler_plugin.c" mine.c
"$SW" try mine.c --no-play > out 2>&1; rc=$?
[ "$rc" -eq 0 ] || fail "try on the example: exit $rc: $(cat out)"
grep -q 'order      claimed 1, measured 1\.0' out || fail "no measured order: $(cat out)"
grep -q 'stability  none' out || fail "no stability: $(cat out)"
grep -q 'PASS: plugin student-euler on chain matches euler' out || fail "no check: $(cat out)"

grep -q 'build ' out && fail "warnings reported for a file without any: $(cat out)"
grep -q 'output ' out && fail "output reported for a plugin that prints nothing: $(cat out)"
# a plugin's printf goes nowhere: try says how much it printed, and why
# nothing shows (student pass: a printf to debug, and silence)
sed 's|^#include <stepwise/integrator.h>|#include <stdio.h>\n#include <stepwise/integrator.h>|;
     s|^    sw_ode_eval(ode, t, y, dydt);|    sw_ode_eval(ode, t, y, dydt);\n    printf("t = %.3f\\n", t);|' mine.c > loud.c
grep -q 'printf("t = ' loud.c || fail "the printing plugin was not made: $(cat loud.c)"
"$SW" try loud.c --no-play > out 2>&1 || fail "a printing euler: exit $?: $(cat out)"
grep -q 'PASS: plugin student-euler on chain matches euler' out || fail "a printing euler fails: $(cat out)"
# at least the checked run's 500 steps of 10 bytes (its measuring runs print more)
n=$(sed -n 's/^  output     your plugin printed \([0-9]*\) \(bytes\|KiB\) .*which stepwise drops.*/\1 \2/p' out)
case $n in
*KiB) ;;
*bytes) [ "${n% bytes}" -ge 5000 ] || fail "printed too few bytes: $n: $(cat out)" ;;
*) fail "no output line for a plugin that prints: $(cat out)" ;;
esac
# the chain's forces do not read t: a step whose stages are at the wrong
# times passes there, and try checks it on the double gyre too (student
# pass: only a hidden part caught it)
grep -q '^  time       PASS on gyre too' out || fail "no check in time for the example: $(cat out)"
sed "s/@NAME@/timely/" "$root/tests/hostile/honest-rk4.c" > timely.c
sed "s/@NAME@/late/; s/t + 0.5 \* h, tmp, k2/t + h, tmp, k2/" "$root/tests/hostile/honest-rk4.c" > late.c
"$SW" try timely.c --no-play > out 2>&1 || fail "an honest rk4: $(cat out)"
grep -q '^  time       PASS on gyre too' out || fail "an honest rk4 in time: $(cat out)"
"$SW" try late.c --no-play > out 2>&1; rc=$?
[ "$rc" -eq 1 ] && grep -q '^  check      PASS' out && grep -q '^  time       on gyre, whose field changes with t .*FAIL' out ||
    fail "an rk4 whose second stage is at t + h: exit $rc: $(cat out)"
# a step that refuses large steps (returns 1) has no stability limit
# there: it stopped, it did not grow (student pass: "largest stable
# w*dt 0.158")
sed "s/@NAME@/careful/; s/^    int n = ode->dim;$/    if (h > 0.05) return 1;\n    int n = ode->dim;/" \
    "$root/tests/hostile/honest-rk4.c" > careful.c
grep -q "if (h > 0.05) return 1;" careful.c || fail "the careful fixture was not made"
"$SW" try careful.c --no-play > out 2>&1
grep -q "^  stability  not measured: the plugin's step function returned 1 (not 0) .*a step that refuses is not one that grows" out ||
    fail "a step that refuses, its stability: $(cat out)"
# try's argument is the file, not a --plugin flag the student never typed
"$SW" try gone.c --no-play > out 2>&1; rc=$?
[ "$rc" -eq 2 ] || fail "try on a missing file: exit $rc"
grep -qx "stepwise: 'gone.c': no such file.*" out || fail "try's message for a missing file: $(cat out)"
printf 'int x = ;\n' > broken.c
"$SW" try broken.c --no-play > out 2>&1
grep -q "^stepwise: 'broken.c' does not compile" out || fail "try's build error: $(cat out)"
"$SW" record spring --plugin broken.c -o x.csv > out 2>&1
grep -q "^stepwise: --plugin 'broken.c' does not compile" out || fail "--plugin's build error: $(cat out)"
# The compiler's warnings are shown (often a bug); in grade's feedback too,
# as a note that takes nothing off (QA: they were shown nowhere)
sed 's|double \*dydt = work; /\* work vector 0 \*/|double *dydt = work; int unused = 3;|' \
    "$root/examples/euler_plugin.c" > warns.c
grep -q "int unused" warns.c || fail "the fixture's edit did not apply"
"$SW" try warns.c --no-play > out 2>&1 || fail "try with a warning: $(cat out)"
grep -q "^  build      1 compiler warning (often a bug: read them); the first: warns.c:[0-9]*:[0-9]*: warning: unused variable 'unused'" out ||
    fail "the warning is not shown: $(cat out)"
mkdir -p wclass
cp warns.c wclass/
printf '# stepwise assignment 1\n# kind: plugin\n# scene: spring\n# integrator: euler\n# dt: 0.02\n# steps: 20\n' > whw.txt
"$SW" grade --assignment whw.txt --feedback wfb wclass > wgrade.out 2>&1 || fail "grade with a warning: $(cat wgrade.out)"
grep -q "^note: the compiler warned 1 time (nothing is taken off; a warning is often a bug); the first: warns.c:[0-9]*:[0-9]*: warning: unused variable" wfb/*.txt ||
    fail "the feedback has no note of the warning: $(cat wfb/*.txt)"

# Claiming order 2 makes midpoint the reference: a failure that names euler.
sed 's/\.order = 1/.order = 2/' "$root/examples/euler_plugin.c" > claims2.c
"$SW" try claims2.c --no-play > out 2>&1; rc=$?
[ "$rc" -eq 1 ] || fail "euler graded as midpoint: exit $rc"
grep -q 'your numbers match euler' out || fail "the matching method is not named: $(cat out)"

# A plugin whose name says symplectic is compared with the symplectic
# method of its order (it once failed against euler, then was told it
# matched symplectic-euler).
cat > symp.c <<'C'
#include <stepwise/integrator.h>
static int step(sw_ode *ode, double t, double *y, double h, double *work)
{
    int n = ode->dim, half = n / 2;
    sw_ode_eval(ode, t, y, work);
    for (int i = half; i < n; i++) y[i] += h * work[i];
    for (int i = 0; i < half; i++) y[i] += h * y[half + i];
    return 0;
}
static const sw_plugin info = { .abi = SW_PLUGIN_ABI, .name = "my-symp", .label = "Symplectic Euler",
                                .order = 1, .evals = 1, .work_vectors = 1, .step = step };
const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
C
"$SW" try symp.c --no-play > out 2>&1 || fail "a symplectic Euler: exit $?: $(cat out)"
grep -q 'PASS: plugin my-symp on chain matches symplectic-euler' out || fail "symplectic: $(cat out)"
sed 's/Symplectic Euler/velocity Verlet/; s/\.order = 1/.order = 2/' symp.c > verlet-claim.c
"$SW" try verlet-claim.c --no-play > out 2>&1; rc=$?
[ "$rc" -eq 1 ] && grep -q 'differs from verlet on chain' out || fail "a Verlet claim is not compared with verlet: $(cat out)"

printf 'this is not C\n' > broken.c
"$SW" try broken.c --no-play > out 2>&1; rc=$?
[ "$rc" -eq 2 ] && grep -q 'does not compile' out || fail "a broken file: exit $rc: $(cat out)"

# --watch: a save runs it again (from broken to fixed).
cp broken.c w.c
"$SW" try w.c --watch --no-play > log 2>&1 &
pid=$!
wait_until 60 grep -q 'watching w.c' log
grep -q 'does not compile' log || fail "--watch: the first run did not report the error"
sleep 1.1   # a new modification time, whatever the file system's resolution
cp "$root/examples/euler_plugin.c" w.c
wait_until 120 grep -q 'PASS: plugin student-euler' log
grep -q 'w.c changed: trying again' log || fail "--watch did not notice the save"
grep -q 'PASS: plugin student-euler' log || fail "--watch did not run the saved file"
kill -INT "$pid"
gone() { ! kill -0 "$pid" 2>/dev/null; }
wait_until 30 gone
kill -0 "$pid" 2>/dev/null && fail "try --watch did not stop on SIGINT"
wait "$pid" 2>/dev/null
pid=""
echo "ok"
