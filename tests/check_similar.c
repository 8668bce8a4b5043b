/* Similarity: the tokenizer's normalisation, winnowed fingerprints with the
 * handout removed, the plugins of tests/data/similar (a copy disguised by
 * renaming, reformatting, new comments and a swapped declaration; four
 * independent RK4 and Euler plugins, each checked correct with `stepwise
 * check --plugin`), hostile inputs, and traces: byte-identical files and
 * identical wrong numbers, with correct traces never flagged. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "grade/similar.h"
#include "stepwise/base.h"

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    ck_assert_msg(f != NULL, "cannot open %s (run the tests from the repository root)", path);
    static char buf[1 << 16];
    *len = fread(buf, 1, sizeof buf, f);
    fclose(f);
    char *copy = malloc(*len + 1);
    ck_assert_ptr_nonnull(copy);
    memcpy(copy, buf, *len);
    copy[*len] = '\0';
    return copy;
}

static int add_file(sw_similar *s, const char *name)
{
    char path[256], err[SW_ERRLEN];
    snprintf(path, sizeof path, "tests/data/similar/%s.c", name);
    size_t len;
    char *src = slurp(path, &len);
    int doc = sw_similar_add_source(s, src, len, err, sizeof err);
    ck_assert_msg(doc >= 0, "%s: %s", path, err);
    free(src);
    return doc;
}

static void init(sw_similar *s, int with_base)
{
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_similar_init(s, NULL, err, sizeof err), SW_OK);
    if (with_base)
        ck_assert_int_eq(sw_similar_add_default_base(s, err, sizeof err), SW_OK);
}

static sw_similar_pair compare(sw_similar *s, int a, int b)
{
    sw_similar_pair p;
    ck_assert_int_eq(sw_similar_compare(s, a, b, &p), SW_OK);
    return p;
}

/* ---- tokens ------------------------------------------------------------------- */

static size_t tokens(const char *src, unsigned char *out, size_t max)
{
    return sw_similar_tokenize(src, strlen(src), out, max);
}

START_TEST(tokens_normalise_names_literals_and_layout)
{
    unsigned char a[128], b[128];
    /* Renamed, re-laid-out, other literals and comments: the same stream. */
    size_t na = tokens("#include <stepwise/integrator.h>\n"
                       "static int step(double *y, int n) { /* Alice */\n"
                       "  for (int i = 0; i < n; i++) y[i] += 0.5 * h; return 0; }", a, sizeof a);
    size_t nb = tokens("#  include \"mine.h\"\n"
                       "// Mallory's\nstatic int\nmy_step(double*state,int dim)\n{\n"
                       "    for(int j=1;j<dim;j++)\n        state[j]+=1e-3*dt;\n    return 7;\n}\n",
                       b, sizeof b);
    ck_assert_int_eq(na, 39);
    ck_assert_int_eq(nb, na);
    ck_assert_int_eq(memcmp(a, b, na), 0);
    ck_assert_int_eq(a[0], tokens("static", b, 1) ? b[0] : 0); /* the include left no token */
    /* Keywords and operators stay apart: += is not = ... + */
    tokens("x += y;", a, sizeof a);
    ck_assert_int_eq(tokens("x = x + y;", b, sizeof b), 6);
    ck_assert_int_ne(a[1], b[1]);
    /* Literals: strings one class, numbers and characters another. */
    ck_assert_int_eq(tokens("\"a\\\"b\" L\"wide\" 'c' 0x1p-3 .5e+2 u8\"x\"", a, sizeof a), 6);
    unsigned char want[] = { SW_TOK_STR, SW_TOK_STR, SW_TOK_NUM, SW_TOK_NUM, SW_TOK_NUM, SW_TOK_STR };
    ck_assert_int_eq(memcmp(a, want, sizeof want), 0);
    /* A run of bytes C does not use is one OTHER token; UTF-8 letters
     * belong to identifiers. */
    ck_assert_int_eq(tokens("\x01 \xff @ ` x \\", a, sizeof a), 3);
    ck_assert_int_eq(a[0], SW_TOK_OTHER);
    ck_assert_int_eq(a[1], SW_TOK_ID);
    ck_assert_int_eq(a[2], SW_TOK_OTHER);
    ck_assert_int_eq(tokens("größe", a, sizeof a), 1);
    ck_assert_int_eq(a[0], SW_TOK_ID);
    /* Unterminated comment, string and continuation: no read past the end. */
    ck_assert_int_eq(tokens("a /* never closed", a, sizeof a), 1);
    ck_assert_int_eq(tokens("a \"never closed", a, sizeof a), 2);
    ck_assert_int_eq(tokens("#include \\", a, sizeof a), 0);
    ck_assert_int_eq(tokens("x\\", a, sizeof a), 2);
    /* The count is returned whole even when out is smaller. */
    ck_assert_int_eq(tokens("a b c d e", a, 2), 5);
    ck_assert_int_eq(sw_similar_tokenize(NULL, 0, NULL, 0), 0);
}
END_TEST

