#!/bin/sh
# What a lesson page says is done when the page is entered: every field of
# sw_lesson_page (lesson/lesson.h) is read in src/app/ as pg->FIELD (the
# lesson runner, app/runner.c, and what it calls), so a directive parsed
# into its field and then left unread — the last step of "Adding a lesson
# directive" in docs/architecture.md — is named here, not silent. The one
# field the app has no use for is `line`, the page's line in its file (the
# linter's messages).
. "$(dirname "$0")/lib.sh"
h="$ROOT/src/lesson/lesson.h"
awk '/^typedef struct sw_lesson_page \{/ { inside = 1; next }
     inside && /^\} sw_lesson_page;/ { inside = 0 }
     inside' "$h" | sed 's|/\*.*||; s|^ *\*.*||' | grep ';' | sed 's/\[.*//; s/;.*//' |
    awk '{ print $NF }' | tr -d '*' >fields
grep -qx ghost fields && [ "$(wc -l <fields)" -ge 20 ] ||
    fail "could not read sw_lesson_page's fields from $h: $(tr '\n' ' ' <fields)"
bad=0
while read -r f; do
    [ "$f" = line ] && continue
    if ! grep -qE "\bpg->$f\b" "$ROOT"/src/app/*.c; then
        echo "FAIL: sw_lesson_page's $f is read nowhere in src/app/ (what entering the page does with it: app/runner.c)"
        bad=$((bad + 1))
    fi
done <fields
[ "$bad" -eq 0 ] || fail "$bad page fields the app never reads"
echo "page fields: $(($(wc -l <fields) - 1)) read by the app, and line"
