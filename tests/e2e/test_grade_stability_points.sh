#!/bin/sh
# `# points stability` for an honest symplectic plugin: symplectic Euler
# and velocity Verlet, each written as a student would and matching its
# method bit for bit on the graded runs, get the stability point. The
# method's limit is measured as the plugin's is; a plugin is never flagged
# symplectic, and the stability watch is laxer for a method that is
# (sim/watch.c), which once gave the method 1.91 and the plugin 1.61.
. "$(dirname "$0")/lib.sh"
needs_jail
json="$ROOT/tests/e2e/json.awk"
cat > symp.c <<'C'
#include <stepwise/integrator.h>
static int step(sw_ode *ode, double t, double *y, double h, double *work)
{
    int n = ode->dim, half = n / 2;
    sw_ode_eval(ode, t, y, work);
    for (int i = half; i < n; i++) y[i] += h * work[i];
    for (int i = 0; i < half; i++) y[i] += h * y[half + i];
    return 0;
}
static const sw_plugin info = { .abi = SW_PLUGIN_ABI, .name = "my-symp", .order = 1, .evals = 1,
                                .work_vectors = 1, .step = step };
const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
C
cat > verlet.c <<'C'
#include <stepwise/integrator.h>
static int step(sw_ode *ode, double t, double *y, double h, double *work)
{
    int n = ode->dim, half = n / 2;
    double *a = work, *b = work + n;
    sw_ode_eval(ode, t, y, a);
    for (int i = 0; i < half; i++) y[i] += h * y[half + i] + 0.5 * h * h * a[half + i];
    sw_ode_eval(ode, t + h, y, b);
    for (int i = half; i < n; i++) y[i] += 0.5 * h * (a[i] + b[i]);
    return 0;
}
static const sw_plugin info = { .abi = SW_PLUGIN_ABI, .name = "my-verlet", .order = 2, .evals = 2,
                                .work_vectors = 2, .step = step };
const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
C
for m in symplectic-euler verlet; do
    cat > hw-$m.txt <<A
# stepwise assignment 1
# scene: chain
# param n: 3
# integrator: $m
# dt: 0.01
# steps: 100
# points x* y*: 2
# points stability: 1
A
    f=symp.c; [ $m = verlet ] && f=verlet.c
    "$SW" grade --assignment hw-$m.txt --gradescope $m.json $f > $m.out 2>&1; rc=$?
    [ $rc -eq 0 ] || fail "$m: exit $rc: $(cat $m.out)"
    awk -f "$json" $m.json > $m.flat || fail "$m: results.json does not parse"
    grep -qx "score=3" $m.flat || fail "$m: an honest plugin lost points: $(grep -e '^score=' -e 'output=stab' $m.flat)"
done
# try shows the method's figure measured the same way beside the plugin's
"$SW" try symp.c --reference symplectic-euler --no-play > try.out 2>&1 || fail "try: $(cat try.out)"
line=$(grep 'stability  largest stable' try.out) || fail "try: no stability line: $(cat try.out)"
mine=$(echo "$line" | sed 's/.*w\*dt \([0-9.]*\) on.*/\1/')
theirs=$(echo "$line" | sed 's/.*(symplectic-euler: \([0-9.]*\), measured the same way).*/\1/')
[ -n "$mine" ] && [ "$mine" = "$theirs" ] || fail "try: the plugin's $mine against the method's $theirs: $line"
echo "ok: stability points for honest symplectic plugins"
