#!/bin/sh
# An independent program passes `stepwise check`: an awk integrator written
# from docs/trace-format.md alone (Euler and RK4 on the spring scene, with
# its own operation order: a = f/m, the damping term formed differently)
# writes traces that pass with the default tolerances; the same program's
# Euler numbers declared as rk4 fail. awk is on every Debian machine.
. "$(dirname "$0")/lib.sh"

cat > spring.awk <<'AWK'
# The spring scene (docs/trace-format.md): mass m at (rest + stretch, 0), at
# rest, on a spring to the origin; force -[k(|d| - rest) + c (v.d/|d|)] d/|d|,
# gravity -m g in y; energy 1/2 m |v|^2 + 1/2 k (|d| - rest)^2 + m g y.
# Variables: method (euler|rk4), dt, steps, k, m, c, rest, stretch, g.
function accel(px, py, qx, qy, A,    len, mag) {
    len = sqrt(px * px + py * py)
    mag = k * (len - rest) + c * (qx * px + qy * py) / len
    A[1] = -mag * px / len / m
    A[2] = -mag * py / len / m - g
}
# derivative of the state (x, y, vx, vy) into D[1..4]
function deriv(S, D,    A) {
    accel(S[1], S[2], S[3], S[4], A)
    D[1] = S[3]; D[2] = S[4]; D[3] = A[1]; D[4] = A[2]
}
function row(n, t,    len) {
    len = sqrt(Y[1] * Y[1] + Y[2] * Y[2])
    printf "%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", n, t, Y[1], Y[2], Y[3], Y[4], \
        m * (Y[3] * Y[3] + Y[4] * Y[4]) / 2 + k * (len - rest) * (len - rest) / 2 + m * g * Y[2]
}
function step(h,    i, K1, K2, K3, K4, T) {
    deriv(Y, K1)
    if (method == "euler") {
        for (i = 1; i <= 4; i++) Y[i] = Y[i] + h * K1[i]
        return
    }
    for (i = 1; i <= 4; i++) T[i] = Y[i] + h / 2 * K1[i]
    deriv(T, K2)
    for (i = 1; i <= 4; i++) T[i] = Y[i] + h / 2 * K2[i]
    deriv(T, K3)
    for (i = 1; i <= 4; i++) T[i] = Y[i] + h * K3[i]
    deriv(T, K4)
    for (i = 1; i <= 4; i++) Y[i] = Y[i] + h * (K1[i] + 2 * K2[i] + 2 * K3[i] + K4[i]) / 6
}
BEGIN {
    print "# stepwise trace 1"
    print "# scene: spring"
    printf "# param k: %.17g\n# param m: %.17g\n# param c: %.17g\n", k, m, c
    printf "# param rest: %.17g\n# param stretch: %.17g\n# param g: %.17g\n", rest, stretch, g
    printf "# integrator: %s\n# dt: %.17g\n# steps: %d\n", label ? label : method, dt, steps
    print "step,t,x0,y0,vx0,vy0,energy"
    Y[1] = rest + stretch; Y[2] = 0; Y[3] = 0; Y[4] = 0
    t = 0
    row(0, t)
    for (n = 1; n <= steps; n++) { step(dt); t += dt; row(n, t) }
}
AWK

spring() { # method dt steps k m c rest stretch g [label]
    awk -v method="$1" -v dt="$2" -v steps="$3" -v k="$4" -v m="$5" -v c="$6" -v rest="$7" \
        -v stretch="$8" -v g="$9" -v label="${10:-}" -f spring.awk
}

# The defaults (docs: k 10, m 1, c 0.5, rest 1, stretch 0.5, g 0, dt 0.02).
spring euler 0.02 500 10 1 0.5 1 0.5 0 > euler.csv
grep -q '^2,0.040000000000000001,1.498,0,-0.19900000000000001,0,' euler.csv \
    || fail "awk rows differ from the worked example: $(grep '^2,' euler.csv)"
"$SW" check euler.csv > out 2>&1 || fail "awk euler on spring fails the check: $(cat out)"

# Other settings, other operation order: still round-off apart.
spring euler 0.01 3000 25 2 0.1 1.2 -0.4 9.81 > euler2.csv
"$SW" check euler2.csv > out 2>&1 || fail "awk euler, gravity: $(cat out)"
spring rk4 0.02 2000 10 1 0.5 1 0.5 9.81 > rk4.csv
"$SW" check rk4.csv > out 2>&1 || fail "awk rk4 on spring: $(cat out)"

# A wrong method fails: Euler numbers declared as rk4, rk4 numbers as heun.
spring euler 0.02 500 10 1 0.5 1 0.5 0 rk4 > wrong.csv
"$SW" check wrong.csv > out 2>&1
rc=$?
[ "$rc" -eq 1 ] || fail "euler numbers checked as rk4: exit $rc, want 1"
grep -q 'first failure: step 1,' out || fail "the wrong method is not caught at step 1: $(cat out)"
spring rk4 0.02 500 10 1 0.5 1 0.5 9.81 heun > wrong2.csv
"$SW" check wrong2.csv > out 2>&1
[ $? -eq 1 ] || fail "rk4 numbers checked as heun pass"
echo "ok"
