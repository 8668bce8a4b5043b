#!/bin/sh
# Every scene under every integrator at an absurd step (dt = 50): a blow-up
# is a result, not a crash. record exits 0 and, when the run diverged, says
# so with the step and time on stderr and in the trace; the renderer draws
# the banner. Run by `make sanitize` too, where UBSan stops on any undefined
# behaviour (NaN and infinities reach the rasteriser and the status line).
. "$(dirname "$0")/lib.sh"
scenes=$("$STEPWISE" list scenes | awk '{ print $1 }')
methods=$("$STEPWISE" list integrators | awk '{ print $1 }')
runs=0 blown=0 fail=0
for sc in $scenes; do
    for m in $methods; do
        "$STEPWISE" record "$sc" -i "$m" --dt 50 --steps 40 --set n=4 -o t.trace 2>err.txt >/dev/null
        rc=$?
        refused="needs a system with masses\|ignore velocities\|one body alone in one central field"
        if [ $rc -eq 2 ] && grep -q "$refused\|has no parameter 'n'" err.txt; then
            # a flow scene refusing a second-order method, rkn refusing drag or damping,
            # dop853-lc refusing all but the orbit, or a scene without n: run without --set
            "$STEPWISE" record "$sc" -i "$m" --dt 50 --steps 40 -o t.trace 2>err.txt >/dev/null
            rc=$?
            grep -q "$refused" err.txt && continue
        fi
        runs=$((runs + 1))
        if [ $rc -ne 0 ]; then
            echo "FAIL: record $sc -i $m --dt 50: exit $rc"; sed 's/^/    /' err.txt; fail=$((fail + 1)); continue
        fi
        if grep -q "diverged\|blew up" err.txt; then
            blown=$((blown + 1))
            grep -Eq "step [0-9]+" err.txt && grep -Eq "t = [0-9.e+-]+" err.txt \
                || { echo "FAIL: $sc/$m: blow-up report lacks step and time: $(cat err.txt)"; fail=$((fail + 1)); }
            grep -q "^# diverged" t.trace || { echo "FAIL: $sc/$m: trace does not record the blow-up"; fail=$((fail + 1)); }
        fi
        "$STEPWISE" play "$sc" -i "$m" --dt 50 --frames 3 --ascii --size 80x24 >frame.txt 2>err.txt
        rc=$?
        # water at its own size refuses implicit methods (no coupled Jacobian), which it took at n = 4
        [ $rc -eq 2 ] && grep -q "needs a Jacobian this system does not provide" err.txt && continue
        if [ $rc -ne 0 ]; then
            echo "FAIL: play $sc -i $m --dt 50 --frames 3: exit $rc"; sed 's/^/    /' err.txt; fail=$((fail + 1))
        fi
    done
done
echo "blow-ups: $runs runs, $blown diverged and were reported, $fail failures"
[ $runs -ge 70 ] && [ $blown -ge 30 ] && [ $fail -eq 0 ]
