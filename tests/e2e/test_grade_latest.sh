#!/bin/sh
# count: latest takes the file modified last. Where a file that scored
# otherwise was modified within 2 s of the counted one (files copied
# without their times: cp, git, some unzips), which is latest is a guess,
# and the gradebook's remarks say so; a minute apart, they do not.
. "$(dirname "$0")/lib.sh"
cat > hw.txt <<'A'
# stepwise assignment 1
# kind: trace
# count: latest
# scene: spring
# integrator: verlet
# dt: 0.01
# steps: 50
A
printf 'Name,ID,Email\nAnn Lee,1,ann@x.org\nBo Chen,2,bo@x.org\n' > roster.csv
for who in "Ann Lee_1" "Bo Chen_2"; do
    d="class/${who}_assignsubmission_file_"
    mkdir -p "$d"
    "$SW" record spring -i verlet --dt 0.01 --steps 50 -o "$d/swing.trace" >/dev/null 2>&1 || fail "record"
    "$SW" record spring -i euler --dt 0.01 --steps 50 -o "$d/swing-v2.trace" >/dev/null 2>&1 || fail "record"
done
# Ann: the Euler draft a minute after the good one; Bo: one second apart
touch -d '2026-01-01 10:00:00' "class/Ann Lee_1_assignsubmission_file_/swing.trace"
touch -d '2026-01-01 10:01:00' "class/Ann Lee_1_assignsubmission_file_/swing-v2.trace"
touch -d '2026-01-01 10:00:00' "class/Bo Chen_2_assignsubmission_file_/swing.trace"
touch -d '2026-01-01 10:00:01' "class/Bo Chen_2_assignsubmission_file_/swing-v2.trace"
"$SW" grade --assignment hw.txt --roster roster.csv --gradebook book.csv class > g.out 2>&1
[ $? -le 1 ] || fail "grade: $(cat g.out)"
grep '^Ann Lee,' book.csv | grep -q ',fail,.*swing-v2.trace' || fail "Ann's latest is not counted: $(cat book.csv)"
grep '^Ann Lee,' book.csv | grep -q 'which is latest is a guess' && fail "Ann's files a minute apart: $(cat book.csv)"
grep '^Bo Chen,' book.csv | grep -q ',fail,.*swing-v2.trace' || fail "Bo's latest is not counted: $(cat book.csv)"
grep '^Bo Chen,' book.csv | grep -q "count: latest: files that scored otherwise were modified within 2 s of the counted one, so which is latest is a guess" ||
    fail "Bo's row does not say his files' times are too close to tell: $(cat book.csv)"
exit 0
