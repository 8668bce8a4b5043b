#!/bin/sh
# A student's own headers: `#include "tableau.h"` beside the .c. The
# headers in a source's folder are copied into the compiler's jail beside
# it (plugin/plugin_headers.c), and listed as part of that submission. In
# a folder that holds several students' .c files none go in (a classmate's
# header is not yours to include), and the compile error says why. Copied
# code in a header counts for --similarity. A link named x.h is never
# followed; more than 12 headers are refused. `try` builds the same way.
# A row's compile error names the file, not the --plugin flag (QA). A path
# outside the jail reads the same whether it exists or not, also where the
# jail is Landlock's (STEPWISE_JAIL=uid: no user namespaces), which says
# "Permission denied" for what exists (QA: an existence oracle).
. "$(dirname "$0")/lib.sh"
needs_jail
sim="$ROOT/tests/data/similar"
export STEPWISE_INCLUDE="$ROOT/include"
mkdir -p class/ada class/bob class/carl flat many
# ada: the weights in a header of her own
cat > class/ada/tableau.h <<'H'
/* RK4's weights and nodes */
#define W_OUTER (1.0 / 6.0)
#define W_INNER (2.0 / 6.0)
#define C_MID 0.5
H
cat > class/ada/rk4.c <<'C'
#include <stepwise/integrator.h>
#include "tableau.h"

static int step(sw_ode *ode, double t, double *y, double h, double *w)
{
    int n = ode->dim;
    double *a = w, *b = w + n, *c = w + 2 * n, *d = w + 3 * n, *z = w + 4 * n;
    sw_ode_eval(ode, t, y, a);
    for (int i = 0; i < n; i++) z[i] = y[i] + C_MID * h * a[i];
    sw_ode_eval(ode, t + C_MID * h, z, b);
    for (int i = 0; i < n; i++) z[i] = y[i] + C_MID * h * b[i];
    sw_ode_eval(ode, t + C_MID * h, z, c);
    for (int i = 0; i < n; i++) z[i] = y[i] + h * c[i];
    sw_ode_eval(ode, t + h, z, d);
    for (int i = 0; i < n; i++) y[i] += h * (W_OUTER * (a[i] + d[i]) + W_INNER * (b[i] + c[i]));
    return 0;
}

static const sw_plugin info = { .abi = SW_PLUGIN_ABI, .name = "ada-rk4", .order = 4, .evals = 4,
                                .work_vectors = 5, .step = step };
const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
C
# bob: Alice's whole method hidden in a header, his .c a single include
cp "$sim/rk4_alice.c" class/bob/method.h
printf '/* my RK4 */\n#include "method.h"\n' > class/bob/rk4.c
cp "$sim/rk4_alice_copy.c" class/carl/rk4.c   # carl: the known copy's source, for a second pair
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
printf 'Name,ID,Email\nAda Lovelace,1001,ada@uni.edu\nBob Brown,1002,bob@uni.edu\nCarl Gauss,1003,carl@uni.edu\n' > roster.csv
"$SW" grade --assignment hw.txt --roster roster.csv --similarity class > g.out 2>&1
[ $? -le 1 ] || fail "grade: $(cat g.out)"
grep -Eq "^  Ada Lovelace +rk4.c +pass +2/2" g.out || fail "ada's header was not built with her source: $(cat g.out)"
grep -Eq "^  Bob Brown +rk4.c +pass +2/2" g.out || fail "bob's header was not built with his source: $(cat g.out)"
grep -Eq "tableau.h +skipped .*not graded on its own: a header, built with the .c beside it" g.out ||
    fail "ada's header's row: $(cat g.out)"
grep -E "Bob Brown \(rk4.c\)  ~  Carl Gauss \(rk4.c\)|Carl Gauss \(rk4.c\)  ~  Bob Brown \(rk4.c\)" g.out >/dev/null ||
    fail "the code copied into bob's header is not paired with carl's: $(cat g.out)"
# a regrade of the whole class into the same books: a header's row is
# not a file of ada's the run left out (student pass: a false warning)
"$SW" grade --assignment hw.txt --roster roster.csv --csv files.csv --gradebook book.csv class > r1.out 2>&1
"$SW" grade --assignment hw.txt --roster roster.csv --csv files.csv --gradebook book.csv class > r2.out 2>&1
grep -q "give their whole folder" r2.out && fail "a regrade warns of a header's row: $(cat r2.out)"

