#!/bin/sh
# `make test`: the unit suite ($1, Check) and the end-to-end suite (against
# the binary $2) side by side, the unit suite's output after the
# end-to-end lines; exits 1 when either failed. The tier (SW_TEST_QUICK)
# and Check's settings come from the environment make gives it.
unit=$1 bin=$2
dir=$(cd "$(dirname "$0")" && pwd)
log=$(mktemp) || exit 1
trap 'rm -f "$log"' EXIT
"$unit" >"$log" 2>&1 &
pid=$!
sh "$dir/e2e/run.sh" "$bin"
e2e=$?
wait "$pid"
rc=$?
echo "== the unit suite ($unit)"
cat "$log"
[ "$rc" -eq 0 ] || echo "unit: FAILED (status $rc, the log above)"
[ "$rc" -eq 0 ] && [ "$e2e" -eq 0 ]