/* ---- sources ------------------------------------------------------------------ */

START_TEST(the_default_base_is_the_handout)
{
    sw_similar s;
    init(&s, 1);
    size_t len;
    char *example = slurp("examples/euler_plugin.c", &len);
    char err[SW_ERRLEN];
    int ex = sw_similar_add_source(&s, example, len, err, sizeof err);
    /* docs/plugins.md prints the same code with the initialiser on two lines. */
    const char docs[] =
        "#include <stepwise/integrator.h>\n\n"
        "static int euler_step(sw_ode *ode, double t, double *y, double h, double *work)\n{\n"
        "    double *dydt = work;\n    sw_ode_eval(ode, t, y, dydt);\n"
        "    for (int i = 0; i < ode->dim; i++)\n        y[i] += h * dydt[i];\n    return 0;\n}\n\n"
        "static const sw_plugin info = {\n"
        "    .abi = SW_PLUGIN_ABI, .name = \"student-euler\", .label = \"explicit Euler (student plugin)\",\n"
        "    .order = 1, .evals = 1, .work_vectors = 1, .step = euler_step,\n};\n\n"
        "const sw_plugin *sw_plugin_info(void);\n"
        "const sw_plugin *sw_plugin_info(void) { return &info; }\n";
    int doc = sw_similar_add_source(&s, docs, sizeof docs - 1, err, sizeof err);
    /* Every fingerprint of the example is the base's: if this fails, the
     * example changed and src/grade/similar.c's handout must follow. */
    ck_assert_int_eq(sw_similar_fingerprints(&s, ex), 0);
    ck_assert_int_eq(sw_similar_fingerprints(&s, doc), 0);
    /* Without the base the example has fingerprints of its own. */
    sw_similar bare;
    init(&bare, 0);
    ex = sw_similar_add_source(&bare, example, len, err, sizeof err);
    ck_assert_int_gt(sw_similar_fingerprints(&bare, ex), 8);
    /* Two students handing in the untouched handout: identical, not flagged. */
    int again = sw_similar_add_source(&s, example, len, err, sizeof err);
    sw_similar_pair p = compare(&s, 0, again);
    ck_assert_double_eq(p.score, 1);
    ck_assert(!p.flagged);
    ck_assert_msg(strstr(p.reason, "all of it the handout") != NULL, "%s", p.reason);
    free(example);
    sw_similar_free(&bare);
    sw_similar_free(&s);
}
END_TEST

START_TEST(a_disguised_copy_is_flagged)
{
    sw_similar s;
    init(&s, 1);
    int alice = add_file(&s, "rk4_alice"), copy = add_file(&s, "rk4_alice_copy");
    sw_similar_pair p = compare(&s, alice, copy);
    /* Measured 32 of 34 fingerprints (0.94; k = 12, w = 8): the copy's own
     * combined declaration "double *s3 = ..., *s4 = ..." and the swapped
     * one break the k-grams around them and nothing else. At least 0.8
     * leaves room for other changes to the defaults. */
    ck_assert_msg(p.flagged && p.score >= 0.8, "%.2f %s", p.score, p.reason);
    ck_assert_int_ge(p.shared, 8);
    ck_assert_msg(strstr(p.reason, "fingerprints of the smaller source shared") != NULL, "%s", p.reason);
    sw_similar_pair *pairs;
    int n;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_similar_pairs(&s, &pairs, &n, err, sizeof err), SW_OK);
    ck_assert_int_eq(n, 1);
    ck_assert_int_eq(pairs[0].a, alice);
    ck_assert_int_eq(pairs[0].b, copy);
    free(pairs);
    sw_similar_free(&s);
}
END_TEST

