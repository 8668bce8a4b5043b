#!/bin/sh
# A switch over the student's actions (sw_action: `switch (act)`,
# `switch (c->action)`, ...) has no `default:` (STYLE.md, "Extendable
# kinds"): each names every action, those another module handles through
# controls.h's generated SW_PLAY_CASES, SW_LESSON_CASES and SW_PANEL_CASES,
# so a new control gets -Wswitch's list of every place that must learn it.
# The checker is tried first on planted switches it must flag and pass.
. "$(dirname "$0")/lib.sh"

# flagged FILE...: "file:line" of each `default:` inside a switch whose
# subject is an action (a name ending in act or action).
flagged() {
    awk '
        FNR == 1 { depth = 0; in_sw = 0 }
        {
            line = $0
            sub(/\/\/.*/, "", line)
            if (!in_sw && line ~ /switch \(([a-z_]+(->|\.))?(act|action)\)/) { in_sw = 1; base = depth }
            if (in_sw && line ~ /(^|[^a-z_])default[ \t]*:/) print FILENAME ":" FNR
            n = split(line, ch, "")
            for (i = 1; i <= n; i++) {
                if (ch[i] == "{") depth++
                else if (ch[i] == "}") { depth--; if (in_sw && depth == base) in_sw = 0 }
            }
        }' "$@"
}

cat >bad.c <<'X'
int f(int act)
{
    switch (act) {
    case 1: { return 1; }
    default:
        return 0;
    }
}
int g(const sw_control *c)
{
    switch (c->action) {
    case 2:
        return 2;
        default: return 0;
    }
}
X
cat >good.c <<'X'
int f(int act)
{
    switch (act) {
    case 1: return 1;
    SW_LESSON_CASES
    case 0: return 0;
    }
    switch (kind) {
    default: return 3; /* not an action */
    }
    return 0;
}
X
[ "$(flagged bad.c | tr '\n' ' ')" = "bad.c:5 bad.c:14 " ] || fail "the checker missed a planted default: $(flagged bad.c)"
[ -z "$(flagged good.c)" ] || fail "the checker flagged a good file: $(flagged good.c)"

hits=$(find "$ROOT/src" -name '*.c' -exec sh -c 'for f; do echo "$f"; done' sh {} + | sort | while read -r f; do flagged "$f"; done)
[ -z "$hits" ] || fail "default: in a switch over actions (name every action instead): $hits"
n=$(grep -rlE 'switch \(([a-z_]+(->|\.))?(act|action)\)' "$ROOT/src" | wc -l)
[ "$n" -ge 3 ] || fail "only $n files switch over actions: has the subject's name changed?"
echo "action switches: none of $n files has a default"
