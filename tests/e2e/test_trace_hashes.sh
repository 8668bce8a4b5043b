#!/bin/sh
# e2e: long (run.sh starts it first)
# Traces are pinned: every scene under every built-in method, 300 steps,
# must reproduce tests/data/trace_hashes.orig.txt bit for bit (the sha256 of
# the data rows). A refactor never changes a hash; a deliberate numerical
# change regenerates the file with tests/data/trace_hashes.sh and says why in
# its commit message. A row the binary makes that the file lacks (a new
# scene or method) fails too, naming the row: pin it with the generator,
# adding only the missing rows, and say so in the commit. The pinned file
# holding a row the binary no longer makes fails as "missing".
. "$(dirname "$0")/lib.sh"
pinned="$ROOT/tests/data/trace_hashes.orig.txt"
sh "$ROOT/tests/data/trace_hashes.sh" "$STEPWISE" > now.txt || fail "the generator failed"
[ -s now.txt ] || fail "the generator printed nothing"
n=0 bad=0
while read -r scene method hash; do
    n=$((n + 1))
    got=$(awk -v s="$scene" -v m="$method" '$1 == s && $2 == m { print $3 }' now.txt)
    if [ "$got" != "$hash" ]; then
        echo "FAIL: $scene $method: pinned $hash, now ${got:-missing}"
        bad=$((bad + 1))
    fi
done < "$pinned"
[ "$n" -ge 90 ] || fail "only $n pinned rows in $pinned"
awk 'NR == FNR { pinned[$1 " " $2] = 1; next } !(($1 " " $2) in pinned) { print "FAIL: not pinned: " $0 }' \
    "$pinned" now.txt > unpinned.txt
cat unpinned.txt
unpinned=$(wc -l < unpinned.txt)
[ "$bad" -eq 0 ] || fail "$bad of $n pinned traces changed"
[ "$unpinned" -eq 0 ] || fail "$unpinned rows not pinned in $pinned (add them: sh tests/data/trace_hashes.sh)"
echo "trace hashes: $n of $n reproduced bit for bit"
