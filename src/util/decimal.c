/* Decimal to double, exactly as strtod, fast (see decimal.h). The method is
 * Clinger's fast path (an exact significand times an exact power of ten,
 * one rounding) and, beyond it, the Eisel-Lemire algorithm: the significand
 * times a 128-bit truncation of the power of ten, which decides the
 * correctly rounded result unless the product lies too close to a halfway
 * point, when it declines (D. Lemire, "Number parsing at a gigabyte per
 * second", Software: Practice and Experience 51(8), 2021, Algorithm 1; as in
 * Go's strconv). The powers' table is computed at first use with exact
 * integer arithmetic, not carried as constants. */
#include "util/decimal.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#define E_MIN (-300)
#define E_MAX 300
#define NPOW (E_MAX - E_MIN + 1)

/* pow_hi:pow_lo = the 128 leading bits of 10^q, truncated (q - E_MIN). */
static uint64_t pow_hi[NPOW], pow_lo[NPOW];
static int have_table; /* the program is single-threaded */

/* A natural number as 32-bit limbs, least significant first. 40 limbs hold
 * 10^300 (997 bits) and 2^1279, whose quotient by 10^300 keeps 282 bits. */
#define LIMBS 40
typedef struct big {
    uint32_t d[LIMBS];
    int n; /* limbs in use; d[n - 1] != 0 */
} big;

static int big_bits(const big *b)
{
    int bits = (b->n - 1) * 32;
    for (uint32_t top = b->d[b->n - 1]; top; top >>= 1)
        bits++;
    return bits;
}

static int big_bit(const big *b, int i)
{
    return i >= 0 && (b->d[i / 32] >> (i % 32)) & 1u;
}

/* The 128 leading bits of b (zeros after its last bit when it has fewer). */
static void big_top(const big *b, uint64_t *hi, uint64_t *lo)
{
    int top = big_bits(b) - 1;
    *hi = *lo = 0;
    for (int i = 0; i < 64; i++)
        *hi = *hi << 1 | (uint64_t)big_bit(b, top - i);
    for (int i = 64; i < 128; i++)
        *lo = *lo << 1 | (uint64_t)big_bit(b, top - i);
}

static void big_mul10(big *b)
{
    uint64_t carry = 0;
    for (int i = 0; i < b->n; i++) {
        uint64_t v = (uint64_t)b->d[i] * 10 + carry;
        b->d[i] = (uint32_t)v;
        carry = v >> 32;
    }
    if (carry)
        b->d[b->n++] = (uint32_t)carry;
}

/* b = floor(b / 10); floor(floor(x / 10^k) / 10) = floor(x / 10^(k+1)). */
static void big_div10(big *b)
{
    uint64_t rem = 0;
    for (int i = b->n - 1; i >= 0; i--) {
        uint64_t v = rem << 32 | b->d[i];
        b->d[i] = (uint32_t)(v / 10);
        rem = v % 10;
    }
    while (b->n > 1 && b->d[b->n - 1] == 0)
        b->n--;
}

static void make_table(void)
{
    big b;
    memset(&b, 0, sizeof b);
    b.d[0] = 1;
    b.n = 1;
    for (int q = 0; q <= E_MAX; q++) {
        big_top(&b, &pow_hi[q - E_MIN], &pow_lo[q - E_MIN]);
        big_mul10(&b);
    }
    /* 10^-q: the leading bits of floor(2^1279 / 10^q), exact as a floor. */
    memset(&b, 0, sizeof b);
    b.d[LIMBS - 1] = 0x80000000u;
    b.n = LIMBS;
    for (int q = -1; q >= E_MIN; q--) {
        big_div10(&b);
        big_top(&b, &pow_hi[q - E_MIN], &pow_lo[q - E_MIN]);
    }
    have_table = 1;
}

