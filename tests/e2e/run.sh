#!/bin/sh
# Runs every end-to-end test (tests/e2e/test_*.sh) against the binary given
# as $1, SW_TEST_JOBS at a time (default: one more than the cores: many
# tests wait on a jail's limits or a terminal, and a core left idle
# while they wait is time lost), and prints
# "N passed, N failed"; exits 1 when any failed. Each test has its own
# scratch directory and tmux servers (lib.sh), so they run side by side;
# a line is printed as each ends, and the logs of the failed ones at the end.
bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
dir=$(cd "$(dirname "$0")" && pwd)
# The engine benchmark program (make bench), for the tests that run it.
if [ -n "${STEPWISE_BENCH:-}" ]; then
    STEPWISE_BENCH=$(cd "$(dirname "$STEPWISE_BENCH")" && pwd)/$(basename "$STEPWISE_BENCH")
    export STEPWISE_BENCH
fi
cores=$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1)
jobs=${SW_TEST_JOBS:-$((cores + 1))}
case $jobs in ''|*[!0-9]*|0) echo "e2e: SW_TEST_JOBS must be a whole number of 1 or more, not '$jobs'" >&2; exit 2 ;; esac
out=$(mktemp -d) || exit 1
trap 'rm -rf "$out"' EXIT
# The tests that take longest start first (a "# e2e: long" line says so),
# so that two cores are not left with one long test at the end.
{ grep -l '^# e2e: long' "$dir"/test_*.sh; grep -L '^# e2e: long' "$dir"/test_*.sh; } |
    tr '\n' '\0' | xargs -0 -n1 -P "$jobs" sh "$dir/run_one.sh" "$bin" "$out"
# A test that needs what this machine lacks (a jail for plugins) exits 77
# with one line saying why: counted as skipped, and the line shown.
pass=0 fail=0 skip=0 parts=0
for t in "$dir"/test_*.sh; do
    [ -e "$t" ] || continue
    name=$(basename "$t" .sh)
    log="$out/$name.log"
    rc=$(cat "$out/$name.rc" 2>/dev/null || echo lost)
    if [ "$rc" = 0 ]; then
        pass=$((pass + 1))
        # a part of a passing test left out here says so: shown, and counted
        while IFS= read -r line; do
            [ -n "$line" ] || continue
            parts=$((parts + 1)); echo "e2e: $name: part skipped (${line#skip: })"
        done <<END
$(grep '^skip: ' "$log")
END
    elif [ "$rc" = 77 ] && grep -q '^skip: ' "$log"; then
        skip=$((skip + 1))
    else
        fail=$((fail + 1)); echo "e2e: $name: FAILED (status $rc)"; sed 's/^/    /' "$log" 2>/dev/null
    fi
done
[ $parts -eq 0 ] || echo "e2e: $parts part(s) of passing tests skipped (above)"
echo "e2e: $pass passed, $fail failed, $skip skipped"
[ "$fail" -eq 0 ]
