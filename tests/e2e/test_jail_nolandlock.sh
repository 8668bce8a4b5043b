#!/bin/sh
# The jail of a user of its own has no namespaces: Landlock is its only
# file boundary. In a container without user namespaces (tests/e2e/nouserns.c)
# on a kernel that does not enable Landlock (tests/e2e/nolandlock.c), no jail
# is built: `autograder --probe` and `grade` refuse in one line naming
# Landlock, and no student's code runs (a plugin that includes a classmate's
# file by its absolute path, or reads the assignment's secret, never gets
# the chance), nothing is written. Where Landlock works the same container
# grades, and --probe names every layer. Needs root; skipped otherwise.
. "$(dirname "$0")/lib.sh"
if [ "$(id -u)" -ne 0 ] || ! cc -std=c11 -O2 -o nouserns "$ROOT/tests/e2e/nouserns.c" 2>/dev/null ||
   ! ./nouserns true 2>/dev/null || ! cc -std=c11 -O2 -o nolandlock "$ROOT/tests/e2e/nolandlock.c" -lseccomp 2>/dev/null ||
   ! ./nolandlock true 2>/dev/null; then
    echo "skip: test_jail_nolandlock: needs root, a user namespace to drop them in and libseccomp"
    exit 77
fi

cat > hw.txt <<'A'
# stepwise assignment 1
# title: RK4 on the chain
# kind: plugin
# secret: not for students
# integrator: rk4
# steps: 20
# points x* y*: 2
# scene: chain
# param n: 4
# dt: 0.01
A
mkdir class
sed 's/@NAME@/alice/' "$ROOT/tests/hostile/honest-rk4.c" > class/alice.c
printf '#include "%s/class/alice.c"\n' "$WORK" > class/mallory.c

# Without Landlock: refused, in one line, naming it; nothing written.
./nouserns ./nolandlock "$SW" autograder --probe > probe.out 2> probe.err && fail "--probe said a jail can be built"
[ "$(wc -l < probe.err)" -eq 1 ] || fail "--probe: not one line: $(cat probe.err)"
grep -q "Landlock" probe.err || fail "--probe does not name Landlock: $(cat probe.err)"
./nouserns ./nolandlock "$SW" grade --assignment hw.txt --csv out.csv class > grade.out 2> grade.err
rc=$?
[ $rc -eq 2 ] || fail "grade exited $rc, not 2: $(cat grade.out grade.err)"
[ "$(wc -l < grade.err)" -eq 1 ] || fail "grade: not one line: $(cat grade.err)"
grep -q "Landlock" grade.err || fail "grade does not name Landlock: $(cat grade.err)"
[ -e out.csv ] && fail "grade wrote out.csv"
grep -q "mallory\|alice" grade.out && fail "grade graded without a jail: $(cat grade.out)"

# With Landlock (where this kernel enables it): the jail of a user of its own.
if ! ./nouserns "$SW" autograder --probe > probe.out 2>&1; then
    echo "ok: refused without Landlock (this kernel has none for the control: $(cat probe.out))"
    exit 0
fi
grep -q "a user of its own.*seccomp, Landlock, limits" probe.out || fail "--probe: $(cat probe.out)"
chmod 755 "$WORK" && chmod -R a+rX "$WORK" || fail "cannot open $WORK to the jail's user"
./nouserns "$SW" grade --assignment hw.txt --csv out.csv class > grade.out 2>&1 || true
grep -q "alice.c .*pass" grade.out || fail "alice's honest plugin did not pass: $(cat grade.out)"
grep -q "mallory.c .*error .*does not compile" grade.out || fail "mallory's include was not refused: $(cat grade.out)"
echo "ok: no jail without Landlock; with it, a classmate's file is out of reach"
