/* Similarity: winnowed k-gram fingerprints of normalised C token streams
 * (Schleimer, Wilkerson, Aiken: "Winnowing", SIGMOD 2003 — the method of
 * MOSS), scored pairwise after the handout (the base) and boilerplate that
 * many sources share are removed; and, for traces, byte-identical files and
 * bit-identical wrong rows. Invariant: nothing here decides a grade; every
 * flag carries the figures that raised it. */
#include "grade/similar.h"

#include <assert.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "stepwise/base.h"
#include "util/infile.h"

enum { DOC_SOURCE = 1, DOC_TRACE };

struct sw_similar_doc {
    int kind;
    int owner;            /* whose (sw_similar_set_owner); each its own by default */
    sw_similar_digest digest;
    uint64_t *fp_all;     /* sources: the winnowed fingerprints, sorted, each once */
    size_t nfp_all;
    uint64_t *fp;         /* ...without the base's and the boilerplate's */
    size_t nfp, nown;     /* nown: without the base's only */
    int correct;          /* traces */
    int have_rows;
    sw_similar_digest rows; /* the lines not starting with '#' */
    long *row;            /* the wrong rows kept, increasing */
    uint64_t *row_hash;
    size_t nrows, cap_rows;
    long wrong_total, last_row;
};

/* ---- hashing ------------------------------------------------------------------ */

/* splitmix64's finaliser: every input bit reaches every output bit. */
static uint64_t mix(uint64_t x)
{
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ULL;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

void sw_similar_digest_init(sw_similar_digest *d)
{
    d->h[0] = 0xcbf29ce484222325ULL;  /* FNV-1a's offset basis */
    d->h[1] = 0x9e3779b97f4a7c15ULL;
    d->bytes = 0;
}

void sw_similar_digest_add(sw_similar_digest *d, const void *bytes, size_t len)
{
    const unsigned char *p = bytes;
    uint64_t a = d->h[0], b = d->h[1];
    for (size_t i = 0; i < len; i++) {
        a = (a ^ p[i]) * 0x100000001b3ULL;                 /* FNV-1a */
        b = ((b ^ p[i]) * 0xff51afd7ed558ccdULL) + (b >> 29); /* a second, unrelated lane */
    }
    d->h[0] = a;
    d->h[1] = b;
    d->bytes += len;
}

static int same_digest(const sw_similar_digest *x, const sw_similar_digest *y)
{
    return x->h[0] == y->h[0] && x->h[1] == y->h[1] && x->bytes == y->bytes;
}

/* The runs of buf[0..n) on lines not starting with '#' into rows; *at:
 * 0 at a line's start, 1 in a line kept, 2 in a line left out. */
static void add_rows(sw_similar_digest *rows, const unsigned char *buf, size_t n, int *at)
{
    size_t run = 0;
    for (size_t i = 0; i < n; i++) {
        if (*at == 0) {
            *at = buf[i] == '#' ? 2 : 1;
            run = i;
        }
        if (buf[i] == '\n') {
            if (*at == 1)
                sw_similar_digest_add(rows, buf + run, i + 1 - run);
            *at = 0;
        }
    }
    if (*at == 1)
        sw_similar_digest_add(rows, buf + run, n - run);
}

int sw_similar_digest_file(const char *path, sw_similar_digest *d, sw_similar_digest *rows, char *err,
                           size_t errlen)
{
    struct stat st;
    const char *what;
    int at = 0;
    sw_similar_digest_init(d);
    if (rows)
        sw_similar_digest_init(rows);
    int fd = sw_infile_open(path, &st, &what);
    if (fd < 0) {
        if (what)
            snprintf(err, errlen, "%.200s: is %s, not a file", path, what);
        else
            snprintf(err, errlen, "%.200s: cannot open: %s", path, strerror(errno));
        return what ? SW_EINVAL : SW_EIO;
    }
    unsigned char buf[1 << 15];
    for (;;) {
        ssize_t n = read(fd, buf, sizeof buf);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            snprintf(err, errlen, "%.200s: cannot read: %s", path, strerror(errno));
            close(fd);
            return SW_EIO;
        }
        if (n == 0)
            break;
        sw_similar_digest_add(d, buf, (size_t)n);
        if (rows)
            add_rows(rows, buf, (size_t)n, &at);
    }
    close(fd);
    return SW_OK;
}

