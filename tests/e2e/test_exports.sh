#!/bin/sh
# Anything not in a header is static (STYLE.md), and a function no other
# object calls needs no header: nm over the build's objects finds every
# global function of src/ that no object (src/, the tests, the plugin
# host) refers to, nor the benchmarks' sources. Such a function must be static, or
# public API (declared in include/stepwise/, for embedders), or one of the
# few kept below with the reason. Issue 39 found nine; a0ccd59 made them
# static, and this keeps it so. Before the real check, the checker is
# tried on planted objects.
. "$(dirname "$0")/lib.sh"

build=$(build_dir)
[ -d "$build/src" ] || fail "no objects under $build/src (set SW_BUILD to the build directory)"
command -v nm >/dev/null || fail "nm is needed"

# Kept global with no caller, and why:
#   main                 a program's entry
#   sw_scene_flow        what a flow scene in a file of its own (the scene
#                        walk-through) builds with (scenes/scenes.h)
#   aligned_alloc memalign posix_memalign pvalloc valloc
#                        the plugin host's allocator overrides (host/host_alloc.c):
#                        the C library calls them by interposition
kept="main sw_scene_flow aligned_alloc memalign posix_memalign pvalloc valloc"

# lonely DEFS_DIR ALL_DIRS...: "name object" for each global function
# defined in an object under DEFS_DIR that no object under ALL_DIRS refers to.
lonely() {
    defs_dir=$1
    shift
    # one nm for all the objects (-A: each line starts with its file)
    find "$defs_dir" -name '*.o' -print0 | sort -z | xargs -0 nm -A -g --defined-only \
        | awk '$2 == "T" { o = $1; sub(/:[^:]*$/, "", o); print $3, o }' >"$WORK/defs" || fail "nm failed on $defs_dir"
    find "$@" -name '*.o' -print0 | xargs -0 nm -u | awk 'NF && $NF !~ /:$/ { print $NF }' \
        | sort -u >"$WORK/uses" || fail "nm failed"
    # the first object defining each name no object uses
    awk 'NR == FNR { used[$1] = 1; next } !($1 in used) && !($1 in seen) { seen[$1] = 1; print $1, $2 }' \
        "$WORK/uses" "$WORK/defs"
}

# The checker itself: one function called from another object, one not,
# one static.
mkdir -p "$WORK/planted"
cat >"$WORK/planted/a.c" <<'EOF'
int called_elsewhere(void);
int called_nowhere(void);
static int kept_inside(void) { return 1; }
int called_elsewhere(void) { return kept_inside(); }
int called_nowhere(void) { return 2; }
EOF
cat >"$WORK/planted/b.c" <<'EOF'
int called_elsewhere(void);
int caller(void);
int caller(void) { return called_elsewhere(); }
EOF
(cd "$WORK/planted" && cc -c a.c && cc -c b.c) || fail "cannot compile the planted objects"
lonely "$WORK/planted" "$WORK/planted" >"$WORK/planted.out"
grep -q '^called_nowhere ' "$WORK/planted.out" || fail "the checker missed a function with no caller: $(cat "$WORK/planted.out")"
grep -q '^called_elsewhere \|^kept_inside ' "$WORK/planted.out" && fail "the checker flagged a called or static function: $(cat "$WORK/planted.out")"

# The real check.
dirs="$build/src"
for d in "$build/tests" "$build/host-obj"; do
    [ -d "$d" ] && dirs="$dirs $d"
done
# shellcheck disable=SC2086 # the directories are words
lonely "$build/src" $dirs >"$WORK/found"
[ -s "$WORK/defs" ] || fail "no global functions found under $build/src"
bad=""
while read -r name obj; do
    case " $kept " in *" $name "*) continue ;; esac
    src=${obj#"$build"/}
    [ -f "$ROOT/${src%.o}.c" ] || continue # a stale object, its source gone
    grep -qw "$name" "$ROOT"/include/stepwise/*.h && continue
    # the benchmark program is compiled from its sources in one command (no objects)
    grep -qw "$name" "$ROOT"/bench/*.c 2>/dev/null && continue
    bad="$bad
  $name (${obj#"$build"/})"
done <"$WORK/found"
[ -z "$bad" ] || fail "global functions no other object calls (make them static, or say here why not):$bad"
echo ok