START_TEST(independent_plugins_are_not_flagged)
{
    static const char *const names[] = { "rk4_alice", "rk4_bob", "rk4_eve", "euler_carol",
                                         "euler_dave" };
    sw_similar s, bare;
    init(&s, 1);
    init(&bare, 0);
    for (int i = 0; i < 5; i++) {
        add_file(&s, names[i]);
        add_file(&bare, names[i]);
    }
    double worst = 0;
    for (int a = 0; a < 5; a++)
        for (int b = a + 1; b < 5; b++) {
            sw_similar_pair p = compare(&s, a, b);
            ck_assert_msg(!p.flagged, "%s and %s: %s", names[a], names[b], p.reason);
            if (p.score > worst)
                worst = p.score;
        }
    /* Alice and Eve wrote RK4 the same textbook way (stage loops into a
     * temporary, four evaluations): measured 11 of 34 fingerprints, 0.32;
     * every other pair shares at most 1 (0.03). */
    sw_similar_pair ae = compare(&s, 0, 2);
    ck_assert_msg(ae.score < 0.45, "%s", ae.reason);
    ck_assert_double_le(worst, ae.score);
    /* The base is what keeps the Euler pair apart: without it Carol and
     * Dave share the handout's plugin block (measured 13 of 30, 0.43). */
    sw_similar_pair cd = compare(&s, 3, 4), cd_bare = compare(&bare, 3, 4);
    ck_assert_int_eq(cd.shared, 0);
    ck_assert_int_ge(cd_bare.shared, 8);
    sw_similar_pair *pairs;
    int n;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_similar_pairs(&s, &pairs, &n, err, sizeof err), SW_OK);
    ck_assert_int_eq(n, 0);
    ck_assert_ptr_null(pairs);
    sw_similar_free(&bare);
    sw_similar_free(&s);
}
END_TEST

START_TEST(identical_files_score_one)
{
    sw_similar s;
    init(&s, 1);
    int a = add_file(&s, "rk4_bob"), b = add_file(&s, "rk4_bob"), c = add_file(&s, "rk4_alice");
    sw_similar_pair p = compare(&s, b, a);
    ck_assert_double_eq(p.score, 1);
    ck_assert(p.flagged);
    ck_assert_int_eq(p.a, a); /* ordered */
    ck_assert_msg(strncmp(p.reason, "identical files (", 17) == 0, "%s", p.reason);
    /* Pairs come highest score first. */
    int copy = add_file(&s, "rk4_alice_copy");
    sw_similar_pair *pairs;
    int n;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_similar_pairs(&s, &pairs, &n, err, sizeof err), SW_OK);
    ck_assert_int_eq(n, 2);
    ck_assert_int_eq(pairs[0].b, b);
    ck_assert_int_eq(pairs[1].a, c);
    ck_assert_int_eq(pairs[1].b, copy);
    ck_assert_double_lt(pairs[1].score, pairs[0].score);
    free(pairs);
    sw_similar_free(&s);
}
END_TEST

/* A deterministic byte stream (an LCG's high bytes). */
static void garbage(char *buf, size_t len, unsigned seed)
{
    unsigned long long x = seed;
    for (size_t i = 0; i < len; i++) {
        x = x * 6364136223846793005ULL + 1442695040888963407ULL;
        buf[i] = (char)(x >> 56);
    }
}

