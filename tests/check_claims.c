/* Every figure the texts quote to a student or a teacher, computed from the
 * library: one row per claim, in tables beside the measurements they use
 * (tests/support/claims_*.c, claims.h says which part holds what). A row names its file and an exact
 * snippet of the text with the figure marked {like this}; the test finds the
 * snippet (so editing the text forces editing the row), parses the figure as
 * written, computes it from the library (runs, the truth module, the
 * stability lab, the live app) and compares within a tolerance that matches
 * how the text rounds it. A claim that is a formula (no {figure}) is
 * compared with the formula's value at the lesson's parameters.
 *
 * Snippets match with every run of white space as one space, and in a
 * lesson file a comment line's leading '#' is dropped, so a snippet may run
 * across the comment header's lines. A guard test asks for a row for every
 * number in the texts that reads like a quoted figure.
 *
 * CK_RUN_SUITE=claims SW_CLAIMS_PRINT=1 build/check_stepwise prints every
 * row's written and computed values (for authors); SW_TEST_QUICK skips
 * computing the rows that bisect for a stability limit. */
#include "claims.h"

/* The tables as one: a new part adds its table here. */
static const struct {
    const claim *rows;
    const size_t *n;
} tables[] = {
    { sw_claims_a, &sw_claims_a_n }, { sw_claims_b, &sw_claims_b_n }, { sw_claims_d, &sw_claims_d_n },
    { sw_claims_e, &sw_claims_e_n }, { sw_claims_m, &sw_claims_m_n }, { sw_claims_s, &sw_claims_s_n },
    { sw_claims_r, &sw_claims_r_n }, { sw_claims_k, &sw_claims_k_n }, { sw_claims_o, &sw_claims_o_n },
    { sw_claims_f, &sw_claims_f_n }, { sw_claims_l, &sw_claims_l_n }, { sw_claims_w, &sw_claims_w_n },
};

static size_t claim_count(void)
{
    size_t n = 0;
    for (size_t t = 0; t < sizeof tables / sizeof tables[0]; t++)
        n += *tables[t].n;
    return n;
}
static const claim *claim_at(size_t i)
{
    for (size_t t = 0; t < sizeof tables / sizeof tables[0]; t++) {
        if (i < *tables[t].n)
            return &tables[t].rows[i];
        i -= *tables[t].n;
    }
    return NULL;

}

/* ---- reading the texts ------------------------------------------------- */

static int isspace_ascii(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

/* The file's text with every run of white space as one space; in a lesson,
 * a comment line's '#' (and the spaces after it) dropped, and with
 * prose_only its settings and goals too (questions, answers and hints stay).
 * Caller frees. */
static char *text_of_(const char *file, int prose_only)
{
    FILE *f = fopen(file, "rb");
    ck_assert_msg(f != NULL, "cannot open %s (run the tests from the repository root)", file);
    fseek(f, 0, SEEK_END);
    long len = ftell(f);
    rewind(f);
    char *raw = malloc((size_t)len + 1), *out = malloc((size_t)len + 2);
    ck_assert(raw && out && fread(raw, 1, (size_t)len, f) == (size_t)len);
    fclose(f);
    raw[len] = 0;
    int lesson = strstr(file, ".lesson") != NULL, line_start = 1;
    size_t n = 0;
    for (long i = 0; i < len; i++) {
        char c = raw[i];
        if (lesson && line_start) {
            long j = i;
            while (j < len && (raw[j] == ' ' || raw[j] == '\t'))
                j++;
            if (j < len && raw[j] == '#') {
                i = j;
                line_start = 0;
                continue;
            }
            /* settings and goals are what the page does, not what it says */
            if (prose_only && j < len && raw[j] == '@' && strncmp(raw + j, "@question", 9) != 0 &&
                strncmp(raw + j, "@answer", 7) != 0 && strncmp(raw + j, "@hint", 5) != 0) {
                while (i < len && raw[i] != '\n')
                    i++;
                continue;
            }
        }
        line_start = c == '\n';
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
            if (n > 0 && out[n - 1] != ' ')
                out[n++] = ' ';
        } else {
            out[n++] = c;
        }
    }
    out[n] = 0;
    free(raw);
    return out;
}

static char *text_of(const char *file) { return text_of_(file, 0); }

/* The snippet as it stands in the text (braces dropped, white space as in
 * text_of), and the figure between the braces ("" when none). */
