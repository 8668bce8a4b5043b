#!/bin/sh
# Student plugins: examples/euler_plugin.c builds as a shared object (with
# the Makefile's flags, warnings as errors), records a trace that passes as
# euler, is graded against euler (pass) and rk4 (fail) on the chain; plugins
# that lack the symbol, carry the wrong interface version, write NaN, fail
# their step or are not shared objects get a clear message, never a crash.
. "$(dirname "$0")/lib.sh"
needs_jail
CC=${CC:-cc}
build() { # name.so source.c
    $CC -std=c11 -O2 -Wall -Wextra -Wpedantic -Wshadow -Wstrict-prototypes -Wmissing-prototypes \
        -Werror -shared -fPIC -I"$root/include" -o "$1" "$2" 2>cc.err || fail "cannot build $2: $(cat cc.err)"
}
# run CMD...: status in $rc; a status above 128 is a crash
run() { "$@" >out 2>err </dev/null; rc=$?; [ "$rc" -lt 128 ] || fail "crashed ($rc): $*"; }

build euler.so "$root/examples/euler_plugin.c"

# --- the example works ---------------------------------------------------------
run "$SW" record spring --plugin ./euler.so --steps 300 -o mine.csv
[ "$rc" -eq 0 ] || fail "record with the plugin: $(cat err)"
grep -qx '# integrator: student-euler' mine.csv || fail "the plugin was not used"
run "$SW" check mine.csv --plugin ./euler.so
[ "$rc" -eq 0 ] || fail "plugin trace against a plugin rerun: $(cat out err)"
run "$SW" check mine.csv --reference euler
[ "$rc" -eq 0 ] || fail "plugin trace against euler: $(cat out err)"
run "$SW" check mine.csv
[ "$rc" -eq 2 ] && grep -q "unknown integrator 'student-euler'.*--plugin" err \
    || fail "a plugin trace without --plugin: exit $rc: $(cat err)"
run "$SW" check --plugin ./euler.so --reference euler --scene chain
[ "$rc" -eq 0 ] || fail "plugin vs euler on chain: $(cat out err)"
grep -q '^PASS: plugin student-euler on chain' out || fail "no PASS line: $(cat out)"
run "$SW" check --plugin ./euler.so --reference rk4 --scene chain --set n=4 --dt 0.005 --steps 40
[ "$rc" -eq 1 ] || fail "plugin euler graded as rk4: exit $rc, want 1"
grep -q 'first failure: step 1,' out || fail "rk4 difference not found at step 1: $(cat out)"
run "$SW" check --json --plugin ./euler.so --reference euler --scene vortex --set n=3 --until 2
[ "$rc" -eq 0 ] && grep -q '"plugin": "student-euler"' out || fail "plugin on a flow scene: $(cat out err)"
# the plugin appears in list integrators
run "$SW" list integrators
grep -q 'student-euler' out && fail "list shows a plugin that was not loaded"

# --- broken plugins: one clear line, exit 2 (NaN: a diverged run) -----------
cat > nosym.c <<'EOF'
int student_forgot_the_entry_point(void);
int student_forgot_the_entry_point(void) { return 0; }
EOF
cat > badabi.c <<'EOF'
#include <stepwise/integrator.h>
static int step(sw_ode *ode, double t, double *y, double h, double *work)
{ (void)ode; (void)t; (void)y; (void)h; (void)work; return 0; }
static const sw_plugin info = { .abi = SW_PLUGIN_ABI + 1, .name = "future", .step = step };
const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
EOF
sed 's/SW_PLUGIN_ABI + 1/1/' badabi.c > oldabi.c
cat > nan.c <<'EOF'
/* Writes NaN from the fourth step on. */
#include <stepwise/integrator.h>
static int step(sw_ode *ode, double t, double *y, double h, double *work)
{
    (void)work;
    for (int i = 0; i < ode->dim; i++)
        y[i] = t > 2.5 * h ? 0.0 / 0.0 : y[i];
    return 0;
}
static const sw_plugin info = { .abi = SW_PLUGIN_ABI, .name = "nan-writer", .step = step };
const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
EOF
cat > refuse.c <<'EOF'
/* Fails its step: returns non-zero from the start. */
#include <stepwise/integrator.h>
static int step(sw_ode *ode, double t, double *y, double h, double *work)
{ (void)ode; (void)t; (void)y; (void)h; (void)work; return -1; }
static const sw_plugin info = { .abi = SW_PLUGIN_ABI, .name = "refuser", .step = step };
const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
EOF
build nosym.so nosym.c
build badabi.so badabi.c
build oldabi.so oldabi.c
build nan.so nan.c
build refuse.so refuse.c
printf 'not a shared object\n' > text.so

