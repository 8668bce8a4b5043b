#!/bin/sh
# Gradescope's autograder contract, per submission (issue 22): build the
# bundle with `stepwise autograder`, unpack it under a temporary
# AUTOGRADER_ROOT as Gradescope would (/autograder/source), and run
# run_autograder for a correct trace, a partly wrong one (the header only),
# a wrong one, the same run written another way (until for steps, an extra
# column), a crashing plugin, a slow one out of CPU time, and a hostile
# plugin that tries to write results.json itself. Each results.json must parse (tests/e2e/json.awk),
# carry Gradescope's fields, and score what the assignment's points say.
# In a container without user namespaces (tests/e2e/nouserns.c, as Docker
# refuses them) plugins run jailed as a user of their own, never without
# a jail: the forger scores 0 and results.json is the grader's. Needs unzip
# (tests/deps.sh installs it).
. "$(dirname "$0")/lib.sh"
needs_jail
json="$ROOT/tests/e2e/json.awk"
command -v unzip >/dev/null 2>&1 || fail "unzip is missing: run 'sh tests/deps.sh'"

cat > assignment.trace <<'A'
# stepwise assignment 1
# title: explicit Euler on the spring, with partial credit
# scene: spring
# integrator: euler
# dt: 0.01
# steps: 200
# points header: 1
# points x* y*: 3
# points vx* vy*: 2
# points energy: 1
# points order: 1
A

# The bundle: the three files Gradescope needs at the root, executable.
# A generous wall clock: a loaded machine must not turn a pass into a limit.
"$SW" autograder --assignment assignment.trace -o ag.zip --source "$ROOT" --wall 300 2>note ||
    fail "autograder: $(cat note)"
grep -q "a trace scores up to 7 points, a plugin up to 7" note || fail "note: $(cat note)"
unzip -Z ag.zip > listing || fail "unzip cannot read the bundle"
for f in setup.sh run_autograder assignment.trace stepwise/Makefile stepwise/src/main.c; do
    grep -q " $f\$" listing || fail "bundle lacks $f: $(head -5 listing)"
done
grep " run_autograder\$" listing | grep -q "^-rwxr-xr-x" || fail "run_autograder not executable"
grep " setup.sh\$" listing | grep -q "^-rwxr-xr-x" || fail "setup.sh not executable"
unzip -tq ag.zip >/dev/null || fail "unzip -t: the CRCs do not check"
"$SW" autograder --assignment assignment.trace -o ag2.zip --source "$ROOT" --wall 300 2>/dev/null
cmp -s ag.zip ag2.zip || fail "the same inputs gave different bundles"
unzip -p ag.zip run_autograder | grep -q -- '--gradescope "$results" --wall 300 "$@"' ||
    fail "run_autograder does not pass the limits on"

# The docs' figures for the bundle against this tree's: docs/gradescope.md
# says "about M MB, N entries". Within 10 %: its two digits round by up to
# 3 %, and the tree may grow some 7 % before the page is due a new
# measurement (the "1.4 MB, 199 files" it said was 28 % and 27 % off).
said=$(grep -o 'about [0-9.]* MB, [0-9]* entries' "$ROOT/docs/gradescope.md")
[ -n "$said" ] || fail "docs/gradescope.md states no 'about M MB, N entries' for the bundle"
bytes=$(wc -c < ag.zip)
entries=$(unzip -Z1 ag.zip | wc -l)
echo "$said" | awk -v bytes="$bytes" -v entries="$entries" '{
    mb = $2 * 1e6; n = $4 + 0
    if (mb < 0.9 * bytes || mb > 1.1 * bytes) { printf "size: says %s MB, is %.2f MB\n", $2, bytes / 1e6; bad = 1 }
    if (n < 0.9 * entries || n > 1.1 * entries) { printf "entries: says %d, are %d\n", n, entries; bad = 1 }
    exit bad }' > drift || fail "docs/gradescope.md's bundle figures drifted (update them): $(cat drift)"
# The help sends '# points' readers to the page that documents them.
"$SW" autograder --help > help.txt
doc=$(tr '\n' ' ' < help.txt | sed -n "s|.*'# points'[^.]*\(docs/[a-z-]*\.md\).*|\1|p")
[ -n "$doc" ] || fail "autograder --help names no page for '# points': $(cat help.txt)"
grep -q '`# points WHAT: N`' "$ROOT/$doc" || fail "autograder --help sends '# points' readers to $doc, which does not document them"

