#!/bin/sh
# e2e: long (run.sh starts it first)
# `make install PREFIX=... DESTDIR=...` installs the binary, the man page, the
# lessons, the public headers, and for embedders the library and its
# pkg-config file; the installed binary finds its lessons, and a program
# builds against the installed stepwise.pc alone.
# Builds in its own build directory (the shared one is left alone), once
# with a staging DESTDIR and once into a real temporary PREFIX that the
# binary is then run from. make test-full builds it from nothing (at -O0);
# the quick tier (SW_TEST_QUICK) starts it from a copy of the objects of
# the plain build under test, so that only what PREFIX changes is compiled.
# Lessons: the tree's lessons/*.lesson when there are any; a lesson file
# dropped into the installed lessons directory in any case, so the lookup
# is tested even before lessons exist.
. "$(dirname "$0")/lib.sh"
build="$dir/build"
mk() { make -s -C "$root" BUILD="$build" BIN="$build/stepwise" OPT=-O0 "$@" >"$dir/make.out" 2>&1 \
       || fail "make $*: $(tail -20 "$dir/make.out")"; }
from=$(build_dir)
if [ -n "${SW_TEST_QUICK:-}" ] && [ -z "${SW_SANITIZED:-}" ] && [ "$from" = "$root/build" ] &&
    [ -f "$from/src/main.o" ] && [ -d "$from/host-obj" ]; then
    mkdir -p "$build"
    # (timestamps kept: make takes them as built; their .d files name the
    # shared build's objects, so they stay behind)
    cp -pR "$from/src" "$from/host-obj" "$build/" || fail "cannot copy the objects of $from"
    find "$build" -name '*.d' -exec rm -f {} + || fail "cannot leave the .d files behind"
fi

# --- staged: DESTDIR + PREFIX -------------------------------------------------
mk -j2 install PREFIX=/opt/sw DESTDIR="$dir/stage"
stage="$dir/stage/opt/sw"
[ -x "$stage/bin/stepwise" ] || fail "no binary in $stage/bin"
[ -x "$stage/libexec/stepwise/stepwise-plugin-host" ] || fail "no plugin host in $stage/libexec/stepwise"
[ -f "$stage/share/man/man1/stepwise.1" ] || fail "no man page"
head -5 "$stage/share/man/man1/stepwise.1" | grep -q '^\.TH STEPWISE 1' || fail "man page has no .TH line"
for h in "$root"/include/stepwise/*.h; do
    cmp -s "$h" "$stage/include/stepwise/$(basename "$h")" || fail "header $(basename "$h") not installed"
done
[ -d "$stage/share/stepwise/lessons" ] || fail "no lessons directory"
n_tree=$(ls "$root"/lessons/*.lesson 2>/dev/null | wc -l)
n_inst=$(ls "$stage"/share/stepwise/lessons/*.lesson 2>/dev/null | wc -l)
[ "$n_tree" -eq "$n_inst" ] || fail "$n_tree lessons in the tree, $n_inst installed"
"$stage/bin/stepwise" --version | grep -q '^stepwise [0-9]' || fail "installed binary --version"

# --- real: PREFIX only, then run the installed binary from elsewhere --------
prefix="$dir/prefix"
mk -j2 install PREFIX="$prefix"
bin="$prefix/bin/stepwise"
[ -x "$bin" ] || fail "no binary in $prefix/bin"
printf '# a stand-in lesson, placed by the install test\n' > "$prefix/share/stepwise/lessons/zz-install-test.lesson"
cd / || exit 1
out=$(env -u STEPWISE_LESSONS "$bin" list lessons 2>&1) || fail "installed list lessons: $out"
echo "$out" | grep -q 'zz-install-test.lesson' || fail "the installed binary does not look in $prefix/share/stepwise/lessons: $out"
for f in "$root"/lessons/*.lesson; do
    [ -e "$f" ] || continue
    echo "$out" | grep -q "$(basename "$f")" || fail "installed lesson $(basename "$f") not listed"
done
# The headless commands work from the install: record, then check.
"$bin" record spring --steps 20 -o "$dir/t.csv" 2>/dev/null && "$bin" check "$dir/t.csv" >/dev/null \
    || fail "installed record/check"
# A student plugin builds against the installed headers alone.
${CC:-cc} -std=c11 -Wall -Wextra -Wpedantic -Werror -shared -fPIC -I"$prefix/include" \
    -o "$dir/p.so" "$root/examples/euler_plugin.c" || fail "plugin against the installed headers"
# ... and runs in the installed host (PREFIX/libexec/stepwise), where a jail can be built
if why=$("$bin" autograder --probe 2>&1); then
    "$bin" check --plugin "$dir/p.so" --reference euler --scene spring >/dev/null || fail "installed plugin check"
else
    echo "skip: the installed plugin check: no jail for plugins can be built here: $why"
fi
# An embedder: a program built with `pkg-config --cflags --libs stepwise` and
# nothing of the tree, which runs a scene under a method through the public API.
[ -f "$prefix/lib/libstepwise.a" ] || fail "no libstepwise.a in $prefix/lib"
cat > "$dir/embed.c" <<'C'
#include <math.h>
#include <stdio.h>
#include <stepwise/stepwise.h>
static void oscillator(void *ctx, double t, const double *y, double *dydt)
{
    (void)ctx;
    (void)t;
    dydt[0] = y[1];
    dydt[1] = -y[0];
}
int main(void)
{
    const sw_scene *sc = sw_scene_find("spring");
    double p[SW_MAX_PARAMS];
    char err[SW_ERRLEN];
    sw_sim s;
    if (!sc)
        return 1;
    sw_scene_defaults(sc, p);
    if (sw_sim_init(&s, sc, p, sw_integrator_find("rk4"), 0.01, err, sizeof err) != SW_OK) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    sw_sim_run_until(&s, 1.0);
    printf("stepwise %s: t=%g steps=%ld\n", sw_version(), s.t, s.steps);
    sw_sim_free(&s);
    /* a system of its own, stepped by rk4 through the public stepper:
     * x'' = -x from (1, 0) for 100 steps of 0.01; the error against
     * cos(1) is RK4's, about h^4 / 120 ~ 1e-10: within 1e-8 */
    sw_ode osc = { .dim = 2, .order = 2, .deriv = oscillator };
    sw_stepper *st = sw_stepper_new(sw_integrator_find("rk4"), &osc, err, sizeof err);
    if (!st) {
        fprintf(stderr, "%s\n", err);
        return 1;
    }
    double t = 0, y[2] = { 1, 0 };
    for (int i = 0; i < 100; i++)
        if (sw_stepper_step(st, &osc, &t, y, 0.01) != SW_OK)
            return 1;
    sw_stepper_delete(st);
    printf("oscillator: x(%g) = %.10f, error %s\n", t, y[0], fabs(y[0] - cos(t)) < 1e-8 ? "small" : "LARGE");
    return 0;
}
C
flags=$(PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --cflags --libs stepwise) || fail "pkg-config does not know the installed stepwise"
# the engine alone: no libseccomp, even for a static link (the library holds no sandbox)
PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --static --libs stepwise | grep -q -- -lseccomp &&
    fail "pkg-config asks an embedder for -lseccomp"