static void split_snippet(const char *snippet, char *plain, size_t plen, char *figure, size_t flen)
{
    size_t n = 0, f = 0;
    int in = 0;
    figure[0] = 0;
    for (const char *c = snippet; *c && n + 1 < plen; c++) {
        if (*c == '{' || *c == '}') {
            in = *c == '{';
            continue;
        }
        if (isspace_ascii(*c)) {
            if (n > 0 && plain[n - 1] != ' ')
                plain[n++] = ' ';
        } else {
            plain[n++] = *c;
        }
        if (in && f + 1 < flen)
            figure[f++] = *c;
    }
    plain[n] = 0;
    figure[f] = 0;
}

/* Figures written in words, and what they stand for. */
static const struct { const char *word; double value; } words[] = {
    { "a", 1 }, { "one", 1 }, { "first", 1 }, { "second", 2 }, { "fourth", 4 }, { "two", 2 },
    { "half", 0.5 }, { "twothirds", 2.0 / 3.0 }, { "tripled", 3 }, { "five", 5 }, { "ten", 10 },
    { "adozen", 12 }, { "nineteen", 19 }, { "seven", 7 }, { "six", 6 }, { "four", 4 },
    { "eight", 8 }, { "ten-thousandfold", 1e4 }, { "halves", 2 }, { "rounding", 1e-12 },
    { "afewthousandths", 0.005 }, { "constant", 0 }, { "twelve", 12 }, { "once", 1 }, { "three", 3 },
    { "sixteen", 16 }, { "eleven", 11 },
};

static const char *const superscripts[] = { "⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹" };

/* Superscript digits at *s as a number (advances *s); -1 when none. */
static int superscript(const char **s)
{
    int value = -1;
    for (int found = 1; found;) {
        found = 0;
        for (int d = 0; d < 10; d++) {
            size_t len = strlen(superscripts[d]);
            if (strncmp(*s, superscripts[d], len) == 0) {
                value = (value < 0 ? 0 : 10 * value) + d;
                *s += len;
                found = 1;
            }
        }
    }
    return value;
}

/* The figure as written: "1.37", "-8.50", "+38.4", "66 %", "100 000",
 * "1e\-9" (roff), "2√2", "√1.16", "10⁴", "²", or a word from the list.
 * Normalised text into norm (for the rounding rule). NaN when unreadable. */
static double parse_figure(const char *figure, char *norm, size_t nlen)
{
    size_t n = 0;
    for (const char *c = figure; *c && n + 1 < nlen;) {
        if (*c == ' ' || *c == '%') {
            c++;
        } else if (strncmp(c, "\xc2\xa0", 2) == 0) {
            c += 2; /* no-break space */
        } else if (strncmp(c, "\xe2\x80\x89", 3) == 0 || strncmp(c, "\xe2\x80\xaf", 3) == 0) {
            c += 3; /* thin spaces */
        } else if (strncmp(c, "\xe2\x88\x92", 3) == 0) {
            norm[n++] = '-'; /* U+2212 minus */
            c += 3;
        } else if (c[0] == '\\' && c[1] == '-') {
            norm[n++] = '-'; /* roff's minus */
            c += 2;
        } else {
            norm[n++] = *c++;
        }
    }
    norm[n] = 0;
    for (size_t i = 0; i < sizeof words / sizeof words[0]; i++)
        if (strcmp(norm, words[i].word) == 0)
            return words[i].value;
    const char *s = norm;
    int sup = superscript(&s);
    if (sup >= 0 && *s == 0)
        return sup;
    s = norm;
    char *end;
    double a = strtod(s, &end);
    if (end == s)
        a = 1;
    s = end;
    if (strncmp(s, "π", strlen("π")) == 0) {
        a *= 3.141592653589793;
        s += strlen("π");
    }
    if (*s == '/') {
        double b = strtod(s + 1, &end);
        if (end == s + 1 || b == 0)
            return NAN;
        a /= b;
        s = end;
    }
    if (strncmp(s, "√", strlen("√")) == 0) {
        s += strlen("√");
        double b = strtod(s, &end);
        if (end == s)
            return NAN;
        a *= sqrt(b);
        s = end;
    }
    if (strncmp(s, "·10", strlen("·10")) == 0) { /* 3·10⁴ */
        s += strlen("·10");
        sup = superscript(&s);
        if (sup < 0)
            return NAN;
        a *= pow(10, sup);
    }
    sup = superscript(&s);
    if (sup >= 0)
        a = pow(a, sup);
    return *s == 0 ? a : NAN;
}

