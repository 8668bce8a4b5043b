#!/bin/sh
# The step watchdog charges a plugin its own CPU time, never the machine's
# load: with --plugin-timeout 1, an honest step that computes for 0.3 s of
# its own CPU passes while five busy loops share its one CPU (the step then
# takes about 1.8 s of wall time: a wall-clock watchdog failed it, blaming an
# endless loop); a step that loops is stopped after 1 s of its CPU time and
# a step that sleeps after 1 s asleep, each named as what it did. grade's
# --wall 1 passes the same honest student under the same load (it counts
# only time with nothing of the submission runnable).
. "$(dirname "$0")/lib.sh"
needs_jail
command -v taskset >/dev/null 2>&1 || { echo "skip: test_plugin_watchdog: no taskset"; exit 77; }
cat > slow.c <<'C'
#define _GNU_SOURCE
#include <stepwise/integrator.h>
#include <time.h>
static double seconds(clockid_t c)
{
    struct timespec ts;
    clock_gettime(c, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
/* Euler, after SPIN s of this thread's CPU time and SLEEP s asleep */
static int step(sw_ode *ode, double t, double *y, double h, double *work)
{
    volatile double sink = 0;
    for (double until = seconds(CLOCK_THREAD_CPUTIME_ID) + SPIN; seconds(CLOCK_THREAD_CPUTIME_ID) < until;)
        sink += 1;
    for (double until = seconds(CLOCK_MONOTONIC) + SLEEP; seconds(CLOCK_MONOTONIC) < until;) {
        struct timespec d = { 0, 20000000 };
        nanosleep(&d, NULL);
    }
    sw_ode_eval(ode, t, y, work);
    for (int i = 0; i < ode->dim; i++)
        y[i] += h * work[i];
    return 0;
}
static const sw_plugin info = { .abi = SW_PLUGIN_ABI, .name = "slow-euler", .label = "Euler, slowly",
                                .order = 1, .evals = 1, .work_vectors = 1, .step = step };
const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
C
for v in "heavy 0.3 0" "loop 1e9 0" "sleepy 0 1e9"; do
    set -- $v
    cc -std=c11 -O2 -shared -fPIC -I"$ROOT/include" -DSPIN=$2 -DSLEEP=$3 -o $1.so slow.c || fail "cannot build $1"
done
busy=""
for i in 1 2 3 4 5; do taskset -c 0 sh -c 'while :; do :; done' & busy="$busy $!"; done
trap 'kill $busy 2>/dev/null' EXIT
STEPWISE_PLUGIN_TIMEOUT=1 taskset -c 0 "$SW" record spring --plugin ./heavy.so --steps 1 -o heavy.csv 2>err
rc=$?
# grade's --wall too: it counts only time with nothing of the submission
# runnable, so the same student graded with --wall 1 passes
mkdir class && { printf '#define SPIN 0.3\n#define SLEEP 0\n'; cat slow.c; } > class/heavy.c
printf '# stepwise assignment 1\n# kind: plugin\n# scene: spring\n# integrator: euler\n# dt: 0.02\n# steps: 1\n# points x* y*: 1\n' > hw.txt
taskset -c 0 "$SW" grade --assignment hw.txt --wall 1 --plugin-timeout 1 class > grade.out 2>&1
kill $busy 2>/dev/null
grep -q "heavy.c .*pass" grade.out || fail "an honest slow plugin under load met --wall: $(cat grade.out)"
[ $rc -eq 0 ] || fail "an honest 0.3 s step under load failed ($rc): $(cat err)"
[ "$(grep -c '^[0-9]' heavy.csv)" -eq 2 ] || fail "heavy.csv lacks rows: $(cat heavy.csv)"
STEPWISE_PLUGIN_TIMEOUT=1 "$SW" record spring --plugin ./loop.so --steps 3 -o loop.csv 2>err && fail "a loop was not stopped"
grep -q "used 1 s of its own CPU time without returning from its step" err || fail "loop: $(cat err)"
STEPWISE_PLUGIN_TIMEOUT=1 "$SW" record spring --plugin ./sleepy.so --steps 3 -o sleepy.csv 2>err && fail "a sleeper was not stopped"
grep -q "slept 1 s without returning from its step" err || fail "sleepy: $(cat err)"
echo "ok: the step watchdog counts the plugin's CPU time (and its sleep), not the load"
