#!/bin/sh
# Time under the student's control, at 80x24: play --until stops the run at
# t = 2.5 exactly, u runs straight there, ',' and ';' step back and '.'
# steps on to the same state; lesson 7 page 5 stops at t = 2.5 by itself;
# bad --until values are refused with exit 2.
. "$(dirname "$0")/lib.sh"

for bad in -1 0 x 2e6 ''; do
    out=$("$STEPWISE" play spring --until "$bad" 2>&1 >/dev/null); rc=$?
    [ $rc -eq 2 ] || fail "--until '$bad': exit $rc, expected 2"
    [ "$(printf '%s\n' "$out" | wc -l)" -eq 1 ] || fail "--until '$bad': not one line: $out"
    echo "$out" | grep -q "greater than 0 and at most" || fail "--until '$bad' does not say what is allowed: $out"
done

tmux_start 80 24
# The clock runs to the stop time and pauses there: t=2.5 on the status line.
type_cmd "$STEPWISE play spring --until 2.5"
wait_for 'stop t=2\.5' || fail "the status line does not show the stop time"
wait_for 'stopped at the stop time t = 2\.5' || fail "the run did not stop at t = 2.5"
screen | grep -Eq '^o spring +euler +dt=0\.02 +t=2\.5 +stop t=2\.5' || fail "the status line does not show t=2.5"
line=$(screen | grep -E '^o spring')
# One step back, fifty back, and fifty-one on again: the same status line.
keys ,
wait_for 'back to t = 2\.48, step 124 ' || fail ", did not step back one step"
keys '\;'
wait_for 'back to t = 1\.48, step 74 ' || fail "; did not step back fifty steps"
i=0
while [ $i -lt 51 ]; do keys .; i=$((i + 1)); done
wait_for '^o spring +euler +dt=0\.02 +t=2\.5 ' || fail ". did not step on to t = 2.5"
[ "$(screen | grep -E '^o spring')" = "$line" ] || fail "stepping on gave another state: $(screen | grep -E '^o spring') vs $line"
keys q
check_terminal_sane until

# u runs straight to the stop time.
type_cmd "$STEPWISE play spring -i rk4 --until 2.5 --speed 0.015625"
wait_for 'u runs straight there' || fail "play --until does not say what it does"
keys u
wait_for 'stopped at the stop time t = 2\.5' || fail "u did not run to the stop time"
screen | grep -Eq '^o spring +rk4 +dt=0\.02 +t=2\.5 ' || fail "u did not land on t=2.5"
keys q
check_terminal_sane u

# Lesson 7 page 5 stops at t = 2.5 by itself (its text says so).
mkdir -p "$WORK/state/stepwise"
printf '07-implicit.lesson 4\n' > "$WORK/state/stepwise/progress"
type_cmd "XDG_STATE_HOME=$WORK/state $STEPWISE lesson 7"
wait_for 'page 5/6' || fail "lesson 7 did not open on page 5"
read_down_to 'stops by itself at t = 2\.5' || fail "the page does not say it stops at 2.5"
wait_for 'stopped at the stop time t = 2\.5' || fail "page 5 did not stop at t = 2.5"
screen | grep -Eq '^o linear-implicit-euler +dt=0\.04 +t=2\.5 +stop t=2\.5' || fail "the status line does not show t=2.5"
keys q
check_terminal_sane lesson-until
echo ok
