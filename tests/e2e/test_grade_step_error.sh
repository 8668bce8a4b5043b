#!/bin/sh
# A plugin whose step returns an error ends its run at that step
# (docs/plugins.md): its row says so, not what the rows it no longer
# wrote look like (once: "step 0 appears twice ... write each step's row
# once", advice about writing a trace).
. "$(dirname "$0")/lib.sh"
needs_jail
printf '# stepwise assignment 1\n# kind: plugin\n# scene: spring\n# integrator: euler\n# dt: 0.01\n# steps: 10\n# points x* y*: 1\n' > hw.txt
mkdir class
sed 's/^    return 0;$/    return t > 2.5 * h ? 5 : 0;/' "$ROOT/examples/euler_plugin.c" > class/ret.c
grep -q "return t > 2.5" class/ret.c || fail "the fixture was not made"
"$SW" grade --assignment hw.txt class > out 2>&1
grep -q "ret.c .*fail .*the plugin's run ended at step 4 (t = 0.04): the plugin's step function returned 5 (not 0) for the step from t = 0.03 with h = 0.01" out \
    || fail "the row: $(cat out)"
grep -q "appears twice" out && fail "trace advice for a plugin: $(cat out)"
echo "ok: a step that returns an error is named as such"
