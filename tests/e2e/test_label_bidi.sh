#!/bin/sh
# A plugin's label is its author's text. One whose label holds Unicode's
# invisible formatting — a right-to-left override (U+202E) that shows
# "drowssap" as "password", an isolate (U+2066..U+2069), a zero-width
# space (U+200B) — is loaded, and every command that shows the label shows
# those characters escaped as \xNN (util/escape.h), never raw: try, the
# live view's message, and the refusal of a label that is also refused for
# a control character. The commands that show only the name (check, record,
# bench, stability) print none of its bytes either.
. "$(dirname "$0")/lib.sh"
needs_jail

# U+202E, U+202C, U+2066, U+2069, U+200B as UTF-8 (printf's octal escapes:
# POSIX sh has no \u).
RLO=$(printf '\342\200\256') PDF=$(printf '\342\200\254') LRI=$(printf '\342\201\246')
PDI=$(printf '\342\201\251') ZWSP=$(printf '\342\200\213')
LABEL="RK4 ${RLO}drowssap${PDF} ${LRI}iso${PDI} zero${ZWSP}width"
SHOWN='RK4 \xe2\x80\xaedrowssap\xe2\x80\xac \xe2\x81\xa6iso\xe2\x81\xa9 zero\xe2\x80\x8bwidth'

# The example plugin with that label and a name of its own; the label goes
# into the C source as \u escapes, as a student would type it.
sed -e 's|"explicit Euler (student plugin)"|"RK4 \\u202Edrowssap\\u202C \\u2066iso\\u2069 zero\\u200Bwidth"|' \
    -e 's|"student-euler"|"bidi-euler"|' "$ROOT/examples/euler_plugin.c" > bidi.c
grep -q 'u202E' bidi.c || fail "the label was not put into bidi.c"
cc -std=c11 -O2 -Wall -Wextra -Werror -shared -fPIC -I"$ROOT/include" -o bidi.so bidi.c 2>cc.err \
    || fail "cannot build the plugin: $(cat cc.err)"

# raw FILE...: whether any of the five characters appears raw in the files.
raw() {
    for c in "$RLO" "$PDF" "$LRI" "$PDI" "$ZWSP"; do
        LC_ALL=C grep -qF -- "$c" "$@" && return 0
    done
    return 1
}
shown() { LC_ALL=C grep -qF -- "$SHOWN" "$@"; }

# the source holds the label raw once compiled: the check of raw() itself
printf '%s\n' "$LABEL" > label.txt
raw label.txt || fail "raw() does not find the characters"

# try: the first line names the plugin and its label
"$STEPWISE" try bidi.c --no-play > out 2> err; rc=$?
[ "$rc" -eq 0 ] || fail "try: exit $rc: $(cat out err)"
raw out err && fail "try printed the label raw: $(od -c out | head)"
shown out || fail "try does not show the label escaped: $(head -1 out)"
grep -q '^bidi\.c: bidi-euler (RK4 ' out || fail "try's first line: $(head -1 out)"

# check, record, bench, stability: the name only, nothing of the label
"$STEPWISE" check --plugin ./bidi.so --reference euler --scene spring > out 2> err; rc=$?
[ "$rc" -eq 0 ] || fail "check --plugin: exit $rc: $(cat out err)"
grep -q 'PASS: plugin bidi-euler' out || fail "check --plugin: $(cat out)"
raw out err && fail "check --plugin printed the label raw"
"$STEPWISE" check --json --plugin ./bidi.so --reference euler --scene spring > out 2> err
raw out err && fail "check --json printed the label raw"
"$STEPWISE" record spring --plugin ./bidi.so -i bidi-euler --steps 20 -o bidi.trace > out 2> err \
    || fail "record --plugin: $(cat err)"
raw out err bidi.trace && fail "record put the label raw in its output or the trace"
"$STEPWISE" check bidi.trace --plugin ./bidi.so > out 2> err || fail "check of the trace: $(cat out err)"
raw out err && fail "check of the trace printed the label raw"
"$STEPWISE" stability spring --plugin ./bidi.so --integrators bidi-euler > out 2> err \
    || fail "stability --plugin: $(cat out err)"
raw out err && fail "stability printed the label raw"
"$STEPWISE" play spring --plugin ./bidi.so -i bidi-euler --ascii --frames 2 > out 2> err \
    || fail "play --ascii: $(cat err)"
raw out err && fail "play --ascii printed the label raw"
grep -q 'spring  bidi-euler' out || fail "play --ascii does not name the plugin: $(head -24 out)"

# a label refused for its control character: the refusal shows it escaped,
# the invisible formatting with it
sed -e 's|"explicit Euler (student plugin)"|"\\u202Eok\\u200B\\033[2J"|' \
    -e 's|"student-euler"|"bidi-refused"|' "$ROOT/examples/euler_plugin.c" > refused.c
cc -std=c11 -O2 -shared -fPIC -I"$ROOT/include" -o refused.so refused.c 2>cc.err \
    || fail "cannot build refused.so: $(cat cc.err)"
"$STEPWISE" check --plugin ./refused.so --reference euler --scene spring > out 2> err; rc=$?
[ "$rc" -eq 2 ] || fail "a label with ESC was not refused: exit $rc: $(cat out err)"
grep -qF "the label '"'\xe2\x80\xaeok\xe2\x80\x8b\x1b[2J'"' is not allowed" err \
    || fail "the refusal does not show the label escaped: $(cat err)"
raw out err && fail "the refusal printed the label raw"
LC_ALL=C grep -q "$(printf '\033')" out err && fail "the refusal printed ESC raw"

# the live view: switching to the plugin names it with its label, escaped
# (and the screen has none of its characters raw)
tmux_start 160 30
type_cmd "$STEPWISE play spring --plugin ./bidi.so"
wait_for 'spring +euler +dt=' || fail "play did not start"
keys I   # the previous integrator, from the first: the last, the plugin
wait_for 'spring +bidi-euler +dt=' || fail "I did not switch to the plugin"
wait_for 'integrator: bidi-euler \(RK4 \\xe2\\x80\\xaedrowssap' \
    || fail "the live view does not show the label escaped"
screen > screen.txt
raw screen.txt && fail "the live view shows the label raw"
shown screen.txt || fail "the live view's message is not the whole escaped label: $(grep integrator screen.txt)"
keys q
wait_exit q
echo ok
