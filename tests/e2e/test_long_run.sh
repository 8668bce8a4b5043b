#!/bin/sh
# Long runs keep memory flat: play at 1000x speed with trails, the graph and
# compare on (all bounded buffers) for over ten minutes of simulated time;
# RSS after warm-up and at the end must agree within 512 KiB.
. "$(dirname "$0")/lib.sh"
tmux_start
type_cmd "$STEPWISE play orbit --speed 1000"
wait_for 'orbit +verlet' || fail "play orbit did not start"
keys t e c
wait_for 'vs +rk4' || fail "compare did not open"
pid=$(app_pid)
[ -n "$pid" ] || fail "no stepwise process"
rss() { awk '/^VmRSS/ { print $2 }' "/proc/$pid/status"; }
sleep 3
before=$(rss)
sleep 9
after=$(rss)
t=$(screen | sed -nE 's/.*orbit +verlet +dt=0\.01 +t=([0-9.]+).*/\1/p' | head -1)
keys q
wait_for 'PROMPT\$ *$' || fail "q did not quit"
echo "RSS $before KiB -> $after KiB, simulated t = $t s"
awk -v t="$t" 'BEGIN { exit !(t >= 600) }' || fail "only $t s simulated (wanted >= 600)"
[ $((after - before)) -le 512 ] || fail "memory grew from $before to $after KiB"
