#!/bin/sh
# The include-direction test: every #include "..." in src/ and include/
# must point down the layers of docs/architecture.md (or stay in its own
# folder); plugin/ and lesson/ must not include each other, nor trace/ and
# measure/; only tui/ includes
# curses; nothing includes tests/. Prints each violation and exits 1.
#
# usage: sh tests/layers.sh [ROOT]      (ROOT: the repository, default .)
#        sh tests/layers.sh --self-test (proves it catches an upward include)
set -u

# rank DIR: the layer of a folder under src/ (main.c is the top).
rank() {
    case "$1" in
        util) echo 0 ;; engine) echo 1 ;; scenes) echo 2 ;; sim) echo 3 ;;
        plugin|lesson) echo 4 ;; trace|measure) echo 5 ;; grade) echo 6 ;;
        app) echo 7 ;; render) echo 8 ;; tui) echo 9 ;; cli) echo 10 ;; main) echo 11 ;;
        *) echo "" ;;
    esac
}

# The layer a public header belongs to: what it describes.
public_dir() {
    case "$1" in
        base.h) echo util ;;
        ode.h|integrator.h|flow.h|particles.h) echo engine ;;
        scene.h) echo scenes ;;
        sim.h|stepwise.h) echo sim ;;
        *) echo "" ;;
    esac
}

check_tree() {
    root=$1
    bad=0 n=0
    files=$(cd "$root" && find src include -name '*.[ch]' | sort)
    for f in $files; do
        case "$f" in
            src/main.c) from=main ;;
            src/*/*) from=$(echo "$f" | cut -d/ -f2) ;;
            include/stepwise/*) from=$(public_dir "$(basename "$f")") ;;
            *) from="" ;;
        esac
        from_rank=$(rank "$from")
        if [ -z "$from_rank" ]; then
            echo "layers: $f is in no layer (docs/architecture.md lists them)"; bad=$((bad + 1)); continue
        fi
        if [ "$from" != tui ] && grep -Eq '^[[:space:]]*#[[:space:]]*include[[:space:]]*<n?curses(w)?(/[a-z]+)?\.h>' "$root/$f"; then
            echo "layers: $f includes curses; only src/tui/ may"; bad=$((bad + 1))
        fi
        incs=$(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$root/$f")
        for inc in $incs; do
            n=$((n + 1))
            case "$inc" in
                stepwise/*) to=$(public_dir "${inc#stepwise/}"); target="include/$inc" ;;
                */*) to=${inc%%/*}; target="src/$inc" ;;
                *) to=""; target="" ;;
            esac
            case "$f" in include/*)
                case "$inc" in stepwise/*) ;; *)
                    echo "layers: $f: public header includes \"$inc\"; it may include only stepwise/*.h"
                    bad=$((bad + 1)); continue ;;
                esac ;;
            esac
            to_rank=$(rank "$to")
            if [ -z "$to_rank" ] || [ ! -f "$root/$target" ]; then
                echo "layers: $f: \"$inc\" is not a header of src/ or include/ (tests/ and the like are off limits)"
                bad=$((bad + 1)); continue
            fi
            if [ "$to_rank" -gt "$from_rank" ]; then
                echo "layers: $f ($from) includes \"$inc\" ($to), which is above it"; bad=$((bad + 1))
            elif [ "$to_rank" -eq "$from_rank" ] && [ "$to" != "$from" ]; then
                echo "layers: $f ($from) includes \"$inc\" ($to): side-by-side layers do not include each other"
                bad=$((bad + 1))
            fi
        done
    done
    echo "layers: $n includes in $(echo "$files" | wc -w) files checked, $bad pointing the wrong way"
    [ "$bad" -eq 0 ]
}

if [ "${1:-}" = "--self-test" ]; then
    t=$(mktemp -d)
    trap 'rm -rf "$t"' EXIT
    mkdir -p "$t/src/engine" "$t/src/app" "$t/src/plugin" "$t/src/lesson" "$t/include/stepwise"
    echo '#include "stepwise/base.h"' > "$t/src/engine/a.h"
    : > "$t/include/stepwise/base.h"
    echo '#include "engine/a.h"' > "$t/src/app/b.h"
    check_tree "$t" >/dev/null || { echo "layers self-test: a clean tree fails"; exit 1; }
    for bad in '#include "app/b.h"' '#include "alloc_count.h"' '#include <curses.h>'; do
        echo "$bad" > "$t/src/engine/c.c"
        check_tree "$t" >/dev/null && { echo "layers self-test: '$bad' in engine/ passes"; exit 1; }
    done
    rm "$t/src/engine/c.c"
    echo '#include "lesson/d.h"' > "$t/src/plugin/e.c"; : > "$t/src/lesson/d.h"
    check_tree "$t" >/dev/null && { echo "layers self-test: plugin/ including lesson/ passes"; exit 1; }
    echo "layers self-test: ok"
    exit 0
fi
check_tree "${1:-.}"
