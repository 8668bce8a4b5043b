#!/bin/sh
# No process of a submission outlives the command that ran it (issue 21):
# a plugin that loops in its step is left running in its jail, then the
# stepwise process above it is killed (SIGKILL, SIGTERM; check, try and
# grade). Every process whose command line names this test's directory
# must be gone within 30 s. (A change of credentials clears a process's
# parent-death signal: the jail's first process once kept a looping
# plugin alive for good after its caller died.)
. "$(dirname "$0")/lib.sh"
needs_jail
cat > loop.c <<'C'
#include <stepwise/integrator.h>
static int step(sw_ode *ode, double t, double *y, double h, double *work)
{
    (void)ode; (void)t; (void)y; (void)h; (void)work;
    for (volatile int spin = 1; spin;)
        ;
    return 0;
}
static const sw_plugin info = { .abi = SW_PLUGIN_ABI, .name = "loop", .label = "loops",
    .order = 1, .evals = 1, .work_vectors = 1, .step = step };
const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
C
cc -std=c11 -shared -fPIC -I"$ROOT/include" -o loop.so loop.c || fail "cannot build the loop plugin"
printf '# stepwise assignment 1\n# scene: spring\n# integrator: euler\n# dt: 0.01\n# steps: 50\n' > a.txt
mkdir class && cp loop.so class/

# pids of the processes whose command line names $WORK (this shell's excluded)
ours() {
    for d in /proc/[0-9]*; do
        p=${d#/proc/}
        [ "$p" = "$$" ] && continue
        { tr '\0' ' ' < "$d/cmdline"; } 2>/dev/null | grep -q "$WORK" && echo "$p"
    done
}
# wait until the plugin's looping process is there: a process in state R
# (running) whose command line names $WORK, beyond the one we started
wait_running() {
    n=0
    while [ $n -lt 1200 ]; do
        for p in $(ours); do
            [ "$p" = "$1" ] && continue
            { grep -q '^State:.*R' "/proc/$p/status"; } 2>/dev/null && return 0
        done
        sleep 0.05; n=$((n + 1))
    done
    return 1
}
gone() {
    n=0
    while [ $n -lt 600 ]; do
        [ -z "$(ours)" ] && return 0
        sleep 0.05; n=$((n + 1))
    done
    return 1
}

for how in KILL TERM; do
    for cmd in "check --plugin $WORK/loop.so --reference euler --scene spring" \
               "try $WORK/loop.so --no-play --reference euler --scene spring" \
               "grade --assignment $WORK/a.txt $WORK/class"; do
        STEPWISE_PLUGIN_TIMEOUT=60 "$SW" $cmd >/dev/null 2>&1 &
        pid=$!
        wait_running "$pid" || { kill -KILL "$pid" 2>/dev/null; fail "$cmd: the plugin never ran"; }
        kill -"$how" "$pid"
        wait "$pid" 2>/dev/null
        gone || fail "SIG$how to '$cmd' left: $(for p in $(ours); do printf '%s(%s) ' "$p" "$({ tr '\0' ' ' < /proc/$p/cmdline; } 2>/dev/null)"; done)"
    done
done
echo ok
