#!/bin/sh
# A course graded with a roster (issue 22): ten students, eight of whom
# submitted in the ways the platforms name files (a plain id prefix, a
# Canvas download, a Moodle folder, a Gradescope submission_ID folder with
# its metadata, plugins named after their authors); one trace claims a
# classmate's name; two students did not submit; a README, an unknown file
# and a file that names nobody are listed. Then: --similarity flags the
# plugin copied with renamed variables and reformatted code and the wrong
# trace copied with a note added, not the independent ones; --feedback writes one report per student; -j 2 gives
# the table and gradebook -j 1 gives, byte for byte; a regrade of one
# student updates one row and keeps the others; --fresh starts over.
. "$(dirname "$0")/lib.sh"
needs_jail
mkdir class
cat > assignment.txt <<'A'
# stepwise assignment 1
# title: homework 4, classical Runge-Kutta on a hanging spring
# scene: spring
# integrator: rk4
# dt: 0.01
# steps: 100
A
cat > roster.csv <<'R'
Name,SID,Email
Ada Lovelace,s1001,ada@uni.edu
Blaise Pascal,s1002,blaise@uni.edu
"Gauss, Carl",s1003,gauss@uni.edu
Dana Scott,s1004,dana@uni.edu
Emmy Noether,s1005,emmy@uni.edu
Felix Klein,s1006,felix@uni.edu
Grace Hopper,s1007,grace@uni.edu
Hedy Lamarr,s1008,hedy@uni.edu
Alan Turing,s1009,alan@uni.edu
Kurt Goedel,s1010,kurt@uni.edu
R
"$SW" record spring -i rk4 --dt 0.01 --steps 100 -o ref.trace >/dev/null 2>&1 || fail "cannot record"
"$SW" record spring -i euler --dt 0.01 --steps 100 -o euler.trace >/dev/null 2>&1 || fail "cannot record"
claim() { sed "s/^# scene/# student: $1\n# scene/" "$2"; }
claim "Ada Lovelace" ref.trace > class/s1001_rk4.trace                          # a plain id
claim "Blaise Pascal" euler.trace > class/pascalblaise_4711_998877_hw4.trace   # Canvas, wrong
mkdir "class/Carl Gauss_55_assignsubmission_file_"                              # Moodle
# Carl's trace goes wrong from step 40 on (a bug of his own, which the
# explainer cannot name); Dana hands in a copy with a note added, so the
# files differ but the wrong numbers do not.
perturb() { awk -F, -v from="$1" -v by="$2" 'BEGIN { OFS = "," }
    /^[0-9]/ && $1 >= from { $3 = $3 + by } { print }' "$3"; }
perturb 40 1e-3 ref.trace > carl.trace
claim "Carl Gauss" carl.trace > "class/Carl Gauss_55_assignsubmission_file_/rk4.trace"
mkdir class/submission_216975964                                               # Gradescope
claim "Dana" carl.trace | sed 's/^# scene/# note: all my own work\n# scene/' > class/submission_216975964/rk4.trace
cat > class/submission_metadata.yml <<'Y'
submission_216975964:
  :submitters:
  - :name: Dana Scott
    :sid: 's1004'
    :email: dana@uni.edu
  :created_at: 2026-12-02 02:52:07.938335000 Z
Y
claim "Ada Lovelace" ref.trace > class/emmy_noether.trace   # claims a classmate's name
cp "$ROOT/tests/data/similar/rk4_alice.c" class/felix_klein_rk4.c
cp "$ROOT/tests/data/similar/rk4_alice_copy.c" class/s1007_rk4.c   # Grace: the copy
cp "$ROOT/tests/data/similar/rk4_bob.c" class/hedy_lamarr.c        # independent
perturb 40 2e-3 ref.trace | claim "Nobody" /dev/stdin > class/zz_unknown.trace   # wrong otherwise
echo "my answers are in the .c file" > class/README.txt
printf 'PK\003\004' > class/notes.docx
export STEPWISE_INCLUDE="$ROOT/include"

"$SW" grade --assignment assignment.txt --roster roster.csv --similarity --feedback fb \
    --csv grades.csv -j 2 class > table 2> err
rc=$?
[ $rc -eq 1 ] || fail "exit $rc, want 1 (some did not pass): $(cat err table)"
# row STUDENT VERDICT REGEX: the table has such a row
has() { grep -E "$1" table > /dev/null || fail "the table lacks '$1': $(cat table)"; }
has "^  Ada Lovelace +s1001_rk4.trace +pass"
has "^  Blaise Pascal +pascalblaise_4711_998\.\.\. +fail .*euler"  # cut within its 24 cells
has "^  Carl Gauss +rk4.trace +fail +[0-9./]* +40"
has "^  Dana Scott +rk4.trace +fail +[0-9./]* +40"
has "^  Emmy Noether +emmy_noether.trace +pass"
has "roster: .*Ada Lovelace.*not believed"
has "^  Felix Klein +felix_klein_rk4.c +pass"
has "^  Grace Hopper +s1007_rk4.c +pass"
has "^  Hedy Lamarr +hedy_lamarr.c +pass"
has "^  Alan Turing .*missing"
has "^  Kurt Goedel .*missing"
has "README.txt +skipped"
has "notes.docx +skipped"
# Gradescope's metadata is read for the roster, never a row of the gradebook
grep -q "submission_metadata" table && fail "the export's metadata is a row: $(grep submission_metadata table)"
has "^  \[zz_unknown\] +zz_unknown.trace +fail +[0-9./]* +40"
has "roster: matches no roster student"
has "2 students on the roster without a submission"
# Similarity: the copy with renamed variables is flagged; the independent
# plugin and the correct traces are not.
has "similar pairs"
grep -E "Felix Klein \(felix_klein_rk4.c\)  ~  Grace Hopper \(s1007_rk4.c\)|Grace Hopper \(s1007_rk4.c\)  ~  Felix Klein \(felix_klein_rk4.c\)" table >/dev/null ||
    fail "the copied plugin is not flagged: $(cat table)"
grep -E "Carl Gauss \(rk4.trace\)  ~  Dana Scott \(rk4.trace\): identical wrong numbers: 61 of 61 rows" table \
    >/dev/null || fail "the copied wrong trace is not flagged: $(grep '~' table)"
grep "~" table | grep -q "Hedy" && fail "the independent plugin is flagged: $(grep '~' table)"
grep "~" table | grep -Eq "Ada|Emmy|Blaise|zz_unknown" &&
    fail "a correct, explained or independently wrong trace is flagged: $(grep '~' table)"

# The gradebook: a row per entry and per missing student, the columns kept.
head -1 grades.csv | grep -q "^student,file,verdict,first_failing_step,message,id,remarks,similar" ||
    fail "gradebook header: $(head -1 grades.csv)"
[ "$(wc -l < grades.csv)" -eq 14 ] || fail "gradebook has $(wc -l < grades.csv) lines, want 14: $(cat grades.csv)"
grep -q '^Alan Turing,,missing,,.*,s1009,' grades.csv || fail "no missing row for Alan Turing: $(cat grades.csv)"
grep '^Grace Hopper,' grades.csv | grep -q "Felix Klein" || fail "Grace's row lacks the pair"
grep '^Emmy Noether,' grades.csv | grep -q "not believed" || fail "Emmy's row lacks the claim"

# Feedback: a file per student, names made safe, the full report inside.
[ -f fb/Ada_Lovelace.txt ] || fail "no feedback for Ada: $(ls fb)"
grep -q "s1001_rk4.trace: pass" fb/Ada_Lovelace.txt || fail "Ada's feedback: $(cat fb/Ada_Lovelace.txt)"
grep -q "No submission" fb/Alan_Turing.txt || fail "Alan's feedback: $(cat fb/Alan_Turing.txt)"
grep -q "euler" fb/Blaise_Pascal.txt || fail "Blaise's feedback: $(cat fb/Blaise_Pascal.txt)"
[ "$(ls fb | wc -l)" -ge 10 ] || fail "feedback files: $(ls fb)"
ls -a fb | grep -q tmp && fail "a temporary left in fb: $(ls -a fb)"

# Without a roster a name comes from the trace: folded as the roster folds
# (ë: e) and reduced to a safe file name, never a path; a feedback
# directory among the submissions is refused.
mkdir loose
{ head -1 ref.trace; echo "# student: ../../x/Zoë \$(rm) O'Brien"; tail -n +2 ref.trace; } > loose/a.trace
"$SW" grade --assignment assignment.txt --feedback fb2 loose > /dev/null 2>&1
[ "$(ls fb2)" = "x_Zoe_rm_O_Brien.txt" ] || fail "feedback name: $(ls -a fb2)"
"$SW" grade --assignment assignment.txt --feedback loose/fb loose > o 2>&1 && fail "feedback among the submissions"
grep -q "inside the submissions directory" o || fail "feedback among the submissions: $(cat o)"

# -j 1 gives the same table and the same gradebook, byte for byte.
"$SW" grade --assignment assignment.txt --roster roster.csv --similarity --csv grades1.csv \
    --fresh -j 1 class > table1 2>/dev/null
"$SW" grade --assignment assignment.txt --roster roster.csv --similarity --csv grades2.csv \
    --fresh -j 2 class > table2 2>/dev/null
cmp grades1.csv grades2.csv || fail "-j 1 and -j 2 gradebooks differ: $(diff grades1.csv grades2.csv)"
cmp grades.csv grades2.csv || fail "gradebooks differ from the first run"
grep -v "passed, .* failed" table1 > t1; grep -v "passed, .* failed" table2 > t2
cmp t1 t2 || fail "-j 1 and -j 2 tables differ: $(diff t1 t2)"

# Regrade one student: Blaise fixes his trace; his row is updated, the
# other fourteen lines stay as they were.
claim "Blaise Pascal" ref.trace > class/pascalblaise_4711_998877_hw4.trace
cp grades.csv before.csv
"$SW" grade --assignment assignment.txt --roster roster.csv --csv grades.csv \
    class/pascalblaise_4711_998877_hw4.trace > regrade 2>&1
rc=$?
[ $rc -eq 0 ] || fail "regrade exit $rc: $(cat regrade)"
grep -q "updated 1 row, kept 12" regrade || fail "the regrade does not say what it kept: $(cat regrade)"
[ "$(wc -l < grades.csv)" -eq 14 ] || fail "regrade left $(wc -l < grades.csv) lines: $(cat grades.csv)"
grep -q '^Blaise Pascal,class/pascalblaise_4711_998877_hw4.trace,pass,' grades.csv ||
    fail "Blaise's row not updated: $(grep Blaise grades.csv)"
grep -v '^Blaise' before.csv > b1; grep -v '^Blaise' grades.csv > b2
cmp b1 b2 || fail "other rows changed: $(diff b1 b2)"
# The same file named another way is the same row.
"$SW" grade --assignment assignment.txt --roster roster.csv --csv grades.csv ./class//s1001_rk4.trace \
    > regrade 2>&1
grep -q "updated 1 row, kept 12" regrade || fail "./class//s1001_rk4.trace: $(cat regrade)"
[ "$(grep -c '^Ada Lovelace,' grades.csv)" -eq 1 ] || fail "Ada twice: $(grep Ada grades.csv)"
# A Gradescope student regraded by their folder alone: the metadata above
# it still says whose it is.
"$SW" grade --assignment assignment.txt --roster roster.csv --csv grades.csv \
    class/submission_216975964 > regrade 2>&1
grep -q "^  Dana Scott .*fail" regrade || fail "Dana's folder alone: $(cat regrade)"
grep -q "updated 1 row, kept 12" regrade || fail "Dana's regrade: $(cat regrade)"
# A gradebook edited by someone else: a kept cell that a spreadsheet would
# run is written back inert; one from an older stepwise (five columns)
# is updated and gets the new columns.
printf 'student,file,verdict,first_failing_step,message\r\nMallory,x.trace,pass,,"=HYPERLINK(""http://evil"")"\r\n' > old.csv
"$SW" grade --assignment assignment.txt --csv old.csv class/s1001_rk4.trace > o 2>&1
grep -q "updated 0 rows, kept 1, added 1" o || fail "old gradebook: $(cat o)"
grep -qF "Mallory,x.trace,pass,,\"'=HYPERLINK(\"\"http://evil\"\")\",,," old.csv ||
    fail "the kept formula: $(cat old.csv)"
head -1 old.csv | grep -q "message,id,remarks,similar" || fail "old gradebook header: $(head -1 old.csv)"
# A gradebook of other columns is not overwritten by a regrade.
printf 'name,score\r\nx,1\r\n' > other.csv
"$SW" grade --assignment assignment.txt --csv other.csv class/s1001_rk4.trace > o 2>&1 &&
    fail "a foreign CSV was updated"
grep -q "is not what --csv writes" o || fail "foreign CSV: $(cat o)"
# ... nor by --fresh: it starts a gradebook over, never a file of another kind
"$SW" grade --assignment assignment.txt --csv other.csv --fresh class/s1001_rk4.trace > o 2>&1 &&
    fail "--fresh wrote over a foreign CSV"
grep -q "^name,score" other.csv || fail "--fresh changed a foreign CSV: $(cat other.csv)"
# --fresh starts over: one graded row and the nine students it has not seen.
"$SW" grade --assignment assignment.txt --roster roster.csv --csv grades.csv --fresh \
    class/pascalblaise_4711_998877_hw4.trace > fresh 2>&1
grep -q "kept" fresh && fail "--fresh kept rows: $(cat fresh)"
[ "$(wc -l < grades.csv)" -eq 11 ] || fail "--fresh wrote $(wc -l < grades.csv) lines: $(cat grades.csv)"
# Each worker keeps its own --wall watchdog when they run side by side:
# two plugins that block forever (asleep in their step, which the 60 s
# step watchdog would stop only later) and a trace with --wall 3 -j 2 all
# end, the plugins stopped with the reason (no limit on how long this
# takes here: --wall counts only time with nothing of a submission
# runnable, and a loaded machine keeps it waiting longer).
mkdir wall
for i in 1 2; do
    sed -e "s/student-euler/wall-$i/" -e 's/^{$/{ for (;;) { struct timespec d = { 1, 0 }; nanosleep(\&d, 0); }/' \
        -e '1i #define _POSIX_C_SOURCE 199309L\n#include <time.h>' "$ROOT/examples/euler_plugin.c" > wall/p$i.c
done
cp ref.trace wall/t.trace
"$SW" grade --assignment assignment.txt --wall 3 --plugin-timeout 60 -j 2 wall > wall.out 2>&1
[ "$(grep -c 'waited 3 s with nothing running' wall.out)" -eq 2 ] || fail "--wall with -j 2: $(cat wall.out)"
grep -q "t.trace .*pass" wall.out || fail "the trace beside them: $(cat wall.out)"
# A submission that keeps running (a loop the 60 s watchdog and --cpu 60
# would stop only later) meets --wall's hard cap, 20 x --wall of wall
# time, and is told that, not that it waited with nothing running.
# (--wall 1, not less: idle time is sampled every 0.25 s, and a moment
# with nothing runnable while the jail is set up counts one sample; at
# --wall 0.2 one sample was the whole guard.)
mkdir capped
sed -e "s/student-euler/capped/" -e 's/^{$/{ for (volatile long spin = 0; ; spin++) ;/' \
    "$ROOT/examples/euler_plugin.c" > capped/p.c
"$SW" grade --assignment assignment.txt --wall 1 --cpu 60 --plugin-timeout 60 capped > capped.out 2>&1
grep -q "grading went on for 20 s of wall time, 20 times --wall, and was stopped" capped.out ||
    fail "--wall's hard cap: $(cat capped.out)"

# Interrupted while plugins spin in their jails with -j 2: nothing of the
# grading outlives it (the jail re-arms its parent-death signal after the
# user namespace cleared it), and no gradebook is written.
mkdir spin_$$
for i in 1 2 3; do
    sed -e "s/student-euler/spin-$i/" -e 's/^{$/{ for (volatile long spin = 0; ; spin++) ;/' \
        "$ROOT/examples/euler_plugin.c" > spin_$$/p$i.c
done
running() { # processes whose command line names spin_$$ (the brackets keep grep's own out)
    grep -las "spi[n]_$$" /proc/[0-9]*/cmdline 2>/dev/null | wc -l
}
"$SW" grade --assignment assignment.txt --plugin-timeout 60 -j 2 --csv spin.csv spin_$$ > spin.out 2>&1 &
gpid=$!
# grade, two workers, and each plugin's jail (its first process, its init
# and the payload) once both plugins run: 9, three times in a row (while
# compiling, cc's payload is counted only for the moment before its exec).
i=0 seen=0
while [ $seen -lt 3 ] && [ $i -lt 300 ]; do
    if [ "$(running)" -ge 9 ]; then seen=$((seen + 1)); else seen=0; fi
    sleep 0.1
    i=$((i + 1))
done
n=$(running)
kill -INT $gpid
wait $gpid
[ "$n" -ge 9 ] || fail "the spinning plugins did not start ($n processes): $(cat spin.out)"
i=0
while [ "$(running)" -gt 0 ] && [ $i -lt 30 ]; do sleep 0.1; i=$((i + 1)); done
[ "$(running)" -eq 0 ] || fail "$(running) processes outlived the interrupted grading"
[ ! -e spin.csv ] || fail "an interrupted grading wrote a gradebook"
echo ok
