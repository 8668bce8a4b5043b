#!/bin/sh
# e2e: long (run.sh starts it first)
# The hostile-plugin zoo (issue 16): plugins that exit, abort, crash, loop in
# their step or in sw_plugin_info(), write one and many elements past their
# work vectors or past y, write ode->dim, return NaN, or carry bad names.
# Every record, check (--json) and grade run on each ends within its limit
# with a one-line verdict (valid JSON where asked), never a pass, no temp
# file left; play disables a failing plugin and leaves the terminal sane.
# Most of it waits on the plugins' 2 s watchdogs, so its parts run side by
# side: each plugin's record and check, the loading and signal cases, the
# grade of the whole zoo, and play (each part's files its own).
. "$(dirname "$0")/lib.sh"
needs_jail
root=$(cd "$(dirname "$0")/../.." && pwd)
json="$root/tests/e2e/json.awk"
SW=$STEPWISE
cd "$WORK" || exit 1

zoo() { # NAME 'statement run in the step from its fourth step on' [work vectors] [info body]
    cat > "$1.c" <<C
#include <stdlib.h>
#include <stepwise/integrator.h>
static int step(sw_ode *ode, double t, double *y, double h, double *work)
{
    double *k = work;
    sw_ode_eval(ode, t, y, k);
    if (t > 2.5 * h) { $2; }
    for (int i = 0; i < ode->dim; i++)
        y[i] += h * k[i];
    return 0;
}
static const sw_plugin info = { .abi = SW_PLUGIN_ABI, .name = "$1", .label = "zoo: $1",
    .order = 1, .evals = 1, .work_vectors = ${3:-1}, .step = step };
const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { ${4:-} return &info; }
C
    cc -std=c11 -O0 -shared -fPIC -I"$root/include" -o "$1.so" "$1.c" || fail "cannot build $1"
}
zoo exits 'exit(0)'
zoo aborts 'abort()'
zoo segv '*(volatile int *)(void *)8 = 1'
zoo loops 'for (volatile int spin = 1; spin;) { }'
zoo over-one 'work[ode->dim] = 1'
zoo over-many 'work[3 * ode->dim + 7] = 1'
zoo over-y 'y[ode->dim] = 1'
zoo writes-dim 'ode->dim += 1'
zoo allocs 'free(malloc(64))'
zoo nan 'k[0] = 0.0 / 0.0'
zoo info-loops '' 1 'for (volatile int spin = 1; spin;) { }'
sed 's/\.name = "nan"/.name = "euler "/' nan.c > badname.c
cc -std=c11 -shared -fPIC -I"$root/include" -o badname.so badname.c || fail "cannot build badname"

# kind: what each one is called in check --json's plugin_failure, and the words
expect() {
    case "$1" in
        exits) echo "exit|ended its process with exit\\(0\\) in its step" ;;
        aborts) echo "crash|crashed with SIGABRT" ;;
        segv) echo "crash|crashed with SIGSEGV" ;;
        loops) echo "timeout|used 2 s of its own CPU time without returning from its step" ;;
        over-one) echo "overrun_work|wrote past its 1 work vector \\(work\\[4\\]" ;;
        over-many) echo "overrun_work|wrote past its 1 work vector \\(work\\[19\\]" ;;
        over-y) echo "overrun_y|wrote past the end of y \\(y\\[4\\]" ;;
        writes-dim) echo "ode_written|changed ode->dim from 4 to 5" ;;
        allocs) echo "allocated|allocated memory in its step" ;;
    esac
}