/* ---- fingerprints ------------------------------------------------------------- */

/* The hash of every k-gram of tok[0..n) into h: n - k + 1 of them (none when
 * n < k). A polynomial rolling hash, h = sum tok[i]·B^(k-1-i), mixed. */
static size_t kgrams(const unsigned char *tok, size_t n, int k, uint64_t *h)
{
    const uint64_t B = 0x100000001b3ULL;
    if (n < (size_t)k)
        return 0;
    uint64_t top = 1, r = 0;
    for (int i = 0; i < k - 1; i++)
        top *= B;
    for (int i = 0; i < k; i++)
        r = r * B + tok[i];
    h[0] = mix(r);
    for (size_t i = (size_t)k; i < n; i++) {
        r = (r - tok[i - (size_t)k] * top) * B + tok[i];
        h[i - (size_t)k + 1] = mix(r);
    }
    return n - (size_t)k + 1;
}

/* Robust winnowing (the paper's section 4): in each window of w hashes the
 * smallest; on a tie the one chosen for the previous window if it is still
 * in, else the rightmost; a chosen position is recorded once. A sequence
 * shorter than one window gives its smallest. In place: fp may be h. */
static size_t winnow(uint64_t *h, size_t n, int w)
{
    size_t nf = 0, last = (size_t)-1, width = n < (size_t)w ? n : (size_t)w;
    for (size_t start = 0; start + width <= n && n > 0; start++) {
        size_t m = start + width - 1;
        for (size_t j = m; j-- > start;)
            if (h[j] < h[m])
                m = j;
        if (last != (size_t)-1 && last >= start && h[last] == h[m])
            m = last;
        if (m != last)
            h[nf++] = h[m]; /* nf <= start <= m: never overwrites an unread hash */
        last = m;
    }
    return nf;
}

