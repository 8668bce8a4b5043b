#!/bin/sh
# One end-to-end test for run.sh: runs $1 against $bin, keeps its log and
# status in $out and prints one line when it ends. The seconds are for the
# developer reading the log; never judged.
t=$1
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
