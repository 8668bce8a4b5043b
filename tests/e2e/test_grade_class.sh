#!/bin/sh
# A class graded in one command (issue 14): thirteen submissions against one
# assignment — correct, honest wrong dt, honest wrong method, wrong
# parameter, a header lying about its method, truncated, a BOM with CRLF
# and reordered columns, float32, %g digits, v-then-x Euler, and plugins
# that crash, overrun and loop; and a README.txt, which gets a 'skipped'
# row. Each verdict must be right and each message must name the mistake;
# the CSV gradebook and results.json must parse; the run must finish within
# its limits and exit 1.
set -u
SW=${STEPWISE:?set STEPWISE to the stepwise binary}
if ! why=$("$SW" autograder --probe 2>&1); then # as lib.sh's needs_jail
    echo "skip: $(basename "$0" .sh): no jail for plugins can be built here: $why"; exit 77
fi
root=$(cd "$(dirname "$0")/../.." && pwd)
json="$root/tests/e2e/json.awk"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
mkdir class

# The assignment: the spring under gravity (2-D and nonlinear, so methods
# differ), explicit Euler, dt 0.01, 300 steps.
cat > assignment.txt <<'A'
# stepwise assignment 1
# title: homework 3, explicit Euler on a hanging spring
# scene: spring
# param g: 9.81
# integrator: euler
# dt: 0.01
# steps: 300
A

# Students written from docs/trace-format.md: Euler, v-then-x Euler and
# Heun on the spring, printing with a given format. a = f/m, not f*(1/m).
cat > spring.awk <<'AWK'
function accel(px, py, qx, qy, A,    len, mag) {
    len = sqrt(px * px + py * py)
    mag = k * (len - rest) + c * (qx * px + qy * py) / len
    A[1] = -mag * px / len / m
    A[2] = -mag * py / len / m - g
}
function out(n, t,    len, e) {
    len = sqrt(X * X + Y * Y)
    e = m * (VX * VX + VY * VY) / 2 + k * (len - rest) * (len - rest) / 2 + m * g * Y
    printf "%d," fmt "," fmt "," fmt "," fmt "," fmt "," fmt "\n", n, t, X, Y, VX, VY, e
}
BEGIN {
    k = 10; m = 1; c = 0.5; rest = 1; g = gg + 0
    if (kk != "") k = kk + 0
    if (fmt == "") fmt = "%.17g"
    print "# stepwise trace 1"
    if (student != "") print "# student: " student
    print "# scene: spring"
    printf "# param g: %s\n# param k: %s\n", gg, k
    printf "# integrator: %s\n# dt: %s\n# steps: %d\n", label, dt, steps
    print "step,t,x0,y0,vx0,vy0,energy"
    X = 1.5; Y = 0; VX = 0; VY = 0; t = 0
    out(0, t)
    for (n = 1; n <= steps; n++) {
        accel(X, Y, VX, VY, A)
        if (method == "euler") {
            X += dt * VX; Y += dt * VY; VX += dt * A[1]; VY += dt * A[2]
        } else if (method == "vthenx") {
            VX += dt * A[1]; VY += dt * A[2]; X += dt * VX; Y += dt * VY
        } else { # heun
            X1 = X + dt * VX; Y1 = Y + dt * VY; VX1 = VX + dt * A[1]; VY1 = VY + dt * A[2]
            accel(X1, Y1, VX1, VY1, B)
            X += dt / 2 * (VX + VX1); Y += dt / 2 * (VY + VY1)
            VX += dt / 2 * (A[1] + B[1]); VY += dt / 2 * (A[2] + B[2])
        }
        t += dt
        out(n, t)
    }
}
AWK
student() { # file student method dt [k] [format] [label]
    awk -v student="$2" -v method="$3" -v dt="$4" -v kk="${5:-}" -v fmt="${6:-}" \
        -v label="${7:-$3}" -v gg=9.81 -v steps=300 -f spring.awk > "class/$1"
}
student correct.trace "Ada Lovelace" euler 0.01
student wrong-dt.trace "Blaise Pascal" euler 0.02
"$SW" record spring -i midpoint --set g=9.81 --dt 0.01 --steps 300 -o class/wrong-method.trace 2>/dev/null
student wrong-k.trace "Carl Gauss" euler 0.01 12
student lying-header.trace "Dana Scott" heun 0.01 "" "" euler
head -120 class/correct.trace > class/truncated.trace
# BOM, CRLF line endings, trailing blanks, a note, and the columns in another order
{ printf '\357\273\277# stepwise trace 1  \r\n# student: Emmy Noether\r\n# note: written on Windows\r\n'
  sed -n '3,8p' class/correct.trace | sed 's/$/\r/'
  printf 'step,t,energy,vy0,vx0,y0,x0\r\n'
  awk -F, 'NR > 9 { printf "%s,%s,%s,%s,%s,%s,%s \r\n", $1, $2, $7, $6, $5, $4, $3 }' class/correct.trace
} > class/bom-crlf.trace
student g-digits.trace "Felix Klein" euler 0.01 "" "%g"
student v-then-x.trace "Grace Hopper" vthenx 0.01 "" "" euler

