/* Replays every seed and every past crash under tests/fuzz/NAME/ through
 * the fuzz targets: a crash found once stays a regression test. */
#include <check.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_targets.h"

static int replay(const char *dir, void (*target)(const uint8_t *, size_t))
{
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
        target(buf, len);
        n++;
    }
    closedir(d);
    return n;
}

START_TEST(corpus_lesson) { ck_assert_int_gt(replay("tests/fuzz/lesson", sw_fuzz_lesson), 3); }
END_TEST
START_TEST(corpus_trace) { ck_assert_int_gt(replay("tests/fuzz/trace", sw_fuzz_trace), 3); }
END_TEST
START_TEST(corpus_parse) { ck_assert_int_gt(replay("tests/fuzz/parse", sw_fuzz_parse), 3); }
END_TEST

Suite *make_fuzz_corpus_suite(void);
Suite *make_fuzz_corpus_suite(void)
{
    Suite *s = suite_create("fuzz_corpus");
    TCase *tc = tcase_create("replay");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, corpus_lesson);
    tcase_add_test(tc, corpus_trace);
    tcase_add_test(tc, corpus_parse);
    suite_add_tcase(s, tc);
    return s;
}