one_line_2() { # what
    [ "$rc" -eq 2 ] || fail "$1: exit $rc, want 2: $(cat err)"
    [ "$(wc -l < err)" -eq 1 ] || fail "$1: stderr is not one line: $(cat err)"
}
run "$SW" record spring --plugin ./nosym.so
one_line_2 "missing symbol"; grep -q 'no sw_plugin_info symbol' err || fail "missing symbol: $(cat err)"
run "$SW" check --plugin ./nosym.so --reference euler --scene spring
one_line_2 "missing symbol (check)"
run "$SW" record spring --plugin ./badabi.so
one_line_2 "wrong interface"; grep -q 'plugin interface 3; this stepwise needs 2' err || fail "abi: $(cat err)"
run "$SW" record spring --plugin ./oldabi.so # built before sw_ode lost its fast-path fields
one_line_2 "old interface"; grep -q 'plugin interface 1; this stepwise needs 2: rebuild it from its .c' err ||
    fail "old abi: $(cat err)"
run "$SW" record spring --plugin ./text.so
one_line_2 "not a shared object"; grep -q 'could not be loaded' err || fail "text.so: $(cat err)"
run "$SW" record spring --plugin ./missing.so
one_line_2 "missing file"
run "$SW" record spring --plugin ./euler.so --plugin ./euler.so
one_line_2 "loaded twice"; grep -q "already exists" err || fail "twice: $(cat err)"

# NaN: a blow-up, reported in words; record exits 0, check fails (1).
run "$SW" record spring --plugin ./nan.so --steps 20 -o nan.csv
[ "$rc" -eq 0 ] || fail "NaN plugin record: exit $rc"
grep -q "nan-writer (plugin) diverged at step 4 .*non-finite" err || fail "NaN message: $(cat err)"
[ "$(grep '^[0-9]' nan.csv | tail -1 | cut -d, -f1,3)" = "4,nan" ] || fail "NaN trace end: $(tail -2 nan.csv)"
run "$SW" check --plugin ./nan.so --reference euler --scene spring --steps 20
[ "$rc" -eq 1 ] || fail "NaN plugin graded: exit $rc, want 1"
grep -q 'the plugin diverged at step 4' out || fail "NaN check report: $(cat out)"
# A step that returns non-zero stops the run, also without a crash.
run "$SW" record spring --plugin ./refuse.so --steps 20 -o refuse.csv
[ "$rc" -eq 0 ] && grep -q "refuser (plugin) stopped at step 1 (t = [0-9.e-]*): the plugin.s step function returned [0-9-]* (not 0) for the step from t = 0 with h = " err ||
    fail "refusing plugin: $rc $(cat err)"
# check says so too, without a "first failure" in the step column
run "$SW" check --plugin ./refuse.so --reference euler --scene spring --steps 20
grep -q "the plugin stopped at step 1" out && ! grep -q "first failure: .*column step" out ||
    fail "refusing plugin, check: $(cat out)"

# --- the Makefile rule builds the same example --------------------------------
make -s -C "$root" plugin-example >make.out 2>&1 || fail "make plugin-example: $(cat make.out)"
[ -f "$root/examples/euler_plugin.so" ] || fail "make plugin-example built nothing"
run "$SW" check --plugin "$root/examples/euler_plugin.so" --reference euler --scene spring
[ "$rc" -eq 0 ] || fail "the make-built plugin: $(cat out err)"
echo "ok"