# float32: a C student computing in single precision
cat > f32.c <<'C'
#include <math.h>
#include <stdio.h>
int main(void)
{
    float k = 10, m = 1, c = 0.5f, rest = 1, g = 9.81f, x = 1.5f, y = 0, vx = 0, vy = 0, dt = 0.01f, t = 0;
    printf("# stepwise trace 1\n# student: Hedy Lamarr\n# scene: spring\n# param g: 9.81\n");
    printf("# integrator: euler\n# dt: 0.01\n# steps: 300\nstep,t,x0,y0,vx0,vy0,energy\n");
    for (int n = 0; n <= 300; n++) {
        float len = sqrtf(x * x + y * y);
        float e = 0.5f * m * (vx * vx + vy * vy) + 0.5f * k * (len - rest) * (len - rest) + m * g * y;
        printf("%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", n, t, x, y, vx, vy, e);
        float mag = k * (len - rest) + c * (vx * x + vy * y) / len;
        float ax = -mag * x / len / m, ay = -mag * y / len / m - g;
        x += dt * vx; y += dt * vy; vx += dt * ax; vy += dt * ay; t += dt;
    }
    return 0;
}
C
cc -O2 -o f32 f32.c -lm && ./f32 > class/float32.trace || fail "cannot build the float32 student"

# Plugins: explicit Euler with a defect from the fourth step on.
plugin() { # file name 'defect'
    cat > "$1" <<C
#include <stepwise/integrator.h>
static int step(sw_ode *ode, double t, double *y, double h, double *work)
{
    sw_ode_eval(ode, t, y, work);
    if (t > 2.5 * h) { $3; }
    for (int i = 0; i < ode->dim; i++)
        y[i] += h * work[i];
    return 0;
}
static const sw_plugin info = { .abi = SW_PLUGIN_ABI, .name = "$2", .label = "Euler ($2)",
    .order = 1, .evals = 1, .work_vectors = 1, .step = step };
const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
C
}
plugin class/crashing.c crashing '*(volatile double *)0 = 1'
plugin overrun.c overrun 'work[ode->dim + 1] = 0'
cc -std=c11 -O2 -shared -fPIC -I"$root/include" -o class/overrun.so overrun.c || fail "cannot build overrun.so"
plugin class/looping.c looping 'for (volatile int spin = 1; spin;) { }'
cp assignment.txt class/README.txt   # not a submission: a row 'skipped' with the reason

# --- grade the class -----------------------------------------------------------
# (timeout: a guard against a hang, never a measure: it ends grade with 124)
timeout 600 "$SW" grade --assignment assignment.txt --csv grades.csv --results results.json class >out 2>err
rc=$?
cat out
[ "$rc" -eq 1 ] || fail "grade exited $rc, want 1: $(cat err)"
grep -q '^grading 13 submissions against assignment.txt (euler on spring, dt 0.01); 1 other entry not graded' out \
    || fail "heading: $(head -1 out)"
grep -q '^13 submissions: 2 passed, 11 failed' out || fail "totals: $(tail -1 out)"

