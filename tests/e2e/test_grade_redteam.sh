#!/bin/sh
# What an outside red team broke in the grader, each checked as it was
# broken (the hostile zoo, test_hostile.sh, has the other attacks):
#   1. a plugin read the class out of the memory it started with (the
#      roster's emails, a classmate's file name, the old gradebook's verdict
#      cells): tests/hostile/heap-scan.c scans its heap, every writable
#      segment and its arguments for markers, and must find the
#      assignment's (its own to know: the scan ran) and nothing else;
#   2. a submission_metadata.yml in a student's own Gradescope folder (or
#      in a folder of it) decided, on a regrade, whose submission it was;
#   3. two file names that escaped to one gradebook cell ("Jos\xe9" as
#      written, and the Latin-1 é) let a regrade of one overwrite the other;
#   4. the compiler was not held to --memory;
#   5. a plugin file too large for the sandbox read as a broken sandbox;
#   6. under --no-sandbox (Gradescope's fallback) a plugin's daemon, out of
#      its session (and then a chain of them), outlived grade and rewrote
#      results.json with a score of its own;
#   7. one student's folder of 15 000 files made a gradebook too large for
#      stepwise to read back, and every regrade after failed (and, fixed
#      first with a cap on the directory named, 30 000 files of one student
#      in a flat directory left classmates ungraded);
#   8. a name with a ';' (a cell boundary where a spreadsheet splits at ';')
#      went into the gradebook unquoted, and one with a right-to-left
#      override (U+202E) into the table as it was;
#   9. a file's name with newlines put a forged "7 of 7 points" line into
#      results.json's output and the feedback, and an escape sequence into
#      a feedback file;
#  10. a file no roster student matched, reduced to a student's name
#      ("AliceéAdams"), took that student's feedback file;
#  11. a file named --no-sandbox, brought in by the teacher's `*`, turned
#      the jail off for the class.
. "$(dirname "$0")/lib.sh"
needs_jail
A=assign.txt
cat > $A <<'EOF'
# stepwise assignment 1
# title: ZQASSIGNMENT rk4 on the spring
# scene: spring
# integrator: rk4
# dt: 0.01
# steps: 100
EOF
mkdir class
"$SW" record spring -i rk4 --dt 0.01 --steps 100 -o class/ZQCLASSMATE_s1001.trace >/dev/null 2>&1 \
    || fail "record failed"
