/* util/decimal: the trace reader's number parser against the C library's
 * strtod, the independent implementation it must equal bit for bit and
 * end for end, on every kind of input a trace can hold: the recorder's
 * %.17g of random doubles over the whole range, short decimals, long
 * significands, integers around 2^53 and 2^64 (exact halfway cases),
 * exponents at and past the table's ends, and malformed text. Tolerance:
 * none; a single differing bit fails. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "util/decimal.h"

static uint64_t rng = 0x9E3779B97F4A7C15u;

static uint64_t next(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return rng;
}

static long checked;

/* Same bits (so -0 and 0 differ) and the same end as strtod, for both
 * entries; the padded one reads the text from a copy followed, past its
 * NUL, by seven '9's: bytes there must never change the number. */
static void same(const char *text)
{
    static char padded[600];
    char *e1, *e2, *e3;
    double a = sw_decimal_parse(text, &e1), b = strtod(text, &e2);
    ck_assert_msg(memcmp(&a, &b, sizeof a) == 0 || (isnan(a) && isnan(b)),
                  "'%s': %.17g, strtod %.17g", text, a, b);
    ck_assert_msg(e1 == e2, "'%s': ends at %td, strtod at %td", text, e1 - text, e2 - text);
    size_t len = strlen(text);
    ck_assert_uint_lt(len + 8, sizeof padded);
    memcpy(padded, text, len + 1);
    memset(padded + len + 1, '9', 7);
    double c = sw_decimal_parse_padded(padded, &e3);
    ck_assert_msg(memcmp(&c, &b, sizeof c) == 0 || (isnan(c) && isnan(b)),
                  "'%s' (padded): %.17g, strtod %.17g", text, c, b);
    ck_assert_msg(e3 - padded == e2 - text, "'%s' (padded): ends at %td, strtod at %td", text, e3 - padded,
                  e2 - text);
    checked++;
}

static double random_double(void)
{
    double d;
    do {
        uint64_t bits = next();
        memcpy(&d, &bits, sizeof d);
    } while (!isfinite(d));
    return d;
}

START_TEST(recorder_numbers)
{
    /* What a trace holds: %.17g of any finite double, and the shorter
     * forms a hand-edited or other tool's trace may hold. */
    static const char *const formats[] = { "%.17g", "%.16g", "%.15g", "%.6g", "%g", "%.3e", "%.10f" };
    char buf[512];
    long n = getenv("SW_TEST_QUICK") ? 20000 : 100000;
    for (long i = 0; i < n; i++) {
        double d = random_double();
        for (size_t f = 0; f < sizeof formats / sizeof formats[0]; f++) {
            snprintf(buf, sizeof buf, formats[f], d);
            same(buf);
        }
        /* Values of the size a scene's state has: 1e-20 .. 1e20. */
        double scaled = ldexp((double)(next() >> 11), -53) * pow(10.0, (double)(next() % 41) - 20.0);
        snprintf(buf, sizeof buf, "%.17g", (next() & 1) ? scaled : -scaled);
        same(buf);
    }
}
END_TEST

START_TEST(digit_strings)
{
    /* Random significands of 1-25 digits, a random point, exponents over
     * and past the table (±300) and the double range. */
    char buf[128];
    long n = getenv("SW_TEST_QUICK") ? 50000 : 300000;
    for (long i = 0; i < n; i++) {
        int nd = 1 + (int)(next() % 25), point = (int)(next() % (uint64_t)(nd + 2)) - 1;
        size_t k = 0;
        if (next() & 1)
            buf[k++] = (next() & 1) ? '-' : '+';
        for (int j = 0; j < nd; j++) {
            if (j == point)
                buf[k++] = '.';
            buf[k++] = (char)('0' + (j == 0 && (next() & 3) ? 1 + next() % 9 : next() % 10));
        }
        if (next() & 1)
            k += (size_t)snprintf(buf + k, sizeof buf - k, "%c%d", (next() & 1) ? 'e' : 'E',
                                  (int)(next() % 700) - 350);
        buf[k] = '\0';
        same(buf);
    }
}
END_TEST

