#!/bin/sh
# A student opens lesson 2, meets its first page's goals with real key
# presses, and turns to the next page; progress is saved and resumed.
. "$(dirname "$0")/lib.sh"
tmux_start
type_cmd "export XDG_STATE_HOME=$WORK/state"
type_cmd "$STEPWISE lesson 2"
wait_for "Euler's method +\(page 1/" || fail "lesson 2 did not open on page 1"
wait_for '✗ steps >= 5' || fail "the first goal is not shown as unmet"
keys n
wait_for 'goals are not met yet' || fail "n turned the page before the goals were met"
keys h
wait_for 'Hint: ' || fail "h did not show a hint"
for i in 1 2 3 4 5; do keys .; done
wait_for '✓ steps >= 5' || fail "five steps did not meet the goal"
wait_for 'press n for the next page' || fail "the page did not say it is complete"
keys n
wait_for "Euler's method +\(page 2/" || fail "n did not open page 2"
keys q
wait_for 'PROMPT\$ *$' || fail "q did not return to the shell"
grep -q '^02-euler.lesson 1$' "$WORK/state/stepwise/progress" || fail "progress was not saved"
# Resume: the lesson reopens at the first page not done.
type_cmd "$STEPWISE lesson 02-euler"
wait_for "Euler's method +\(page 2/" || fail "the lesson did not resume on page 2"
keys q
wait_for 'PROMPT\$ *$' || fail "q did not return to the shell"
check_terminal_sane lesson
# The menu lists lessons with progress.
type_cmd "$STEPWISE"
wait_for '1/[0-9]+ pages' || fail "the menu does not show lesson 2's progress"
screen | grep -q ' 1\. ' || fail "the menu does not number the lessons"
keys q
wait_for 'PROMPT\$ *$' || fail "q did not leave the menu"
echo ok
