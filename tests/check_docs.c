/* The docs' lists checked against the tables they describe, in both
 * directions (issue 39: no silent gap): README's integrator table and its
 * key list, lessons/README.md's directives and locks, docs/scenes.md's
 * sections. A row the code lacks fails, and so does a built-in the doc
 * lacks. Run from the repository root (as make does). */
#include <check.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "lesson/controls.h"
#include "lesson/parse.h"
#include "stepwise/stepwise.h"

/* The whole file, NUL-terminated; fails the test when it cannot be read. */
static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    ck_assert_msg(f != NULL, "cannot open %s (run from the repository root)", path);
    static const size_t cap = 1 << 20;
    char *buf = malloc(cap);
    ck_assert_ptr_nonnull(buf);
    size_t n = fread(buf, 1, cap - 1, f);
    fclose(f);
    ck_assert_msg(n < cap - 1, "%s is larger than this test reads", path);
    buf[n] = '\0';
    return buf;
}

/* The text between the first `from` and the next `to` after it (cut in
 * place); fails when either is missing. */
static char *between(char *text, const char *from, const char *to, const char *path)
{
    char *a = strstr(text, from);
    ck_assert_msg(a != NULL, "%s: no '%s'", path, from);
    char *b = strstr(a + strlen(from), to);
    ck_assert_msg(b != NULL, "%s: no '%s' after '%s'", path, to, from);
    *b = '\0';
    return a;
}

/* README's integrator table lists the built-ins, in list order, each once. */
START_TEST(readme_integrator_table)
{
    char *text = slurp("README.md");
    char *table = between(text, "| name | method | order | evaluations per step |\n| --- | --- | --- | --- |\n",
                          "\n\n", "README.md");
    char *line = strchr(table, '\n') + 1;
    line = strchr(line, '\n') + 1; /* past the head and the rule */
    int rows = 0;
    for (; *line == '|'; rows++) {
        char name[64];
        ck_assert_msg(sscanf(line, "| %63[^ |] |", name) == 1, "README: a row without a name: %.40s", line);
        const sw_integrator *m = sw_integrator_at(rows);
        ck_assert_msg(m != NULL, "README's integrator table has a row '%s' past the %d built-ins", name,
                      sw_integrator_count());
        ck_assert_msg(strcmp(name, m->name) == 0,
                      "README's integrator table: row %d is '%s', the table's method %d is '%s'", rows + 1, name,
                      rows + 1, m->name);
        char *end = strchr(line, '\n');
        if (!end) {
            rows++;
            break;
        }
        line = end + 1;
    }
    ck_assert_msg(rows == sw_integrator_count(), "README's integrator table has %d rows for %d built-ins", rows,
                  sw_integrator_count());
    free(text);
}
END_TEST

/* How README writes a key that is no character. */
static const char *key_word(int key)
{
    switch (key) {
    case ' ': return "space";
    case SW_KEY_UP: return "Up";
    case SW_KEY_DOWN: return "Down";
    case SW_KEY_LEFT: return "Left";
    case SW_KEY_RIGHT: return "Right";
    case SW_KEY_TAB: return "Tab";
    case SW_KEY_BTAB: return "Shift-Tab";
    case SW_KEY_PGDN: return "PgDn";
    case SW_KEY_PGUP: return "PgUp";
    case SW_KEY_ESC: return "`Esc`";
    default: return NULL; /* a character: named in backquotes */
    }
}

/* The keys README's paragraph on playing names: each character in
 * backquotes, and `X`–`Y` as the range X..Y. */
static void named_keys(const char *s, unsigned char named[128])
{
    memset(named, 0, 128);
    static const char dash[] = "`\xe2\x80\x93`"; /* `–` */
    for (const char *p = strchr(s, '`'); p; p = strchr(p + 1, '`')) {
        const char *q = strchr(p + 1, '`');
        if (!q)
            break;
        if (q == p + 2 && (unsigned char)p[1] < 128) {
            int lo = p[1], hi = lo;
            if (strncmp(q, dash, strlen(dash)) == 0 && q[strlen(dash) + 1] == '`')
                hi = q[strlen(dash)];
            for (int c = lo; c <= hi && c < 128; c++)
                named[c] = 1;
        }
        p = q; /* the closing quote opens nothing */
    }
}

/* README's key list (from "In a scene:" to "No terminal?") names a key of
 * every control of play and lessons, names no key that does nothing, and
 * names exactly the pick keys of the built-ins. */
START_TEST(readme_key_list)
{
    char *text = slurp("README.md");
    const char *keys = between(text, "In a scene:", "\nNo terminal?", "README.md");
    unsigned char named[128];
    named_keys(keys, named);
    int n;
    const sw_control *cs = sw_controls(&n);
    for (int i = 0; i < n; i++) {
        if (cs[i].context == SW_CTX_PANEL || cs[i].action == SW_ACT_PICK_METHOD)
            continue; /* the panel's keys are the arrows it shows; picking is checked below */
        int found = 0;
        for (const int *k = cs[i].keys; *k && !found; k++)
            found = key_word(*k) ? strstr(keys, key_word(*k)) != NULL : *k < 128 && named[*k];
        ck_assert_msg(found, "README's key list (\"In a scene:\") names no key of '%s'", cs[i].name);
    }
    const sw_control *c;
    int arg;
    for (int k = 1; k < 128; k++)
        ck_assert_msg(!named[k] || sw_key_lookup(k, SW_CTX_PLAY | SW_CTX_LESSON | SW_CTX_PANEL, &c, &arg),
                      "README's key list names `%c`, which no control has", k);
    const int *pick = sw_control_of(SW_ACT_PICK_METHOD)->keys;
    for (int i = 0; pick[i]; i++)
        ck_assert_msg(named[pick[i]] == (i < sw_integrator_count()), "README's key list %s `%c`, %s%s",
                      named[pick[i]] ? "names" : "lacks", pick[i],
                      i < sw_integrator_count() ? "the pick key of " : "a pick key past the built-ins",
                      i < sw_integrator_count() ? sw_integrator_at(i)->name : "");
    free(text);
}
END_TEST

