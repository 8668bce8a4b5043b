#!/bin/sh
# Long runs keep memory flat: play at 1000x speed with trails, the graph and
# compare on (all bounded buffers) for over ten minutes of simulated time;
# RSS after warm-up and ten simulated minutes later must agree within 512 KiB.
. "$(dirname "$0")/lib.sh"
tmux_start
type_cmd "$STEPWISE play orbit --speed 1000"
wait_for 'orbit +verlet' || fail "play orbit did not start"
keys t e c
wait_for 'vs +rk4' || fail "compare did not open"
keys ' ' # (compare restarts every run at t = 0, paused)
wait_for 'running|slow' || fail "space did not run the compare"
pid=$(app_pid)
[ -n "$pid" ] || fail "no stepwise process"
rss() { awk '/^VmRSS/ { print $2 }' "/proc/$pid/status"; }
# Simulated time on the main status line; a loaded machine gets there in
# slow motion, so the test waits for simulated time, not wall time.
sim_t() { screen | sed -nE 's/.*orbit +verlet +dt=0\.01 +t=([0-9.]+).*/\1/p' | head -1; }
sim_past() { awk -v t="$(sim_t)" -v w="$1" 'BEGIN { exit !(t + 0 >= w) }'; }
# Warm: past t = 100 s, and the first frames' allocations done (RSS the same
# over a second). Then ten more minutes of simulated time, and at least 9 s
# of frames, must not grow it.
steady() { r=$(rss); sleep 1; [ "$r" = "$(rss)" ]; }
wait_until 300 sim_past 100 || fail "the orbit did not reach t = 100 s (warm-up): t = $(sim_t)"
wait_until 120 steady || fail "memory kept growing during the warm-up: $(rss) KiB"
before=$(rss) t0=$(sim_t) wall0=$(date +%s)
later() { sim_past "$(awk -v t="$t0" 'BEGIN { print t + 600 }')" && [ $(( $(date +%s) - wall0 )) -ge 9 ]; }
wait_until 600 later || fail "the orbit did not run 600 s more from t = $t0: t = $(sim_t)"
after=$(rss)
t=$(sim_t)
keys q
wait_for 'PROMPT\$ *$' || fail "q did not quit"
echo "RSS $before KiB -> $after KiB, simulated t = $t s"
[ $((after - before)) -le 512 ] || fail "memory grew from $before to $after KiB"