cp "$ROOT/tests/hostile/heap-scan.c" class/s1004_mallory.c
cat > roster.csv <<'EOF'
Name,ID,Email
Alice Adams,s1001,alice.ZQROSTER@u.edu
Mallory Mars,s1004,mallory@u.edu
EOF
# a gradebook to read back, with a classmate's verdict cell in it
"$SW" grade --assignment $A --roster roster.csv --csv book.csv class/ZQCLASSMATE_s1001.trace >/dev/null 2>&1
printf 'ZQBOOKROW,elsewhere/x.trace,pass,,,,,,2,2,\r\n' >> book.csv
# Not in the sanitizer pass (SW_SANITIZED): there ASan owns SIGSEGV and its
# shadow memory, and the scan's probing of unmapped pages ends in a
# forbidden system call of ASan's own (SIGSYS), which says nothing.
for j in ${SW_SANITIZED:+skip} 1 2; do
    [ "$j" = skip ] && break
    "$SW" grade --assignment $A --roster roster.csv --csv book.csv --feedback fb$j -j $j class >out$j.txt 2>&1
    [ $? -le 1 ] || fail "1: grade -j $j exited $?: $(cat out$j.txt)"
    all=$(cat out$j.txt book.csv fb$j/* 2>/dev/null)
    # The plugin runs in its host, which never held the grader's memory:
    # not even its own assignment's title is there to find.
    printf '%s\n' "$all" | grep -q "SCAN" || fail "1: -j $j: the scan did not run: $(grep -i mallory out$j.txt)"
    printf '%s\n' "$all" | grep -q "SCAN-[ARCB]" && fail "1: -j $j: the plugin read the grader's memory: $(printf '%s\n' "$all" | grep -o 'SCAN[-A-Z]*' | head -1)"
done

# 2: the export's metadata decides; a copy in a student's folder is refused
mkdir -p gs/submission_111 gs/submission_444
cp class/ZQCLASSMATE_s1001.trace gs/submission_111/rk4.trace
"$SW" record spring -i euler --dt 0.01 --steps 100 -o gs/submission_444/rk4.trace >/dev/null 2>&1
cat > gs/submission_metadata.yml <<'EOF'
submission_111:
  :submitters:
  - :name: Alice Adams
    :sid: 's1001'
    :email: alice.ZQROSTER@u.edu
submission_444:
  :submitters:
  - :name: Mallory Mars
    :sid: 's1004'
    :email: mallory@u.edu
EOF
sed 's/Mallory Mars/Alice Adams/; s/s1004/s1001/; s/mallory@/alice@/' gs/submission_metadata.yml \
    | sed -n '/submission_444/,$p' > gs/submission_444/submission_metadata.yml
"$SW" grade --assignment $A --roster roster.csv --csv gs.csv --fresh gs >/dev/null 2>&1
for again in gs/submission_444 gs/submission_444/rk4.trace; do
    "$SW" grade --assignment $A --roster roster.csv --csv gs.csv "$again" >out.txt 2>&1
    grep -q "^Alice Adams,gs/submission_444" gs.csv && fail "2: regrading $again gave Mallory's file to Alice"
    grep -q "^Mallory Mars,gs/submission_444/rk4.trace,fail" gs.csv || fail "2: regrading $again lost Mallory's row: $(cat gs.csv)"
done
grep -q "inside a submission's folder" out.txt || grep -q "inside a submission's folder" gs.csv \
    || fail "2: the planted metadata is not named as refused"
# ... and one planted deeper in the upload, beside a file in a folder of it
mkdir gs/submission_444/sub
mv gs/submission_444/submission_metadata.yml gs/submission_444/sub/
cp gs/submission_444/rk4.trace gs/submission_444/sub/rk4.trace
"$SW" grade --assignment $A --roster roster.csv --csv gs.csv --fresh gs >/dev/null 2>&1
"$SW" grade --assignment $A --roster roster.csv --csv gs.csv gs/submission_444/sub/rk4.trace >out.txt 2>&1
grep -q "^Alice Adams,gs/submission_444" gs.csv && fail "2: a deeper planted metadata gave Mallory's file to Alice"
grep -q "^Mallory Mars,gs/submission_444/sub/rk4.trace,fail" gs.csv || fail "2: the deeper file's row: $(cat gs.csv)"

# 3: names that once escaped alike keep rows of their own
mkdir esc
cp class/ZQCLASSMATE_s1001.trace "esc/$(printf 'Jos\351.trace')"
"$SW" record spring -i euler --dt 0.01 --steps 100 -o 'esc/Jos\xe9.trace' >/dev/null 2>&1
"$SW" grade --assignment $A --csv esc.csv --fresh esc >/dev/null 2>&1
"$SW" grade --assignment $A --csv esc.csv "esc/$(printf 'Jos\351.trace')" >/dev/null 2>&1
[ "$(grep -c ',pass,' esc.csv)" -eq 1 ] && [ "$(grep -c ',fail,' esc.csv)" -eq 1 ] \
    || fail "3: a regrade of one name changed the other's row: $(cat esc.csv)"

# 4: a compiler that would take 800 MB is held to --memory 64 (not in the
# sanitizer pass, SW_SANITIZED: ASan reserves terabytes of address space,
# so that build sets no address-space limit at all)
if [ -z "${SW_SANITIZED:-}" ]; then
mkdir bomb
{
    cat "$ROOT/examples/euler_plugin.c"
    echo '#define X1(x) x,x'
    i=2
    while [ $i -le 21 ]; do echo "#define X$i(x) X$((i - 1))(x),X$((i - 1))(x)"; i=$((i + 1)); done
    echo 'double big[] = { X21(1.0) };'
} > bomb/bomb.c
"$SW" grade --assignment $A --memory 64 --cpu 30 --wall 120 bomb >out.txt 2>&1
grep -q "reached the grader's --memory limit of 64 MiB while building it" out.txt || fail "4: the build was not held to --memory: $(cat out.txt)"
# ... in words the teacher and the student can each act on (the student
# cannot raise --memory; their source is what asks the compiler for more)
grep -q "the teacher's --memory sets it; a source that needs more of the compiler.*should be made smaller" out.txt \
    || fail "4: the message does not say who can do what: $(cat out.txt)"
grep -q "raise --memory" out.txt && fail "4: the student is told to raise --memory: $(cat out.txt)"
fi

# 5: a plugin file too large is said to be one
mkdir big
head -c 70000000 /dev/zero > big/big.so
"$SW" grade --assignment $A big >out.txt 2>&1
grep -q "too large" out.txt || fail "5: an oversized .so: $(cat out.txt)"
grep -q "could not be set up" out.txt && fail "5: an oversized .so read as a broken sandbox"

# 6: a daemon of a plugin run without the jail does not outlive grade
mkdir dmn
cat > dmn/daemon.c <<EOF
#define _GNU_SOURCE
#include <stepwise/integrator.h>
#include <stdio.h>
#include <string.h>
#include <sched.h>
#include <unistd.h>
static int step(sw_ode *ode, double t, double *y, double h, double *work)
{ sw_ode_eval(ode, t, y, work); for (int i = 0; i < ode->dim; i++) y[i] += h * work[i]; return 0; }
static const sw_plugin info = { .abi = SW_PLUGIN_ABI, .name = "daemon", .order = 1, .evals = 1,
                                .work_vectors = 1, .step = step };
static void loop(void)
{
    for (int i = 0; i < 1000; i++) { /* 10 s: rewrite a written results.json, beat a heart */
        char buf[64] = "";
        FILE *f = fopen("$WORK/gs.json", "r");
        if (f) { fread(buf, 1, sizeof buf - 1, f); fclose(f); }
        if (f && !strstr(buf, "FORGED") && strstr(buf, "score")) {
            FILE *o = fopen("$WORK/gs.json.x", "w");
            if (o) { fputs("{\"score\": 7, \"output\": \"FORGED\"}\n", o); fclose(o); rename("$WORK/gs.json.x", "$WORK/gs.json"); }
        }
        FILE *h = fopen("$WORK/heart", "a");
        if (h) { fputc('.', h); fclose(h); }
        usleep(10000);
    }
    _exit(0);
}
const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void)
{
    static int done;
    /* out of its session, then a chain of 150, each the child of the one
     * before and each at work: a killer of children alone sees one a round */
    if (!done++ && fork() == 0) { setsid(); for (int k = 0; k < 150 && fork() == 0; k++) ; loop(); }
    /* not before the daemon beat once (however busy the machine: a
     * condition, not a time), so that the test proves something; yielding,
     * never asleep, which the watchdog would end */
    while (access("$WORK/heart", F_OK) != 0)
        sched_yield();
    return &info;
}
EOF
"$SW" grade --assignment $A --gradescope gs.json --no-sandbox dmn >out.txt 2>&1
[ -s heart ] || fail "6: the daemon never ran (the test proves nothing): $(cat out.txt)"
beats=$(wc -c < heart)
sleep 1
[ "$(wc -c < heart)" -eq "$beats" ] || fail "6: a plugin's daemon outlived grade"
grep -q FORGED gs.json && fail "6: the daemon rewrote results.json: $(cat gs.json)"
grep -q '"score": 0' gs.json || fail "6: results.json: $(cat gs.json)"

