#!/bin/sh
# Runs every end-to-end test (tests/e2e/test_*.sh) against the binary given
# as $1 and prints "N passed, N failed"; exits 1 when any failed.
bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
dir=$(cd "$(dirname "$0")" && pwd)
# The engine benchmark program (make bench), for the tests that run it.
if [ -n "${STEPWISE_BENCH:-}" ]; then
    STEPWISE_BENCH=$(cd "$(dirname "$STEPWISE_BENCH")" && pwd)/$(basename "$STEPWISE_BENCH")
    export STEPWISE_BENCH
fi
# A test that needs what this machine lacks (a jail for plugins) exits 77
# with one line saying why: counted as skipped, and the line shown.
pass=0 fail=0 skip=0 parts=0
for t in "$dir"/test_*.sh; do
    [ -e "$t" ] || continue
    name=$(basename "$t" .sh)
    log=$(mktemp)
    t0=$(date +%s)
    STEPWISE="$bin" sh "$t" >"$log" 2>&1
    rc=$?
    took=$(( $(date +%s) - t0 )) # for the developer reading the log; never judged
    if [ $rc -eq 0 ]; then
        pass=$((pass + 1)); echo "e2e: $name: ok ($took s)"
        # a part of a passing test left out here says so: shown, and counted
        while IFS= read -r line; do
            [ -n "$line" ] || continue
            parts=$((parts + 1)); echo "e2e: $name: part skipped (${line#skip: })"
        done <<EOF
$(grep '^skip: ' "$log")
EOF
    elif [ $rc -eq 77 ] && grep -q '^skip: ' "$log"; then
        skip=$((skip + 1)); echo "e2e: $name: skipped ($(grep -m1 '^skip: ' "$log" | cut -c7-))"
    else
        fail=$((fail + 1)); echo "e2e: $name: FAILED"; sed 's/^/    /' "$log"
    fi
    rm -f "$log"
done
[ $parts -eq 0 ] || echo "e2e: $parts part(s) of passing tests skipped (above)"
echo "e2e: $pass passed, $fail failed, $skip skipped"
[ "$fail" -eq 0 ]
