#!/bin/sh
# e2e: long (run.sh starts it first)
# The grader's own work is never charged to the student (docs/grading.md,
# "limits"): its measuring runs of a plugin's order and stability limit run
# in a host of their own, on the grader's budget, and their CPU time is not
# counted in --cpu. An honest but slow RK4 (a fixed amount of work in each
# step) whose graded run takes a third of --cpu keeps its order point,
# although the measuring runs, which span the graded run four times over
# (about 15 times its steps), take several times --cpu. (Before, they ran
# in the graded run's host and it ran out of --cpu: "order not measured".)
# CPU time is counted, not wall time, so the machine's load changes
# nothing; the slowness is calibrated on this machine first.
. "$(dirname "$0")/lib.sh"
if [ -n "${SW_TEST_QUICK:-}" ]; then echo "skip: it burns minutes of CPU by design: run at the full tier (make test-full, which CI runs)"; exit 77; fi
needs_jail
. "$(dirname "$0")/slow_rk4.sh"
calibrate_spin
# --cpu: three graded runs and a second for the build, in whole seconds
cpu=$(( (3 * took + 999) / 1000 + 1 ))

mkdir class
slow_rk4 $spin > class/slow.c
cat > hw.txt <<A
# stepwise assignment 1
# kind: plugin
# scene: spring
# integrator: rk4
# dt: 0.01
# steps: 200
# points x* y*: 1
# points order: 1
A
"$SW" grade --assignment hw.txt --cpu "$cpu" --csv g.csv --feedback fb class > g.out 2>&1; rc=$?
[ $rc -eq 0 ] || fail "grade exited $rc (graded run $took ms, --cpu $cpu): $(cat g.out fb/slow.txt)"
score=$(grep '^slow,class/slow.c,' g.csv | awk -F, '{ print $(NF-2) "/" $(NF-1) }')
[ "$score" = 2/2 ] || fail "the slow RK4 lost points (graded run $took ms, --cpu $cpu): $(cat g.csv fb/slow.txt)"
grep -q 'order: 1 of 1' fb/slow.txt || fail "no order point: $(cat fb/slow.txt)"