/* lessons/README.md shows every directive as `@NAME, and every `@NAME it
 * shows is one (`@directive`, the table's head, stands for any; a word it
 * also shows escaped, `\@home`, is prose shown as typed). */
START_TEST(lesson_guide_directives)
{
    char *text = slurp("lessons/README.md");
    for (int k = 0; sw_lp_directive_name(k); k++) {
        char want[80];
        int found = 0;
        snprintf(want, sizeof want, "`@%s", sw_lp_directive_name(k));
        for (const char *p = strstr(text, want); p && !found; p = strstr(p + 1, want)) {
            char next = p[strlen(want)];
            found = !(next >= 'a' && next <= 'z');
        }
        ck_assert_msg(found, "lessons/README.md never shows '@%s'", sw_lp_directive_name(k));
    }
    int seen = 0;
    for (const char *p = strstr(text, "`@"); p; p = strstr(p + 1, "`@")) {
        char word[64];
        if (sscanf(p + 2, "%63[a-z]", word) != 1)
            continue;
        char escaped[80];
        snprintf(escaped, sizeof escaped, "`\\@%s`", word);
        if (strcmp(word, "directive") == 0 || strstr(text, escaped))
            continue;
        int known = 0;
        for (int k = 0; sw_lp_directive_name(k) && !known; k++)
            known = strcmp(word, sw_lp_directive_name(k)) == 0;
        ck_assert_msg(known, "lessons/README.md shows '@%s', which is no directive", word);
        seen++;
    }
    ck_assert_int_ge(seen, 19); /* the checker read the file: at least one mention of each */
    free(text);
}
END_TEST

/* The guide's lock table has a row per lock group, and "all", and no more. */
START_TEST(lesson_guide_locks)
{
    char *text = slurp("lessons/README.md");
    char *table = between(text, "| control | keys |\n| --- | --- |\n", "\n\n", "lessons/README.md");
    char *line = strchr(strchr(table, '\n') + 1, '\n') + 1;
    int rows = 0, groups = 0;
    for (; *line == '|'; rows++) {
        char name[64];
        ck_assert_msg(sscanf(line, "| `%63[^`]` |", name) == 1, "lessons/README.md: a lock row without a name");
        ck_assert_msg(sw_lock_find(name) != 0 && (strcmp(name, "all") == 0 || sw_lock_name(sw_lock_find(name))),
                      "lessons/README.md's lock table has '%s', which is no lock group", name);
        groups += strcmp(name, "all") != 0;
        char *end = strchr(line, '\n');
        if (!end) {
            rows++;
            break;
        }
        line = end + 1;
    }
    for (int b = 0; b < SW_LOCK_NGROUPS; b++) {
        char want[64];
        snprintf(want, sizeof want, "| `%s` |", sw_lock_name(1u << b));
        ck_assert_msg(strstr(table, want), "lessons/README.md's lock table has no row for '%s'",
                      sw_lock_name(1u << b));
    }
    ck_assert_int_eq(groups, SW_LOCK_NGROUPS);
    free(text);
}
END_TEST

/* docs/scenes.md has a section per scene, and every section is a scene or
 * one of the sections on all of them. */
START_TEST(scenes_doc_sections)
{
    static const char *const general[] = { "The two kinds of system", "Stepping", "Order of operations" };
    char *text = slurp("docs/scenes.md");
    for (int i = 0; i < sw_scene_count(); i++) {
        char head[80];
        snprintf(head, sizeof head, "\n## %s\n", sw_scene_at(i)->name);
        ck_assert_msg(strstr(text, head), "docs/scenes.md has no section '## %s'", sw_scene_at(i)->name);
    }
    int sections = 0;
    for (const char *p = strstr(text, "\n## "); p; p = strstr(p + 1, "\n## ")) {
        char title[80];
        ck_assert(sscanf(p + 4, "%79[^\n]", title) == 1);
        int known = sw_scene_find(title) != NULL;
        for (size_t g = 0; g < sizeof general / sizeof general[0] && !known; g++)
            known = strcmp(title, general[g]) == 0;
        ck_assert_msg(known, "docs/scenes.md's section '## %s' is no scene (nor a general section)", title);
        sections++;
    }
    ck_assert_int_eq(sections, sw_scene_count() + (int)(sizeof general / sizeof general[0]));
    free(text);
}
END_TEST

Suite *make_docs_suite(void);
Suite *make_docs_suite(void)
{
    Suite *s = suite_create("docs");
    TCase *tc = tcase_create("docs");
    tcase_add_test(tc, readme_integrator_table);
    tcase_add_test(tc, readme_key_list);
    tcase_add_test(tc, lesson_guide_directives);
    tcase_add_test(tc, lesson_guide_locks);
    tcase_add_test(tc, scenes_doc_sections);
    suite_add_tcase(s, tc);
    return s;
}
