#!/bin/sh
# The evidence for check's default tolerances (docs/trace-format.md,
# "Tolerances"): an independent awk implementation of euler, midpoint, heun
# and rk4 on particles joined by damped springs (the spring scene, and the
# chain as src/scenes/spring_scenes.c builds it) passes `stepwise check` with
# the defaults on every run in the doc's first table, and stepwise traces of
# one method checked as another fail on every run in the second. Prints the
# worst tolerance ratio of each run (<= 1 passes).
. "$(dirname "$0")/lib.sh"

cat > springs.awk <<'AWK'
# Particles of mass m joined by damped springs (force on a, spring a-b:
# -[k(|d| - rest) + c (dv.d)/|d|] d/|d|, d = x_a - x_b), gravity -m g in y.
# Variables: scene (spring|chain), method (euler|midpoint|heun|rk4), dt,
# steps, and parameters k m c rest g, stretch (spring), nn and pluck (chain).
function deriv(t, y, d,    i, j, a, b, dx, dy, len, dvx, dvy, mag, fx, fy) {
    for (i = 0; i < n; i++) {
        d[2*i] = y[2*n + 2*i]; d[2*i+1] = y[2*n + 2*i + 1]
        F[2*i] = 0; F[2*i+1] = -m * g
    }
    for (j = 0; j < ns; j++) {
        a = sa[j]; b = sb[j]
        if (b >= 0) { dx = y[2*a] - y[2*b]; dy = y[2*a+1] - y[2*b+1]
                      dvx = y[2*n+2*a] - y[2*n+2*b]; dvy = y[2*n+2*a+1] - y[2*n+2*b+1] }
        else        { dx = y[2*a] - sax[j]; dy = y[2*a+1] - say[j]
                      dvx = y[2*n+2*a]; dvy = y[2*n+2*a+1] }
        len = sqrt(dx*dx + dy*dy)
        # magnitude along the spring, damping on the velocity's projection
        mag = k * (len - rest) + c * (dvx*dx + dvy*dy) / len
        fx = -mag * dx / len; fy = -mag * dy / len
        F[2*a] += fx; F[2*a+1] += fy
        if (b >= 0) { F[2*b] -= fx; F[2*b+1] -= fy }
    }
    for (i = 0; i < 2*n; i++) d[2*n + i] = F[i] / m
}
function energy(y,    e, i, j, a, b, dx, dy, s) {
    e = 0
    for (i = 0; i < n; i++) e += m * (y[2*n+2*i]^2 + y[2*n+2*i+1]^2) / 2 + m * g * y[2*i+1]
    for (j = 0; j < ns; j++) {
        a = sa[j]; b = sb[j]
        if (b >= 0) { dx = y[2*a] - y[2*b]; dy = y[2*a+1] - y[2*b+1] }
        else { dx = y[2*a] - sax[j]; dy = y[2*a+1] - say[j] }
        s = sqrt(dx*dx + dy*dy) - rest
        e += k * s * s / 2
    }
    return e
}
function row(step, t,    line, i) {
    line = sprintf("%d,%.17g", step, t)
    for (i = 0; i < n; i++)
        line = line sprintf(",%.17g,%.17g,%.17g,%.17g", Y[2*i], Y[2*i+1], Y[2*n+2*i], Y[2*n+2*i+1])
    print line sprintf(",%.17g", energy(Y))
}
function step(t, h,    i) {
    if (method == "euler") {
        deriv(t, Y, K1); for (i = 0; i < dim; i++) Y[i] += h * K1[i]
    } else if (method == "midpoint") {
        deriv(t, Y, K1); for (i = 0; i < dim; i++) T[i] = Y[i] + h / 2 * K1[i]
        deriv(t + h/2, T, K2); for (i = 0; i < dim; i++) Y[i] += h * K2[i]
    } else if (method == "heun") {
        deriv(t, Y, K1); for (i = 0; i < dim; i++) T[i] = Y[i] + h * K1[i]
        deriv(t + h, T, K2); for (i = 0; i < dim; i++) Y[i] += h / 2 * (K1[i] + K2[i])
    } else {
        deriv(t, Y, K1); for (i = 0; i < dim; i++) T[i] = Y[i] + h / 2 * K1[i]
        deriv(t + h/2, T, K2); for (i = 0; i < dim; i++) T[i] = Y[i] + h / 2 * K2[i]
        deriv(t + h/2, T, K3); for (i = 0; i < dim; i++) T[i] = Y[i] + h * K3[i]
        deriv(t + h, T, K4)
        for (i = 0; i < dim; i++) Y[i] += h / 6 * (K1[i] + 2*K2[i] + 2*K3[i] + K4[i])
    }
}
BEGIN {
    if (scene == "spring") {
        if (k == "") k = 10; if (m == "") m = 1; if (c == "") c = 0.5
        if (rest == "") rest = 1; if (stretch == "") stretch = 0.5; if (g == "") g = 0
        n = 1; ns = 1; sa[0] = 0; sb[0] = -1; sax[0] = 0; say[0] = 0
        Y[0] = rest + stretch; Y[1] = 0; Y[2] = 0; Y[3] = 0
        params = sprintf("# param k: %.17g\n# param m: %.17g\n# param c: %.17g\n# param rest: %.17g\n# param stretch: %.17g\n# param g: %.17g", k, m, c, rest, stretch, g)
    } else {
        if (nn == "") nn = 10; if (k == "") k = 100; if (m == "") m = 1; if (c == "") c = 0
        if (rest == "") rest = 1; if (g == "") g = 0; if (pluck == "") pluck = 0.5
        n = nn; ns = n + 1
        for (j = 0; j <= n; j++) {
            if (j == 0) { sa[j] = 0; sb[j] = -1; sax[j] = 0; say[j] = 0 }
            else if (j == n) { sa[j] = n - 1; sb[j] = -1; sax[j] = (n + 1) * rest; say[j] = 0 }
            else { sa[j] = j; sb[j] = j - 1 }
        }
        for (i = 0; i < 4*n; i++) Y[i] = 0
        for (i = 0; i < n; i++) Y[2*i] = (i + 1) * rest
        Y[2*int(n/2) + 1] = pluck
        params = sprintf("# param n: %d\n# param k: %.17g\n# param m: %.17g\n# param c: %.17g\n# param rest: %.17g\n# param g: %.17g\n# param pluck: %.17g", n, k, m, c, rest, g, pluck)
    }
    dim = 4 * n
    print "# stepwise trace 1"
    print "# scene: " scene
    print params
    print "# integrator: " method
    printf "# dt: %.17g\n# steps: %d\n", dt, steps
    line = "step,t"
    for (i = 0; i < n; i++) line = line ",x" i ",y" i ",vx" i ",vy" i
    print line ",energy"
    t = 0
    row(0, t)
    for (s = 1; s <= steps; s++) { step(t, dt); t += dt; row(s, t) }
}
AWK

