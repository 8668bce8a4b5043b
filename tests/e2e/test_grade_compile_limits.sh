#!/bin/sh
# A .c that does not compile is one line naming the compiler's first
# error, however much the compiler says: a source whose 2 MiB of errors
# filled the jail's channel once held its build until the 60 s timeout
# (the log refused as too large, its sender blocked), then the wall clock:
# a 'limit' that blamed the grader's guard.
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
echo "ok: a build's errors, however many, give its first one"