# The submissions.
"$SW" record spring --integrator euler --dt 0.01 --steps 200 -o good.trace 2>/dev/null
"$SW" record spring --integrator euler --dt 0.01 --until 2 -o until.trace 2>/dev/null
"$SW" record spring --integrator rk4 --dt 0.01 --steps 200 -o wrong.trace 2>/dev/null
sed 's/^# param k: 10$/# param k: 12/' good.trace > header.trace
grep -q "param k: 12" header.trace || fail "no param k line to change"
awk -F, '/^#/ { print; next } /^step/ { print $0 ",ke"; next } { print $0 ",0" }' good.trace > extra.trace
sed 's|y\[i\] += h \* dydt\[i\];|y[i] += h * dydt[i];\n    if (t > 0.5) *(volatile int *)0 = 1;|' \
    "$ROOT/examples/euler_plugin.c" > crash.c
grep -q "volatile int" crash.c || fail "crash.c not made"

# run_autograder for one submission file: $1 the file, $2 the name of the
# container (a directory), $3 an optional STEPWISE override, $4 another bundle;
# WRAP, a command to run run_autograder under.
grade_in() {
    r=$WORK/$2
    mkdir -p "$r/source" "$r/submission"
    (cd "$r/source" && unzip -q "$WORK/${4:-ag.zip}") || fail "$2: unzip"
    [ -n "$1" ] && cp "$1" "$r/submission/"
    AUTOGRADER_ROOT=$r STEPWISE=${3:-$SW} ${WRAP:-} sh "$r/source/run_autograder" > "$r/stdout" 2>&1 ||
        fail "$2: run_autograder exited non-zero: $(cat "$r/stdout")"
    [ -s "$r/results/results.json" ] || fail "$2: no results.json: $(cat "$r/stdout")"
    awk -f "$json" "$r/results/results.json" > "$r/flat" || fail "$2: results.json does not parse"
}

