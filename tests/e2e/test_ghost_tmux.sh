#!/bin/sh
# The ghost's gap visible at 80x24: lesson 3 page 3 ("Euler's ball lands
# off the mark by about 0.44 m") stops at t = 2 with the camera close on
# the ball: ball (o) and ghost (') in cells of their own, and the picture
# writes the gap, 0.44 m. (Where they share a cell it shows '&':
# tests/check_gap.c.)
. "$(dirname "$0")/lib.sh"
tmux_start 80 24
mkdir -p "$WORK/state/stepwise"
printf '03-particles-with-mass.lesson 2\n' > "$WORK/state/stepwise/progress"
type_cmd "XDG_STATE_HOME=$WORK/state $STEPWISE lesson 3"
wait_for 'Particles with mass +\(page 3/6\)' || fail "lesson 3 did not open on page 3"
keys g
wait_for "ghost on: the exact solution, drawn '" || fail "g did not say how the ghost is drawn"
keys ' '
wait_for 'stopped at the stop time t = 2 ' || fail "the run did not stop at t = 2"
screen | grep -Eq '^o projectile +euler +dt=0\.05 +t=2 ' || fail "the status line does not show t=2"
# the picture is the left half: the gap with its unit, ball and ghost apart
pic=$(screen | sed -n '3,18p' | cut -c1-40)
echo "$pic" | grep -Eq '((gap to )?ghost )?0\.44 m' || fail "the gap 0.44 m is not written beside the ball"
echo "$pic" | grep -q 'o' || fail "the ball is not drawn: $pic"
echo "$pic" | grep -q "'" || fail "the ghost is not drawn apart from the ball: $pic"
keys q
check_terminal_sane ghost
echo ok
