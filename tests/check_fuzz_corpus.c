/* Replays every seed and every past crash under tests/fuzz/NAME/ through
 * the fuzz targets: a crash found once stays a regression test, and each
 * file's verdict (accepted whole, or refused) must be the one pinned in
 * tests/data/fuzz_verdicts.txt ("TARGET FILE accept|refuse"), so a parser
 * that starts refusing a good lesson or accepting a broken trace fails. */
#include <check.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_targets.h"

/* The pinned verdict of TARGET/FILE: 1 accept, 0 refuse, -1 not listed. */
static int pinned(const char *target, const char *file)
{
    FILE *f = fopen("tests/data/fuzz_verdicts.txt", "r");
    ck_assert_msg(f != NULL, "no tests/data/fuzz_verdicts.txt (run the tests from the repository root)");
    char line[512], t[64], name[300], verdict[16];
    int found = -1;
    while (fgets(line, sizeof line, f))
        if (line[0] != '#' && sscanf(line, "%63s %299s %15s", t, name, verdict) == 3 &&
            strcmp(t, target) == 0 && strcmp(name, file) == 0)
            found = strcmp(verdict, "accept") == 0;
    fclose(f);
    return found;
}

static int replay(const char *target, int (*run)(const uint8_t *, size_t))
{
    char dir[128];
    snprintf(dir, sizeof dir, "tests/fuzz/%s", target);
    DIR *d = opendir(dir);
    ck_assert_msg(d != NULL, "no corpus directory %s (run the tests from the repository root)", dir);
    int n = 0;
    for (struct dirent *e; (e = readdir(d));) {
        if (e->d_name[0] == '.')
            continue;
        char path[512];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        FILE *f = fopen(path, "rb");
        ck_assert_ptr_nonnull(f);
        static uint8_t buf[1 << 20];
        size_t len = fread(buf, 1, sizeof buf, f);
        fclose(f);
        int want = pinned(target, e->d_name), got = run(buf, len);
        ck_assert_msg(want >= 0, "%s: no verdict in tests/data/fuzz_verdicts.txt (add '%s %s accept|refuse')",
                      path, target, e->d_name);
        ck_assert_msg(got == want, "%s: %s, pinned to %s", path, got ? "accepted" : "refused",
                      want ? "accept" : "refuse");
        n++;
    }
    closedir(d);
    return n;
}

START_TEST(corpus_lesson) { ck_assert_int_gt(replay("lesson", sw_fuzz_lesson), 3); }
END_TEST
START_TEST(corpus_trace) { ck_assert_int_gt(replay("trace", sw_fuzz_trace), 3); }
END_TEST
START_TEST(corpus_canvas) { ck_assert_int_ge(replay("canvas", sw_fuzz_canvas), 3); }
END_TEST
START_TEST(corpus_runner) { ck_assert_int_ge(replay("runner", sw_fuzz_runner), 3); }
END_TEST
START_TEST(corpus_check) { ck_assert_int_ge(replay("check", sw_fuzz_check), 4); }
END_TEST
START_TEST(corpus_parse) { ck_assert_int_gt(replay("parse", sw_fuzz_parse), 3); }
END_TEST
START_TEST(corpus_channel) { ck_assert_int_ge(replay("channel", sw_fuzz_channel), 6); }
END_TEST
START_TEST(corpus_roster) { ck_assert_int_ge(replay("roster", sw_fuzz_roster), 7); }
END_TEST
START_TEST(corpus_gradebook) { ck_assert_int_ge(replay("gradebook", sw_fuzz_gradebook), 5); }
END_TEST
START_TEST(corpus_similar) { ck_assert_int_ge(replay("similar", sw_fuzz_similar), 4); }
END_TEST

Suite *make_fuzz_corpus_suite(void);
Suite *make_fuzz_corpus_suite(void)
{
    Suite *s = suite_create("fuzz_corpus");
    TCase *tc = tcase_create("replay");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, corpus_lesson);
    tcase_add_test(tc, corpus_trace);
    tcase_add_test(tc, corpus_canvas);
    tcase_add_test(tc, corpus_runner);
    tcase_add_test(tc, corpus_check);
    tcase_add_test(tc, corpus_parse);
    tcase_add_test(tc, corpus_channel);
    tcase_add_test(tc, corpus_roster);
    tcase_add_test(tc, corpus_similar);
    tcase_add_test(tc, corpus_gradebook);
    suite_add_tcase(s, tc);
    return s;
}
