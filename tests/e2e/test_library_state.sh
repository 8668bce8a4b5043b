#!/bin/sh
# The embedder's library keeps no global mutable state but what
# docs/embedding.md's "Threads" lists (issue 39: "global mutable state and
# no statement about threads"). nm reads the writable variables (.data,
# .bss) of the objects the library is made of (the Makefile's CORE_OBJ,
# asked of make itself); each must be one of those below, and the doc's
# Threads section must name the file each lives in. A new one fails here
# until the doc says what a thread may do with it.
. "$(dirname "$0")/lib.sh"

build=$(build_dir)
# (a make of its own: under `make sanitize` the parent's MAKEFLAGS would
# bring its jobserver, whose warning a nested make prints)
objs=$(env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL make -s -C "$ROOT" BUILD="$build" \
    --eval='sw-print-core-obj: ; @echo $(CORE_OBJ)' sw-print-core-obj) ||
    fail "make could not say which objects the library is made of"
objs=$(echo "$objs" | tr ' ' '\n' | grep '\.o$') # the objects only, whatever else make said
[ -n "$objs" ] || fail "make names no objects for the library"
doc="$ROOT/docs/embedding.md"

# name file: each writable variable the library may hold, and its file.
cat >"$WORK/known" <<'EOF'
extra engine/integrators.c
extra_disabled engine/integrators.c
nextra engine/integrators.c
memo sim/truth_along.c
EOF

for o in $objs; do
    [ -f "$o" ] || fail "no $o: build first (make)"
done
for o in $objs; do
    nm -f sysv "$o" || echo "nm failed on $o" >"$WORK/nm-failed"
done | awk -F'|' '
    $4 ~ /OBJECT/ {
        name = $1; sec = $7; gsub(/ /, "", name); gsub(/ /, "", sec)
        # a sanitizer build`s own bookkeeping (ASan`s ODR indicators), not the library`s state
        if (name ~ /^_+(odr_asan|asan|ubsan|sancov)/) next
        if (sec ~ /^\.bss/ || (sec ~ /^\.data($|\.)/ && sec !~ /^\.data\.rel\.ro/)) print name
    }' | sort -u >"$WORK/found"
[ -e "$WORK/nm-failed" ] && fail "$(cat "$WORK/nm-failed")"
[ -s "$WORK/found" ] || fail "nm found no writable variable in the library at all (the method table's registrations are one): is nm reading it?"

# The section of the doc that states the rule.
awk '/^## Threads/ { on = 1; next } /^## / { on = 0 } on' "$doc" >"$WORK/threads"
[ -s "$WORK/threads" ] || fail "$doc has no \"## Threads\" section"

while IFS= read -r name; do
    file=$(awk -v n="$name" '$1 == n { print $2 }' "$WORK/known")
    [ -n "$file" ] || fail "the library holds a writable global '$name' that docs/embedding.md's Threads does not list (say what a thread may do with it there, and add it here)"
    grep -q "$file" "$WORK/threads" || fail "docs/embedding.md's Threads does not name $file, where '$name' lives"
done <"$WORK/found"

# Each one listed is still there (else the doc and this list say too much).
while read -r name file; do
    grep -qx "$name" "$WORK/found" || fail "'$name' ($file) is no longer in the library: drop it here and from docs/embedding.md's Threads"
done <"$WORK/known"
echo ok
