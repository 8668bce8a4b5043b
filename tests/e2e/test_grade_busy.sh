#!/bin/sh
# Limits that never fail an honest student (issue 35): a class of honest
# RK4 plugins (measured order and stability paid for), wrong ones and
# traces is graded with the default limits on an idle machine and again
# with two busy loops holding both cores, with -j 2 both times. The two
# gradebooks must give every student the same verdict and score, and no
# honest plugin may end at a limit: --cpu counts a submission's own
# processes only, and the wall clock is a guard, not a measure. (No time
# is asserted: the loaded run only has to give the same answers.) -j 1
# gives the same gradebook, error rows included.
. "$(dirname "$0")/lib.sh"
needs_jail
cat > assignment.txt <<'A'
# stepwise assignment 1
# title: RK4 on a chain, measured
# scene: chain
# param n: 4
# integrator: rk4
# dt: 0.005
# steps: 400
# points x* y*: 4
# points order: 1
# points stability: 1
A
mkdir class
"$SW" record chain --set n=4 -i rk4 --dt 0.005 --steps 400 -o class/trace-good.trace >/dev/null 2>&1 ||
    fail "cannot record"
"$SW" record chain --set n=4 -i euler --dt 0.005 --steps 400 -o class/trace-euler.trace >/dev/null 2>&1 ||
    fail "cannot record"
for i in 1 2 3 4 5 6; do
    sed "s/@NAME@/honest-$i/" "$ROOT/tests/hostile/honest-rk4.c" > class/honest$i.c
done
# a midpoint called rk4, and one whose stages all sit at t (right on the chain)
sed "s/@NAME@/wrong-1/; s/sw_ode_eval(ode, t + 0.5 \* h, tmp, k3);/sw_ode_eval(ode, t + 0.5 * h, tmp, k3); for (int i = 0; i < n; i++) k3[i] = k2[i];/" \
    "$ROOT/tests/hostile/honest-rk4.c" > class/wrong1.c
cp "$ROOT/examples/euler_plugin.c" class/euler.c
# error rows: one that does not compile, one with no sw_plugin_info
printf '#include <stepwise/integrator.h>\nint broken = ;\n' > class/bad.c
printf '#include <stepwise/integrator.h>\nint nothing;\n' > class/nosym.c
grade() { # CSV [JOBS]
    "$SW" grade --assignment assignment.txt -j "${2:-2}" --csv "$1" class > "$1.out" 2>&1
    [ $? -le 1 ] || fail "grade ($1) did not finish: $(cat "$1.out")"
}
grade idle.csv
# -j 1 gives the same gradebook byte for byte, error rows included: they
# name the student's file, never the grader's temporary build
grade one.csv 1
cmp -s idle.csv one.csv || fail "-j 1 and -j 2 gradebooks differ: $(diff idle.csv one.csv)"
grep -q "bad.c' does not compile (.*): bad.c:2:" idle.csv || fail "the compile error does not name bad.c: $(grep bad idle.csv)"
grep -q 'stepwise-grade-\|/tmp/' idle.csv && fail "a row names a temporary path: $(grep 'stepwise-grade-\|/tmp/' idle.csv)"
busy=""
trap 'kill $busy 2>/dev/null' EXIT
for core in 1 2; do
    sh -c 'while :; do :; done' &
    busy="$busy $!"
done
grade busy.csv
kill $busy 2>/dev/null
busy=""
# the verdict and score columns (file, verdict, score), row by row
cols() { awk -F, 'NR > 1 { print $2 "," $3 "," $4 "," $9 "," $10 }' "$1"; }
cols idle.csv > idle.cols
cols busy.csv > busy.cols
[ -s idle.cols ] || fail "no rows in the gradebook: $(cat idle.csv.out)"
cmp -s idle.cols busy.cols || fail "a busy machine changed a verdict or a score: $(diff idle.cols busy.cols)"
for f in honest1 honest2 honest3 honest4 honest5 honest6; do
    grep -q "$f.c,pass," idle.cols || fail "$f: not a pass when idle: $(grep "$f" idle.csv.out)"
    grep -q "$f.c,pass," busy.cols || fail "$f: not a pass on a busy machine: $(grep "$f" busy.csv.out)"
done
grep -q "limit" idle.cols busy.cols && fail "a submission ended at a limit: $(grep limit idle.cols busy.cols)"
grep -q "wrong1.c,fail," idle.cols || fail "wrong1: not a fail: $(grep wrong1 idle.csv.out)"
echo ok
