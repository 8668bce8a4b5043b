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
# The gradebook's student cell escapes a backslash as its file cell does
# (one function): the literal name Jo\xe9 and the Latin-1 Joé once gave
# one student cell, Jo\xe9, for two students.
mkdir esc
"$SW" record spring -i rk4 --dt 0.01 --steps 10 -o 'esc/Jo\xe9.trace' >/dev/null 2>&1 || fail "record"
cp 'esc/Jo\xe9.trace' "esc/$(printf 'Jo\351').trace"
printf '# stepwise assignment 1\n# scene: spring\n# integrator: rk4\n# dt: 0.01\n# steps: 10\n' > hws.txt
"$SW" grade --assignment hws.txt --csv esc.csv esc > out3 2>&1 || fail "grade: $(cat out3)"
tr -d '\r' < esc.csv | grep -qxF 'Jo\x5cxe9,esc/Jo\x5cxe9.trace,pass,,,,,,2,2,' || fail "the literal name's cells: $(cat esc.csv)"
tr -d '\r' < esc.csv | grep -qxF 'Jo\xe9,esc/Jo\xe9.trace,pass,,,,,,2,2,' || fail "the Latin-1 name's cells: $(cat esc.csv)"
echo "ok: the grade table escapes a message once, the gradebook a name as its file"