one_plugin() { # NAME: its record and checks, its files NAME.*
    p=$1
    words=$(expect "$p" | cut -d'|' -f2); kind=$(expect "$p" | cut -d'|' -f1)
    # record: the trace up to the step, a one-line verdict, exit 1, no temp
    # file (each timeout guards against a hang: it would give 124, not 1;
    # generous: a loop is stopped after 2 s of its own CPU time, which a
    # loaded machine stretches)
    timeout 300 "$SW" record spring --plugin "./$p.so" --steps 20 -o "$p.trace" >"$p.out" 2>"$p.err"; rc=$?
    [ "$rc" -eq 1 ] || fail "record $p: exit $rc, want 1: $(cat "$p.err")"
    [ "$(wc -l < "$p.err")" -eq 1 ] || fail "record $p: stderr is not one line: $(cat "$p.err")"
    grep -Eq "$words.* at step 4" "$p.err" || fail "record $p: message lacks '$words ... at step 4': $(cat "$p.err")"
    ls "$p".trace.tmp.* >/dev/null 2>&1 && fail "record $p left a temporary file"
    grep -q '^# diverged: step 4,' "$p.trace" || fail "record $p: the trace does not end at step 4"
    # step 4 did not run: no row claims it did (the rows end at step 3)
    last=$(grep '^[0-9]' "$p.trace" | tail -1 | cut -d, -f1)
    [ "$last" = 3 ] || fail "record $p: the last row is step $last, want 3 (step 4 failed)"
    # check --json: a failure with the step, valid JSON, never a pass
    timeout 300 "$SW" check --json --plugin "./$p.so" --reference euler --scene spring --steps 20 >"$p.out" 2>"$p.err"; rc=$?
    [ "$rc" -eq 1 ] || fail "check $p: exit $rc, want 1: $(cat "$p.out" "$p.err")"
    awk -f "$json" "$p.out" > "$p.fields" || fail "check $p: not JSON: $(cat "$p.out")"
    grep -qx 'pass=false' "$p.fields" || fail "check $p: not a failure"
    grep -qx "plugin_failure.kind=$kind" "$p.fields" || fail "check $p: plugin_failure.kind is not $kind: $(grep plugin_failure "$p.fields")"
    grep -qx 'plugin_failure.step=4' "$p.fields" || fail "check $p: plugin_failure.step is not 4"
    grep -qx 'failing_step=4' "$p.fields" || fail "check $p: failing_step is not 4"
    # and the trace it recorded, checked against its own plugin: still a failure
    timeout 300 "$SW" check "$p.trace" --plugin "./$p.so" >"$p.out" 2>"$p.err"; rc=$?
    [ "$rc" -eq 1 ] || fail "check $p.trace against its own plugin: exit $rc, want 1 (a fake pass?)"
}

# NaN: a numerical blow-up, reported as such (record exits 0; check fails).
part_nan() {
    "$SW" record spring --plugin ./nan.so --steps 20 -o nan.trace 2>nan.err; rc=$?
    [ "$rc" -eq 0 ] && grep -q 'diverged at step 4 .*non-finite' nan.err || fail "nan record: $rc $(cat nan.err)"
    "$SW" check --json --plugin ./nan.so --reference euler --scene spring --steps 20 >nan.out 2>nan.err
    [ $? -eq 1 ] || fail "nan check: not a failure"
    awk -f "$json" nan.out > nan.fields || fail "nan check: not JSON"
    grep -qx 'plugin_diverged.step=4' nan.fields || fail "nan check: plugin_diverged.step is not 4"
}

# Loading: a loop in sw_plugin_info() and a bad name are bad input (exit 2),
# one line that says why.
one_load() { # NAME WORDS: record and check --json of it, its files NAME.*
    p=$1
    for cmd in "record spring --plugin ./$p.so" "check --json --plugin ./$p.so --reference euler --scene spring"; do
        # shellcheck disable=SC2086
        timeout 300 "$SW" $cmd >"$p.out" 2>"$p.err"; rc=$?
        [ "$rc" -eq 2 ] || fail "$cmd: exit $rc, want 2"
        [ "$(wc -l < "$p.err")" -eq 1 ] || fail "$cmd: stderr is not one line: $(cat "$p.err")"
        case "$cmd" in
            record*) grep -q "$2" "$p.err" || fail "$cmd: no message '$2': $(cat "$p.err")" ;;
            *--json*) awk -f "$json" "$p.out" > "$p.fields" || fail "$cmd: not JSON: $(cat "$p.out")" ;;
        esac
    done
}

# grade: the whole zoo in one command, each a failure or an error, within limits.
part_grade() {
    mkdir zoo
    cp exits.so aborts.so segv.so loops.so over-one.so over-many.so over-y.so writes-dim.so nan.so \
       info-loops.so badname.so zoo/
    cp loops.c zoo/loops-source.c
    printf '# stepwise assignment 1\n# scene: spring\n# integrator: euler\n# dt: 0.02\n# steps: 20\n' > a.txt
    timeout 600 "$SW" grade --assignment a.txt --csv g.csv --results r.json zoo >g.out 2>g.err; rc=$?
    [ "$rc" -eq 1 ] || fail "grade the zoo: exit $rc, want 1: $(cat g.out g.err)"
    awk -f "$json" r.json > g.fields || fail "results.json is not JSON"
    # every plugin fails: a class mean of 0, out of the homework's 1 point (values)
    grep -qx 'score=0' g.fields && grep -qx 'max_score=1' g.fields || fail "zoo score: $(grep score g.fields | head -3)"
    [ "$(grep -c ',pass,' g.csv)" -eq 0 ] || fail "a zoo plugin passed: $(cat g.csv)"
    [ "$(wc -l < g.csv)" -eq 13 ] || fail "gradebook rows: $(cat g.csv)"
    grep -q 'loops-source.c,limit,4,the plugin used 2 s of its own CPU time without returning.*,0,1,.$' g.csv || fail "looping .c source: $(cat g.csv)"
    grep -q 'info-loops.so,error,,.*,0,1,.$' g.csv || fail "info loop in grade: $(cat g.csv)"
}