/* Half a unit of the last digit written: "1.37" 0.005, "66" 0.5, "3.3e-7" 0.05e-7. */
static double half_unit(const char *norm)
{
    const char *dot = strchr(norm, '.'), *e = strpbrk(norm, "eE");
    int decimals = 0;
    if (dot)
        for (const char *c = dot + 1; *c >= '0' && *c <= '9'; c++)
            decimals++;
    int exponent = e ? atoi(e + 1) : 0;
    return 0.5 * pow(10, exponent - decimals);
}

static const char *kind_name(claim_kind k)
{
    static const char *const names[] = { "rounded", "abs", "rel", "exact", "at most", "at least", "magnitude" };
    return names[k];
}

/* Whether computed c holds the written figure w under the row's rule. */
static int holds(const claim *cl, double w, double c, const char *norm, double *tol_out)
{
    double tol = cl->tol;
    switch (cl->kind) {
    case ROUNDED:
        tol = half_unit(norm) * (1 + 1e-9);
        *tol_out = tol;
        return fabs(c - w) <= tol;
    case ABS:
        *tol_out = tol;
        return fabs(c - w) <= tol;
    case REL:
        *tol_out = tol * fabs(w);
        return fabs(c - w) <= tol * fabs(w);
    case EXACT:
        *tol_out = 1e-9 * fabs(w);
        return fabs(c - w) <= 1e-9 * fabs(w);
    case ATMOST:
        *tol_out = tol;
        return c <= w * (1 + 1e-12) && (tol <= 0 || c >= w * (1 - tol));
    case ATLEAST:
        *tol_out = tol;
        return c >= w * (1 - 1e-12) && (tol <= 0 || c <= w * (1 + tol));
    case MAGNITUDE:
        *tol_out = tol;
        return c > 0 && w > 0 && fabs(log10(c / w)) <= tol;
    }
    return 0;
}

static int print_values(void)
{
    const char *v = getenv("SW_CLAIMS_PRINT");
    return v && *v && strcmp(v, "0") != 0;
}

/* Rows whose computation bisects for a stability limit (a second or more
 * under valgrind each): SW_TEST_QUICK skips computing them. */
static int is_slow(double (*compute)(void))
{
    double (*const slow[])(void) = { cl_l7_im_limit, cl_l7_verlet_theory, cl_l7_verlet_measured, cl_verlet_measured_wdt,
                                     cl_rk4_measured_wdt, cl_rk4_damped_measured, cl_rk4_small_stretch,
                                     cl_gyre_first_error, cl_gyre_slope_min, cl_gyre_slope_max,
                                     cl_water_euler_1s, cl_water_euler_8s, cl_dam_worst, cl_dam_ahead_least,
                                     cl_dam_ahead_most, cl_dam_behind_least, cl_dam_behind_most, cl_dam_default_nu,
                                     cl_big_dam_blowup, cl_big_dam_builds, cl_big_dam_build_every };
    for (size_t i = 0; i < sizeof slow / sizeof slow[0]; i++)
        if (slow[i] == compute)
            return 1;
    return 0;
}

/* Row i: the snippet is in its file, the figure parses, and the library's
 * value holds it. */
START_TEST(claim_holds)
{
    const claim *cl = &claim_at(_i)[0];
    char plain[1024], figure[128], norm[128];
    split_snippet(cl->snippet, plain, sizeof plain, figure, sizeof figure);
    char *text = text_of(cl->file);
    int found = strstr(text, plain) != NULL;
    free(text);
    ck_assert_msg(found, "%s: the text no longer says \"%s\": update its row in tests/support/claims_*.c", cl->file,
                  plain);
    double w;
    if (figure[0]) {
        w = parse_figure(figure, norm, sizeof norm);
        ck_assert_msg(!isnan(w), "%s: cannot read the figure {%s} in \"%s\"", cl->file, figure, plain);
        ck_assert_msg(cl->formula == NULL, "row %d has both a figure and a formula", _i);
    } else {
        ck_assert_msg(cl->formula != NULL, "%s: \"%s\" marks no {figure} and names no formula", cl->file, plain);
        snprintf(norm, sizeof norm, "formula");
        w = cl->formula();
    }
    if (getenv("SW_TEST_QUICK") && is_slow(cl->compute))
        return; /* the text and its figure were checked; the bisection runs in the plain pass */
    clock_t start = clock();
    double c = cl->compute(), tol = 0, cpu = (double)(clock() - start) / CLOCKS_PER_SEC;
    int ok = holds(cl, w, c, norm, &tol);
    if (print_values() || !ok)
        fprintf(stderr, "%-4s %3d %s: \"%s\": written %.6g, computed %.6g (%s, tol %.3g; %.2f s)\n", ok ? "ok" : "FAIL",
                _i, cl->file, plain, w, c, kind_name(cl->kind), tol, cpu);
    ck_assert_msg(ok, "%s: \"%s\": the text says %.6g, the library gives %.6g (%s %.3g: %s)", cl->file, plain, w, c,
                  kind_name(cl->kind), tol, cl->why);
}
END_TEST

