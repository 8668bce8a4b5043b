#!/bin/sh
# `make run` opens the next unfinished lesson (issue 25, finding 10):
# `stepwise lesson --next` opens lesson 1 on a first run, the lesson after
# one finished (where it was left when half done), and the menu when every
# lesson is done; it takes no lesson name.
. "$(dirname "$0")/lib.sh"

"$STEPWISE" lesson --next 2 >/dev/null 2>&1
[ $? -eq 2 ] || fail "lesson --next 2 is not refused with status 2"
grep -q 'lesson --next$' "$ROOT/Makefile" || grep -q 'lesson --next *$' "$ROOT/Makefile" ||
    fail "make run does not open the next lesson"

pages() { grep -c '^--- ' "$ROOT/lessons/$1.lesson"; }
tmux_start 80 24
mkdir -p "$WORK/state/stepwise"
type_cmd "export XDG_STATE_HOME=$WORK/state"

# A first run: lesson 1, page 1.
type_cmd "$STEPWISE lesson --next"
wait_for 'page 1/' || fail "a first run does not open a lesson on page 1"
screen | grep -q 'Lesson 1\|flow' || fail "a first run does not open lesson 1"
keys q
wait_for 'lesson 1 continues' || fail "q after lesson 1 does not say how to continue"

# Lesson 1 finished, lesson 2 half done: lesson 2 where it was left.
printf '01-flow-fields.lesson %s\n02-euler.lesson 2\n' "$(pages 01-flow-fields)" > "$WORK/state/stepwise/progress"
type_cmd "$STEPWISE lesson --next"
wait_for "Euler's method +\(page 3/" || fail "lesson --next does not resume lesson 2 at page 3"
keys q
wait_for 'lesson 2 continues' || fail "q after lesson 2 does not say how to continue"

# Every lesson finished: the menu.
: > "$WORK/state/stepwise/progress"
for f in "$ROOT"/lessons/[0-9][0-9]-*.lesson; do
    b=$(basename "$f")
    printf '%s %s\n' "$b" "$(grep -c '^--- ' "$f")" >> "$WORK/state/stepwise/progress"
done
type_cmd "$STEPWISE lesson --next"
wait_for 'numerical integration of particle systems' || fail "with every lesson done, --next does not open the menu"
keys q
check_terminal_sane next
echo ok
