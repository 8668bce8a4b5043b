#!/bin/sh
# A .c that does not compile is one line naming the compiler's first
# error, however much the compiler says: a source whose 2 MiB of errors
# filled the jail's channel once held its build until the 60 s timeout
# (the log refused as too large, its sender blocked), then the wall clock:
# a 'limit' that blamed the grader's guard. And a build is the
# submission's own work, held to --cpu (docs/grading.md): a source that
# compiles for seconds (here some 7 s of CPU, a table of 3 million numbers)
# once had 60 s of its own whatever --cpu said.
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
awk 'BEGIN { print "#include <stepwise/integrator.h>"
             s = ""; for (i = 0; i < 200; i++) s = s "@"
             for (i = 0; i < 24; i++) print s }' > noisy.c
"$SW" grade --assignment hw.txt --wall 100 noisy.c > out 2>&1
[ $? -eq 1 ] || fail "grade: $(cat out)"
grep -q "noisy.c *error .*does not compile .*noisy.c:2:1: error: stray '@' in program" out ||
    fail "noisy: not the compiler's first error: $(cat out)"
# three million initialisers from a few lines (a source and its headers
# are at most 1 MiB: the expansion, not the file, is what takes the time)
cat > slow.c <<'C'
#define A 1.5, 2.5, 3.5, 4.5, 5.5, 6.5, 7.5, 8.5, 9.5, 1.25,
#define B A A A A A A A A A A
#define C_ B B B B B B B B B B
#define D C_ C_ C_ C_ C_ C_ C_ C_ C_ C_
#define E D D D D D D D D D D
#define F E E E E E E E E E E
static const double t[] = { F F F 0 };
double get(int i) { return t[i]; }
C
"$SW" grade --assignment hw.txt --cpu 1 --wall 100 slow.c > out 2>&1
[ $? -eq 1 ] || fail "grade: $(cat out)"
grep -q "slow.c *error .*did not compile within the submission's CPU time: the compiler used all 1 s left of it .*--cpu" out ||
    fail "slow: the build was not held to --cpu: $(cat out)"
echo "ok: a build's errors, however many, give its first one; a build is held to --cpu"