/* Texts that look like a quoted figure but are not one (the guard below
 * would otherwise ask for a row): a formula checked by the rows above at
 * the lesson's values, a setting the page makes, a size. */
static const struct { const char *file, *snippet; } not_figures[] = {
    { L2, "halving Δt divides the error by 2^p" },        /* the formula; the ratios have rows */
    { L5, "a Δt of 0.005 is far too long for that" },     /* the page's step; the limit has a row */
    { L5, "Look at Euler's factor 1 - cΔt + kΔt² with c = 0" }, /* the formula; its rows are above */
    { STAB, "which makes its map 3×3" },                   /* a matrix's size */
};

static const char *const guarded[] = { L1, L2, L3, L4, L5, L6, L7, L8, L9, L10, L11, README, MAN, STAB };

/* Mark the first occurrence of snippet in text as covered. */
static void cover(const char *text, const char *snippet, unsigned char *covered)
{
    char plain[1024], figure[128];
    split_snippet(snippet, plain, sizeof plain, figure, sizeof figure);
    const char *at = strstr(text, plain);
    if (at)
        memset(covered + (at - text), 1, strlen(plain));
}

static int ends_with_word(const char *text, size_t end, const char *word)
{
    size_t n = strlen(word);
    if (end < n || strncmp(text + end - n, word, n) != 0)
        return 0;
    unsigned char before = end > n ? (unsigned char)text[end - n - 1] : ' ';
    return !((before >= 'a' && before <= 'z') || (before >= 'A' && before <= 'Z'));
}

/* A number at text[i] that reads like a quoted figure: after "≈", "about",
 * "near", "within", "factor", "by", "ratio" or "of", or before "%",
 * "times", "×" or "fold". */
static int figure_like(const char *text, size_t i, size_t *len)
{
    static const char *const before[] = { "≈", "about", "near", "within", "factor", "by", "ratio", "of" };
    static const char *const after[] = { "%", "times", "×", "fold", "-fold" };
    unsigned char prev = i > 0 ? (unsigned char)text[i - 1] : ' ';
    if (!(text[i] >= '0' && text[i] <= '9') || (prev >= '0' && prev <= '9') || prev == '.' || prev == '_' ||
        (prev >= 'a' && prev <= 'z') || (prev >= 'A' && prev <= 'Z'))
        return 0;
    size_t j = i;
    while ((text[j] >= '0' && text[j] <= '9') || (text[j] == '.' && text[j + 1] >= '0' && text[j + 1] <= '9'))
        j++;
    *len = j - i;
    size_t b = i;
    if (b > 0 && (text[b - 1] == '-' || text[b - 1] == '+'))
        b--;
    while (b > 0 && text[b - 1] == ' ')
        b--;
    for (size_t k = 0; k < sizeof before / sizeof before[0]; k++)
        if (ends_with_word(text, b, before[k]))
            return 1;
    while (text[j] == ' ')
        j++;
    for (size_t k = 0; k < sizeof after / sizeof after[0]; k++)
        if (strncmp(text + j, after[k], strlen(after[k])) == 0)
            return 1;
    return 0;
}

/* Every figure-like number in the guarded texts is in some row's snippet
 * (or named above as not a figure): a figure added without a row fails. */
START_TEST(every_figure_has_a_row)
{
    const char *file = guarded[_i];
    char *text = text_of_(file, 1);
    size_t len = strlen(text);
    if (strcmp(file, STAB) == 0 && strstr(text, "<!-- generated"))
        len = (size_t)(strstr(text, "<!-- generated") - text); /* the table has its own test */
    unsigned char *covered = calloc(len + 1, 1);
    for (size_t r = 0; r < claim_count(); r++)
        if (strcmp(claim_at(r)[0].file, file) == 0)
            cover(text, claim_at(r)[0].snippet, covered);
    for (size_t r = 0; r < sizeof not_figures / sizeof not_figures[0]; r++)
        if (strcmp(not_figures[r].file, file) == 0)
            cover(text, not_figures[r].snippet, covered);
    int missing = 0;
    for (size_t i = 0; i < len; i++) {
        size_t n;
        if (figure_like(text, i, &n) && !covered[i]) {
            fprintf(stderr, "%s: no row for the figure in \"...%.*s...\"\n", file,
                    (int)(i + n + 20 < len ? n + 40 : len - (i > 20 ? i - 20 : 0)), text + (i > 20 ? i - 20 : 0));
            missing++;
        }
    }
    free(covered);
    free(text);
    ck_assert_msg(missing == 0, "%s: %d figure(s) with no row in tests/support/claims_*.c (listed on stderr)", file,
                  missing);
}
END_TEST