# only sw_ names leave the library: no grader, lesson, jail or helper names
others=$(nm -g --defined-only "$prefix/lib/libstepwise.a" | awk 'NF == 3 { print $3 }' | grep -v '^sw_' | head -5)
[ -z "$others" ] || fail "the installed library exports names that are not sw_: $others"
nm -g --defined-only "$prefix/lib/libstepwise.a" | grep -q ' T sw_sim_init$' || fail "the library lacks sw_sim_init"
for s in sw_grade sw_lesson sw_jail sw_roster sw_trace_read sw_plugin_load; do
    nm -g --defined-only "$prefix/lib/libstepwise.a" | grep -q " $s" && fail "the engine library holds $s"
done
# shellcheck disable=SC2086
${CC:-cc} -std=c11 -Wall -Wextra -Werror -o "$dir/embed" "$dir/embed.c" $flags || fail "an embedder does not build against stepwise.pc: $flags"
out=$("$dir/embed") || fail "the embedder failed: $out"
# examples/embed, each built from the prefix with pkg-config alone and run
for e in particles stiff_spring orbit; do
    # shellcheck disable=SC2086
    ${CC:-cc} -std=c11 -Wall -Wextra -Werror -o "$dir/$e" "$ROOT/examples/embed/$e.c" $flags ||
        fail "examples/embed/$e.c does not build against stepwise.pc"
    "$dir/$e" > "$dir/$e.out" || fail "examples/embed/$e failed: $(cat "$dir/$e.out")"
done
# particles: the closed form of a ball under gravity and linear drag; euler
# at h = 0.01 is first order (an error of order h times the motion's second
# derivative, 1e-3 to 1e-1 m), rk4 fourth (below 1e-8 m)
awk '/^euler:/ { split($0, a, ": "); e = a[3] + 0; ok += (e > 1e-3 && e < 1e-1) }
     /^rk4:/ { split($0, a, ": "); e = a[3] + 0; ok += (e < 1e-8) } END { exit ok != 2 }' "$dir/particles.out" ||
    fail "examples/embed/particles: $(cat "$dir/particles.out")"
# stiff_spring: rk4 beyond its limit blows up; rodas4 stays bounded
grep -q "^rk4: .*blown up" "$dir/stiff_spring.out" && grep -q "^rodas4: |x(1)| = 0\.[0-9]*: bounded" "$dir/stiff_spring.out" ||
    fail "examples/embed/stiff_spring: $(cat "$dir/stiff_spring.out")"
# orbit: every frame reached, back at the start after one period (1e-8: the
# method's default tolerances are 1e-6 relative, 1e-9 absolute per step)
awk '{ for (i = 1; i <= NF; i++) if ($i == "within") d = $(i + 1) + 0 } END { exit !(d < 1e-8) }' "$dir/orbit.out" &&
    grep -q "^dop853: 189 frames" "$dir/orbit.out" || fail "examples/embed/orbit: $(cat "$dir/orbit.out")"
echo "$out" | grep -q '^stepwise [0-9.]*: t=1 steps=100$' || fail "the embedder ran: $out"
echo "$out" | grep -q '^oscillator: x(1) = 0.54030230.., error small$' || fail "the embedder's own system under rk4: $out"

mk uninstall PREFIX="$prefix"
[ ! -e "$bin" ] && [ ! -e "$prefix/share/man/man1/stepwise.1" ] && [ ! -e "$prefix/lib/libstepwise.a" ] &&
    [ ! -e "$prefix/lib/pkgconfig/stepwise.pc" ] || fail "uninstall left files"
echo "ok"