ratio() { sed -n 's/.*"tolerance_ratio": \([^,]*\),*$/\1/p' out | tail -1; }
good() { # name, then awk -v settings
    name=$1; shift
    awk "$@" -f springs.awk > t.csv || fail "awk: $name"
    "$SW" check --json t.csv > out 2>&1 || fail "$name: a correct implementation fails: $(grep -A12 first_failure out)"
    printf 'pass  %-34s worst ratio %s\n' "$name" "$(ratio)"
}
bad() { # name scene method reference [record options]
    name=$1 scene=$2 method=$3 ref=$4; shift 4
    "$SW" record "$scene" -i "$method" "$@" -o t.csv 2>/dev/null || fail "record: $name"
    "$SW" check --json t.csv --reference "$ref" > out 2>&1
    [ $? -eq 1 ] || fail "$name: a wrong method passes"
    printf 'fail  %-34s first failing step %s\n' "$name" \
        "$(sed -n '/first_failure/,/}/s/.*"step": \([0-9]*\),/\1/p' out)"
}
good "spring euler 500"            -v scene=spring -v method=euler -v dt=0.02 -v steps=500
good "spring euler c=0 2000"       -v scene=spring -v method=euler -v dt=0.02 -v steps=2000 -v c=0
good "spring euler g=9.81 5000"    -v scene=spring -v method=euler -v dt=0.02 -v steps=5000 -v g=9.81
good "spring rk4 g=9.81 20000"     -v scene=spring -v method=rk4 -v dt=0.02 -v steps=20000 -v g=9.81
good "spring rk4 k=1e4 dt=1e-3"    -v scene=spring -v method=rk4 -v dt=0.001 -v steps=5000 -v k=10000
good "chain euler 500"             -v scene=chain -v method=euler -v dt=0.01 -v steps=500
good "chain rk4 5000"              -v scene=chain -v method=rk4 -v dt=0.01 -v steps=5000
good "chain heun 2000"             -v scene=chain -v method=heun -v dt=0.01 -v steps=2000
good "chain midpoint n=30 1000"    -v scene=chain -v method=midpoint -v dt=0.005 -v steps=1000 -v nn=30
good "chain rk4 g=9.81 2000"       -v scene=chain -v method=rk4 -v dt=0.01 -v steps=2000 -v g=9.81
bad "rk4 as euler, spring" spring rk4 euler
bad "rk4 as euler, chain" chain rk4 euler
bad "heun as rk4, chain" chain heun rk4
bad "euler as symplectic-euler" spring euler symplectic-euler
bad "verlet as symplectic-euler" chain verlet symplectic-euler
bad "midpoint as heun, chain" chain midpoint heun
bad "midpoint as heun, spring g" spring midpoint heun --set g=9.81
bad "midpoint as heun, dt 1e-4" chain midpoint heun --dt 1e-4 --steps 50000 --every 100
bad "rk4 as euler, dt 1e-5" spring rk4 euler --dt 1e-5 --steps 100000 --every 1000
bad "rk4 as rk45, orbit" orbit rk4 rk45
echo "ok"
