#!/bin/sh
# record and check, headless (no terminal, TERM unset): a trace passes against
# itself, one changed value at step 37 fails naming step 37, an rk4 trace
# checked as euler fails, midpoint checked as heun fails, a blow-up is a
# result (exit 0, trace ends at the diverged step), an interrupted record
# leaves nothing under the real name, and bad options exit 2 with one line.
. "$(dirname "$0")/lib.sh"
unset TERM
# run CMD...: status in $rc, stdout in out, stderr in err
run() { "$@" >out 2>err </dev/null; rc=$?; }

# --- a recorded trace passes against itself --------------------------------
run "$SW" record spring --steps 200 -o a.csv
[ "$rc" -eq 0 ] || fail "record exited $rc: $(cat err)"
[ -s a.csv ] || fail "no trace written"
[ "$(head -1 a.csv)" = "# stepwise trace 1" ] || fail "first line: $(head -1 a.csv)"
grep -qx 'step,t,x0,y0,vx0,vy0,energy' a.csv || fail "header row missing"
grep -qx '# integrator: euler' a.csv || fail "integrator metadata missing"
grep -qx '# param k: 10' a.csv || fail "parameter metadata missing"
[ "$(grep -c '^[0-9]' a.csv)" -eq 201 ] || fail "expected 201 rows"
run "$SW" check a.csv
[ "$rc" -eq 0 ] || fail "check of an untouched trace exited $rc: $(cat out err)"
grep -q '^PASS' out || fail "no PASS line: $(cat out)"

# the worked example of docs/trace-format.md, written by hand with only the
# required metadata and short decimals, passes
run "$SW" check "$root/tests/data/traces/spring-euler-by-hand.trace"
[ "$rc" -eq 0 ] || fail "the hand-written worked example fails: $(cat out err)"

# record to stdout equals record to a file, byte for byte
run "$SW" record spring --steps 200
cmp -s out a.csv || fail "stdout trace differs from the -o trace"

# --- one value changed at step 37 fails, naming step 37 ----------------------
awk -F, -v OFS=, '$1 == "37" { $3 = $3 + 1e-6 } { print }' a.csv > b.csv
cmp -s a.csv b.csv && fail "the edit did not change the trace"
run "$SW" check b.csv
[ "$rc" -eq 1 ] || fail "changed trace: exit $rc, want 1: $(cat out err)"
grep -q 'first failure: step 37,.*column x0' out || fail "step 37 not named: $(cat out)"
[ ! -s err ] || fail "a mismatch is no error, yet stderr has: $(cat err)"

# --- a wrong method fails -------------------------------------------------
run "$SW" record spring --steps 200 -i rk4 -o rk4.csv
sed 's/^# integrator: rk4$/# integrator: euler/' rk4.csv > rk4-as-euler.csv
run "$SW" check rk4-as-euler.csv
[ "$rc" -eq 1 ] || fail "rk4 trace checked as euler: exit $rc, want 1"
run "$SW" check rk4.csv --reference euler
[ "$rc" -eq 1 ] || fail "rk4 trace --reference euler: exit $rc, want 1"
# midpoint and heun agree on the linear 1-D spring; on a plucked chain they differ
run "$SW" record chain -i midpoint -o mid.csv
run "$SW" check mid.csv --reference heun
[ "$rc" -eq 1 ] || fail "midpoint trace checked as heun: exit $rc, want 1"
run "$SW" check mid.csv
[ "$rc" -eq 0 ] || fail "midpoint trace against itself: exit $rc"
# the caveat docs/trace-format.md states: on the default spring they agree
run "$SW" record spring -i midpoint -o mid-spring.csv
run "$SW" check mid-spring.csv --reference heun
[ "$rc" -eq 0 ] || fail "midpoint and heun should agree on the linear spring (documented): exit $rc"

# --- every, until, rk45 -----------------------------------------------------
run "$SW" record orbit -i rk45 --until 3 --every 5 -o rk45.csv
[ "$rc" -eq 0 ] || fail "rk45 record: $(cat err)"
# the run stops within 1e-9 dt of until (the sum of steps may round just below it)
tail -1 rk45.csv | awk -F, '{ d = $2 - 3; if (d < 0) d = -d; if (d > 1e-11) exit 1 }' \
    || fail "rk45 trace does not end at t = 3: $(tail -1 rk45.csv)"
