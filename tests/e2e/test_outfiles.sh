#!/bin/sh
# Output files the Unix way (docs/robustness.md, "Files, output and
# interruption"): devices stay devices, links stay links, modes are kept,
# long names work, FIFOs are streamed, and an interrupted bench leaves no
# file behind.
. "$(dirname "$0")/lib.sh"
kind() { stat -c %F "$1"; }

# A device is written, not replaced (as root a rename would replace it):
# /dev/zero takes writes like /dev/null (which another program's bug on a
# shared machine may have replaced already).
"$SW" record spring --steps 5 -o /dev/zero 2>err || fail "record -o /dev/zero: $(cat err)"
[ "$(kind /dev/zero)" = "character special file" ] || fail "/dev/zero is now a $(kind /dev/zero)"

# A symbolic link is followed: the link stays, its target gets the trace.
ln -s real.trace link.trace
"$SW" record spring --steps 5 -o link.trace 2>err || fail "record -o link.trace: $(cat err)"
[ -L link.trace ] || fail "link.trace is no longer a link"
grep -q '^# stepwise trace 1' real.trace || fail "the link's target did not get the trace"

# An existing file keeps its mode.
echo old > private.trace
chmod 600 private.trace
"$SW" record spring --steps 5 -o private.trace 2>err || fail "record -o private.trace: $(cat err)"
[ "$(stat -c %a private.trace)" = 600 ] || fail "private.trace is now mode $(stat -c %a private.trace)"
grep -q '^5,' private.trace || fail "private.trace was not rewritten"

# A 251-byte name: the temporary's name must still fit in 255 bytes.
long=$(printf '%0251d' 0)
"$SW" record spring --steps 5 -o "$long" 2>err || fail "a 251-byte name: $(cat err)"
[ -s "$long" ] || fail "no file under the 251-byte name"

# A FIFO is streamed to its reader, never renamed over.
mkfifo pipe
cat pipe > got &
reader=$!
"$SW" record spring --steps 50 -o pipe 2>err || fail "record -o pipe: $(cat err)"
wait $reader
[ -p pipe ] || fail "the FIFO was replaced"
grep -q '^50,' got || fail "the reader did not get the whole trace"

# Nothing else was left behind (no temporaries).
left=$(ls | grep -v -e '^err$' -e '^got$' -e '^pipe$' -e '^link.trace$' -e '^real.trace$' \
       -e '^private.trace$' -e "^$long\$")
[ -z "$left" ] || fail "left behind: $left"

# bench --csv --svg stopped during its sweep leaves no file: Ctrl-C as a
# student types it (tmux), SIGTERM and SIGHUP as a system sends them. The
# sweep is bench's whole default one (tens of seconds): a signal a second
# in lands within it however fast the machine.
for sig in TERM HUP; do
    mkdir "b-$sig"
    "$SW" bench --csv "b-$sig/p.csv" --svg "b-$sig/p.svg" >/dev/null 2>&1 &
    pid=$!
    sleep 1
    kill -s "$sig" "$pid" 2>/dev/null || fail "bench finished within a second: the test needs a longer sweep"
    wait "$pid"
    rc=$?
    [ "$rc" -gt 128 ] || fail "bench after SIG$sig: exit $rc, expected death by the signal"
    [ -z "$(ls -A "b-$sig")" ] || fail "SIG$sig during bench left: $(ls -A "b-$sig")"
done
mkdir b-INT
tmux_start
type_cmd "$SW bench --csv b-INT/p.csv --svg b-INT/p.svg >/dev/null"
sleep 1
keys C-c
wait_exit "Ctrl-C during bench"
type_cmd 'echo BENCH-EXIT-$?'
wait_for '^BENCH-EXIT-130' || fail "Ctrl-C did not stop bench with status 130"
[ -z "$(ls -A b-INT)" ] || fail "Ctrl-C during bench left: $(ls -A b-INT)"
echo "output files: ok"
