#!/bin/sh
# A grader without its plugin host (stepwise-plugin-host not built or not
# installed) stops before grading, in one line naming the program and how
# to get it, exit 2, nothing written: never a row of 'error 0/N' charged to
# every student, honest or not.
. "$(dirname "$0")/lib.sh"
cat > hw.txt <<'A'
# stepwise assignment 1
# kind: plugin
# integrator: euler
# scene: spring
# steps: 10
# dt: 0.01
# points x* y*: 1
A
mkdir class
cp "$ROOT/examples/euler_plugin.c" class/ada.c
STEPWISE_PLUGIN_HOST=$WORK/no-such-host "$SW" grade --assignment hw.txt --csv out.csv class > out 2> err
rc=$?
[ $rc -eq 2 ] || fail "exit $rc, not 2: $(cat out err)"
[ "$(wc -l < err)" -eq 1 ] || fail "not one line: $(cat err)"
grep -q "the plugin host (stepwise-plugin-host) is missing" err || fail "the message: $(cat err)"
[ -e out.csv ] && fail "out.csv was written"
grep -q "ada" out && fail "a student was graded: $(cat out)"
echo "ok: no plugin host, no grading"
