#!/bin/sh
# The include-direction test: every #include "..." in src/ and include/
# must point down the layers of docs/architecture.md (or stay in its own
# folder); plugin/ and lesson/ must not include each other, nor trace/ and
# measure/; only tui/ includes
# curses; nothing includes tests/; no header includes itself through others.
# With --objects BUILD it also fails on an include circle between modules:
# module A uses B (A's code calls or reads what B's .c defines, as B's
# header declares it) and B uses A, directly or round a longer cycle. The
# uses are read from the compiled objects (nm), because a header shared by
# a family (app.h, lesson/parse.h) hides which of its files calls which.
# Prints each violation and exits 1.
#
# usage: sh tests/layers.sh [--objects BUILD] [ROOT]  (ROOT: the repository, default .)
#        sh tests/layers.sh --self-test (proves it catches an upward include and a circle)
set -u

# Circles between files this branch could not edit, reported but not failed
# until their owners break them (issue 23). Keep this empty.
KNOWN_CIRCLES=""

# rank DIR: the layer of a folder under src/ (main.c is the top).
rank() {
    case "$1" in
        util) echo 0 ;; engine) echo 1 ;; scenes) echo 2 ;; sim) echo 3 ;;
        plugin|lesson) echo 4 ;; trace|measure) echo 5 ;; grade) echo 6 ;;
        app) echo 7 ;; render) echo 8 ;; tui) echo 9 ;; cli|host) echo 10 ;; main) echo 11 ;;
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
    # A header that includes itself through other headers (the guard hides it).
    hcycles=$(cd "$root" && for f in $files; do case "$f" in *.h)
        sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$f" |
            while read -r inc; do
                case "$inc" in stepwise/*) echo "$f include/$inc" ;; */*) echo "$f src/$inc" ;; esac
            done ;;
    esac; done | cycles)
    if [ -n "$hcycles" ]; then
        echo "$hcycles" | sed 's/^/layers: headers include each other: /'
        bad=$((bad + $(echo "$hcycles" | wc -l)))
    fi
    echo "layers: $n includes in $(echo "$files" | wc -w) files checked, $bad pointing the wrong way"
    [ "$bad" -eq 0 ]
}

# cycles: edges "A B [why]" (A uses B) on stdin; prints one cycle through each
# strongly connected group of two or more: "A -> B (why) -> ... -> A".
cycles() {
    awk '
    { if ($1 == $2) next
      if (!($1 in id)) { id[$1] = ++n; name[n] = $1 }
      if (!($2 in id)) { id[$2] = ++n; name[n] = $2 }
      a = id[$1]; b = id[$2]; r[a, b] = 1
      w = $0; sub(/^[^ ]+ [^ ]+ ?/, "", w); why[a, b] = w }
    END {
      for (k = 1; k <= n; k++) for (i = 1; i <= n; i++) if ((i, k) in r)
          for (j = 1; j <= n; j++) if ((k, j) in r) r[i, j] = 1
      for (i = 1; i <= n; i++) {
          if (done[i] || !((i, i) in r)) continue
          line = name[i]; v = i; split("", seen); seen[i] = 1; steps = 0
          do {  # the first step from v that still leads back to i
              for (j = 1; j <= n; j++)
                  if ((v, j) in why && (j == i || (!(j in seen) && (j, i) in r))) break
              if (j > n) break
              line = line " -> " name[j] (why[v, j] != "" ? " (" why[v, j] ")" : "")
              seen[j] = 1; v = j
          } while (v != i && ++steps < n)
          for (j = 1; j <= n; j++) if ((i, j) in r && (j, i) in r) done[j] = 1
          print line
      }
    }'
}

