# Sourced by the tests of an honest but slow plugin (test_grade_measure_cpu.sh,
# test_grade_stability_slow.sh): lib.sh first.

# slow_rk4 SPIN: an honest RK4 that spins SPIN rounds in each step, as one .c
slow_rk4() {
    printf '#define SPIN %s\n' "$1"
    cat "$ROOT/tests/data/cheat/common.h"
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

# Calibrate: 200 steps' spin (a graded run's; RK4 on a small system adds
# microseconds) to 0.2 s of CPU or more, doubled from 1e5 rounds a step,
# timed as a program of its own: sets spin, and took (ms).
calibrate_spin() {
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
}