START_TEST(empty_huge_and_garbage_inputs)
{
    sw_similar s;
    char err[SW_ERRLEN];
    init(&s, 1);
    int e1 = sw_similar_add_source(&s, "", 0, err, sizeof err);
    int e2 = sw_similar_add_source(&s, "/* only a comment */\n", 21, err, sizeof err);
    ck_assert_int_eq(sw_similar_fingerprints(&s, e1), 0);
    sw_similar_pair p = compare(&s, e1, e2);
    ck_assert(!p.flagged);
    ck_assert_double_eq(p.score, 0);
    /* Two empty files are identical, but hold nothing of anyone's. */
    int e3 = sw_similar_add_source(&s, "", 0, err, sizeof err);
    ck_assert(!compare(&s, e1, e3).flagged);

    /* The largest source compared: 1 MiB of garbage, then one byte more. */
    char *big = malloc(SW_SIMILAR_SOURCE_MAX + 1);
    ck_assert_ptr_nonnull(big);
    garbage(big, SW_SIMILAR_SOURCE_MAX + 1, 1);
    int g1 = sw_similar_add_source(&s, big, SW_SIMILAR_SOURCE_MAX, err, sizeof err);
    ck_assert_int_ge(g1, 0);
    ck_assert_int_eq(sw_similar_add_source(&s, big, SW_SIMILAR_SOURCE_MAX + 1, err, sizeof err),
                     SW_EINVAL);
    ck_assert_msg(strstr(err, "too large to compare") != NULL, "%s", err);
    /* Two unrelated garbage files are not flagged (measured 544 of 3562
     * fingerprints, 0.15: random bytes make few token kinds, so a 1 MiB
     * one holds some of anything's k-grams); the same garbage twice is
     * identical. */
    garbage(big, 65536, 2);
    int g2 = sw_similar_add_source(&s, big, 65536, err, sizeof err);
    int g3 = sw_similar_add_source(&s, big, 65536, err, sizeof err);
    p = compare(&s, g1, g2);
    ck_assert_msg(!p.flagged && p.score < 0.3, "%s", p.reason);
    ck_assert(compare(&s, g2, g3).flagged);
    /* A huge real-looking source: a plugin repeated to 1 MiB. */
    size_t len, at = 0;
    char *bob = slurp("tests/data/similar/rk4_bob.c", &len);
    while (at + len <= SW_SIMILAR_SOURCE_MAX) {
        memcpy(big + at, bob, len);
        at += len;
    }
    int huge = sw_similar_add_source(&s, big, at, err, sizeof err);
    int bob_doc = sw_similar_add_source(&s, bob, len, err, sizeof err);
    ck_assert(compare(&s, huge, bob_doc).flagged); /* bob is contained in it */
    free(bob);
    free(big);
    /* Mixed kinds and bad indices are refused. */
    sw_similar_digest d;
    sw_similar_digest_init(&d);
    int t = sw_similar_add_trace(&s, &d, NULL, 0, err, sizeof err);
    ck_assert_int_eq(sw_similar_compare(&s, e1, t, &p), SW_EINVAL);
    ck_assert_int_eq(sw_similar_compare(&s, e1, e1, &p), SW_EINVAL);
    ck_assert_int_eq(sw_similar_compare(&s, -1, e1, &p), SW_EINVAL);
    ck_assert_int_eq(sw_similar_fingerprints(&s, t), -1);
    sw_similar_free(&s);

    sw_similar_opts o;
    sw_similar_defaults(&o);
    o.k = 1;
    ck_assert_int_eq(sw_similar_init(&s, &o, err, sizeof err), SW_EINVAL);
    ck_assert_str_eq(err, "similarity: k (k-gram length) must be 2..100");
    sw_similar_free(&s); /* a failed init leaves s freeable */
}
END_TEST

START_TEST(boilerplate_many_share_is_ignored)
{
    /* MOSS's -m: a passage in more than max_docs sources is boilerplate.
     * Twelve sources that share a block and differ only in a name and a
     * number: with the default (10) the block is ignored and nothing is
     * flagged; counted (max_docs 0), every pair is. (A ring of more than max_docs copiers hides the same
     * way: raise max_docs for a large class; identical files are always
     * flagged.) */
    size_t len;
    char *alice = slurp("tests/data/similar/rk4_alice.c", &len);
    for (int max_docs = 10; max_docs >= 0; max_docs -= 10) {
        sw_similar_opts o;
        sw_similar_defaults(&o);
        o.max_docs = max_docs;
        sw_similar s;
        char err[SW_ERRLEN];
        ck_assert_int_eq(sw_similar_init(&s, &o, err, sizeof err), SW_OK);
        sw_similar_add_default_base(&s, err, sizeof err);
        for (int i = 0; i < 12; i++) {
            char src[8192];
            int n = snprintf(src, sizeof src, "%s\nstatic int own%d(void) { return %d; }\n",
                             alice, i, i);
            ck_assert_int_ge(sw_similar_add_source(&s, src, (size_t)n, err, sizeof err), 0);
        }
        sw_similar_pair *pairs;
        int n;
        ck_assert_int_eq(sw_similar_pairs(&s, &pairs, &n, err, sizeof err), SW_OK);
        ck_assert_int_eq(n, max_docs ? 0 : 66);
        /* ... and how much was taken as common is counted, for the teacher */
        if (max_docs)
            ck_assert_uint_gt(s.ncommon, 0);
        else
            ck_assert_uint_eq(s.ncommon, 0);
        free(pairs);
        sw_similar_free(&s);
    }
    free(alice);
}
END_TEST

