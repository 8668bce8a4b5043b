#!/bin/sh
# In a folder, x.so beside x.c is x.c's build, and the source is what is
# graded (red team 3, F5): an upload often holds both, the .so built on
# the student's own machine (here, not even an ELF file), and under
# `count: latest` the newer, unloadable .so was counted: error 0/N over a
# passing .c. Now the .so is listed as not graded, saying why, and the .c
# counts; a .so alone, or beside another name's .c, is still graded.
. "$(dirname "$0")/lib.sh"
needs_jail
cheat="$ROOT/tests/data/cheat"
mkdir -p class/ada class/bob
{ cat "$cheat/common.h"; grep -v '"common.h"' "$cheat/honest_rk4.c"; } > class/ada/rk4.c
printf '\317\372\355\376 not an ELF file: built on a Mac\n' > class/ada/rk4.so
touch -d '+1 minute' class/ada/rk4.so 2>/dev/null || touch class/ada/rk4.so
printf 'garbage\n' > class/bob/other.so
{ cat "$cheat/common.h"; grep -v '"common.h"' "$cheat/honest_rk4.c"; } > class/bob/rk4.c
cat > hw.txt <<'A'
# stepwise assignment 1
# kind: plugin
# count: latest
# scene: chain
# param n: 3
# integrator: rk4
# dt: 0.01
# steps: 50
# points x* y*: 2
A
printf 'Name,ID,Email\nAda Lovelace,1001,ada@uni.edu\nBob Brown,1002,bob@uni.edu\n' > roster.csv
"$SW" grade --assignment hw.txt --roster roster.csv --gradebook book.csv class > g.out 2>&1
[ $? -le 1 ] || fail "grade: $(cat g.out)"
grep -q "rk4.so.*not graded: a build of 'rk4.c' beside it, which is graded" g.out || fail "ada's rk4.so: $(cat g.out)"
grep -q "^Ada Lovelace,1001,ada@uni.edu,2,2,pass," book.csv || fail "ada's row: $(cat book.csv)"
# bob's other.so has no source beside it: graded (and unusable), his rk4.c too
grep -q "other.so .*error" g.out || fail "bob's other.so was not graded: $(cat g.out)"
exit 0
