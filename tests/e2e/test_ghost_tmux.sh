#!/bin/sh
# The ghost's gap visible at 80x24: lesson 3 page 3 ("Euler's ball lands
# off the mark by about 0.44 m") stops at t = 2, where ball and ghost share
# a cell: the cell shows '&' and the picture writes the gap, 0.44 m.
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
# the picture is the left half: the gap with its unit, and '&' where both are
screen | cut -c1-40 | grep -Eq '(gap to )?ghost 0\.44 m' || fail "the gap 0.44 m is not written beside the ball"
screen | cut -c1-40 | grep -q '&' || fail "no '&' where the ball and the ghost share a cell"
keys q
check_terminal_sane ghost
echo ok
