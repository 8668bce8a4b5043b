#!/bin/sh
# Everything the code knows about a method lives in its row
# (docs/architecture.md, "Adding an integrator"): no method's name appears
# as a string in src/ outside the method table (engine/integrators.c) and
# the method's own file (the one that defines its row's step function).
# A scene's row may name its default method (.integrator = "NAME"), and a
# comment may name anything. The names are the built-ins `stepwise list
# integrators` prints. Before the real check, the checker is tried on
# planted lines it must flag and lines it must let pass.
. "$(dirname "$0")/lib.sh"

table="$ROOT/src/engine/integrators.c"
[ -f "$table" ] || fail "no method table at $table"

# Each row's name and its step function, from the table's named fields.
awk '
    /\.name = "/ { n = $0; sub(/.*\.name = "/, "", n); sub(/".*/, "", n) }
    /\.step = sw_step_/ { s = $0; sub(/.*\.step = /, "", s); sub(/[^a-z0-9_].*/, "", s); print n, s }
' "$table" >"$WORK/steps" || fail "awk failed on the table"

# check DIR: print "file:line: name" for each line of DIR's C files naming a
# method as a whole string where it may not.
check() {
    "$SW" list integrators | awk '{ print $1 }' >"$WORK/names" || fail "list integrators failed"
    [ -s "$WORK/names" ] || fail "list integrators printed no names"
    while IFS= read -r name; do
        step=$(awk -v n="$name" '$1 == n { print $2 }' "$WORK/steps")
        [ -n "$step" ] || fail "$name: no row with .name = \"$name\" and a .step in $table"
        own=$(grep -l "^int $step(" "$ROOT"/src/engine/*.c)
        [ -n "$own" ] || fail "$name: no file in src/engine defines $step"
        grep -rnF --include='*.c' --include='*.h' "\"$name\"" "$1" | while IFS= read -r hit; do
            file=${hit%%:*}
            text=${hit#*:*:}
            case "$(cd "$(dirname "$file")" && pwd)/$(basename "$file")" in
            "$table" | "$own") continue ;;
            esac
            # a comment's line, or a scene row's default method
            if printf '%s\n' "$text" | grep -Eq '^[[:space:]]*(\*|/\*|//)|\.integrator = "'; then
                continue
            fi
            echo "${hit%"$text"} $name"
        done
    done <"$WORK/names"
}

# The checker itself: planted lines.
mkdir -p "$WORK/planted/sub"
cat >"$WORK/planted/sub/bad.c" <<'EOF'
static int drawn(const sw_integrator *m) { return strcmp(m->name, "rk4") == 0; }
static const char *order[] = { "euler", "verlet" };
EOF
cat >"$WORK/planted/good.c" <<'EOF'
/* "rk4" named in a comment */
 * and "verlet" in a comment's later line
    .integrator = "verlet",
static const char *label = "rk4 (stages at t)";
EOF
check "$WORK/planted" >"$WORK/planted.out"
grep -q 'bad.c:1: rk4$' "$WORK/planted.out" || fail "the checker missed strcmp(m->name, \"rk4\"): $(cat "$WORK/planted.out")"
grep -q 'bad.c:2: euler$' "$WORK/planted.out" || fail "the checker missed a list of names: $(cat "$WORK/planted.out")"
grep -q 'bad.c:2: verlet$' "$WORK/planted.out" || fail "the checker missed the second name on a line"
grep -q 'good.c' "$WORK/planted.out" && fail "the checker flagged a comment, a scene default or a longer string: $(cat "$WORK/planted.out")"

check "$ROOT/src" >"$WORK/found"
if [ -s "$WORK/found" ]; then
    sed 's/^/    /' "$WORK/found"
    fail "a method named outside its row's files (above): put what the code knows about it in its row (engine/integrators.c, docs/architecture.md)"
fi
echo ok