/* The parser reads figures as the texts write them. */
START_TEST(figures_parse)
{
    char norm[64];
    ck_assert_double_eq_tol(parse_figure("1.37", norm, sizeof norm), 1.37, 1e-15);
    ck_assert_double_eq_tol(half_unit(norm), 0.005, 1e-15);
    ck_assert_double_eq_tol(parse_figure("100 000", norm, sizeof norm), 1e5, 1e-9);
    ck_assert_double_eq_tol(parse_figure("+38.4", norm, sizeof norm), 38.4, 1e-12);
    ck_assert_double_eq_tol(half_unit(norm), 0.05, 1e-15);
    ck_assert_double_eq_tol(parse_figure("−8.50", norm, sizeof norm), -8.5, 1e-12);
    ck_assert_double_eq_tol(half_unit(norm), 0.005, 1e-15);
    ck_assert_double_eq_tol(parse_figure("66 %", norm, sizeof norm), 66, 1e-12);
    ck_assert_double_eq_tol(half_unit(norm), 0.5, 1e-15);
    ck_assert_double_eq_tol(parse_figure("1e\\-9", norm, sizeof norm), 1e-9, 1e-24);
    ck_assert_double_eq_tol(parse_figure("3.3e-7", norm, sizeof norm), 3.3e-7, 1e-20);
    ck_assert_double_eq_tol(half_unit(norm), 0.05e-7, 1e-20);
    ck_assert_double_eq_tol(parse_figure("2√2", norm, sizeof norm), 2 * sqrt(2), 1e-15);
    ck_assert_double_eq_tol(parse_figure("√1.16", norm, sizeof norm), sqrt(1.16), 1e-15);
    ck_assert_double_eq_tol(parse_figure("10⁴", norm, sizeof norm), 1e4, 1e-9);
    ck_assert_double_eq_tol(parse_figure("3·10⁴", norm, sizeof norm), 3e4, 1e-9);
    ck_assert_double_eq_tol(parse_figure("²", norm, sizeof norm), 2, 1e-15);
    ck_assert_double_eq_tol(parse_figure("two thirds", norm, sizeof norm), 2.0 / 3, 1e-15);
    ck_assert(isnan(parse_figure("1.3x", norm, sizeof norm)));
    /* a rule that cannot fail would pass this */
    claim c = { "", "", cl_zero, ROUNDED, 0, "", NULL };
    double tol;
    parse_figure("1.37", norm, sizeof norm);
    ck_assert(holds(&c, 1.37, 1.374, norm, &tol));
    ck_assert(!holds(&c, 1.37, 1.376, norm, &tol));
    c.kind = ATMOST;
    c.tol = 0.2;
    ck_assert(holds(&c, 0.7, 0.65, norm, &tol));
    ck_assert(!holds(&c, 0.7, 0.71, norm, &tol));
    ck_assert(!holds(&c, 0.7, 0.5, norm, &tol));
}
END_TEST

/* Every row's snippet is unique to its place: a snippet found twice in its
 * file could survive the edit of the figure it was written for. */
START_TEST(snippets_unique)
{
    char plain[1024], figure[128];
    split_snippet(claim_at(_i)[0].snippet, plain, sizeof plain, figure, sizeof figure);
    char *text = text_of(claim_at(_i)[0].file);
    const char *first = strstr(text, plain);
    int twice = first && strstr(first + 1, plain) != NULL;
    free(text);
    ck_assert_msg(!twice, "%s: \"%s\" occurs more than once; make the snippet longer", claim_at(_i)[0].file, plain);
}
END_TEST

Suite *make_claims_suite(void);
Suite *make_claims_suite(void)
{
    Suite *s = suite_create("claims");
    TCase *tc = tcase_create("claims");
    int n = (int)(claim_count());
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, figures_parse);
    tcase_add_loop_test(tc, snippets_unique, 0, n);
    tcase_add_loop_test(tc, claim_holds, 0, n);
    tcase_add_loop_test(tc, every_figure_has_a_row, 0, (int)(sizeof guarded / sizeof guarded[0]));
    suite_add_tcase(s, tc);
    return s;
}
