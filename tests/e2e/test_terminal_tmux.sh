#!/bin/sh
# The terminal in a plain sh (dash restores nothing for us): fatal signals
# leave it sane and off the alternate screen; an unknown or missing TERM is
# named (and leaks nothing under the sanitizer); --braille draws Braille in
# the live UI and falls back to ASCII with a note under LC_ALL=C; the
# lesson menu scrolls through 60 lessons and shows a broken lesson's error
# without leaving; wide characters take two cells in the lesson pane.
. "$(dirname "$0")/lib.sh"
tmux_start
type_cmd "ulimit -c 0"

alt_screen() { tmux display -p -t "$SESSION" '#{alternate_on}'; }

# ---- fatal signals: the terminal is restored, then the process dies of the signal
for pair in SEGV:11 ABRT:6 QUIT:3 BUS:7 FPE:8; do
    sig=${pair%:*} num=${pair#*:}
    keys "clear" Enter
    # a sanitizer build reports a SEGV/BUS/FPE and exits 1 after the restore;
    # without its handlers the process dies of the signal, as checked here
    type_cmd "ASAN_OPTIONS=handle_segv=0:handle_sigbus=0:handle_sigfpe=0:handle_abort=0 $STEPWISE play orbit; echo SIG$sig-EXIT=\$?"
    wait_for 'orbit +verlet' || fail "play orbit did not start (before SIG$sig)"
    pid=$(app_pid)
    [ -n "$pid" ] || fail "no stepwise process (SIG$sig)"
    kill -"$sig" "$pid"
    wait_for "SIG$sig-EXIT=$((128 + num))" || fail "SIG$sig: stepwise did not die of the signal (exit $((128 + num)))"
    [ "$(alt_screen)" = 0 ] || fail "SIG$sig left the alternate screen on"
    check_terminal_sane "$sig"
done

# ---- TERM: unknown and unset are named; exit 2, nothing leaked
keys "clear" Enter
type_cmd "TERM=frob-term $STEPWISE play spring; echo FROB-EXIT=\$?"
wait_for 'FROB-EXIT=[0-9]' || fail "TERM=frob-term: no exit"
screen | grep -q "unknown terminal type TERM='frob-term'" || fail "an unknown TERM is not named"
screen | grep -q 'FROB-EXIT=2' || fail "an unknown TERM: exit status is not 2"
screen | grep -q 'Sanitizer' && fail "an unknown TERM: the sanitizer complained"
keys "clear" Enter
type_cmd "env -u TERM $STEPWISE lesson 1; echo UNSET-EXIT=\$?"
wait_for 'UNSET-EXIT=[0-9]' || fail "TERM unset: no exit"
screen | grep -q 'TERM is not set' || fail "an unset TERM is not said"
screen | grep -q 'UNSET-EXIT=2' || fail "TERM unset: exit status is not 2"
screen | grep -q 'Sanitizer' && fail "TERM unset: the sanitizer complained"

# ---- Braille: drawn with --braille; ASCII and a note in the C locale
braille_cells() { screen | LC_ALL=C grep -c "$(printf '\342[\240-\243]')"; }
keys "clear" Enter
type_cmd "$STEPWISE play spring --braille"
wait_for 'spring +euler' || fail "play --braille did not start"
some_braille() { [ "$(braille_cells)" -gt 0 ]; }
wait_until 30 some_braille || fail "play --braille draws no Braille"
keys q
wait_exit "braille"
keys "clear" Enter
type_cmd "LC_ALL=C $STEPWISE play spring --braille"
wait_for 'Braille needs a UTF-8 locale' || fail "no note that Braille needs UTF-8 under LC_ALL=C"
[ "$(braille_cells)" -eq 0 ] || fail "Braille drawn under LC_ALL=C"
keys b
sleep 0.3
[ "$(braille_cells)" -eq 0 ] || fail "b turned Braille on under LC_ALL=C"
keys q
check_terminal_sane braille

# ---- the menu: 60 lessons, every one reachable; a broken one says why and stays
mkdir menu
src=$(ls "$ROOT"/lessons/01-*.lesson)
i=1
while [ $i -le 60 ]; do
    n=$(printf '%02d' $i)
    sed "s/^title: .*/title: Lesson number $n/" "$src" > "menu/$n-x.lesson"
    i=$((i + 1))
done
printf 'title: Broken\n--- P\n@scene nope\nText.\n' > menu/30-x.lesson
keys "clear" Enter
type_cmd "XDG_STATE_HOME=$WORK/state STEPWISE_LESSONS=$WORK/menu $STEPWISE lesson; echo MENU-EXIT=\$?"
wait_for '> +1\. Lesson number 01' || fail "the menu did not open on lesson 1"
i=0
while [ $i -lt 45 ]; do keys Down; i=$((i + 1)); done
wait_for '> +46\. Lesson number 46' || fail "lesson 46 is not shown after 45 Downs"
keys 5 9
wait_for '> +59\. Lesson number 59' || fail "typing 59 did not show lesson 59"
keys NPage
wait_for '> +60\. Lesson number 60' || fail "PgDn did not reach the last lesson"
keys PPage PPage PPage PPage PPage PPage
wait_for '> +1\. Lesson number 01' || fail "PgUp did not go back to the first lesson"
keys 3 0
wait_for '> +30\. .*\(broken\)' || fail "the broken lesson is not marked in the menu"
keys Enter
wait_for "cannot open this lesson: .*30-x.lesson:3:8: unknown scene 'nope'" || fail "the broken lesson's error is not shown"
screen | grep -q 'MENU-EXIT=[0-9]' && fail "choosing a broken lesson left the menu"
keys Down
wait_for '> +31\. Lesson number 31' || fail "the menu does not work after the error"
screen | grep -q 'cannot open this lesson' && fail "the error stays after a key"
keys q
wait_for 'MENU-EXIT=0' || fail "q did not leave the menu with status 0"
check_terminal_sane menu

# ---- wide characters in the lesson pane: whole, two cells each, wrapped without a cut
mkdir wide
cjk=一二三四五六七八九十一二三四五六七八九十一二三四五六七八九十一二三四五六七八九十一二三四五六七八九十
{
    printf 'title: Wide\n--- 日本語のページ\n@scene spring\n'
    printf '%s%s%s\n' "$cjk" "$cjk" "$cjk"
    printf '\n  ab日本語cd|\n  abcdefghij|\n  ab🙂🙂🙂cd|\n'
} > wide/01-wide.lesson
"$STEPWISE" lesson --check wide/01-wide.lesson >/dev/null || fail "the wide lesson does not pass --check"
keys "clear" Enter
type_cmd "XDG_STATE_HOME=$WORK/state STEPWISE_LESSONS=$WORK/wide $STEPWISE lesson 1"
wait_for '日本語のページ' || fail "the wide title is not shown whole"
screen | grep -q 'ab日本語cd|' || fail "a line with CJK is garbled"
screen | grep -q 'ab🙂🙂🙂cd|' || fail "a line with emoji is garbled"
# the two lines are as wide as each other: their bars line up
c1=$(screen | grep 'ab日本語cd|' | sed 's/ab日本語cd|.*//' | wc -m)
c2=$(screen | grep 'abcdefghij|' | sed 's/abcdefghij|.*//' | wc -m)
[ "$c1" = "$c2" ] || fail "the CJK line starts at another column ($c1, $c2)"
shown=$(screen | sed 's/[^一二三四五六七八九十]//g' | tr -d '\n')
[ "$shown" = "$cjk$cjk$cjk" ] || fail "the CJK paragraph is cut or garbled: $shown"
keys q
check_terminal_sane wide
echo ok
