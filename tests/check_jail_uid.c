/* The uid jail's user ids (plugin/jail.c): two jails started together
 * never share one. Each takes the first id from its place in the range
 * that no other jail has claimed and no process runs as; before the
 * claim, two jails could both see an id unused (neither had a process of
 * it yet) and share it, and the first to end killed the other's runs
 * (sw_jail_kill_user). No root needed: a claim is an flock. */
#include <check.h>
#include <stdio.h>
#include <unistd.h>

#include "plugin/jail.h"

START_TEST(two_claims_at_once_differ)
{
    unsigned a = 0, b = 0, c = 0;
    int fa = sw_jail_claim_uid(17, &a);
    ck_assert_msg(fa >= 0, "no claim in /tmp: %d", fa);
    int fb = sw_jail_claim_uid(17, &b);
    ck_assert_msg(fb >= 0, "no second claim in /tmp: %d", fb);
    ck_assert_msg(a != b, "two jails claimed the same user id %u", a);
    ck_assert(a >= 61000 && a < 64000 && b >= 61000 && b < 64000);
    /* let go of the first, and the id is free again; its file goes with it */
    char path[64];
    snprintf(path, sizeof path, "/tmp/stepwise-uid-%u.lock", a);
    ck_assert_int_eq(access(path, F_OK), 0);
    sw_jail_release_uid(a, fa);
    ck_assert_msg(access(path, F_OK) != 0, "%s is left behind", path);
    int fc = sw_jail_claim_uid(a - 61000, &c); /* from its own place: no other jail's claim between */
    ck_assert_msg(fc >= 0 && c == a, "the released id %u was not taken again (got %u)", a, c);
    sw_jail_release_uid(b, fb);
    sw_jail_release_uid(c, fc);
}
END_TEST

Suite *make_jail_uid_suite(void);
Suite *make_jail_uid_suite(void)
{
    Suite *s = suite_create("jail_uid");
    TCase *tc = tcase_create("claim");
    tcase_add_test(tc, two_claims_at_once_differ);
    suite_add_tcase(s, tc);
    return s;
}
