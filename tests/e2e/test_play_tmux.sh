#!/bin/sh
# play in a real terminal: the status line names the integrator and dt, keys
# change them, ? lists every key, and q and signals leave the shell sane.
. "$(dirname "$0")/lib.sh"
tmux_start

type_cmd "$STEPWISE play spring"
wait_for 'spring +euler +dt=0\.02 ' || fail "status line with 'euler' and 'dt=0.02' did not appear"
keys i
wait_for 'spring +symplectic-euler +dt=0\.02 ' || fail "i did not switch to the next integrator"
keys +
wait_for 'symplectic-euler +dt=0\.04 ' || fail "+ did not double dt"
keys -
wait_for 'symplectic-euler +dt=0\.02 ' || fail "- did not halve dt"
keys 5
wait_for 'spring +rk4 +dt=0\.02 ' || fail "5 did not pick rk4"
keys '?'
wait_for '\? (closes|next page) \(1/[0-9]+\)' || fail "? did not open the help"
for k in 'i  Tab' 'I  Shift-Tab' '1-9' '\+  -' 'halve dt' 'space' 'one step' 'reset to t = 0' \
         '\[  \]' 'compare' 'ghost' 'trails' 'graph of energy' 'Braille' 'parameter panel' \
         'recording a trace' 'work-precision' 'this help' 'quit'; do
    screen | grep -Eq -- "$k" || fail "help does not list '$k'"
done
# the help's further pages (120x40 holds all but the last lines), then closed
n=$(screen | sed -n 's/.*? [a-z ]* (1\/\([0-9]*\)).*/\1/p' | head -1)
while [ "${n:-1}" -gt 0 ]; do keys '?'; n=$((${n:-1} - 1)); done
wait_for 'i method' || fail "? did not close the help"
keys q
wait_for 'PROMPT\$ *$' || fail "q did not return to the shell"
check_terminal_sane q

for sig in TERM INT HUP; do
    type_cmd "$STEPWISE play orbit"
    wait_for 'orbit +verlet' || fail "play orbit did not start (before SIG$sig)"
    pid=$(app_pid)
    [ -n "$pid" ] || fail "no stepwise process"
    kill -"$sig" "$pid"
    wait_exit "SIG$sig"
    check_terminal_sane "$sig"
done

# Not a terminal: play refuses with a pointer to record and --ascii, exit 2.
out=$("$STEPWISE" play spring </dev/null 2>&1 >/dev/null); rc=$?
[ $rc -eq 2 ] || { echo "play without a terminal: exit $rc, expected 2"; exit 1; }
echo "$out" | grep -q "stepwise record" || { echo "message does not point to record: $out"; exit 1; }

# R records what is on screen; the trace passes stepwise check.
tmux_start
type_cmd "$STEPWISE play spring -i rk4"
wait_for 'spring +rk4' || fail "play spring did not start"
keys R
wait_for 'recording from t = 0' || fail "R did not start recording"
wait_for 'spring +rk4 .* steps [1-9]' || fail "the recording did not run"
keys R
wait_for 'recorded [0-9]+ steps to stepwise-spring-' || fail "R did not write the trace"
keys q
wait_for 'PROMPT\$ *$' || fail "q did not quit"
trace=$(ls "$WORK"/stepwise-spring-*.trace | head -1)
[ -f "$trace" ] || fail "no trace file in $WORK"
"$STEPWISE" check "$trace" >/dev/null || fail "the recorded trace does not pass stepwise check"
rm -f "$WORK"/stepwise-spring-*.trace

# A recording in progress when SIGTERM arrives is written whole.
type_cmd "$STEPWISE play orbit"
wait_for 'orbit +verlet' || fail "play orbit did not start"
keys R
wait_for 'recording from t = 0' || fail "R did not start recording"
wait_for 'orbit +verlet .* steps [1-9]' || fail "the recording did not run"
kill -TERM "$(app_pid)"
wait_for 'PROMPT\$' || fail "no prompt after SIGTERM while recording"
check_terminal_sane TERM-recording
trace=$(ls "$WORK"/stepwise-orbit-*.trace 2>/dev/null | head -1)
[ -f "$trace" ] || fail "the recording was lost on SIGTERM"
ls "$WORK" | grep -q '\.tmp' && fail "a temporary file was left behind"
"$STEPWISE" check "$trace" >/dev/null || fail "the trace written on SIGTERM does not pass check"
tail -c 1 "$trace" | od -c | grep -q '\\n' || fail "the trace does not end with a whole line"

# An error inside the live loop restores the terminal before its message.
type_cmd "STEPWISE_FORCE_ERROR=20 $STEPWISE play spring; echo EXIT=\$?"
wait_for 'EXIT=2' || fail "the forced error did not exit 2"
screen | grep -q 'stepwise: forced error after 20 frames' || fail "the error message is not on the restored screen"
check_terminal_sane forced-error
echo ok