static void mul64(uint64_t a, uint64_t b, uint64_t *hi, uint64_t *lo)
{
#ifdef __SIZEOF_INT128__
    __extension__ typedef unsigned __int128 u128;
    u128 p = (u128)a * b;
    *hi = (uint64_t)(p >> 64);
    *lo = (uint64_t)p;
#else
    uint64_t a0 = (uint32_t)a, a1 = a >> 32, b0 = (uint32_t)b, b1 = b >> 32;
    uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    uint64_t mid = (p00 >> 32) + (uint32_t)p01 + (uint32_t)p10;
    *lo = mid << 32 | (uint32_t)p00;
    *hi = p11 + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
#endif
}

/* x > 0 */
static int leading_zeros(uint64_t x)
{
#if defined(__GNUC__)
    return __builtin_clzll(x);
#else
    int n = 0;
    for (uint64_t bit = (uint64_t)1 << 63; !(x & bit); bit >>= 1)
        n++;
    return n;
#endif
}

/* floor(x / 65536) for a negative x too. */
static long floor_div65536(long x)
{
    return x >= 0 ? x / 65536 : -((-x + 65535) / 65536);
}

/* w · 10^q correctly rounded into *out (w > 0, E_MIN <= q <= E_MAX);
 * 0 when the product cannot decide, or the result is not a normal double. */
static int eisel_lemire(uint64_t w, int q, int neg, double *out)
{
    int lz = leading_zeros(w);
    w <<= lz;
    /* 217706 / 2^16 = log2(10) to 7 digits: the binary exponent of 10^q. */
    long exp2 = floor_div65536(217706L * q) + 64 + 1023 - lz;
    uint64_t hi, lo;
    mul64(w, pow_hi[q - E_MIN], &hi, &lo);
    if ((hi & 0x1FF) == 0x1FF && lo + w < w) {
        /* The low bits are all ones: the truncated power's next 64 bits
         * may carry into them. */
        uint64_t yhi, ylo;
        mul64(w, pow_lo[q - E_MIN], &yhi, &ylo);
        uint64_t mhi = hi, mlo = lo + yhi;
        if (mlo < lo)
            mhi++;
        if ((mhi & 0x1FF) == 0x1FF && mlo + 1 == 0 && ylo + w < w)
            return 0;
        hi = mhi;
        lo = mlo;
    }
    uint64_t msb = hi >> 63;
    uint64_t mant = hi >> (msb + 9);
    exp2 -= (long)(1 ^ msb);
    if (lo == 0 && (hi & 0x1FF) == 0 && (mant & 3) == 1)
        return 0; /* exactly halfway, or so near that the truncation hides which side */
    mant += mant & 1;
    mant >>= 1;
    if (mant >> 53) {
        mant >>= 1;
        exp2++;
    }
    if (exp2 <= 0 || exp2 >= 0x7FF)
        return 0; /* subnormal or overflow: strtod's */
    uint64_t bits = (uint64_t)exp2 << 52 | (mant & 0x000FFFFFFFFFFFFFu);
    if (neg)
        bits |= (uint64_t)1 << 63;
    memcpy(out, &bits, sizeof *out);
    return 1;
}

static int is_digit(char c)
{
    return (unsigned char)(c - '0') < 10;
}

/* Eight digits at a time (where the caller guarantees the bytes can be
 * read): one test that all eight bytes are '0'-'9', and their value by
 * three multiplications (Lemire's method, as in fast_float). Little-endian
 * machines only; elsewhere one digit at a time. */
#if defined(__BYTE_ORDER__) && defined(__ORDER_LITTLE_ENDIAN__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
#define SWAR 1
static uint64_t load8(const char *p)
{
    uint64_t v;
    memcpy(&v, p, sizeof v);
    return v;
}

/* Each byte in 0x30..0x39: its high nibble 3, and still 3 after adding 6.
 * A byte of 0xFA or more carries into the next one's test, but its own
 * high nibble already fails. */
