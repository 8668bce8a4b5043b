/* Similarity between submissions, for a teacher to look at (never a
 * verdict). C sources: a token stream with identifiers, literals, comments
 * and layout normalised, k-gram hashes winnowed into fingerprints (MOSS:
 * Schleimer, Wilkerson and Aiken 2003), the handout's fingerprints removed,
 * and pairs scored by the fingerprints they share. Traces: byte-identical
 * files and identical wrong numbers; correct traces are identical by design
 * and never flagged (docs/grading.md, "Similarity"). */
#ifndef SW_GRADE_SIMILAR_H
#define SW_GRADE_SIMILAR_H

#include <stddef.h>
#include <stdint.h>

/* bytes of one source compared: a plugin's source with its headers (at
 * most 1 MiB to be built, plugin/plugin_headers.h) and a newline each */
#define SW_SIMILAR_SOURCE_MAX (((size_t)1 << 20) + 256)
#define SW_SIMILAR_DOCS_MAX 4096                /* documents in one set */
#define SW_SIMILAR_ROWS_MAX 4096                /* wrong rows kept per trace */

/* Token classes: every identifier is one token, every number (and
 * character constant) one, every string one; keywords and operators are
 * their own; comments, layout and #include lines are dropped. */
enum {
    SW_TOK_ID = 1,
    SW_TOK_NUM,
    SW_TOK_STR,
    SW_TOK_OTHER   /* a run of bytes C does not use (garbage, stray non-ASCII) */
    /* then the keywords and operators */
};

typedef struct sw_similar_opts {
    int k;                  /* k-gram length in tokens (default 12) */
    int w;                  /* winnowing window in k-grams (default 8): every match of at
                             * least w + k - 1 tokens shares a fingerprint */
    double threshold;       /* sources are flagged from this score on (default 0.5) */
    int min_shared;         /* ...and this many shared fingerprints (default 8) */
    int max_docs;           /* a fingerprint in more sources than this is boilerplate and
                             * ignored (MOSS's -m; default 10; 0: never) */
    double trace_threshold; /* traces: share of rows wrong in both that are equal (default 0.9) */
    int trace_min_rows;     /* ...and at least this many such rows (default 3) */
    int own_runs;           /* every student ran their own values (a homework's per-student
                             * parameters): two identical traces are a copy even when correct
                             * (default 0: correct traces are alike by design) */
} sw_similar_opts;

/* The defaults above. */
void sw_similar_defaults(sw_similar_opts *o);

/* A 128-bit digest of a file's bytes (not cryptographic: a label for
 * "byte-identical", computed while reading). */
typedef struct sw_similar_digest {
    uint64_t h[2];
    uint64_t bytes;
} sw_similar_digest;

void sw_similar_digest_init(sw_similar_digest *d);
void sw_similar_digest_add(sw_similar_digest *d, const void *bytes, size_t len);
/* The digest of a whole file, and (rows, unless NULL) of its lines that do
 * not start with '#': a trace's rows without its header, whose parameters
 * or name a copy may have edited. 0, or SW_EIO / SW_EINVAL with err
 * "FILE: what". */
int sw_similar_digest_file(const char *path, sw_similar_digest *d, sw_similar_digest *rows, char *err,
                           size_t errlen);

typedef struct sw_similar_doc sw_similar_doc;

typedef struct sw_similar {
    sw_similar_opts opt;
    sw_similar_doc *docs;
    int ndocs;
    uint64_t *base;          /* sorted k-gram hashes of the handout */
    size_t nbase;
    int prepared;            /* the sources' kept fingerprints match the base and set */
    size_t ncommon;          /* fingerprints more than max_docs sources share, not counted */
} sw_similar;

/* Start an empty set (opt NULL: the defaults). 0, or SW_EINVAL when an
 * option is out of range (err says which). */
int sw_similar_init(sw_similar *s, const sw_similar_opts *opt, char *err, size_t errlen);
void sw_similar_free(sw_similar *s);

/* Add handout code whose k-grams no source is blamed for (MOSS's -b); may
 * be called more than once, before or after sources are added. 0 or an
 * error. */
int sw_similar_add_base(sw_similar *s, const char *src, size_t len, char *err, size_t errlen);
/* The handout every plugin starts from (examples/euler_plugin.c's shape:
 * the include, the step function's signature and Euler loop, the sw_plugin
 * initialiser and sw_plugin_info) as the base. */
int sw_similar_add_default_base(sw_similar *s, char *err, size_t errlen);

/* Add a C source; returns its index (>= 0), or SW_EINVAL (larger than
 * SW_SIMILAR_SOURCE_MAX, or too many documents) / SW_ENOMEM with err. */
int sw_similar_add_source(sw_similar *s, const char *src, size_t len, char *err, size_t errlen);
/* Add a trace by its digest and its rows' (NULL: not known); correct: it
 * passed (it is then never flagged, but with own_runs). Two traces whose
 * rows are the same under different headers, one of them correct, are
 * flagged as identical ones are. Returns its index or an error. */
int sw_similar_add_trace(sw_similar *s, const sw_similar_digest *d, const sw_similar_digest *rows,
                         int correct, char *err, size_t errlen);
/* Row `row` (0-based, increasing) of trace doc: its values and whether it
 * is wrong against the reference (only wrong rows are kept, at most
 * SW_SIMILAR_ROWS_MAX). 0 or SW_ENOMEM. */
int sw_similar_trace_row(sw_similar *s, int doc, long row, const double *values, int n, int wrong);

/* Doc's owner (a student's number, >= 0): fingerprints are common code
 * when more than max_docs owners share them, each doc its own owner until
 * set. */
void sw_similar_set_owner(sw_similar *s, int doc, int owner);

/* One compared pair. */
typedef struct sw_similar_pair {
    int a, b;              /* document indices, a < b */
    double score;          /* 0..1; 1 for identical files */
    int shared, of;        /* fingerprints shared / of the smaller source; or rows
                            * equal / rows wrong in both */
    int flagged;
    char reason[160];      /* one line, e.g. "identical files (1234 bytes)" */
} sw_similar_pair;

/* Compare documents a and b (both sources or both traces) into p, flagged
 * or not. 0, or SW_EINVAL for a bad index or mixed kinds. */
int sw_similar_compare(sw_similar *s, int a, int b, sw_similar_pair *p);
/* Every flagged pair, highest score first, into a new *out (free it);
 * *n is how many. 0 or SW_ENOMEM. */
int sw_similar_pairs(sw_similar *s, sw_similar_pair **out, int *n, char *err, size_t errlen);

/* A source's tokens (see the enum above) into out, at most max; returns
 * how many there are (may exceed max). */
size_t sw_similar_tokenize(const char *src, size_t len, unsigned char *out, size_t max);
/* Fingerprints source doc keeps after the base is removed (-1 for a trace). */
int sw_similar_fingerprints(sw_similar *s, int doc);

#endif
