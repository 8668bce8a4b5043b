#!/bin/sh
# One end-to-end test for run.sh (run_one.sh BIN OUT TEST): runs TEST
# against BIN, keeps its log and status in the directory OUT and prints one
# line when it ends. Nothing is exported to the test but STEPWISE (a test's
# own variables, such as a trace held in $out, must not reach its
# programs' environment). The seconds are for the developer reading the
# log; never judged.
bin=$1 out=$2 t=$3
name=$(basename "$t" .sh)
t0=$(date +%s)
STEPWISE="$bin" sh "$t" >"$out/$name.log" 2>&1
rc=$?
took=$(( $(date +%s) - t0 ))
echo "$rc" >"$out/$name.rc"
case $rc in
    0) echo "e2e: $name: ok ($took s)" ;;
    77) if grep -q '^skip: ' "$out/$name.log"; then
            echo "e2e: $name: skipped ($(grep -m1 '^skip: ' "$out/$name.log" | cut -c7-))"
        else
            echo "e2e: $name: FAILED ($took s, log at the end)"
        fi ;;
    *) echo "e2e: $name: FAILED ($took s, log at the end)" ;;
esac
exit 0