# play: a failing plugin is disabled with a message, the UI goes on, q leaves a sane terminal.
# (A pause after each exit: on a loaded machine keys typed the instant the
# shell is back can be lost, which is the harness's flake, not the terminal's.)
sane() {
    wait_exit "$1"
    sleep 0.3
    s=""
    for try in 1 2 3; do # the marker is computed by the shell, so the typed line cannot match it
        type_cmd "stty -a | tr ' ;' '\n\n' | grep -E '^-?(icanon|echo|isig)\$' | tr '\n' ' '; echo STTY-\$((40+$try))"
        wait_for "STTY-4$try\$" 5 && s=$(screen | grep -E "STTY-4$try\$" | tail -1)
        [ -n "$s" ] && break
    done
    case "$s" in
        '') fail "no answer from stty after $1" ;;
        *-icanon*|*-echo\ *|*-isig*) fail "terminal left raw after $1: $s" ;;
    esac
    echo "$s" | grep -q 'icanon' || fail "no stty line after $1: $s"
}
part_play() {
    trap tmux_cleanup EXIT # (its tmux server is this part's: the test's own trap does not know it)
    tmux_start
    # (The loop is stopped after 2 s of its own CPU time, or at the latest
    # 50 x 2 s of wall time (host_link.c's WATCH_WALL): on a loaded machine
    # the first can take longer than the default wait, so the wait is the
    # second's, with a margin.)
    for p in exits aborts segv loops over-one over-many over-y writes-dim allocs; do
        type_cmd "$SW play spring --plugin ./$p.so -i $p"
        wait_for "plugin $p disabled" 130 || fail "play: $p was not disabled"
        wait_for 'spring +euler +dt=0\.02' 5 || fail "play: the UI did not go on under euler after $p"
        keys q
        sane "play-$p"
    done
    # NaN is a numerical blow-up: the banner says so and the UI waits for a key.
    type_cmd "$SW play spring --plugin ./nan.so -i nan"
    wait_for 'BLOWN UP at step 4' 10 || fail "play: the NaN plugin's blow-up is not shown"
    keys q
    sane "play-nan"
    # Refused at load: one line, no curses started, a sane shell.
    for p in info-loops badname; do
        type_cmd "$SW play spring --plugin ./$p.so"
        wait_for "stepwise: --plugin './$p.so'" 130 || fail "play: no one-line refusal of $p"
        sane "play-$p"
    done
    # Ctrl-C in play while the plugin loops (a 60 s watchdog): the UI ends at once, sane.
    type_cmd "STEPWISE_PLUGIN_TIMEOUT=60 $SW play spring --plugin ./loops.so -i loops"
    wait_for 'spring +loops' 5 || fail "play with the looping plugin did not start"
    stepping() { [ -n "$(child_of "$(app_pid)")" ]; } # the plugin's sandboxed child runs (and loops)
    wait_until 30 stepping || fail "play: the looping plugin's child never ran"
    keys C-c
    wait_exit "Ctrl-C during a plugin loop"
    sane "play-loop-ctrl-c"
}

# The parts side by side, each in a subshell with its log; then their verdicts.
parts=""
start() { # NAME COMMAND...
    name=$1; shift
    ( "$@" ) > "part-$name.log" 2>&1 &
    parts="$parts $name:$!"
}
for p in exits aborts segv loops over-one over-many over-y writes-dim allocs; do
    start "$p" one_plugin "$p"
done
start nan part_nan
start info-loops one_load info-loops 'sw_plugin_info() used 2 s of its own CPU time without returning'
start badname one_load badname "name 'euler ' is not allowed"
start grade part_grade
start play part_play
failed=""
for np in $parts; do
    wait "${np#*:}" || { failed="$failed ${np%%:*}"; cat "part-${np%%:*}.log"; }
done
[ -z "$failed" ] || fail "the zoo's part(s)$failed failed (above)"

# A looping plugin never holds off a signal: with a 60 s watchdog, timeout's
# SIGTERM after 1 s still ends record, leaving no file behind (a record
# that held it off would be killed 30 s later: 137, not 124). (Alone, after
# the parts: its second is not shared with them.)
STEPWISE_PLUGIN_TIMEOUT=60 timeout -k 30 1 "$SW" record spring --plugin ./loops.so --steps 20 -o sig.trace 2>err; rc=$?
[ "$rc" -eq 124 ] || fail "record with a looping plugin under timeout 1: exit $rc: $(cat err)"
grep -q 'record interrupted at step' err || fail "no interrupt message: $(cat err)"
ls sig.trace sig.trace.tmp.* >/dev/null 2>&1 && fail "an interrupted record left a file"
echo "ok"
