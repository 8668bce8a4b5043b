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
needs_jail
cheat="$ROOT/tests/data/cheat"

slow() { # SPIN: an honest RK4 that spins SPIN rounds in each step, as one .c
    printf '#define SPIN %s\n' "$1"
    cat "$cheat/common.h"
    cat <<'C'
static int slow(sw_ode *ode, double t, double *y, double h, double *work)
{
    for (volatile long i = 0; i < SPIN; i++) {
    }
    return rk4(ode, t, y, h, work);
}
CHEATER("slow-rk4", slow)
C
}

# the children's CPU time (user + system) in a file `times` wrote, in ms
# (times runs in this shell: in a $(...) subshell it counts the subshell's)
ms() { awk 'NR == 2 { split($1, u, /[ms]/); split($2, s, /[ms]/); printf "%d\n", (u[1] * 60 + u[2] + s[1] * 60 + s[2]) * 1000 }' "$1"; }

# Calibrate: 200 steps' spin (the graded run's; RK4 on the spring adds
# microseconds) to 0.2 s of CPU or more, doubled from 1e5 rounds a step,
# timed as a program of its own.
spin=100000
while :; do
    printf '#define SPIN %s\nint main(void)\n{\n    for (int s = 0; s < 200; s++)\n        for (volatile long i = 0; i < SPIN; i++) {\n        }\n    return 0;\n}\n' "$spin" > cal.c
    cc -std=c11 -O2 -o cal cal.c || fail "cannot build the calibration"
    times > t0.txt
    ./cal
    times > t1.txt
    took=$(( $(ms t1.txt) - $(ms t0.txt) ))
    [ "$took" -ge 200 ] && break
    [ "$spin" -lt 1000000000 ] || fail "200 steps of $spin rounds take only $took ms"
    spin=$((spin * 2))
done
# --cpu: three graded runs and a second for the build, in whole seconds
cpu=$(( (3 * took + 999) / 1000 + 1 ))

mkdir class
slow $spin > class/slow.c
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