# 7: a folder brings at most 64 entries, and a regrade reads the book back
mkdir -p many/s1001_alice many/s1004_mallory/a/b
cp class/ZQCLASSMATE_s1001.trace many/s1001_alice/rk4.trace
i=0
while [ $i -lt 300 ]; do : > "many/s1004_mallory/a/b/$i.txt"; i=$((i + 1)); done
"$SW" grade --assignment $A --roster roster.csv --csv many.csv --fresh many >out.txt 2>&1
[ "$(grep -c "beyond its first 64 entries" many.csv)" -eq 1 ] || fail "7: no row says the folder was cut: $(tail -3 many.csv)"
[ "$(wc -l < many.csv)" -le 70 ] || fail "7: $(wc -l < many.csv) rows from one folder"
"$SW" grade --assignment $A --roster roster.csv --csv many.csv many/s1001_alice/rk4.trace >out.txt 2>&1
[ $? -le 1 ] || fail "7: the regrade could not read the gradebook back: $(cat out.txt)"
# ... and in a flat directory no number of another's files pushes a classmate out
mkdir flat
cp class/ZQCLASSMATE_s1001.trace flat/s1001_rk4.trace
i=0
while [ $i -lt 1500 ]; do : > "flat/s1004_$i.txt"; i=$((i + 1)); done
"$SW" grade --assignment $A --roster roster.csv --csv flat.csv --fresh flat >out.txt 2>&1
grep -q "^Alice Adams,flat/s1001_rk4.trace,pass" flat.csv || fail "7: a classmate pushed out of a flat directory: $(grep Alice flat.csv)"
grep -q "and 500 more entries not graded" flat.csv || fail "7: the entries past 1000 are not counted: $(tail -1 flat.csv)"