# The gradebook: a strict CSV reader (quoted fields, doubled quotes); one
# record per submission, seven fields each.
cat > csv.awk <<'AWK'
# prints each record as FILE<TAB>VERDICT<TAB>STEP<TAB>MESSAGE<TAB>STUDENT; exits 1 when malformed
function field(    f, c) {
    if (substr(line, pos, 1) == "\"") {
        pos++; f = ""
        for (;;) {
            if (pos > length(line)) { bad = 1; return f }
            c = substr(line, pos, 1)
            if (c == "\"") {
                if (substr(line, pos + 1, 1) == "\"") { f = f "\""; pos += 2; continue }
                pos++; return f
            }
            f = f c; pos++
        }
    }
    c = index(substr(line, pos), ",")
    if (c == 0) { f = substr(line, pos); pos = length(line) + 1; return f }
    f = substr(line, pos, c - 1); pos += c - 1; return f
}
{
    sub(/\r$/, ""); line = $0; pos = 1; n = 0
    while (pos <= length(line) + 1) {
        F[++n] = field()
        if (substr(line, pos, 1) == ",") { pos++; continue }
        if (pos > length(line)) break
        bad = 1; break
    }
    if (bad || n != 11) { print "malformed line " NR ": " $0 > "/dev/stderr"; exit 1 }
    if (NR == 1) { if (line != "student,file,verdict,first_failing_step,message,id,remarks,similar,score,max,part") exit 1; next }
    printf "%s\t%s\t%s\t%s\t%s\t%s/%s\n", F[2], F[3], F[4], F[5], F[1], F[9], F[10]
}
AWK
awk -f csv.awk grades.csv > rows || fail "grades.csv is not well formed: $(cat grades.csv)"
[ "$(wc -l < rows)" -eq 14 ] || fail "grades.csv has $(wc -l < rows) records, want 14 (13 and README.txt)"
# row FILE VERDICT STEP REGEX: the gradebook says so
row() {
    r=$(grep "^class/$1	" rows) || fail "$1 is not in the gradebook"
    v=$(printf '%s' "$r" | cut -f2); s=$(printf '%s' "$r" | cut -f3); m=$(printf '%s' "$r" | cut -f4)
    [ "$v" = "$2" ] || fail "$1: verdict $v, want $2 ($m)"
    [ "$s" = "$3" ] || fail "$1: first failing step '$s', want '$3' ($m)"
    if [ -z "$4" ]; then
        [ -z "$m" ] || fail "$1: a pass with a message: $m"
    else
        printf '%s\n' "$m" | grep -Eq -- "$4" || fail "$1: message does not say '$4': $m"
    fi
}
row correct.trace pass "" ""
row bom-crlf.trace pass "" ""
row wrong-dt.trace fail 1 'dt differs; your numbers match euler with dt = 0.02, twice the assignment.s 0.01'
row wrong-method.trace fail 1 'integrator differs; your numbers match midpoint'
row wrong-k.trace fail 0 'param k differs; your numbers match k = 12 \(the assignment has k = 10\)'
row lying-header.trace fail 1 'your header says euler, but your numbers match heun'
row truncated.trace fail 111 'the trace ends after step 110 with 111 rows; the reference goes on to step 300'
row float32.trace fail 1 'single-precision floats'
row g-digits.trace fail 1 'at most 6 significant digits .*%g.*print with %\.17g'
row v-then-x.trace fail 1 'your numbers match symplectic-euler .*did you update v before x\?'
row crashing.c fail 4 'the plugin crashed with SIGSEGV .* at step 4'
row overrun.so fail 4 'the plugin wrote past its 1 work vector \(work\[5\].* at step 4 \(its sw_plugin asks for .work_vectors = 1; work\[5\] needs [0-9]*\)'
row looping.c limit 4 'the plugin used 2 s of its own CPU time without returning from its step at step 4'
row README.txt skipped "" 'not a submission: a \.txt file; traces end in \.trace or \.csv'
grep -q '^class/correct.trace	.*	Ada Lovelace	2/2$' rows || fail "the student's name is not in the gradebook"
grep -q '^class/bom-crlf.trace	.*	Emmy Noether	2/2$' rows || fail "the BOM student's name is lost"
grep -q '^class/overrun.so	.*	overrun	0/1$' rows || fail "a plugin is named after its file"

# results.json: Gradescope's fields, parsed strictly.
awk -f "$json" results.json > fields || fail "results.json is not JSON"
# Without '# points' lines a trace has two checks (header, values) and a
# plugin one: the two passes, and five traces whose header alone is right,
# 9 points over the 13 submissions (README.txt is none): the class's mean,
# out of the larger maximum (this homework takes either kind).
awk -F= '$1 == "score" { d = $2 - 9 / 13; exit !(d < 1e-12 && d > -1e-12) }' fields &&
    grep -qx 'max_score=2' fields || fail "score: $(grep score fields | head -2)"
[ "$(grep -c '^tests\[[0-9]*\]\.name=' fields)" -eq 14 ] || fail "results.json lacks 14 tests"
[ "$(grep -c '^tests\[[0-9]*\]\.output=' fields)" -eq 14 ] || fail "a test has no output"
grep -q '^tests\[[0-9]*\]\.name=Emmy Noether (class/bom-crlf.trace)$' fields || fail "test names: $(grep name= fields)"
grep -q '^tests\[[0-9]*\]\.extra_data\.notes=written on Windows$' fields || fail "the note is not carried"
grep -q '^tests\[[0-9]*\]\.output=FAIL: class/wrong-dt.trace' fields || fail "outputs: $(grep output= fields | head -2)"
echo ok
