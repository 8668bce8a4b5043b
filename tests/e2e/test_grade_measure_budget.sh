#!/bin/sh
# The measured order's reference run is the grader's work, and bounded:
# on a tree galaxy the tight reference run behind the probe's errors once
# took 44 min of CPU for one check (n = 20 000, two steps). Now the probe
# gives it a budget in evaluations (SW_MEASURE_REF_WORK), and past it the
# order falls back as any run without a truth does: here, on the spring,
# since the values match. (timeout: a guard against the hang, never a
# measure of speed.)
. "$(dirname "$0")/lib.sh"
needs_jail
sed 's/@NAME@/ada/' "$ROOT/tests/hostile/honest-rk4.c" > rk4.c
timeout 900 "$SW" check --plugin rk4.c --reference rk4 --scene galaxy --set n=5000 --set theta=0.5 --steps 2 \
    > out 2>&1
rc=$?
[ $rc -eq 0 ] || fail "check exited $rc: $(cat out)"
grep -q "order: claimed 4, measured [34]\.[0-9]* (on the undamped spring: the run checked cannot show an order" out \
    || fail "the order: $(cat out)"
echo "ok: the probe's reference run stays within its budget"