# Gradescope's format: score, execution_time, output, and each test with
# name, score, max_score, output and visibility; the scores add up.
# $1 container, $2 the score, $3 the sum of max_score, $4 the number of tests.
expect() {
    f=$WORK/$1/flat
    grep -qx "score=$2" "$f" || fail "$1: score is not $2: $(grep '^score=' "$f"; grep '\.output=' "$f")"
    grep -q '^execution_time=[0-9]' "$f" || fail "$1: no execution_time"
    grep -q '^output=' "$f" || fail "$1: no output"
    n=$(grep -c '^tests\[[0-9]*\]\.name=' "$f")
    [ "$n" = "$4" ] || fail "$1: $n tests, not $4"
    for key in score max_score output visibility status; do
        m=$(grep -c "^tests\[[0-9]*\]\.$key=" "$f")
        [ "$m" = "$n" ] || fail "$1: $m of $n tests have '$key'"
    done
    sum=$(awk -F= '/^tests\[[0-9]+\]\.score=/ { s += $2 } /^tests\[[0-9]+\]\.max_score=/ { m += $2 }
                   END { printf "%g %g", s, m }' "$f")
    [ "$sum" = "$2 $3" ] || fail "$1: tests add up to '$sum', not '$2 $3'"
}

grade_in good.trace good;     expect good 7 7 4
grade_in header.trace header; expect header 6 7 4
grep -q 'tests\[0\]\.output=param k: yours 12' "$WORK/header/flat" || fail "header: $(grep 'tests\[0\]' "$WORK/header/flat")"
grade_in wrong.trace wrong;   expect wrong 0 7 4
grep -q 'did you implement rk4' "$WORK/wrong/flat" || fail "wrong: the explainer's words are missing"
grade_in until.trace until;   expect until 7 7 4
grade_in extra.trace extra;   expect extra 7 7 4
grep -q "column ke ignored" "$WORK/extra/flat" || fail "extra: no warning about the ignored column"
grade_in crash.c crash;       expect crash 0 7 4
grep -q 'tests\[0\]\.output=not scored: .*SIGSEGV' "$WORK/crash/flat" ||
    fail "crash: $(grep 'tests\[0\]' "$WORK/crash/flat")"

# Hostile: a correct Euler that first tries to write results.json (full
# marks and more) where Gradescope reads it. In the jail the system call
# is refused and the plugin stopped (0 points); without the jail (below)
# the write succeeds, and the grader's own results.json replaces it.
hostile() {
    sed "s|^static int euler_step|#include <stdio.h>\nstatic void forge(void) { FILE *f = fopen(\"$WORK/$1/results/results.json\", \"w\"); if (f) { fputs(\"{\\\\\"score\\\\\": 100}\", f); fclose(f); } }\nstatic int euler_step|; s|    double \*dydt = work; /\* work vector 0 \*/|    double *dydt = work;\n    forge();|" \
        "$ROOT/examples/euler_plugin.c" > hostile.c
    grep -q "forge();" hostile.c || fail "hostile.c not made"
    mkdir -p "$WORK/$1/results"
}
hostile hostile
grade_in hostile.c hostile;   expect hostile 0 7 4
grep -q 'tests\[0\]\.output=not scored: .*SIGSYS' "$WORK/hostile/flat" ||
    fail "hostile: $(grep 'tests\[0\]' "$WORK/hostile/flat")"

# A correct but slow plugin out of its CPU time (a bundle with --cpu 1):
# the verdict is 'limit', not 'fail', and it scores 0.
"$SW" autograder --assignment assignment.trace -o slow.zip --source "$ROOT" --cpu 1 --wall 300 2>/dev/null ||
    fail "autograder --cpu 1"
sed 's|        y\[i\] += h \* dydt\[i\];|        y[i] += h * dydt[i];\n    for (volatile long spin = 0; spin < 20000000L; spin++)\n        ;|' \
    "$ROOT/examples/euler_plugin.c" > slow.c
grep -q "spin" slow.c || fail "slow.c not made"
grade_in slow.c slow "" slow.zip; expect slow 0 7 4
grep -q '^output=.*for slow.c (limit)' "$WORK/slow/flat" || fail "slow: $(grep '^output=' "$WORK/slow/flat")"
grep -q 'SIGXCPU' "$WORK/slow/flat" || fail "slow: the CPU limit is not named"

# Uploaded as a folder: the files in it are graded (one level down).
mkdir -p "$WORK/folder/submission/hw3"
cp header.trace "$WORK/folder/submission/hw3/"
grade_in "" folder;          expect folder 6 7 4

# Nothing gradable uploaded: every check at 0, saying why.
grade_in "" empty;            expect empty 0 7 4
grep -q "no submission to grade" "$WORK/empty/flat" || fail "empty: no reason given"

# A probe that fails: run_autograder says plugins are not run, and never
# turns the jail off; a trace is graded all the same.
cat > nojail.sh <<S
#!/bin/sh
[ "\$1 \${2:-}" = "autograder --probe" ] && { echo "no jail (test)" >&2; exit 1; }
exec "$SW" "\$@"
S
chmod +x nojail.sh
grade_in good.trace nojail "$WORK/nojail.sh"; expect nojail 7 7 4
grep -q "no jail (test)); they are not run" "$WORK/nojail/stdout" || fail "nojail: run_autograder did not say why"
unzip -p ag.zip run_autograder | grep -q -- "--no-sandbox" && fail "run_autograder still turns the jail off"

# The container: root in a user namespace of its own where no other can be
# made (tests/e2e/nouserns.c). The jail is a user of its own there: the
# forger and a good plugin, each as Gradescope would run it.
if [ "$(id -u)" -eq 0 ] && cc -std=c11 -O2 -o nouserns "$ROOT/tests/e2e/nouserns.c" 2>/dev/null &&
   ./nouserns true; then
    cp "$ROOT/examples/euler_plugin.c" euler.c
    for c in container-good container-hostile; do
        f=euler.c
        [ $c = container-hostile ] && { hostile $c; f=hostile.c; }
        WRAP=$WORK/nouserns grade_in $f $c
    done
    expect container-good 7 7 4
    expect container-hostile 0 7 4
    grep -q "score=100" "$WORK/container-hostile/flat" && fail "container: the plugin's results.json was taken"
    for c in container-good container-hostile; do
        grep -q "a user of its own" "$WORK/$c/stdout" || fail "$c: run_autograder did not say how plugins run: $(cat "$WORK/$c/stdout")"
        grep -q "user of its own, seccomp" "$WORK/$c/flat" || fail "$c: results.json does not say how plugins ran"
    done
else
    echo "skip: the container (no user namespaces): needs root and a user namespace to drop them in"
fi

# A grader that fails outright still leaves a results.json with a score.
printf '#!/bin/sh\nexit 3\n' > broken.sh
chmod +x broken.sh
grade_in good.trace broken "$WORK/broken.sh"
grep -qx "score=0" "$WORK/broken/flat" || fail "broken: $(cat "$WORK/broken/flat")"
echo "ok: gradescope bundle ($(wc -c < ag.zip) bytes)"
