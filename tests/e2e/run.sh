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
pass=0 fail=0
for t in "$dir"/test_*.sh; do
    [ -e "$t" ] || continue
    name=$(basename "$t" .sh)
    log=$(mktemp)
    if STEPWISE="$bin" sh "$t" >"$log" 2>&1; then
        pass=$((pass + 1)); echo "e2e: $name: ok"
    else
        fail=$((fail + 1)); echo "e2e: $name: FAILED"; sed 's/^/    /' "$log"
    fi
    rm -f "$log"
done
echo "e2e: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