START_TEST(halfway_integers)
{
    /* Around 2^53 every other integer is halfway between two doubles, and
     * around 2^54-2^64 the halfway points are integers too: round to even. */
    char buf[64];
    for (int e = 53; e <= 63; e++)
        for (int64_t d = -3000; d <= 3000; d++) {
            snprintf(buf, sizeof buf, "%llu", (unsigned long long)(((uint64_t)1 << e) + (uint64_t)d));
            same(buf);
            snprintf(buf, sizeof buf, "%llue-5", (unsigned long long)(((uint64_t)1 << e) + (uint64_t)d));
            same(buf);
        }
    /* The same halfway significands times powers of ten. */
    for (int i = 0; i < 200000; i++) {
        uint64_t m = ((uint64_t)1 << 53) + (next() % ((uint64_t)1 << 53)) * 2 + 1;
        snprintf(buf, sizeof buf, "%llue%d", (unsigned long long)m, (int)(next() % 80) - 40);
        same(buf);
    }
    /* Exact midpoints between neighbouring doubles, printed in full. */
    for (int i = 0; i < 20000; i++) {
        double d = ldexp(1.0 + ldexp((double)(next() >> 12), -52), (int)(next() % 120) - 60);
        long double mid = ((long double)d + (long double)nextafter(d, INFINITY)) / 2;
        snprintf(buf, sizeof buf, "%.25Lg", mid);
        same(buf);
        snprintf(buf, sizeof buf, "%.19Lg", mid); /* near halfway, within the fast path */
        same(buf);
    }
}
END_TEST

START_TEST(edges_and_malformed)
{
    static const char *const cases[] = {
        "0", "-0", "+0", "0.0", "-0.0", "0e999", "00000000000000000000000000001", "1", "-1",
        "1.", ".5", "-.5e-3", "+.5E+3", ".", "-", "+", "", "e5", "1e", "1e+", "1e-", "1e5x",
        "1.2.3", "--1", "+-1", " 1", "1 ", "0x10", "0x1p3", "inf", "-inf", "infinity", "nan",
        "nan(123)", "NaN", "1e308", "1.7976931348623157e308", "1.7976931348623159e308", "1e309",
        "2.2250738585072014e-308", "2.2250738585072011e-308", "4.9406564584124654e-324",
        "1e-324", "1e-400", "1e300", "1e-300", "1e301", "1e-301", "9007199254740993",
        "9007199254740992", "18446744073709551615", "18446744073709551616", "9999999999999999999",
        "10000000000000000000", "0.1", "0.2", "0.3", "1.4995000000000001", "123456789012345678e-30",
        "1e22", "1e23", "9007199254740991e22", "9007199254740993e-22", "1e0000000000000000000001",
        "1e-99999999999999999999", "1,5", "1e5.5", "12e", "0.000000000000000000000000000001e30",
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        same(cases[i]);
    /* Every power of ten in and past the table, and neighbours of each. */
    char buf[64];
    for (int q = -330; q <= 330; q++)
        for (int m = 1; m <= 9; m++) {
            snprintf(buf, sizeof buf, "%de%d", m, q);
            same(buf);
            snprintf(buf, sizeof buf, "%d.0000000000000001e%d", m, q);
            same(buf);
            snprintf(buf, sizeof buf, "%d999999999999999999e%d", m, q);
            same(buf);
        }
    /* Eight digits at a time meets every boundary: runs of 1-24 digits
     * with the point at every place (or none), leading zeros or not, and
     * each way a number can stop (the end, an exponent, a comma, a blank,
     * a letter, a second point). */
    static const char *const tails[] = { "", "e5", "E-7", ",", " ", "x", ".", ".5" };
    for (int len = 1; len <= 24; len++)
        for (int point = -1; point <= len; point++)
            for (size_t t = 0; t < sizeof tails / sizeof tails[0]; t++)
                for (int lead = 0; lead < 2; lead++) {
                    size_t k = 0;
                    if (lead)
                        k += (size_t)snprintf(buf + k, sizeof buf - k, "-000");
                    for (int i = 0; i < len; i++) {
                        if (i == point)
                            buf[k++] = '.';
                        buf[k++] = (char)('0' + (i == 0 ? 1 + next() % 9 : next() % 10));
                    }
                    if (point == len)
                        buf[k++] = '.';
                    snprintf(buf + k, sizeof buf - k, "%s", tails[t]);
                    same(buf);
                }
    ck_assert(sw_decimal_parse("2.5", NULL) == 2.5); /* end may be NULL, as for strtod */
    ck_assert_int_gt(checked, 10000);
}
END_TEST

Suite *make_decimal_suite(void);
Suite *make_decimal_suite(void)
{
    Suite *s = suite_create("decimal");
    TCase *tc = tcase_create("decimal");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, recorder_numbers);
    tcase_add_test(tc, digit_strings);
    tcase_add_test(tc, halfway_integers);
    tcase_add_test(tc, edges_and_malformed);
    suite_add_tcase(s, tc);
    return s;
}