run "$SW" check rk45.csv
[ "$rc" -eq 0 ] || fail "rk45 trace against itself: $(cat out err)"
run "$SW" record spring --every 7 --steps 50 -o every.csv
rows=$(grep '^[0-9]' every.csv | cut -d, -f1 | tr '\n' ' ')
[ "$rows" = "0 7 14 21 28 35 42 49 50 " ] || fail "--every 7 rows: $rows"

# --- a blow-up is a result ---------------------------------------------------
run "$SW" record spring --set k=1e6 --set c=0 --steps 1000 -o blow.csv
[ "$rc" -eq 0 ] || fail "blow-up record exited $rc"
grep -q 'diverged at step' err || fail "no blow-up message on stderr: $(cat err)"
[ "$(wc -l < err)" -eq 1 ] || fail "blow-up message is not one line"
grep -q '^# diverged: step ' blow.csv || fail "no '# diverged:' line in the trace"
step=$(sed -n 's/^# diverged: step \([0-9]*\),.*/\1/p' blow.csv)
last=$(grep '^[0-9]' blow.csv | tail -1 | cut -d, -f1)
[ "$step" = "$last" ] || fail "last row is step $last, diverged at $step"
[ "$last" -lt 1000 ] || fail "the run did not stop at the blow-up"
run "$SW" check blow.csv
[ "$rc" -eq 0 ] || fail "a diverged trace fails against itself: $(cat out err)"

# --- an interrupted record leaves nothing under the real name --------------
"$SW" record chain --set n=2000 --steps 1000000 --every 100000 -o big.csv </dev/null >/dev/null 2>err &
pid=$!
tmp_made() { ls big.csv.tmp.* >/dev/null 2>&1; }
wait_until 60 tmp_made
ls big.csv.tmp.* >/dev/null 2>&1 || fail "no temporary file while recording"
sleep 0.3
[ -e big.csv ] && fail "big.csv exists before the run finished"
kill -INT $pid
wait $pid
[ -e big.csv ] && fail "an interrupted record left big.csv"
ls big.csv.tmp.* >/dev/null 2>&1 && fail "an interrupted record left its temporary file"
grep -q 'interrupted' err || fail "no message on interrupt: $(cat err)"

# --- bad input: exit 2, one line, nothing written ---------------------------
for args in "nosuchscene" "spring --dt 0" "spring --steps 0" "spring --steps 10000001" \
            "spring --until 1e9" "spring --steps 5 --until 1" "spring --set q=1" \
            "spring --integrator nope" "spring --every 0" "spring --frobnicate" "spring --dt" \
            "" "spring chain" "spring -o /nonexistent-dir/x.csv"; do
    # shellcheck disable=SC2086
    run "$SW" record $args
    [ "$rc" -eq 2 ] || fail "record $args: exit $rc, want 2"
    [ "$(wc -l < err)" -eq 1 ] || fail "record $args: stderr is not one line: $(cat err)"
    [ ! -s out ] || fail "record $args wrote to stdout"
done
for args in "" "a.csv b.csv" "a.csv --steps 5" "a.csv --against b.csv --reference rk4" \
            "--scene spring" "a.csv --rtol -1" "nosuch.csv"; do
    # shellcheck disable=SC2086
    run "$SW" check $args
    [ "$rc" -eq 2 ] || fail "check $args: exit $rc, want 2"
    [ "$(wc -l < err)" -eq 1 ] || fail "check $args: stderr is not one line: $(cat err)"
done

# --- --against: two files ----------------------------------------------------
run "$SW" check b.csv --against a.csv
[ "$rc" -eq 1 ] || fail "--against with a changed value: exit $rc"
grep -q 'step 37' out || fail "--against does not name step 37"
run "$SW" check a.csv --against a.csv
[ "$rc" -eq 0 ] || fail "--against itself: exit $rc"
run "$SW" check a.csv --against mid.csv
[ "$rc" -eq 2 ] || fail "spring against chain: exit $rc, want 2"

# --- help --------------------------------------------------------------------
for cmd in record check; do
    run "$SW" $cmd --help
    [ "$rc" -eq 0 ] || fail "$cmd --help exited $rc"
    grep -q "^usage: stepwise $cmd" out || fail "$cmd --help has no usage line"
done
echo "ok"
