#!/bin/sh
# try's report at 80 columns (student pass: a long line split words in
# two at the terminal's edge): each line too wide goes on under its own
# text, broken between words, and no screen line is wider than the
# terminal. Redirected to a file the report is not wrapped (scripts and
# the other tests read whole lines).
. "$(dirname "$0")/lib.sh"
needs_jail
# a float for a double: a warning, and values that differ in the ninth digit
sed 's/double \*dydt = work; \/\* work vector 0 \*\//double *dydt = work; float hf = h; (void)hf;/' \
    "$ROOT/examples/euler_plugin.c" > warns.c
grep -q "float hf" warns.c || fail "the fixture was not made"
tmux_start 80 24
type_cmd "cd '$PWD' && STEPWISE_INCLUDE='$ROOT/include' $STEPWISE try warns.c --no-play; echo try-done"
wait_for '^try-done' 120 || fail "try did not finish: $(screen)"
screen | awk 'length > 80 { bad = 1 } END { exit bad }' || fail "a line wider than 80: $(screen)"
# the warning's line goes on under its text, at column 14
screen | grep -q '^  build      1 compiler warning' || fail "no build line: $(screen)"
screen | grep -Eq '^             [^ ]' || fail "no line hangs under its text: $(screen)"
# no word cut at the edge: every screen line ends on a whole word (the
# next line, when it goes on, starts with a blank)
screen | awk '/^warns.c: / { on = 1 } on && prev != "" && length(prev) == 80 && $0 !~ /^ / { bad = 1 }
              { prev = on ? $0 : "" } END { exit bad }' ||
    fail "a word split at the edge: $(screen)"
# to a file, whole lines
STEPWISE_INCLUDE="$ROOT/include" "$STEPWISE" try warns.c --no-play > out.txt 2>&1
grep -q "^  build      1 compiler warning (often a bug: read them); the first: warns.c:.*Wfloat-conversion" out.txt ||
    fail "the report to a file: $(cat out.txt)"
exit 0