static int cmp_u64(const void *a, const void *b)
{
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

static size_t sort_unique(uint64_t *v, size_t n)
{
    size_t m = 0;
    qsort(v, n, sizeof *v, cmp_u64);
    for (size_t i = 0; i < n; i++)
        if (m == 0 || v[i] != v[m - 1])
            v[m++] = v[i];
    return m;
}

static int contains(const uint64_t *v, size_t n, uint64_t x)
{
    return n > 0 && bsearch(&x, v, n, sizeof x, cmp_u64) != NULL;
}

/* The k-gram hashes of src (kgrams) or its fingerprints (winnowed), sorted,
 * each once, in a new *out. 0 or SW_ENOMEM. */
static int hashes_of(const sw_similar *s, const char *src, size_t len, int winnowed,
                     uint64_t **out, size_t *nout)
{
    size_t ntok = sw_similar_tokenize(src, len, NULL, 0);
    unsigned char *tok = malloc(ntok + 1);
    uint64_t *h = malloc((ntok + 1) * sizeof *h);
    if (!tok || !h) {
        free(tok);
        free(h);
        return SW_ENOMEM;
    }
    sw_similar_tokenize(src, len, tok, ntok);
    size_t n = kgrams(tok, ntok, s->opt.k, h);
    free(tok);
    if (winnowed)
        n = winnow(h, n, s->opt.w);
    *out = h;
    *nout = sort_unique(h, n);
    return SW_OK;
}

/* ---- the set ------------------------------------------------------------------ */

void sw_similar_defaults(sw_similar_opts *o)
{
    o->k = 12;
    o->w = 8;
    o->threshold = 0.5;
    o->min_shared = 8;
    o->max_docs = 10;
    o->trace_threshold = 0.9;
    o->trace_min_rows = 3;
    o->own_runs = 0;
}

int sw_similar_init(sw_similar *s, const sw_similar_opts *opt, char *err, size_t errlen)
{
    memset(s, 0, sizeof *s);
    if (opt)
        s->opt = *opt;
    else
        sw_similar_defaults(&s->opt);
    const sw_similar_opts *o = &s->opt;
    const char *bad = o->k < 2 || o->k > 100 ? "k (k-gram length) must be 2..100"
                    : o->w < 1 || o->w > 100 ? "w (window) must be 1..100"
                    : !(o->threshold > 0 && o->threshold <= 1) ? "the threshold must be in (0, 1]"
                    : o->min_shared < 1 ? "min_shared must be at least 1"
                    : o->max_docs < 0 ? "max_docs must be 0 (off) or more"
                    : !(o->trace_threshold > 0 && o->trace_threshold <= 1)
                        ? "the trace threshold must be in (0, 1]"
                    : o->trace_min_rows < 1 ? "trace_min_rows must be at least 1" : NULL;
    if (bad) {
        snprintf(err, errlen, "similarity: %s", bad);
        return SW_EINVAL;
    }
    s->docs = calloc(SW_SIMILAR_DOCS_MAX, sizeof *s->docs);
    if (!s->docs) {
        snprintf(err, errlen, "similarity: out of memory");
        return SW_ENOMEM;
    }
    return SW_OK;
}

void sw_similar_free(sw_similar *s)
{
    for (int i = 0; s->docs && i < s->ndocs; i++) {
        free(s->docs[i].fp_all);
        free(s->docs[i].fp);
        free(s->docs[i].row);
        free(s->docs[i].row_hash);
    }
    free(s->docs);
    free(s->base);
    memset(s, 0, sizeof *s);
}

/* The fp arrays go stale when the base or the set of sources changes
 * (prepare() rebuilds them). */
static void stale(sw_similar *s) { s->prepared = 0; }

int sw_similar_add_base(sw_similar *s, const char *src, size_t len, char *err, size_t errlen)
{
    if (len > SW_SIMILAR_SOURCE_MAX) {
        snprintf(err, errlen, "similarity: the base is %zu bytes; at most %zu", len,
                 SW_SIMILAR_SOURCE_MAX);
        return SW_EINVAL;
    }
    uint64_t *h;
    size_t n;
    if (hashes_of(s, src, len, 0, &h, &n) != SW_OK) {
        snprintf(err, errlen, "similarity: out of memory");
        return SW_ENOMEM;
    }
    uint64_t *all = realloc(s->base, (s->nbase + n + 1) * sizeof *all);
    if (!all) {
        free(h);
        snprintf(err, errlen, "similarity: out of memory");
        return SW_ENOMEM;
    }
    memcpy(all + s->nbase, h, n * sizeof *h);
    free(h);
    s->base = all;
    s->nbase = sort_unique(all, s->nbase + n);
    stale(s);
    return SW_OK;
}

/* examples/euler_plugin.c without its comments: what every student is
 * handed (tests/check_similar.c holds the two together). */
static const char handout[] =
    "#include <stepwise/integrator.h>\n"
    "static int euler_step(sw_ode *ode, double t, double *y, double h, double *work)\n"
    "{\n"
    "    double *dydt = work;\n"
    "    sw_ode_eval(ode, t, y, dydt);\n"
    "    for (int i = 0; i < ode->dim; i++)\n"
    "        y[i] += h * dydt[i];\n"
    "    return 0;\n"
    "}\n"
    "static const sw_plugin info = {\n"
    "    .abi = SW_PLUGIN_ABI,\n"
    "    .name = \"student-euler\",\n"
    "    .label = \"explicit Euler (student plugin)\",\n"
    "    .order = 1,\n"
    "    .evals = 1,\n"
    "    .work_vectors = 1,\n"
    "    .step = euler_step,\n"
    "};\n"
    "const sw_plugin *sw_plugin_info(void);\n"
    "const sw_plugin *sw_plugin_info(void) { return &info; }\n";

int sw_similar_add_default_base(sw_similar *s, char *err, size_t errlen)
{
    return sw_similar_add_base(s, handout, sizeof handout - 1, err, errlen);
}

static sw_similar_doc *new_doc(sw_similar *s, int kind, char *err, size_t errlen)
{
    if (s->ndocs == SW_SIMILAR_DOCS_MAX) {
        snprintf(err, errlen, "similarity: more than %d documents", SW_SIMILAR_DOCS_MAX);
        return NULL;
    }
    sw_similar_doc *d = &s->docs[s->ndocs];
    memset(d, 0, sizeof *d);
    d->kind = kind;
    d->owner = -1 - s->ndocs; /* its own, unlike any owner set */
    d->last_row = -1;
    return d;
}

int sw_similar_add_source(sw_similar *s, const char *src, size_t len, char *err, size_t errlen)
{
    if (len > SW_SIMILAR_SOURCE_MAX) {
        snprintf(err, errlen, "similarity: %zu bytes is too large to compare (at most %zu)", len,
                 SW_SIMILAR_SOURCE_MAX);
        return SW_EINVAL;
    }
    sw_similar_doc *d = new_doc(s, DOC_SOURCE, err, errlen);
    if (!d)
        return SW_EINVAL;
    sw_similar_digest_init(&d->digest);
    sw_similar_digest_add(&d->digest, src, len);
    if (hashes_of(s, src, len, 1, &d->fp_all, &d->nfp_all) != SW_OK) {
        snprintf(err, errlen, "similarity: out of memory");
        return SW_ENOMEM;
    }
    s->ndocs++;
    stale(s);
    return s->ndocs - 1;
}

int sw_similar_add_trace(sw_similar *s, const sw_similar_digest *dg, const sw_similar_digest *rows,
                         int correct, char *err, size_t errlen)
{
    sw_similar_doc *d = new_doc(s, DOC_TRACE, err, errlen);
    if (!d)
        return SW_EINVAL;
    d->digest = *dg;
    d->have_rows = rows && rows->bytes > 0;
    if (d->have_rows)
        d->rows = *rows;
    d->correct = correct != 0;
    return s->ndocs++;
}

/* A row's values as bits, -0 as 0 and every NaN as one NaN. */
static uint64_t row_hash(const double *v, int n)
{
    uint64_t h = 0x243f6a8885a308d3ULL;
    for (int i = 0; i < n; i++) {
        double x = v[i] == 0 ? 0.0 : isnan(v[i]) ? NAN : v[i];
        uint64_t bits;
        memcpy(&bits, &x, sizeof bits);
        h = mix(h ^ bits) + (uint64_t)i;
    }
    return mix(h ^ (uint64_t)n);
}

int sw_similar_trace_row(sw_similar *s, int doc, long row, const double *values, int n, int wrong)
{
    assert(doc >= 0 && doc < s->ndocs && s->docs[doc].kind == DOC_TRACE);
    sw_similar_doc *d = &s->docs[doc];
    assert(row > d->last_row);
    d->last_row = row;
    if (!wrong)
        return SW_OK;
    d->wrong_total++;
    if (d->nrows == SW_SIMILAR_ROWS_MAX)
        return SW_OK;
    if (d->nrows == d->cap_rows) {
        size_t cap = d->cap_rows ? 2 * d->cap_rows : 64;
        long *r = realloc(d->row, cap * sizeof *r);
        if (r)
            d->row = r;
        uint64_t *h = r ? realloc(d->row_hash, cap * sizeof *h) : NULL;
        if (!h)
            return SW_ENOMEM;
        d->row_hash = h;
        d->cap_rows = cap;
    }
    d->row[d->nrows] = row;
    d->row_hash[d->nrows++] = row_hash(values, n);
    return SW_OK;
}

/* ---- comparing ---------------------------------------------------------------- */

void sw_similar_set_owner(sw_similar *s, int doc, int owner)
{
    assert(doc >= 0 && doc < s->ndocs && owner >= 0);
    s->docs[doc].owner = owner;
    s->prepared = 0;
}

typedef struct owned_fp {
    uint64_t fp;
    int owner;
} owned_fp;

static int cmp_owned(const void *a, const void *b)
{
    const owned_fp *x = a, *y = b;
    if (x->fp != y->fp)
        return x->fp < y->fp ? -1 : 1;
    return (x->owner > y->owner) - (x->owner < y->owner);
}

/* Each source's fingerprints without the base's and without those more
 * than max_docs owners' sources share (MOSS's -m: boilerplate nobody
 * handed out, such as the loop over ode->dim). Owners, not sources: ten
 * copies of one file are one student's (red team 4 hid a copy so). */
static int prepare(sw_similar *s)
{
    size_t total = 0;
    if (s->prepared)
        return SW_OK;
    for (int i = 0; i < s->ndocs; i++)
        if (s->docs[i].kind == DOC_SOURCE)
            total += s->docs[i].nfp_all;
    owned_fp *all = malloc((total + 1) * sizeof *all);
    uint64_t *common = malloc((total + 1) * sizeof *common);
    size_t ncommon = 0, at = 0;
    if (!all || !common) {
        free(all);
        free(common);
        return SW_ENOMEM;
    }
    for (int i = 0; i < s->ndocs; i++)
        if (s->docs[i].kind == DOC_SOURCE)
            for (size_t k = 0; k < s->docs[i].nfp_all; k++)
                all[at++] = (owned_fp){ s->docs[i].fp_all[k], s->docs[i].owner };
    qsort(all, total, sizeof *all, cmp_owned);
    for (size_t i = 0; i < total;) {
        size_t j = i, owners = 0;
        for (; j < total && all[j].fp == all[i].fp; j++)
            owners += j == i || all[j].owner != all[j - 1].owner;
        if (s->opt.max_docs > 0 && owners > (size_t)s->opt.max_docs)
            common[ncommon++] = all[i].fp; /* sorted, as contains() needs */
        i = j;
    }
    for (int i = 0; i < s->ndocs; i++) {
        sw_similar_doc *d = &s->docs[i];
        if (d->kind != DOC_SOURCE)
            continue;
        free(d->fp);
        d->fp = malloc((d->nfp_all + 1) * sizeof *d->fp);
        if (!d->fp) {
            free(all);
            free(common);
            return SW_ENOMEM;
        }
        d->nfp = d->nown = 0;
        for (size_t j = 0; j < d->nfp_all; j++) {
            if (contains(s->base, s->nbase, d->fp_all[j]))
                continue;
            d->nown++;
            if (!contains(common, ncommon, d->fp_all[j]))
                d->fp[d->nfp++] = d->fp_all[j];
        }
    }
    free(all);
    free(common);
    s->ncommon = ncommon;
    s->prepared = 1;
    return SW_OK;
}

static size_t shared_count(const uint64_t *a, size_t na, const uint64_t *b, size_t nb)
{
    size_t i = 0, j = 0, n = 0;
    while (i < na && j < nb) {
        if (a[i] < b[j])
            i++;
        else if (a[i] > b[j])
            j++;
        else
            n++, i++, j++;
    }
    return n;
}

static void compare_sources(const sw_similar *s, const sw_similar_doc *a, const sw_similar_doc *b,
                            sw_similar_pair *p, int say)
{
    if (same_digest(&a->digest, &b->digest)) {
        p->score = 1;
        p->shared = p->of = (int)a->nfp;
        p->flagged = a->nown > 0;
        snprintf(p->reason, sizeof p->reason, "identical files (%llu bytes)%s",
                 (unsigned long long)a->digest.bytes, p->flagged ? "" : ", all of it the handout");
        return;
    }
    size_t shared = shared_count(a->fp, a->nfp, b->fp, b->nfp);
    size_t of = a->nfp < b->nfp ? a->nfp : b->nfp, all = a->nfp + b->nfp - shared;
    p->shared = (int)shared;
    p->of = (int)of;
    p->score = of ? (double)shared / (double)of : 0;
    p->flagged = shared >= (size_t)s->opt.min_shared && p->score >= s->opt.threshold;
    if (say || p->flagged)
        snprintf(p->reason, sizeof p->reason, "%zu of %zu fingerprints of the smaller source shared "
             "(%.0f%%; Jaccard %.2f)", shared, of, 100 * p->score,
             all ? (double)shared / (double)all : 0.0);
}

static void compare_traces(const sw_similar *s, const sw_similar_doc *a, const sw_similar_doc *b,
                           sw_similar_pair *p, int say)
{
    int copy = s->opt.own_runs || !(a->correct && b->correct);
    if (same_digest(&a->digest, &b->digest) && copy) {
        p->score = 1;
        p->flagged = 1;
        snprintf(p->reason, sizeof p->reason, "byte-identical files (%llu bytes)%s",
                 (unsigned long long)a->digest.bytes,
                 s->opt.own_runs ? ", where each student ran values of their own" : "");
        return;
    }
    /* a correct trace copied with its header edited; two wrong ones are
     * compared row by row below, which says where they agree */
    if (a->have_rows && b->have_rows && same_digest(&a->rows, &b->rows) && copy && (a->correct || b->correct)) {
        p->score = 1;
        p->flagged = 1;
        snprintf(p->reason, sizeof p->reason, "the same rows, byte for byte (%llu bytes), under headers "
                 "that differ (parameters or a name edited?)", (unsigned long long)a->rows.bytes);
        return;
    }
    if (a->correct && b->correct) {
        if (say)
            snprintf(p->reason, sizeof p->reason, "both correct: identical by design");
        return;
    }
    size_t i = 0, j = 0, both = 0, equal = 0;
    long first = -1;
    while (i < a->nrows && j < b->nrows) {
        if (a->row[i] < b->row[j]) {
            i++;
        } else if (a->row[i] > b->row[j]) {
            j++;
        } else {
            both++;
            if (a->row_hash[i] == b->row_hash[j] && equal++ == 0)
                first = a->row[i];
            i++, j++;
        }
    }
    p->shared = (int)equal;
    p->of = (int)both;
    p->score = both ? (double)equal / (double)both : 0;
    p->flagged = equal >= (size_t)s->opt.trace_min_rows && p->score >= s->opt.trace_threshold;
    if (!say && !p->flagged)
        return;
    if (equal)
        snprintf(p->reason, sizeof p->reason, "identical wrong numbers: %zu of %zu rows wrong in "
                 "both are equal bit for bit (first: row %ld)", equal, both, first);
    else
        snprintf(p->reason, sizeof p->reason, "no equal wrong rows (%zu rows wrong in both)", both);
}

/* a and b prepared, of one kind, a < b; the reason written when say is
 * set or the pair is flagged (a class has millions of quiet pairs). */
static void compare_docs(const sw_similar *s, int a, int b, sw_similar_pair *p, int say)
{
    p->score = 0;
    p->shared = p->of = p->flagged = 0;
    p->reason[0] = '\0';
    p->a = a;
    p->b = b;
    if (s->docs[a].kind == DOC_SOURCE)
        compare_sources(s, &s->docs[a], &s->docs[b], p, say);
    else
        compare_traces(s, &s->docs[a], &s->docs[b], p, say);
}

int sw_similar_compare(sw_similar *s, int a, int b, sw_similar_pair *p)
{
    memset(p, 0, sizeof *p);
    if (a < 0 || b < 0 || a >= s->ndocs || b >= s->ndocs || a == b ||
        s->docs[a].kind != s->docs[b].kind)
        return SW_EINVAL;
    if (prepare(s) != SW_OK)
        return SW_ENOMEM;
    compare_docs(s, a < b ? a : b, a < b ? b : a, p, 1);
    return SW_OK;
}

static int pair_cmp(const void *x, const void *y)
{
    const sw_similar_pair *a = x, *b = y;
    if (a->score != b->score)
        return a->score < b->score ? 1 : -1;
    return a->a != b->a ? a->a - b->a : a->b - b->b;
}

int sw_similar_pairs(sw_similar *s, sw_similar_pair **out, int *n, char *err, size_t errlen)
{
    size_t cap = 0, count = 0;
    sw_similar_pair *v = NULL, p;
    *out = NULL;
    *n = 0;
    if (prepare(s) != SW_OK)
        goto nomem;
    for (int a = 0; a < s->ndocs; a++)
        for (int b = a + 1; b < s->ndocs; b++) {
            if (s->docs[a].kind != s->docs[b].kind)
                continue;
            compare_docs(s, a, b, &p, 0);
            if (!p.flagged)
                continue;
            if (count == cap) {
                cap = cap ? 2 * cap : 16;
                sw_similar_pair *grown = realloc(v, cap * sizeof *v);
                if (!grown)
                    goto nomem;
                v = grown;
            }
            v[count++] = p;
        }
    if (count)
        qsort(v, count, sizeof *v, pair_cmp);
    *out = v;
    *n = (int)count;
    return SW_OK;
nomem:
    free(v);
    snprintf(err, errlen, "similarity: out of memory");
    return SW_ENOMEM;
}

int sw_similar_fingerprints(sw_similar *s, int doc)
{
    if (doc < 0 || doc >= s->ndocs || s->docs[doc].kind != DOC_SOURCE || prepare(s) != SW_OK)
        return -1;
    return (int)s->docs[doc].nfp;
}
