#!/bin/sh
# Every number explained where it appears, at 80x24 (issue 25, findings 2,
# 6, 7, 9, 10): the meter's labels and its one word, err in metres (m for
# velocities) started again by a dt change, the dt messages, lesson 1's page
# on the status lines, the hint in sight, a page done before shown fresh,
# pages that start paused, q saying how to continue, play projectile
# paused, fireworks' message said once.
. "$(dirname "$0")/lib.sh"

# play bounce: the region view and the meter agree (free motion maps by 1).
out=$("$STEPWISE" play bounce --view region --ascii --frames 5) || fail "play bounce --view region failed"
echo "$out" | grep -q '×1 per step: neutral' || fail "the region view does not say ×1 per step: $out"
echo "$out" | grep -Eq '0 modes|x0\.000000' && fail "the region view says 0 modes or x0: $out"
echo "$out" | grep -q 'growth ×1\.000000 per step: neutral' || fail "the meter does not say neutral: $out"

# screen_joined REGEX: the screen's lines joined by spaces (a message wrapped anywhere)
screen_joined() { screen | tr '\n' ' ' | grep -Eq -- "$1"; }

tmux_start 80 24
mkdir -p "$WORK/state/stepwise"
type_cmd "export XDG_STATE_HOME=$WORK/state"

# The meter reads as what it is; the word agrees with the number.
type_cmd "$STEPWISE play spring -i rk4 --dt 0.4"
wait_for 'stiffness·dt 1\.26 of limit 2\.94' || fail "the meter does not say stiffness·dt of limit"
wait_for '2\.83 undamped' || fail "the damped limit is shown without the undamped one"
wait_for 'growth ×0\.889082(/step| per step:) decays' || fail "the growth and its word are not shown"
screen | grep -q '|L|dt' && fail "the meter still says |L|dt"
# err is a position error in metres; m shows velocities; a dt change starts again.
wait_for 'err [0-9.e+-]+ m ' || fail "err has no unit"
keys m
wait_for 'v err [0-9.e+-]+ m/s' || fail "m did not switch err to the velocity error"
keys m
wait_for 'err [0-9.e+-]+ m ' || fail "m did not switch back"
wait_for 'dt=0\.4 +t=[1-9]' || fail "the run did not pass t = 1"
keys -
wait_for 'restarted at t = 0, paused; dt=0\.2: position error' || fail "a dt change does not restart or say position error"
keys q
check_terminal_sane meter

# Fireworks: the reason is said once, not nested in itself.
type_cmd "$STEPWISE play fireworks"
wait_for 'o fireworks' || fail "fireworks did not open"
keys -
wait_for 'no error to compare' || fail "fireworks' dt message is missing"
screen | grep -q 'no error to compare (no error' && fail "fireworks' message is duplicated: $(screen | tail -5)"
keys q
check_terminal_sane fireworks

# play projectile waits for space: its flight is not over before it is seen.
# The message names the scene's report time, not how long the motion lasts.
type_cmd "$STEPWISE play projectile"
wait_for 'paused: this scene reports at t = 2 s' || fail "play projectile does not start paused"
screen | grep -Eq 't=0\.000 ' || fail "the projectile moved before space"
keys q
check_terminal_sane projectile

# Lesson 1 pages 2 and 3 name the fields of both lines.
printf '01-flow-fields.lesson 1\n' > "$WORK/state/stepwise/progress"
type_cmd "$STEPWISE lesson 1"
wait_for 'The status line' || fail "lesson 1 has no page on the status line"
wait_for 'err … m +position error in metres' || fail "the page does not explain err"
keys Space
wait_for '✓ t >= 1' || fail "space did not run the page"
keys n
wait_for 'The stability meter' || fail "lesson 1 has no page on the meter"
wait_for 'stiffness·dt … of limit 2\.83' || fail "the page does not explain the meter"
keys q
wait_for_text 'lesson 1 continues at page 3 of [0-9]+: .*stepwise lesson 1' || fail "q did not say how to continue"
check_terminal_sane lesson1

# Lesson 2 page 3: doubling dt is not answered with "halve dt again".
printf '02-euler.lesson 2\n' > "$WORK/state/stepwise/progress"
type_cmd "$STEPWISE lesson 2"
wait_for 'Bigger steps, bigger errors' || fail "lesson 2 did not open on page 3"
keys +
wait_for 'dt=0\.2: position error' || fail "doubling dt gave no message"
screen | grep -q 'halve dt again' && fail "the message says halve dt after a doubling: $(screen | tail -5)"
keys q
check_terminal_sane lesson2

# Lesson 5 page 4: h shows the hint within the 24 rows.
printf '05-springs.lesson 3\n' > "$WORK/state/stepwise/progress"
type_cmd "$STEPWISE lesson 5"
wait_for 'Remedy 1: heavy damping' || fail "lesson 5 did not open on page 4"
keys h
wait_for 'Hint: ' || fail "h did not bring the hint into view at 80x24"
keys q
check_terminal_sane hint

# Lesson 9 page 1 starts paused: its goals wait for the student.
printf '09-adaptive.lesson 0\n' > "$WORK/state/stepwise/progress"
type_cmd "$STEPWISE lesson 9"
wait_for 'One step size does not fit all' || fail "lesson 9 did not open"
wait_for 'PAUSED' || fail "lesson 9 page 1 does not start paused"
screen | grep -q '✓ t >= 4' && fail "a goal was met before the page was read"
keys N
keys q
check_terminal_sane lesson9

# Lesson 8 page 2: the message speaks of what Verlet keeps, as the page does.
printf '08-energy-orbits.lesson 1\n' > "$WORK/state/stepwise/progress"
type_cmd "$STEPWISE lesson 8"
wait_for 'Verlet keeps the orbit' || fail "lesson 8 did not open on page 2"
keys 6
wait_for 'orbit +verlet' || fail "6 did not pick verlet"
keys -
wait_until 30 screen_joined 'Symplectic: +energy +and +path +kept, +the +error +is +phase' || fail "the message does not say the error is phase"
keys q
check_terminal_sane lesson8

# Lesson 7: the region view of page 3 does not carry over to page 4.
printf '07-implicit.lesson 2\n' > "$WORK/state/stepwise/progress"
type_cmd "$STEPWISE lesson 7"
wait_for "Backward Euler's region" || fail "lesson 7 did not open on page 3"
keys s
wait_for 'stability region of implicit-euler' || fail "s did not show the region"
keys +
wait_for '✓ dt >= 0\.08' || fail "+ did not meet the goal"
keys n
wait_for 'What it costs, what it does' || fail "n did not open page 4"
screen | grep -q 'stability region of' && fail "page 4 still shows page 3's region view"
keys q
check_terminal_sane clean-page

# A finished lesson reopens fresh: its pages are marked done before.
printf '02-euler.lesson 6\n' > "$WORK/state/stepwise/progress"
type_cmd "$STEPWISE lesson 2"
wait_for "Euler's method +\(page 1/" || fail "a finished lesson does not reopen on page 1"
wait_for 'earlier session' || fail "the page does not say it was done before"
screen | grep -q '✓ steps >= 5' && fail "the goal is ticked from last time"
keys q
wait_for_text 'next: .*stepwise lesson 3' || fail "q after a finished lesson does not name the next one"
check_terminal_sane reopened
echo ok