static int eight_digits(uint64_t v)
{
    return ((v & 0xF0F0F0F0F0F0F0F0u) | (((v + 0x0606060606060606u) & 0xF0F0F0F0F0F0F0F0u) >> 4)) ==
           0x3333333333333333u;
}

static uint64_t eight_value(uint64_t v)
{
    v -= 0x3030303030303030u;
    v = v * 10 + (v >> 8); /* pairs of digits, in every other byte */
    return (((v & 0x000000FF000000FFu) * 0x000F424000000064u) +
            (((v >> 16) & 0x000000FF000000FFu) * 0x0000271000000001u)) >> 32;
}
#else
#define SWAR 0
static uint64_t load8(const char *p) { (void)p; return 0; }
static int eight_digits(uint64_t v) { (void)v; return 0; }
static uint64_t eight_value(uint64_t v) { return v; }
#endif

/* Up to `stop`, the digits at *pp into *w, eight at a time when the bytes
 * may be read past the string's end (padded), then one at a time. */
static inline void digits(const char **pp, const char *stop, uint64_t *w, int padded)
{
    const char *p = *pp;
    uint64_t v = *w;
    if (SWAR && padded)
        while (stop - p >= 8 && eight_digits(load8(p))) {
            v = v * 100000000u + eight_value(load8(p));
            p += 8;
        }
    for (; p < stop && is_digit(*p); p++)
        v = v * 10 + (uint64_t)(*p - '0');
    *pp = p;
    *w = v;
}

static inline double parse(const char *s, char **end, int padded)
{
    static const double pow10[] = { 1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                    1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                    1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22 };
    const char *p = s;
    int neg = 0, any = 0, nd = 0;
    uint64_t w = 0;
    long q = 0;
    if (*p == '+' || *p == '-')
        neg = *p++ == '-';
    if (p[0] == '0' && (p[1] == 'x' || p[1] == 'X'))
        goto slow; /* hexadecimal */
    for (; *p == '0'; p++)
        any = 1;
    const char *d0 = p;
    digits(&p, d0 + 19, &w, padded);
    nd = (int)(p - d0);
    if (is_digit(*p))
        goto slow; /* more than 19 significant digits */
    any |= nd > 0;
    if (*p == '.') {
        p++;
        if (nd == 0)
            for (; *p == '0'; p++, q--)
                any = 1;
        d0 = p;
        digits(&p, p + (19 - nd), &w, padded);
        if (is_digit(*p))
            goto slow;
        q -= p - d0;
        any |= p > d0;
    }
    if (!any)
        goto slow; /* no digits: inf, nan, hexadecimal, blanks, or no number */
    if (*p == 'e' || *p == 'E') {
        const char *e = p + 1;
        int eneg = 0;
        long x = 0;
        if (*e == '+' || *e == '-')
            eneg = *e++ == '-';
        if (!is_digit(*e))
            goto slow;
        for (; is_digit(*e); e++)
            if (x < 100000)
                x = x * 10 + (*e - '0');
        q += eneg ? -x : x;
        p = e;
    }
    double v;
    if (w == 0)
        v = 0.0;
    else if (w <= (uint64_t)1 << 53 && q >= -22 && q <= 22)
        v = q < 0 ? (double)w / pow10[-q] : (double)w * pow10[q]; /* both exact: one rounding */
    else {
        if (q < E_MIN || q > E_MAX)
            goto slow;
        if (!have_table)
            make_table();
        if (!eisel_lemire(w, (int)q, neg, &v))
            goto slow;
        if (end)
            *end = (char *)p;
        return v;
    }
    if (end)
        *end = (char *)p;
    return neg ? -v : v;
slow:
    return strtod(s, end);
}

double sw_decimal_parse(const char *s, char **end) { return parse(s, end, 0); }

double sw_decimal_parse_padded(const char *s, char **end) { return parse(s, end, 1); }

void sw_decimal_init(void)
{
    if (!have_table)
        make_table();
}