/* ---- traces ------------------------------------------------------------------- */

static sw_similar_digest digest_of(const char *text)
{
    sw_similar_digest d;
    sw_similar_digest_init(&d);
    sw_similar_digest_add(&d, text, strlen(text));
    return d;
}

/* Rows 0..rows-1 of a made-up trace: x = step/10 + offset; rows from
 * `wrong_from` on are wrong. */
static int add_trace(sw_similar *s, const char *text, int correct, int rows, int wrong_from,
                     double offset)
{
    char err[SW_ERRLEN];
    sw_similar_digest d = digest_of(text);
    int doc = sw_similar_add_trace(s, &d, NULL, correct, err, sizeof err);
    ck_assert_int_ge(doc, 0);
    for (int r = 0; r < rows; r++) {
        double row[3] = { r, r * 0.01, r / 10.0 + (r >= wrong_from ? offset : 0) };
        ck_assert_int_eq(sw_similar_trace_row(s, doc, r, row, 3, r >= wrong_from), SW_OK);
    }
    return doc;
}

START_TEST(traces_identical_wrong_numbers)
{
    sw_similar s;
    init(&s, 0);
    /* Correct traces are the same by design: never flagged, even byte-identical. */
    int c1 = add_trace(&s, "# student: A\nrows", 1, 50, 50, 0);
    int c2 = add_trace(&s, "# student: A\nrows", 1, 50, 50, 0);
    sw_similar_pair p = compare(&s, c1, c2);
    ck_assert(!p.flagged);
    ck_assert_str_eq(p.reason, "both correct: identical by design");
    /* A wrong trace copied with the name changed: its wrong rows are equal. */
    int w1 = add_trace(&s, "# student: Bea\n...", 0, 100, 1, 1e-3);
    int w2 = add_trace(&s, "# student: Cy\n...", 0, 100, 1, 1e-3);
    p = compare(&s, w1, w2);
    ck_assert(p.flagged);
    ck_assert_double_eq(p.score, 1);
    ck_assert_str_eq(p.reason, "identical wrong numbers: 99 of 99 rows wrong in both are equal "
                               "bit for bit (first: row 1)");
    /* The same file byte for byte. */
    int w3 = add_trace(&s, "# student: Bea\n...", 0, 100, 1, 1e-3);
    p = compare(&s, w1, w3);
    ck_assert(p.flagged);
    ck_assert_msg(strncmp(p.reason, "byte-identical files (", 22) == 0, "%s", p.reason);
    /* Wrong in the same rows, differently: not flagged. */
    int w4 = add_trace(&s, "# student: Di\n...", 0, 100, 1, 2e-3);
    p = compare(&s, w1, w4);
    ck_assert(!p.flagged);
    ck_assert_int_eq(p.shared, 0);
    ck_assert_int_eq(p.of, 99);
    /* A correct and a wrong trace share no wrong rows. */
    ck_assert(!compare(&s, c1, w1).flagged);
    /* Two equal wrong rows are not enough (trace_min_rows 3). */
    int w5 = add_trace(&s, "# student: Ed\n...", 0, 100, 98, 1e-3);
    p = compare(&s, w1, w5);
    ck_assert_int_eq(p.shared, 2);
    ck_assert(!p.flagged);
    sw_similar_pair *pairs;
    int n;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_similar_pairs(&s, &pairs, &n, err, sizeof err), SW_OK);
    ck_assert_int_eq(n, 3); /* w1-w2, w1-w3, w2-w3 */
    free(pairs);
    sw_similar_free(&s);
}
END_TEST