# one folder for everyone: no header goes with any source, and ada is told why
cp class/ada/rk4.c flat/ada_rk4.c
cp class/ada/tableau.h flat/
cp "$sim/rk4_bob.c" flat/bob_rk4.c
"$SW" grade --assignment hw.txt --roster roster.csv flat > f.out 2>&1
[ $? -le 1 ] || fail "grade flat: $(cat f.out)"
grep -Eq "^  Ada Lovelace +ada_rk4.c +error .*tableau.h: No such file or directory \(its folder holds 2 .c files, so the .h files beside it were not used" f.out ||
    fail "ada's error in a shared folder: $(cat f.out)"
grep -Eq "^  Bob Brown +bob_rk4.c +pass" f.out || fail "bob in the shared folder: $(cat f.out)"
# the row names the file, not a command-line flag the student never typed
grep -q "error .*--plugin" f.out && fail "the row names --plugin: $(cat f.out)"
grep -Eq "^  Ada Lovelace +ada_rk4.c +error +0/2 +- +'ada_rk4.c' does not compile" f.out ||
    fail "ada's row does not start with her file: $(cat f.out)"
grep -Eq "tableau.h +skipped .*its folder holds 2 of them" f.out || fail "the shared header's row: $(cat f.out)"

# one student's own folder with two sources (a draft beside the final):
# the headers go with both, as try builds them (student pass: the final
# scored 0 in grade and on Gradescope where try and check had passed)
mkdir -p own/ada
cp class/ada/rk4.c class/ada/tableau.h own/ada/
sed 's/C_MID \* h \* b/C_MID * h * a/' class/ada/rk4.c > own/ada/draft.c
"$SW" grade --assignment hw.txt --roster roster.csv own > o.out 2>&1
grep -Eq "^  Ada Lovelace +rk4.c +pass +2/2" o.out || fail "ada's own folder of two sources: $(cat o.out)"
grep -Eq "^  Ada Lovelace +draft.c +fail" o.out || fail "ada's draft: $(cat o.out)"
grep -Eq "tableau.h +skipped .*not graded on its own: a header, built with the .c beside it" o.out ||
    fail "the header's row in ada's own folder: $(cat o.out)"
# Gradescope's one submission is one student's, roster or not
"$SW" grade --assignment hw.txt --gradescope gs.json own/ada > gs.out 2>&1
grep -q '"score": 2' gs.json || fail "Gradescope, a header beside two sources: $(cat gs.out gs.json)"
# a compile error in a file not counted is said, with its file's name alone
printf 'int x = ;\n' > own/ada/broken.c
"$SW" grade --assignment hw.txt --gradescope gs.json own/ada > gs.out 2>&1
grep -q "Also graded, not counted (the best counts): broken.c, 0 of 2 points (error: 'broken.c' does not compile " gs.json ||
    fail "Gradescope: the broken file's line: $(cat gs.json)"

# ten more copies of one student's file do not make it common code: a
# fingerprint is common when more than max(10, a quarter) of the students
# share it, not of the files (red team 4 hid a copy so)
mkdir -p flood/ada flood/bob flood/carl
cp "$sim/rk4_alice.c" flood/ada/rk4.c
cp "$sim/rk4_alice_copy.c" flood/bob/rk4.c
for i in 1 2 3 4 5 6 7 8 9 10; do cp "$sim/rk4_alice_copy.c" "flood/bob/try$i.c"; done
cp "$sim/rk4_bob.c" flood/carl/rk4.c
"$SW" grade --assignment hw.txt --roster roster.csv --similarity flood > fl.out 2>&1
grep -Eq "Ada Lovelace \(rk4.c\)  ~  Bob Brown \((rk4|try[0-9]+).c\)|Bob Brown \((rk4|try[0-9]+).c\)  ~  Ada Lovelace \(rk4.c\)" fl.out ||
    fail "a copy flooded eleven times is not paired: $(cat fl.out)"

# a source and its headers are at most 1 MiB together: sparse files of
# 60 MiB each filled the uid jail's disk (red team 4), and a header padded
# past what --similarity reads hid a copy from it
mkdir -p big
cp class/ada/rk4.c class/ada/tableau.h big/
truncate -s 60M big/pad.h
"$SW" grade --assignment hw.txt big > b.out 2>&1
grep -Eq "rk4.c +error .*the source and its headers are 60\.[0-9] MiB; a plugin's source with its headers may be at most 1 MiB" b.out ||
    fail "a 60 MiB header: $(cat b.out)"
