#!/bin/sh
# The engine benchmark's peer comparison (`make bench`), quick: every
# candidate's reported error is within its target, and so is the largest
# error of the runs at the tighter settings below its own (the setting
# holds, not just reaches, the target: bench_peer.c), stepwise's methods all
# reach it, the reference is cross-checked far below the target (the
# chain's long double reference estimates its own error at most 1e-11), and, when
# the benchmark was built with GSL, the side-by-side table has a row per
# problem with a time ratio, an evaluations ratio and the derivative's
# floor (a number, or - for steps fused with the field). Timings are
# printed, never checked.
set -u
BENCH=${STEPWISE_BENCH:?set STEPWISE_BENCH to the engine benchmark program (make bench)}
fail() { echo "FAIL: $*"; exit 1; }
out=$("$BENCH" --quick --peer 2>&1) || fail "exited $?: $out"
echo "$out" | grep -q '^peer comparison' || fail "no peer comparison: $out"
# candidate rows: library method setting error evals time below
rows=$(echo "$out" | awk '($1 == "stepwise" || $1 == "GSL") && $2 != "engine"')
[ -n "$rows" ] || fail "no candidate rows: $out"
echo "$rows" | awk '$NF != "reached" && $NF != "held" && $NF != "refused" && (NF != 8 || $(NF-3) + 0 > 1e-6 || $NF + 0 > 1e-6 || $NF + 0 <= 0) { bad = 1 } END { exit bad }' \
    || fail "a candidate's error, or the largest below its setting, is not in (0, 1e-6]: $rows"
for m in rk4 rk45 dop853; do
    [ "$(echo "$rows" | grep -c "^  stepwise  $m ")" -eq 2 ] || fail "stepwise $m not reached on both problems: $rows"
done
# (a number: "nan" + 0 is 0 to awk, and a cross-check that blew up would pass)
num='/^[0-9]+(\.[0-9]+)?(e[-+]?[0-9]+)?$/'
echo "$out" | grep -E 'differs from it by' | awk "{ if (\$NF !~ $num || \$NF + 0 > 1e-9) exit 1 }" \
    || fail "a reference is not within 1e-9 of its cross-check: $out"
# the chain's reference is the long double run, its own error estimated
# at most 1e-11 (bench_chain_ref.c)
echo "$out" | grep -q 'chain n = [0-9]*, T = [0-9.]*, state [0-9]*: reference RK4 in long double' \
    || fail "the chain's reference is not the long double run: $out"
echo "$out" | grep -E "reference's own error, estimated" | tr -d ')' | awk "{ if (\$NF !~ $num || \$NF + 0 > 1e-11 || \$NF + 0 <= 0) exit 1 }" \
    || fail "the chain reference's error estimate is not in (0, 1e-11]: $out"
if echo "$out" | grep -q 'against GSL'; then
    table=$(echo "$out" | grep '^  | [a-z]* n = [0-9]*, error 1e-06 | ')
    [ "$(echo "$table" | grep -c .)" -eq 2 ] || fail "no side-by-side rows: $out"
    echo "$table" | awk -F'|' 'NF != 9 || $7 !~ /^ ([0-9]+\.[0-9][0-9]|-) $/ { bad = 1 } END { exit bad }' \
        || fail "a side-by-side row without its columns (ratio, evaluations, floor, verdict): $table"
fi
echo "bench peer: ok"
