#!/bin/sh
# docs/architecture.md's walk-through "Adding a lesson directive", done as
# the docs say in a scratch copy of the tree: `@trails on|off`, trails
# shown or not when the page is entered, in its three files: its page
# field in sw_lesson_page (lesson/lesson.h), its function and its line in
# directives[] (lesson/directives.c), what entering the page does with it
# (app/runner.c). It builds (warnings as errors), `lesson --check` takes a
# good line and names file, line and column of a bad one and of a second
# on one page (the table's .once), a page with it turns the trails on or
# off when entered; and nothing is silent: before the runner's line, the
# page fields test (tests/e2e/test_page_fields.sh) names the field the app
# never reads and app/runner.c; the docs test (tests/check_docs.c) names
# lessons/README.md's missing @trails until it is written.
# Full tier only (make test-full).
. "$(dirname "$0")/lib.sh"
. "$ROOT/tests/e2e/walkthrough.sh"
walkthrough_full directive
walkthrough_copy

# 1. its page field
echo '    int trails;               /* -1 / 0 / 1: trails off or on (@trails) */' >"$WORK/field"
insert_before "$copy/src/lesson/lesson.h" '^    int events; ' "$WORK/field" || fail "no 'int events;' in sw_lesson_page"
# 2. its function and its line in directives[]
cat >"$WORK/fn" <<'X'
static int d_trails(sw_lp_parser *ps, size_t pos) { return sw_lp_on_off(ps, pos, "@trails", &sw_lp_page(ps)->trails); }
static void i_trails(sw_lesson_page *pg) { pg->trails = -1; }

X
insert_before "$copy/src/lesson/directives.c" '^/\* The directives: one line each' "$WORK/fn" ||
    fail "no 'The directives: one line each' comment above the table in directives.c"
echo '    { .name = "trails", .run = d_trails, .once = 1, .init = i_trails },' >"$WORK/row"
insert_in_table "$copy/src/lesson/directives.c" '^} directives\[\] = \{' "$WORK/row" ||
    fail "no directives[] table closed by '};' in directives.c"
# Nothing silent: with the field parsed and the runner not told, the page
# fields test names it and runner.c
STEPWISE=$SW sh "$copy/tests/e2e/test_page_fields.sh" >"$WORK/fields.log" 2>&1 &&
    fail "the page fields test passed with @trails parsed and never applied"
grep -q "sw_lesson_page's trails is read nowhere in src/app/ (.*app/runner.c)" "$WORK/fields.log" ||
    { cat "$WORK/fields.log"; fail "the page fields test does not name trails and runner.c"; }

# 3. what entering the page does with it
cat >"$WORK/enter" <<'X'
    if (pg->trails >= 0)
        a->trails = pg->trails;
X
insert_before "$copy/src/app/runner.c" '^    if \(pg->events >= 0\)' "$WORK/enter" || fail "no '@events' step in runner.c"

walkthrough_build stepwise build/check_stepwise
SWC=$copy/stepwise
STEPWISE=$SWC sh "$copy/tests/e2e/test_page_fields.sh" >"$WORK/fields.log" 2>&1 ||
    { cat "$WORK/fields.log"; fail "the page fields test fails with the runner's line in"; }

# lesson --check: a good line, a bad one, one too many
cat >"$WORK/good.lesson" <<'X'
title: Trails
--- On
@scene orbit
@trails on
The orbit leaves its trail.
--- Off
@trails off
And now it does not.
X
"$SWC" lesson --check "$WORK/good.lesson" >"$WORK/check.log" 2>&1 || fail "lesson --check refused @trails: $(cat "$WORK/check.log")"
printf 'title: T\n--- P\n@scene orbit\n@trails maybe\nText.\n' >"$WORK/bad.lesson"
"$SWC" lesson --check "$WORK/bad.lesson" >"$WORK/bad.log" 2>&1
[ $? -eq 2 ] || fail "lesson --check did not exit 2 on '@trails maybe'"
grep -q 'bad.lesson:4:[0-9]*: ' "$WORK/bad.log" || fail "no FILE:LINE:COL for '@trails maybe': $(cat "$WORK/bad.log")"
printf 'title: T\n--- P\n@scene orbit\n@trails on\n@trails off\nText.\n' >"$WORK/twice.lesson"
"$SWC" lesson --check "$WORK/twice.lesson" >"$WORK/twice.log" 2>&1
[ $? -eq 2 ] || fail "lesson --check took @trails twice on one page"
grep -q 'twice.lesson:5:' "$WORK/twice.log" || fail "the second @trails is not named: $(cat "$WORK/twice.log")"

# entering the pages: trails on, then off (a program of the copy's library)
cat >"$WORK/enter.c" <<'X'
#include <stdio.h>
#include "app/runner.h"
int main(int argc, char **argv)
{
    static sw_runner r;
    static sw_app a;
    char err[512];
    (void)argc;
    if (sw_runner_start(&r, &a, argv[1], 0, err, sizeof err) != 0)
        return puts(err), 1;
    a.trails = 0;
    sw_runner_enter(&r, &a, 0);
    int on = a.trails;
    sw_runner_enter(&r, &a, 1);
    printf("%d %d\n", on, a.trails);
    sw_runner_free(&r);
    sw_app_free(&a);
    return 0;
}
X
(cd "$copy" && cc -std=c11 -D_DEFAULT_SOURCE -Iinclude -Isrc "$WORK/enter.c" build/libstepwise-tool.a -lseccomp -lm -ldl \
    -o "$WORK/enter") >"$WORK/cc.log" 2>&1 || { cat "$WORK/cc.log"; fail "the page-entering program does not build"; }
got=$(XDG_STATE_HOME=$WORK/state "$WORK/enter" "$WORK/good.lesson") || fail "entering the pages failed: $got"
[ "$got" = "1 0" ] || fail "entering the pages gave trails '$got', not '1 0' (on, then off)"

# Named, not silent: the authoring guide's directives
(cd "$copy" && CK_RUN_SUITE=docs CK_FORK=yes ./build/check_stepwise) >"$WORK/docs.log" 2>&1 &&
    fail "the docs test passed without @trails in lessons/README.md"
grep -q "lessons/README.md never shows '@trails'" "$WORK/docs.log" ||
    { cat "$WORK/docs.log"; fail "the docs test does not name the missing @trails"; }
echo "directive walk-through: 3 files; the runner's line and the guide's row named until written; trails on and off"