# 8: ';' quoted in the gradebook, bidirectional controls escaped everywhere
mkdir names
{ echo '# stepwise trace 1'; echo '# student: Mallory;=cmd|calc'; sed 1d class/ZQCLASSMATE_s1001.trace; } > names/m.trace
{ echo '# stepwise trace 1'; printf '# student: Eve\342\200\256lamrof\n'; sed 1d class/ZQCLASSMATE_s1001.trace; } > names/e.trace
"$SW" grade --assignment $A --csv names.csv --fresh names >out.txt 2>&1
grep -q '^"Mallory;=cmd|calc",' names.csv || fail "8: a ';' left unquoted: $(grep Mallory names.csv)"
if grep -q "$(printf '\342\200\256')" out.txt names.csv; then fail "8: U+202E shown as it is"; fi
grep -q 'Eve\\xe2\\x80\\xaelamrof' names.csv || fail "8: U+202E not escaped: $(grep Eve names.csv)"

# 9: a name's newlines and escapes reach no report raw
mkdir nl
cp names/m.trace "nl/$(printf 'x\n\nstepwise: 7 of 7 points (pass)\n\033[32mPASS.trace')"
"$SW" grade --assignment $A --gradescope nl.json --feedback nlfb nl >out.txt 2>&1
grep -q "^stepwise: 7 of 7" nl.json nlfb/* && fail "9: a forged line from a file's name"
if grep -q "$(printf '\033')" nl.json nlfb/*; then fail "9: an escape sequence reached a report"; fi
grep -q 'x\\x0a\\x0astepwise' nlfb/* || fail "9: the name is not shown escaped: $(cat nlfb/*)"

# 10: an unmatched file never takes a roster student's feedback file
# (AliceΣAdams: the roster keeps the Σ and matches no one; a file name
# has no room for it and reduces to Alice_Adams)
mkdir fbn
cp class/ZQCLASSMATE_s1001.trace fbn/s1001_alice.trace
"$SW" record spring -i euler --dt 0.01 --steps 100 -o "fbn/$(printf 'Alice\316\243Adams.trace')" >/dev/null 2>&1
"$SW" grade --assignment $A --roster roster.csv --feedback fbfb fbn >out.txt 2>&1
head -1 fbfb/Alice_Adams.txt | grep -q "^Feedback for Alice Adams$" || fail "10: Alice's feedback file: $(head -1 fbfb/Alice_Adams.txt)"
[ -f fbfb/unmatched-Alice_Adams.txt ] || fail "10: the unmatched file's feedback: $(ls fbfb)"

# 11: a file named like an option is refused, not obeyed
mkdir glob
cp class/ZQCLASSMATE_s1001.trace glob/a.trace
: > glob/--no-sandbox
(cd glob && "$SW" grade --assignment ../$A * >../out.txt 2>&1; echo $? > ../rc.txt)
[ "$(cat rc.txt)" -eq 2 ] && grep -q "both an option and a file" out.txt || fail "11: $(cat out.txt)"
(cd glob && "$SW" grade --assignment ../$A -- * >../out.txt 2>&1)
grep -q "a.trace.*pass" out.txt || fail "11: after -- the files are graded: $(cat out.txt)"
echo "red team: the eleven breaks hold"
