#!/bin/sh
# The lesson pane as a student sees it (issue 37), at 80x24 and 120x40:
# the lesson's title with its page and the page's title stay on the top
# rows while Down scrolls the text; a question folded under the text opens
# within a few presses; o gives the text the whole width and o again the
# picture; the p panel stays over the picture, the goals in sight.
. "$(dirname "$0")/lib.sh"
mkdir -p "$WORK/state/stepwise"
for size in "80 24" "120 40"; do
    set -- $size
    cols=$1
    tmux_start "$1" "$2"
    printf '05-springs.lesson 3\n' > "$WORK/state/stepwise/progress"
    type_cmd "XDG_STATE_HOME=$WORK/state STEPWISE_LESSONS=$ROOT/lessons $STEPWISE lesson 5"
    wait_for 'Springs, damping, stiffness +\(page 4/7\)' || fail "${cols}: lesson 5 did not open on page 4"
    presses=0
    while ! screen_has 'B\) Too much damping' && [ $presses -lt 8 ]; do
        keys Down; presses=$((presses + 1)); sleep 0.3
        screen | sed -n 1p | grep -Eq 'Springs, damping, stiffness +\(page 4/7\)' ||
            fail "${cols}: the lesson's title and page left the top row after $presses Down"
        screen | sed -n 2p | grep -q 'Remedy 1: heavy damping' ||
            fail "${cols}: the page's title left the second row after $presses Down"
    done
    echo "${cols} columns: the question's answers after $presses Down, the titles on top throughout"
    [ $presses -le 4 ] || fail "${cols}: $presses presses of Down to the question"
    # o: the text full width (the title at column 2), o again: the picture back
    keys o
    wait_for 'reading mode' || fail "${cols}: o did not say the reading mode"
    col=$(screen | sed -n 1p | awk '{ print index($0, "Springs") }')
    [ "$col" -eq 2 ] || fail "${cols}: in the reading mode the text starts at column $col"
    keys o
    wait_for 'side by side' || fail "${cols}: o again did not bring the picture back"
    col=$(screen | sed -n 1p | awk '{ print index($0, "Springs") }')
    [ "$col" -gt 30 ] || fail "${cols}: after o again the text starts at column $col"
    # p: the panel over the picture, the goals beside it
    keys p
    wait_for 'Left/Right change' || fail "${cols}: p did not open the panel"
    screen_has 'Goals:' || fail "${cols}: the panel hides the goals"
    screen_has 't >= 0\.5' || fail "${cols}: the panel hides the goal t >= 0.5"
    keys Escape q
    check_terminal_sane "pane-$cols"
done
echo ok
