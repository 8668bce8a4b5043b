#!/bin/sh
# A plugin's name and label are how stepwise lists it, not what it is
# graded on (red team 3, F4): an honest RK4 named 'rk4' or 'RK4' (a
# built-in's name), 'my rk4 (Ada)' (a blank, brackets), 300 characters
# long, or labelled in Latin-1 (what an old editor writes) scored error
# 0/N with "the name 'rk4' is not allowed". Graded, each passes with every
# point and a note in its feedback that says what it was graded as;
# outside grading (record, check) such a plugin is still refused with one
# line, exit 2. And an honest RK4 that uses M_PI (not ISO C: the grader
# compiles with -D_DEFAULT_SOURCE, as docs/plugins.md says) compiles.
. "$(dirname "$0")/lib.sh"
needs_jail
cheat="$ROOT/tests/data/cheat"
mkdir class
honest() { # FILE NAME [LABEL]: an honest RK4 with that name and label, as one .c
    {
        cat "$cheat/common.h"
        printf 'static const sw_plugin info = { .abi = SW_PLUGIN_ABI, .name = "%s", %s.order = 4, .evals = 4,\n' \
            "$2" "${3:+.label = \"$3\", }"
        printf '    .work_vectors = 5, .step = rk4 };\nconst sw_plugin *sw_plugin_info(void);\n'
        printf 'const sw_plugin *sw_plugin_info(void) { return &info; }\n'
    } > "class/$1.c"
}
honest builtin rk4
honest upper RK4
honest blank 'my rk4 (Ada)'
honest long "$(printf '%0300d' 0 | tr 0 r)"
honest latin1 rk4-jose 'M\xe9thode RK4 de Jos\xe9'
honest fine rk4-ada 'RK4 by Ada'
{
    printf '#include <math.h>\n'
    cat "$cheat/common.h"
    printf 'static int pi_rk4(sw_ode *ode, double t, double *y, double h, double *work)\n'
    printf '{ return rk4(ode, t, y, h * (M_PI / M_PI), work); }\nCHEATER("pi-rk4", pi_rk4)\n'
} > class/pi.c
cat > hw.txt <<'A'
# stepwise assignment 1
# kind: plugin
# scene: chain
# param n: 3
# integrator: rk4
# dt: 0.01
# steps: 50
# points x* y*: 2
A
"$SW" grade --assignment hw.txt --csv g.csv --feedback fb class > g.out 2>&1; rc=$?
[ $rc -eq 0 ] || fail "grade exited $rc: $(cat g.out)"
score() { grep "^$1,class/$1.c," g.csv | awk -F, '{ print $3 " " $(NF-2) "/" $(NF-1) }'; }
for s in builtin upper blank long latin1 fine pi; do
    [ "$(score $s)" = "pass 2/2" ] || fail "$s: $(score $s): $(cat fb/$s.txt)"
done
grep -q "note: its name 'rk4' is not allowed (it shadows the built-in method 'rk4'): graded as 'student-plugin'" fb/builtin.txt \
    || fail "builtin: no note: $(cat fb/builtin.txt)"
grep -q "note: its name 'RK4' is not allowed" fb/upper.txt || fail "upper: no note: $(cat fb/upper.txt)"
grep -q "note: its name 'rrrr.*is not allowed (a name has 1 to 40 characters)" fb/long.txt || fail "long: no note: $(cat fb/long.txt)"
grep -q "note: its label 'M\\\\xe9thode.*is not allowed (.*not UTF-8.*): shown as its name" fb/latin1.txt \
    || fail "latin1: no note: $(cat fb/latin1.txt)"
grep -q "note: its" fb/fine.txt && fail "a plugin with an allowed name got a note: $(cat fb/fine.txt)"
# outside grading the tool still refuses them, in one line
cc -std=c11 -shared -fPIC -I"$ROOT/include" -o builtin.so class/builtin.c || fail "cannot build builtin.so"
"$SW" record chain --plugin ./builtin.so --steps 5 -o b.trace 2> err; rc=$?
[ $rc -eq 2 ] && [ "$(wc -l < err)" -eq 1 ] && grep -q "the name 'rk4' is not allowed" err \
    || fail "record of a plugin named rk4: exit $rc: $(cat err)"
exit 0
