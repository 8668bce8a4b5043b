#!/bin/sh
# The grade table shows a message escaped once, as the gradebook and the
# feedback do: a compiler's error quoting a student's real escape byte
# reads \x1b, and the student's literal text "\x1b" reads \x5cx1b. The
# table once escaped the already escaped message again (\x5cx1b for the
# real byte, \x5cx5cx1b for the text), so the two could not be told apart
# there. No raw escape byte reaches the terminal either way.
. "$(dirname "$0")/lib.sh"
needs_jail
cat > hw.txt <<'A'
# stepwise assignment 1
# kind: plugin
# scene: chain
# param n: 3
# integrator: rk4
# dt: 0.01
# steps: 10
A
printf '#include <stepwise/integrator.h>\n#error "real \033[31m literal \\x1b[2J"\n' > bad.c
"$SW" grade --assignment hw.txt --feedback fb bad.c > out 2>&1
[ $? -eq 1 ] || fail "grade: $(cat out)"
grep -q "$(printf '\033')" out && fail "a raw escape byte reached the table: $(cat -v out)"
grep -qF 'real \x1b[31m literal \x5cx1b[2J' out || fail "the table's message is not escaped once: $(grep bad.c out)"
grep -qF 'real \x1b[31m literal \x5cx1b[2J' fb/*.txt || fail "the feedback's message: $(cat fb/*.txt)"
# the roster's remark on a file named with both: once, as in the feedback
printf 'name,email\nAda Park,ada@uni.edu\n' > roster.csv
mkdir class
cp bad.c "class/zz$(printf '\033')x\\x1b.c"
"$SW" grade --assignment hw.txt --roster roster.csv class > out2 2>&1
grep -q "$(printf '\033')" out2 && fail "a raw escape byte reached the table: $(cat -v out2)"
grep -qF "roster: matches no roster student: no folder or file name in 'class/zz\x1bx\x5cx1b.c'" out2 ||
    fail "the table's remark is not escaped once: $(grep roster: out2)"
echo "ok: the grade table escapes a message once"
