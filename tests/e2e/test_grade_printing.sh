#!/bin/sh
# A plugin that prints heavily runs out of its CPU time, and nothing named
# printing as the cause: its row now says how much it printed (its host
# counts what the plugin writes to stdout and stderr, then drops it). One
# that runs out of CPU time without printing is told the limit alone.
# Both end at --cpu 1 however fast the machine is (each loops for ever).
. "$(dirname "$0")/lib.sh"
needs_jail
cat > hw.txt <<'A'
# stepwise assignment 1
# kind: plugin
# scene: chain
# param n: 3
# integrator: euler
# dt: 0.01
# steps: 100
A
mkdir class
for name in chatty quiet; do
    if [ $name = chatty ]; then body='for (;;) printf("t = %g, y0 = %.17g\n", t, y[0]);'
    else body='for (volatile long k = 0;; k++) ;'; fi
    cat > class/$name.c <<C
#include <stdio.h>
#include <stepwise/integrator.h>
static int step(sw_ode *ode, double t, double *y, double h, double *work)
{
    sw_ode_eval(ode, t, y, work);
    for (int i = 0; i < ode->dim; i++) y[i] += h * work[i];
    $body
    return 0;
}
static const sw_plugin info = { .abi = SW_PLUGIN_ABI, .name = "$name", .order = 1, .evals = 1,
                                .work_vectors = 1, .step = step };
const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
C
done
"$SW" grade --assignment hw.txt --cpu 1 --plugin-timeout 120 --wall 240 --feedback fb class > out 2>&1
[ $? -eq 1 ] || fail "grade: $(cat out)"
grep -q "^  chatty .*limit .*ran out of its CPU time (SIGXCPU) after printing [0-9.]* [MG]iB to stdout and stderr (printing costs CPU time" out \
    || fail "the printing plugin is not told it printed: $(cat out)"
grep -q "after printing" fb/chatty.txt || fail "the feedback does not say it: $(cat fb/chatty.txt)"
grep -q "^  quiet .*limit .*ran out of its CPU time (SIGXCPU) at step" out || fail "the quiet one: $(cat out)"
grep -q "^  quiet .*printing" out && fail "the quiet one is told it printed: $(cat out)"
echo "ok: a plugin out of CPU time after printing much is told so"
