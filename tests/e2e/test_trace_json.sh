#!/bin/sh
# `record` then `check --json`: the output parses as JSON (a strict parser in
# awk below, since a fresh Debian has awk but no python or jq) and has the
# fields docs/trace-format.md documents, for a pass, a failure and an error.
. "$(dirname "$0")/lib.sh"

# A strict JSON parser (RFC 8259 grammar, one value, nothing after it), in
# awk: tests/e2e/json.awk. Prints each scalar as "path=value".
cp "$ROOT/tests/e2e/json.awk" json.awk || exit 1

# field NAME: the value of NAME in fields (fails when absent)
field() { grep "^$1=" fields | head -1 | sed "s/^$1=//"; }
has() { grep -q "^$1=" fields || fail "no field $1 in: $(cat out)"; }

# The parser itself rejects broken JSON (so a pass below means something).
for broken in '{"a": 1,}' '{"a": nan}' '{"a": "x' '{"a": 1} x' '[1 2]' '{"a": 01}'; do
    printf '%s\n' "$broken" | awk -f json.awk >/dev/null 2>&1 && fail "parser accepts: $broken"
done
printf '{"a": [1, -2.5e-3, "q\\"\\u00e9"], "b": {"c": null, "d": true}}\n' | awk -f json.awk > fields \
    || fail "parser rejects valid JSON"
[ "$(field 'a\[1\]')" = "-2.5e-3" ] && [ "$(field b.d)" = "true" ] || fail "parser paths: $(cat fields)"

# --- pass --------------------------------------------------------------------
"$SW" record chain --steps 100 -o a.csv 2>/dev/null || fail "record"
"$SW" check --json a.csv > out 2>err
[ $? -eq 0 ] || fail "check --json of a good trace: $(cat out err)"
awk -f json.awk out > fields || fail "not JSON: $(cat out)"
for f in format version status pass exit trace plugin against reference scene integrator dt rtol atol \
         columns rows_expected rows_got rows_compared values_compared values_failed first_failure \
         largest_error max_abs_error max_rel_error reference_diverged plugin_diverged message; do
    has "$f"
done
[ "$(field format)" = "stepwise check 1" ] || fail "format"
[ "$(field status)" = "pass" ] && [ "$(field pass)" = "true" ] && [ "$(field exit)" = "0" ] || fail "pass fields"
[ "$(field scene)" = "chain" ] && [ "$(field integrator)" = "verlet" ] || fail "scene/integrator"
[ "$(field rows_compared)" = "101" ] && [ "$(field values_failed)" = "0" ] || fail "row counts"
[ "$(field columns)" = "$((2 + 4 * 10 + 1))" ] || fail "columns: $(field columns)"
[ "$(field first_failure)" = "null" ] || fail "first_failure should be null on a pass"

# --- fail at step 37 ---------------------------------------------------------
awk -F, -v OFS=, '$1 == "37" { $7 = $7 * 1.001 } { print }' a.csv > b.csv
"$SW" check --json b.csv > out 2>err
[ $? -eq 1 ] || fail "check --json of a changed trace: exit not 1"
awk -f json.awk out > fields || fail "not JSON: $(cat out)"
[ "$(field status)" = "fail" ] && [ "$(field pass)" = "false" ] && [ "$(field exit)" = "1" ] || fail "fail fields"
[ "$(field first_failure.kind)" = "value" ] || fail "kind"
[ "$(field first_failure.step)" = "37" ] || fail "first_failure.step: $(field first_failure.step)"
[ "$(field first_failure.column)" = "x1" ] || fail "first_failure.column: $(field first_failure.column)"
[ "$(field first_failure.line)" = "$((17 + 37 + 1))" ] || fail "first_failure.line: $(field first_failure.line)"
for f in t expected got abs_error rel_error tolerance_ratio; do has "first_failure.$f"; done
awk -v r="$(field first_failure.rel_error)" 'BEGIN { exit !(r > 0.0009 && r < 0.0011) }' \
    || fail "rel_error $(field first_failure.rel_error), want 0.001"
[ "$(field values_failed)" = "1" ] || fail "values_failed: $(field values_failed)"

# --- a diverged reference, a missing-rows failure, an error -----------------
"$SW" record spring --set k=1e6 --set c=0 --steps 100 -o blow.csv 2>/dev/null
"$SW" check --json blow.csv > out 2>err || fail "diverged trace against itself"
awk -f json.awk out > fields || fail "not JSON: $(cat out)"
has reference_diverged.step
has reference_diverged.reason
head -30 a.csv > short.csv
"$SW" check --json short.csv > out 2>err
[ $? -eq 1 ] || fail "short trace: exit not 1"
awk -f json.awk out > fields || fail "not JSON: $(cat out)"
[ "$(field first_failure.kind)" = "missing_rows" ] || fail "short: kind $(field first_failure.kind)"
[ "$(field rows_got)" = "13" ] && [ "$(field rows_expected)" = "101" ] || fail "short: row counts"
printf 'garbage\n' > 'we"ird\name.csv'
"$SW" check --json 'we"ird\name.csv' > out 2>err
[ $? -eq 2 ] || fail "garbage: exit not 2"
awk -f json.awk out > fields || fail "error object is not JSON: $(cat out)"
[ "$(field status)" = "error" ] && [ "$(field exit)" = "2" ] || fail "error fields"
field error | grep -q 'name.csv:1: not a stepwise trace' || fail "error text: $(field error)"
echo "ok"
