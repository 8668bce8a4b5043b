#!/bin/sh
# The engine benchmark (`make bench`) with --quick: its tables run to the
# end (small sizes; the implicit methods against rk4; Barnes-Hut at n = 1e3, 1e4, allocating nothing); every
# hand-written baseline reproduces the generic step bit for bit; every
# default scene gets a frame-cost row; the heavy views (through the app) and
# the large-n memory rows (against the hand-fused loop) are there, within
# twice the hand-fused loop's resident memory and three times the state;
# --frame-view runs one heavy view alone.
# Timings are printed, never checked: they vary from machine to machine.
. "$(dirname "$0")/lib.sh"
BENCH=${STEPWISE_BENCH:?set STEPWISE_BENCH to the engine benchmark program (make bench)}
out=$("$BENCH" --quick 2>&1) || fail "exited $?: $out"
echo "$out" | grep -q '^throughput: ns per particle-step' || fail "no throughput table"
[ "$(echo "$out" | grep -c 'bitwise equal after 200 steps')" -eq 4 ] \
    || fail "baselines (euler, rk4 on chain and vortex) do not all match: $(echo "$out" | grep -E ' (euler|rk4) ')"
echo "$out" | grep -q 'differs by' && fail "a baseline differs"
echo "$out" | grep -q '^implicit steps: chain' || fail "no implicit-steps table"
for m in rk4 implicit-euler implicit-midpoint linear-implicit-euler; do
    echo "$out" | grep -Eq "^  $m +[0-9.e+-]+ +[0-9.]+ +\\[" || fail "no implicit-steps row for $m"
done
echo "$out" | grep -q '^frame cost' || fail "no frame-cost table"
for s in vortex river gyre projectile bounce fireworks spring stiff-spring chain orbit; do
    echo "$out" | grep -Eq "^  $s +[0-9]" || fail "no frame row for $s"
done
echo "$out" | grep -q '^peak memory: vortex n = 10000' || fail "no memory table"
echo "$out" | grep -Eq '^  rk4 +[0-9.]+ +[0-9.-]+ +3$' || fail "no memory row for rk4 (three work vectors)"
echo "$out" | grep -q 'failed' && fail "a memory probe failed: $out"
echo "$out" | grep -q '^frame cost of the heavy views' || fail "no heavy-view frame table"
for v in 'plain' 'compare+ghost' 'lanes+ghost'; do
    echo "$out" | grep -Fq "  vortex    10000 $v " || fail "no heavy-view row for vortex $v"
done
echo "$out" | grep -Eq '^  chain +10000 plain +verlet ' || fail "no heavy-view row for the chain"
# the keys' table (its milliseconds are timings: printed, not asserted); a
# sweep that never came in would say so on its row
echo "$out" | grep -q '^keys at n = 1e3 (--quick)' || fail "no keys table"
for s in chain vortex; do
    for k in w k c + - ';'; do
        echo "$out" | grep -Eq "^  $s +1000 [$k] +[0-9.]+ " || fail "no keys row for $s '$k'"
    done
done
echo "$out" | grep -q '(sweep not done)' && fail "a key's sweep never came in: $out"
echo "$out" | grep -q "^  (the baseline's vortex seeds equal the scene's)" || fail "baseline vortex seeds differ"
for s in chain vortex; do
    echo "$out" | grep -Eq "^  $s +100000 +[0-9.]+ +[0-9.]+ +[0-9.]+ +[0-9.]+ +[0-9.]+ +[0-9.]+ " \
        || fail "no million-particle row for $s"
    # resident memory, not time: within twice the hand-fused loop's (issue
    # 26) and three times the state (issue 41)
    echo "$out" | grep -Eq "^  $s +100000 .* yes +[0-9.]+ +[a-zA-Z]+$" \
        || fail "$s at n = 100000 is over twice the hand-fused memory"
    echo "$out" | grep -Eq "^  $s +100000 .* yes$" || fail "$s at n = 100000 is over three times its state"
done
echo "$out" | grep -q '^Barnes-Hut against the direct sum' || fail "no Barnes-Hut table"
echo "$out" | grep -q '^  allocations during the timed evaluations: 0$' || fail "the tree allocated: $out"
echo "$out" | grep -q '^water: one SPH evaluation' || fail "no water table"
# (its fitted exponent is a timing: printed, not asserted)
echo "$out" | grep -Eq '^  fitted exponent of n: [0-9.]+ \(a cell list' || fail "no water exponent: $out"
[ "$(echo "$out" | grep -c '^  allocations during the timed evaluations: 0$')" -ge 2 ] || fail "water allocated: $out"
# the count probe bench/instructions.sh runs under callgrind
for kind in generic base; do
    "$BENCH" --count-probe chain 20 rk4 3 $kind || fail "count probe ($kind) exited $?"
done
"$BENCH" --count-probe nosuch 20 rk4 3 generic && fail "count probe accepted an unknown scene"
"$BENCH" --tree-probe 2000 0.5 2 || fail "tree probe exited $?"
"$BENCH" --tree-probe 2000 0 2 2>/dev/null; [ $? -eq 2 ] || fail "tree probe took theta = 0"
# one heavy view alone (paired timings, callgrind): a row, and bad views refused
one=$("$BENCH" --frame-view vortex 1000 compare+ghost 1 2>&1) || fail "--frame-view exited $?: $one"
echo "$one" | grep -Fq "  vortex     1000 compare+ghost " || fail "no --frame-view row: $one"
"$BENCH" --frame-view vortex 1000 sideways 1 2>/dev/null; [ $? -eq 2 ] || fail "--frame-view took an unknown view"
one=$("$BENCH" --frame-view water 300 plain 0.1 0.0005 2>&1) || fail "--frame-view with a step exited $?: $one"
echo "$one" | grep -Eq '^  water +[0-9]+ plain ' || fail "no --frame-view row for water: $one"
"$BENCH" --frame-view water 300 plain 0.1 0 2>/dev/null; [ $? -eq 2 ] || fail "--frame-view took a step of 0"
"$BENCH" --frame-view nosuch 1000 plain 1 2>/dev/null; [ $? -eq 2 ] || fail "--frame-view took an unknown scene"
echo "engine benchmark: ok"
