#!/bin/sh
# The embedder's library keeps no global mutable state but what
# docs/embedding.md's "Threads" lists (issue 39: "global mutable state and
# no statement about threads"). nm reads the writable variables (.data,
# .bss) of build/libstepwise.a; each must be one of those below, and the
# doc's Threads section must name the file each lives in. A new one fails
# here until the doc says what a thread may do with it.
. "$(dirname "$0")/lib.sh"

build=${SW_BUILD:-$ROOT/build}
lib="$build/libstepwise.a"
[ -f "$lib" ] || fail "no $lib (make builds it; set SW_BUILD to the build directory)"
doc="$ROOT/docs/embedding.md"

# name file: each writable variable the library may hold, and its file.
cat >"$WORK/known" <<'EOF'
extra engine/integrators.c
extra_disabled engine/integrators.c
nextra engine/integrators.c
memo sim/truth_along.c
EOF

nm -f sysv "$lib" | awk -F'|' '
    $4 ~ /OBJECT/ {
        name = $1; sec = $7; gsub(/ /, "", name); gsub(/ /, "", sec)
        if (sec ~ /^\.bss/ || (sec ~ /^\.data($|\.)/ && sec !~ /^\.data\.rel\.ro/)) print name
    }' | sort -u >"$WORK/found" || fail "nm failed on $lib"
[ -s "$WORK/found" ] || fail "nm found no writable variable in $lib at all (the method table's registrations are one): is nm reading it?"

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