START_TEST(trace_rows_and_digests)
{
    sw_similar s;
    init(&s, 0);
    char err[SW_ERRLEN];
    /* -0 is 0 and every NaN is one NaN: a row's hash is its values. */
    sw_similar_digest d1 = digest_of("a"), d2 = digest_of("b");
    int a = sw_similar_add_trace(&s, &d1, NULL, 0, err, sizeof err);
    int b = sw_similar_add_trace(&s, &d2, NULL, 0, err, sizeof err);
    double nan2 = -NAN;
    for (int r = 0; r < 3; r++) {
        double ra[2] = { 0.0, NAN }, rb[2] = { -0.0, nan2 };
        sw_similar_trace_row(&s, a, r, ra, 2, 1);
        sw_similar_trace_row(&s, b, r, rb, 2, 1);
    }
    ck_assert(compare(&s, a, b).flagged);
    /* At most SW_SIMILAR_ROWS_MAX wrong rows are kept per trace. */
    sw_similar_digest d3 = digest_of("c");
    int c = sw_similar_add_trace(&s, &d3, NULL, 0, err, sizeof err);
    for (long r = 0; r < SW_SIMILAR_ROWS_MAX + 100; r++) {
        double v = (double)r;
        ck_assert_int_eq(sw_similar_trace_row(&s, c, r, &v, 1, 1), SW_OK);
    }
    sw_similar_free(&s);

    /* A file's digest is its bytes' digest. */
    char path[] = "/tmp/sw_similar_XXXXXX";
    int fd = mkstemp(path);
    ck_assert_int_ge(fd, 0);
    ck_assert_int_eq(write(fd, "step,t\n0,0\n", 11), 11);
    close(fd);
    sw_similar_digest f, m = digest_of("step,t\n0,0\n");
    ck_assert_int_eq(sw_similar_digest_file(path, &f, NULL, err, sizeof err), SW_OK);
    ck_assert(f.h[0] == m.h[0] && f.h[1] == m.h[1] && f.bytes == 11);
    unlink(path);
    ck_assert_int_eq(sw_similar_digest_file(path, &f, NULL, err, sizeof err), SW_EIO);
    ck_assert_msg(strstr(err, "cannot open") != NULL, "%s", err);
    ck_assert_int_eq(sw_similar_digest_file("/tmp", &f, NULL, err, sizeof err), SW_EINVAL);
    /* One byte apart: different digests. */
    sw_similar_digest x = digest_of("0.1234567"), y = digest_of("0.1234568");
    ck_assert(x.h[0] != y.h[0] && x.h[1] != y.h[1]);
}
END_TEST

/* Fingerprints are common code when more than max_docs owners share
 * them: eleven copies of one owner's file are not (red team 4). */
START_TEST(common_code_counts_owners)
{
    sw_similar s;
    char err[SW_ERRLEN];
    init(&s, 1);
    const char *code = "#include <stepwise/integrator.h>\nstatic int st(sw_ode *o, double t, double *y, double h, "
                       "double *w) { for (int i = 0; i < o->dim; i++) { double a = y[i] * h; w[i] = a * a + t; "
                       "y[i] += w[i] * 0.5 - a / 3.0; } return 0; }\n";
    int a = sw_similar_add_source(&s, code, strlen(code), err, sizeof err);
    sw_similar_set_owner(&s, a, 0);
    int copies[11];
    for (int i = 0; i < 11; i++) { /* not byte-identical: a comment apart */
        char text[600];
        snprintf(text, sizeof text, "%s/* copy %d */\n", code, i);
        copies[i] = sw_similar_add_source(&s, text, strlen(text), err, sizeof err);
        sw_similar_set_owner(&s, copies[i], 1);
    }
    ck_assert(compare(&s, a, copies[0]).flagged);
    /* twelve owners: common code, never paired */
    for (int i = 0; i < 11; i++)
        sw_similar_set_owner(&s, copies[i], 2 + i);
    ck_assert(!compare(&s, a, copies[0]).flagged);
    sw_similar_free(&s);
}
END_TEST