# Which module uses which, from the objects under BUILD/src whose source
# still exists: "A B sym, sym" lines (at most three symbols named).
object_uses() {
    build=$1 root=$2
    (cd "$build" && find src -name '*.o' | sort) | while read -r o; do
        m=${o%.o}
        [ -f "$root/$m.c" ] || continue
        nm -P -g "$build/$o" | awk -v m="$m" '{ print ($2 == "U" ? "U" : "D"), m, $1 }'
    done | awk '$1 == "D" { def[$3] = $2; next } { use[++n] = $2 " " $3 }
        END { for (i = 1; i <= n; i++) { split(use[i], p, " ")
                  if (p[2] in def && def[p[2]] != p[1]) print p[1], def[p[2]], p[2] } }' |
        sort -u | awk '{ k = $1 " " $2; if (!(k in s)) { s[k] = $3; c[k] = 1; o[++n] = k } else if (c[k]++ < 3) s[k] = s[k] ", " $3 }
            END { for (i = 1; i <= n; i++) print o[i], s[o[i]] }'
}

check_objects() {
    build=$1 root=$2
    command -v nm >/dev/null 2>&1 || { echo "layers: nm (binutils) not found: cannot look for circles"; return 1; }
    found=$(object_uses "$build" "$root" | cycles)
    nbad=0 nknown=0
    if [ -n "$found" ]; then
        while IFS= read -r c; do
            members=$(echo "$c" | sed 's/ ([^)]*)//g' | tr ' ' '\n' | grep -v '^->$' | sort -u | tr '\n' ' ' | sed 's/ $//')
            if echo "$KNOWN_CIRCLES" | grep -qxF "$members"; then
                echo "layers: known include circle (left to its owners): $c"; nknown=$((nknown + 1))
            else
                echo "layers: include circle: $c"; nbad=$((nbad + 1))
            fi
        done <<END
$found
END
    fi
    echo "layers: $(cd "$build" && find src -name '*.o' | wc -l) objects checked: $nbad include circles ($nknown known)"
    [ "$nbad" -eq 0 ]
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
    echo '#include "engine/f.h"' > "$t/src/engine/g.h"; echo '#include "engine/g.h"' > "$t/src/engine/f.h"
    check_tree "$t" >/dev/null && { echo "layers self-test: headers including each other pass"; exit 1; }
    rm "$t/src/engine/f.h" "$t/src/engine/g.h"
    echo '#include "lesson/d.h"' > "$t/src/plugin/e.c"; : > "$t/src/lesson/d.h"
    check_tree "$t" >/dev/null && { echo "layers self-test: plugin/ including lesson/ passes"; exit 1; }
    # A circle hidden behind one shared header: a.c calls b.c, b.c calls c.c, c.c calls a.c.
    mkdir -p "$t/build/src/engine"
    printf 'int sw_a(void), sw_b(void), sw_c(void);\n' > "$t/src/engine/family.h"
    printf '#include "family.h"\nint sw_a(void) { return sw_b(); }\n' > "$t/src/engine/a.c"
    printf '#include "family.h"\nint sw_b(void) { return sw_c(); }\n' > "$t/src/engine/b.c"
    printf '#include "family.h"\nint sw_c(void) { return 1; }\n' > "$t/src/engine/c.c"
    for m in a b c; do ${CC:-cc} -c "$t/src/engine/$m.c" -o "$t/build/src/engine/$m.o" || exit 1; done
    check_objects "$t/build" "$t" >/dev/null || { echo "layers self-test: objects without a circle fail"; exit 1; }
    printf '#include "family.h"\nint sw_c(void) { return sw_a(); }\n' > "$t/src/engine/c.c"
    ${CC:-cc} -c "$t/src/engine/c.c" -o "$t/build/src/engine/c.o" || exit 1
    check_objects "$t/build" "$t" | grep -qF 'include circle: src/engine/a -> src/engine/b (sw_b) -> src/engine/c (sw_c) -> src/engine/a (sw_a)' ||
        { echo "layers self-test: the circle a -> b -> c -> a passes"; exit 1; }
    echo "layers self-test: ok"
    exit 0
fi
objects=""
if [ "${1:-}" = "--objects" ]; then objects=${2:?--objects needs the build directory}; shift 2; fi
check_tree "${1:-.}" || exit 1
[ -z "$objects" ] || check_objects "$objects" "${1:-.}"
