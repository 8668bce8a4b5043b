#!/bin/sh
# Bad input to bench and stability: one line on stderr naming what was wrong,
# exit status 2, and no output file left behind (not even a temporary).
. "$(dirname "$0")/lib.sh"

# expect_usage PATTERN ARGS...: exit 2, one stderr line matching PATTERN, no stdout.
expect_usage() {
    pat=$1; shift
    "$SW" "$@" >"$dir/out" 2>"$dir/err"
    rc=$?
    [ "$rc" -eq 2 ] || fail "$*: exit $rc, want 2"
    [ "$(wc -l <"$dir/err")" -eq 1 ] || fail "$*: want one line on stderr, got: $(cat "$dir/err")"
    grep -q -- "$pat" "$dir/err" || fail "$*: stderr '$(cat "$dir/err")' lacks '$pat'"
    [ -s "$dir/out" ] && fail "$*: wrote to stdout: $(head -3 "$dir/out")"
    return 0
}

expect_usage "unknown scene 'nosuch'; scenes: vortex" bench nosuch
expect_usage "unknown integrator 'bogus'; integrators: euler" bench spring --integrators euler,bogus
expect_usage "listed twice" bench spring --integrators rk4,rk4
expect_usage "one SCENE" bench spring chain --set k=1
expect_usage "spring has no parameter 'kk'" bench spring --set kk=1
expect_usage "outside its range" bench spring --set k=-1
expect_usage "--repeats '0' is not allowed" bench --repeats 0
expect_usage "unknown option '--frobnicate'" bench --frobnicate
expect_usage "--csv needs a value" bench spring --csv
expect_usage "cannot create a file there" bench spring --csv "$dir/no/such/dir/p.csv"
mkdir "$dir/sub"
expect_usage "is a directory" bench spring --svg "$dir/sub"
rmdir "$dir/sub"
expect_usage "nothing to measure: fireworks has no exact solution" bench fireworks
expect_usage "stability needs a SCENE" stability
expect_usage "takes one SCENE" stability spring chain
expect_usage "unknown integrator 'nope'" stability spring --integrators nope
expect_usage "stability --all takes no SCENE" stability --all spring
expect_usage "bench: unknown option '--engine'" bench --engine

# A failed --svg open must not leave the --csv file (or its temporary) behind.
"$SW" bench spring --quick --csv "$dir/p.csv" --svg "$dir/no/dir/p.svg" >/dev/null 2>&1
[ $? -eq 2 ] || fail "unwritable --svg: want exit 2"
[ -z "$(ls "$dir" | grep -v -e '^out$' -e '^err$')" ] || fail "left behind: $(ls "$dir")"

# Help exits 0 and documents the stability criterion.
"$SW" stability --help | grep -q "fixed simulated time" || fail "stability --help lacks the criterion"
"$SW" stability --help | grep -q "one-step map" || fail "stability --help lacks the theory"
"$SW" bench --help | grep -q "least-squares slope" || fail "bench --help lacks the fit"
echo "bench and stability errors: ok"