if [ "$(id -u)" -eq 0 ]; then
    STEPWISE_JAIL=uid "$SW" grade --assignment hw.txt big > bu.out 2>&1
    grep -Eq "rk4.c +error .*may be at most 1 MiB" bu.out || fail "a 60 MiB header, uid jail: $(cat bu.out)"
fi

# a header's name of 66 bytes (30 Cyrillic letters) is built with it; one
# past the limit is refused with a message, never left out in silence
# (red team 4: a correct rk4.c lost every point)
mkdir -p named
sed 's/tableau\.h/тестовые_коэффициенты_рк4.h/' class/ada/rk4.c > named/rk4.c
cp class/ada/tableau.h "named/тестовые_коэффициенты_рк4.h"
"$SW" grade --assignment hw.txt named > n.out 2>&1
grep -Eq "rk4.c +pass +2/2" n.out || fail "a header with a long name: $(cat n.out)"
rm named/*.h
long=$(printf 'x%.0s' $(seq 1 210)).h
cp class/ada/tableau.h "named/$long"
"$SW" grade --assignment hw.txt named > n.out 2>&1
grep -Eq "rk4.c +error .*a header's name may be at most 199" n.out || fail "a header's name too long: $(cat n.out)"

# a link named .h is not a header: never followed into the jail
mkdir -p linked
echo '#define W_OUTER (1.0 / 6.0)' > outside.h
ln -s ../outside.h linked/tableau.h
cp class/ada/rk4.c linked/rk4.c
"$SW" grade --assignment hw.txt linked > l.out 2>&1
grep -Eq "rk4.c +error .*tableau.h: No such file or directory" l.out || fail "a linked header was used: $(cat l.out)"

# more than 12 headers: refused, saying so
cp class/ada/rk4.c class/ada/tableau.h many/
for i in 1 2 3 4 5 6 7 8 9 10 11 12; do echo "/* $i */" > many/h$i.h; done
"$SW" grade --assignment hw.txt many > m.out 2>&1
grep -q "its folder holds 13 headers (.h files); a plugin is built with at most 12" m.out ||
    fail "13 headers: $(cat m.out)"

# try, in the student's own folder with other sources: the headers go in
cp "$sim/rk4_bob.c" class/ada/scratch.c
"$SW" try class/ada/rk4.c --no-play > t.out 2>&1 || fail "try with a header: $(cat t.out)"
grep -q "PASS" t.out || fail "try with a header did not pass: $(cat t.out)"

# what exists outside the jail reads as what does not
if [ "$(id -u)" -eq 0 ]; then
    mkdir -p oracle
    for f in /etc/passwd /etc/no-such-file-here; do
        printf '#include "%s"\n' "$f" > oracle/probe.c
        cat "$ROOT/examples/euler_plugin.c" >> oracle/probe.c
        for mode in uid ns; do
            STEPWISE_JAIL=$mode "$SW" try oracle/probe.c --no-play > o.out 2>&1
            [ "$mode" = ns ] && grep -q "user namespaces" o.out && continue
            grep -q "fatal error: $f: No such file or directory" o.out ||
                fail "#include \"$f\" ($mode): $(cat o.out)"
        done
        printf '#if __has_include("%s")\n#error seen\n#endif\n' "$f" > oracle/probe.c
        cat "$ROOT/examples/euler_plugin.c" >> oracle/probe.c
        STEPWISE_JAIL=uid "$SW" try oracle/probe.c --no-play > o.out 2>&1
        grep -q "Permission denied\|seen" o.out && fail "__has_include(\"$f\") told: $(cat o.out)"
    done
    # a binary file included: its first error, in either jail, not the
    # teacher's --output its log ran into in the uid jail (red team 4)
    mkdir -p binary
    { echo '#include "/etc/ld.so.cache"'; cat "$ROOT/examples/euler_plugin.c"; } > binary/probe.c
    STEPWISE_JAIL=uid "$SW" grade --assignment hw.txt binary > bin.out 2>&1
    grep -Eq "probe.c +error .*does not compile .*ld.so.cache:1:[0-9]+: error" bin.out ||
        fail "a binary file included, uid jail: $(cat bin.out)"
fi
exit 0
