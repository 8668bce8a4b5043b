#!/bin/sh
# A roster student whose upload holds nothing gradable (a README, a link,
# a FIFO) has not submitted: a `missing` row saying their files were left
# out, a 0 row in --gradebook and --lms, and a count in the summary. Before,
# the skipped rows made them "seen", and they had no gradebook row at all,
# so an LMS import left them without a grade (QA, 2026-12-07). And a
# trace named in capitals (.CSV) is graded.
. "$(dirname "$0")/lib.sh"
cat > a.txt <<'A'
# stepwise assignment 1
# scene: spring
# integrator: euler
# dt: 0.02
# steps: 10
A
printf 'Name,ID,Email\nAnn Lee,1,ann@x.org\nBo Chen,2,bo@x.org\nCy Dee,3,cy@x.org\n' > roster.csv
mkdir -p "sub/Ann Lee_1_assignsubmission_file_" "sub/Bo Chen_2_assignsubmission_file_"
"$SW" record spring -i euler --dt 0.02 --steps 10 -o "sub/Ann Lee_1_assignsubmission_file_/s.trace" >/dev/null 2>&1 ||
    fail "record"
echo "see my notes" > "sub/Bo Chen_2_assignsubmission_file_/README.txt"
ln -s /etc/hostname "sub/Bo Chen_2_assignsubmission_file_/s.trace"
mkfifo "sub/Bo Chen_2_assignsubmission_file_/pipe.csv"
"$SW" grade --assignment a.txt --roster roster.csv --gradebook book.csv --lms lms.csv sub > g.out 2>&1
rc=$?
[ $rc -eq 1 ] || fail "exit $rc, want 1 (two students without a submission): $(cat g.out)"
grep -Eq "^  Bo Chen +missing .*no gradable submission: the 3 entries matched to this student \(roster line 3\) were not graded" g.out ||
    fail "Bo's missing row: $(cat g.out)"
grep -Eq "^  Cy Dee +missing .*no submission matched this student" g.out || fail "Cy's row: $(cat g.out)"
grep -q "2 students on the roster without a submission" g.out || fail "the summary's count: $(cat g.out)"
grep -q '^Bo Chen,2,bo@x.org,0,2,missing,,,no gradable submission (the files sent were not graded),' book.csv ||
    fail "Bo's gradebook row: $(cat book.csv)"
tr -d '\r' < lms.csv > lms.txt   # the LMS file's lines end in CRLF
grep -q '^Bo Chen,2,bo@x.org,0,2$' lms.txt || fail "Bo's LMS row: $(cat lms.csv)"
grep -q '^Cy Dee,3,cy@x.org,0,2$' lms.txt || fail "Cy's LMS row: $(cat lms.csv)"
grep -q '^Ann Lee,1,ann@x.org,2,2$' lms.txt || fail "Ann's LMS row: $(cat lms.csv)"
# A trace's extension in capitals is a trace (a spreadsheet's SWING.CSV);
# a plugin's is not what the compiler reads: skipped, saying to rename it.
mkdir -p caps
"$SW" record spring -i euler --dt 0.02 --steps 10 -o caps/ann_SWING.CSV >/dev/null 2>&1 || fail "record"
cp "$ROOT/examples/euler_plugin.c" caps/bo_rk4.C
"$SW" grade --assignment a.txt caps > c.out 2>&1
grep -Eq "ann_SWING.CSV +pass" c.out || fail "a .CSV trace was not graded: $(cat c.out)"
grep -Eq "bo_rk4.C +skipped .*not graded: a .C file; a plugin ends in lower-case .c or .so \(rename it\)" c.out ||
    fail "a .C source: $(cat c.out)"
exit 0