/* Write text to a new temporary file; its path into path (room for 32). */
static void temp_file(char *path, const char *text)
{
    strcpy(path, "/tmp/sw_similar_XXXXXX");
    int fd = mkstemp(path);
    ck_assert_int_ge(fd, 0);
    ck_assert_int_eq(write(fd, text, strlen(text)), (ssize_t)strlen(text));
    close(fd);
}

/* A trace's rows are its lines not starting with '#', however the file
 * is read: a copy whose header was edited has the same rows, and is
 * flagged unless both are correct (QA: a copy with its parameter edited
 * was not paired). */
START_TEST(trace_rows_under_another_header)
{
    const char *orig = "# stepwise trace 1\n# param k: 10.9\nstep,t,x0\n0,0,1.5\n1,0.01,1.49\n",
               *edited = "# stepwise trace 1\n# param k: 9\nstep,t,x0\n0,0,1.5\n1,0.01,1.49\n",
               *other = "# stepwise trace 1\n# param k: 9\nstep,t,x0\n0,0,1.5\n1,0.01,1.48\n",
               *no_end = "# x\nstep,t,x0\n0,0,1.5\n1,0.01,1.49"; /* no final newline */
    char pa[32], pb[32], pc[32], pd[32], err[SW_ERRLEN];
    temp_file(pa, orig);
    temp_file(pb, edited);
    temp_file(pc, other);
    temp_file(pd, no_end);
    sw_similar_digest fa, fb, fc, fd, ra, rb, rc, rd, want = digest_of("step,t,x0\n0,0,1.5\n1,0.01,1.49\n");
    ck_assert_int_eq(sw_similar_digest_file(pa, &fa, &ra, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_similar_digest_file(pb, &fb, &rb, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_similar_digest_file(pc, &fc, &rc, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_similar_digest_file(pd, &fd, &rd, err, sizeof err), SW_OK);
    ck_assert(ra.h[0] == want.h[0] && ra.h[1] == want.h[1] && ra.bytes == want.bytes);
    ck_assert(rb.h[0] == want.h[0] && rb.bytes == want.bytes);
    ck_assert(rd.bytes == want.bytes - 1); /* the same rows but the last newline */
    ck_assert(fa.h[0] != fb.h[0]);
    for (int correct = 0; correct < 4; correct++) {
        sw_similar s;
        init(&s, 0);
        int a = sw_similar_add_trace(&s, &fa, &ra, correct & 1, err, sizeof err);
        int b = sw_similar_add_trace(&s, &fb, &rb, (correct >> 1) & 1, err, sizeof err);
        int c = sw_similar_add_trace(&s, &fc, &rc, 0, err, sizeof err);
        sw_similar_pair p = compare(&s, a, b);
        /* flagged where one is correct and not both; two wrong ones are
         * left to their wrong rows (none given here) */
        ck_assert_int_eq(p.flagged, correct == 1 || correct == 2);
        if (p.flagged)
            ck_assert_msg(strstr(p.reason, "the same rows") != NULL, "%s", p.reason);
        ck_assert(!compare(&s, b, c).flagged); /* one value apart */
        sw_similar_free(&s);
    }
    unlink(pa);
    unlink(pb);
    unlink(pc);
    unlink(pd);
}
END_TEST

Suite *make_similar_suite(void);
Suite *make_similar_suite(void)
{
    Suite *s = suite_create("similar");
    TCase *tc = tcase_create("sources");
    tcase_set_timeout(tc, 30);
    tcase_add_test(tc, tokens_normalise_names_literals_and_layout);
    tcase_add_test(tc, the_default_base_is_the_handout);
    tcase_add_test(tc, a_disguised_copy_is_flagged);
    tcase_add_test(tc, independent_plugins_are_not_flagged);
    tcase_add_test(tc, identical_files_score_one);
    tcase_add_test(tc, empty_huge_and_garbage_inputs);
    tcase_add_test(tc, boilerplate_many_share_is_ignored);
    suite_add_tcase(s, tc);
    tc = tcase_create("traces");
    tcase_add_test(tc, traces_identical_wrong_numbers);
    tcase_add_test(tc, trace_rows_and_digests);
    tcase_add_test(tc, trace_rows_under_another_header);
    tcase_add_test(tc, common_code_counts_owners);
    suite_add_tcase(s, tc);
    return s;
}
