#!/bin/sh
# Prints the pinned trace hashes: for every scene and every built-in method,
# in list order, "SCENE METHOD HASH" where HASH is the first 16 hex digits of
# the sha256 of the data rows (lines not starting with '#') of
#     stepwise record SCENE -i METHOD --steps 300 -o -
# or "SCENE METHOD refused" when the method cannot step the scene.
#
# usage: sh tests/data/trace_hashes.sh ./stepwise > tests/data/trace_hashes.orig.txt
#
# With a second argument, a file of "SCENE METHOD" lines, only those pairs
# are recorded and every other pair is printed as "SCENE METHOD skipped"
# (the quick tier's subset: tests/e2e/test_trace_hashes.sh).
#
# tests/e2e/test_trace_hashes.sh checks that the binary reproduces
# tests/data/trace_hashes.orig.txt bit for bit. Regenerate that file only for
# a deliberate numerical change (a new method, a corrected formula), and say
# in the commit message which rows changed and why: a refactor must never
# change a hash.
bin=${1:-./stepwise}
pick=${2:-}
for sc in $("$bin" list scenes | awk '{ print $1 }'); do
    for m in $("$bin" list integrators | awk '{ print $1 }'); do
        if [ -n "$pick" ] && ! grep -qx "$sc $m" "$pick"; then
            echo "$sc $m skipped"
        elif out=$("$bin" record "$sc" -i "$m" --steps 300 -o - 2>/dev/null); then
            h=$(printf '%s\n' "$out" | grep -v '^#' | sha256sum | cut -c1-16)
            echo "$sc $m $h"
        else
            echo "$sc $m refused"
        fi
    done
done
