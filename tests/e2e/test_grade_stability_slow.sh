#!/bin/sh
# e2e: long (run.sh starts it first)
# An honest but slow plugin keeps its stability point (docs/grading.md,
# "The stability point is decided"): in at most two runs of the spring
# against the method's own measured limit, in a host of their own
# on the grader's budget (4 x --cpu + 30 s). Before, the plugin's limit
# was measured by a bisection of about 10^5 steps, which ran an honest RK4
# taking 1-2 ms a step out of that budget: "stability: 0 of 1: stability
# not measured: the plugin ran out of its CPU time (SIGXCPU) (the
# grader's budget ...)", a point lost to the grader's own limit.
# A cheater that is fast on its graded run and slow only on the spring
# (which it can tell apart), where it does not move at all, still loses
# the point: it ran out of the grader's budget slower a step than its
# graded run went, which is its own doing.
# CPU time is counted, not wall time, so the machine's load changes
# nothing; the slowness is calibrated on this machine first.
. "$(dirname "$0")/lib.sh"
if [ -n "${SW_TEST_QUICK:-}" ]; then echo "skip: it burns minutes of CPU by design: run at the full tier (make test-full, which CI runs)"; exit 77; fi
needs_jail
. "$(dirname "$0")/slow_rk4.sh"

# RK4 on the graded chain; on the spring (one particle, dim 4) SPIN
# rounds a step and no motion at all: stable at every step, unlike RK4
cheater() {
    printf '#define SPIN %s\n' "$1"
    cat "$ROOT/tests/data/cheat/common.h"
    cat <<'C'
static int sly(sw_ode *ode, double t, double *y, double h, double *work)
{
    if (ode->dim != 4)
        return rk4(ode, t, y, h, work);
    for (volatile long i = 0; i < SPIN; i++) {
    }
    return 0;
}
CHEATER("sly-rk4", sly)
C
}

# 1-2 ms a step: the old bisection (about 10^5 steps) takes well over
# the grader's 38 s, the two runs (at most 1 600 steps) a few seconds
calibrate_spin

mkdir class
slow_rk4 $spin > class/slow.c
# 200 times slower a step on the spring (0.2-0.4 s): out of the grader's
# 38 s within the first of the two runs
cheater $((spin * 200)) > class/sly.c
cat > hw.txt <<'A'
# stepwise assignment 1
# kind: plugin
# scene: chain
# integrator: rk4
# dt: 0.01
# steps: 200
# points x* y*: 1
# points stability: 1
A
"$SW" grade --assignment hw.txt --cpu 2 -j 2 --csv g.csv --feedback fb class > g.out 2>&1; rc=$?
[ $rc -le 1 ] || fail "grade exited $rc (200 steps $took ms): $(cat g.out)"
score() { grep "^$1,class/$1.c," g.csv | awk -F, '{ print $(NF-2) "/" $(NF-1) }'; }
[ "$(score slow)" = 2/2 ] || fail "the slow honest RK4 lost points (200 steps $took ms): $(cat fb/slow.txt)"
grep -q "stability: 1 of 1" fb/slow.txt || fail "no stability point: $(cat fb/slow.txt)"
grep -q "stability limit within 5 % of rk4's" fb/slow.txt || fail "the decision's words: $(cat fb/slow.txt)"
[ "$(score sly)" = 1/2 ] || fail "the cheater scored $(score sly): $(cat fb/sly.txt)"
# its point is lost to its own slowness ("ran out of the grader's CPU
# budget ... slower a step than its graded run"): the budget holds for
# all the grader's hosts together (a host that died in steps read ahead
# and was started again once got a budget afresh, and the runs ended)
grep -q "stability: 0 of 1: stability not measured: the plugin ran out of the grader's CPU budget" \
    fb/sly.txt || fail "the cheater's stability: $(cat fb/sly.txt)"
exit 0
