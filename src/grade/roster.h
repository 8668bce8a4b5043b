/* Class rosters: a CSV of students (a name, optional ids and email), read
 * bounded and checked, and the rules that match a submission's path (the
 * names Gradescope, Canvas and Moodle downloads use, or a plain id, email
 * or name prefix) to one student. A name a file declares about itself is
 * checked against the roster, never believed (docs/grading.md, "Roster"). */
#ifndef SW_GRADE_ROSTER_H
#define SW_GRADE_ROSTER_H

#include <stddef.h>

#define SW_ROSTER_MAX 10000            /* students in a roster */
#define SW_ROSTER_CELL_MAX 256         /* bytes in one CSV cell */
#define SW_ROSTER_COLS_MAX 64          /* cells in one CSV row */
#define SW_ROSTER_FILE_MAX (8u << 20)  /* bytes in a roster or a metadata file */
#define SW_ROSTER_IDS 3                /* id columns kept (Canvas: ID, SIS User ID, SIS Login ID) */
#define SW_ROSTER_GROUP_MAX 16         /* submitters of one Gradescope group submission */

/* Negative results of matching a path (either means: no student). */
enum {
    SW_ROSTER_NONE = -1,      /* nothing in the path names a student */
    SW_ROSTER_AMBIGUOUS = -2  /* it names two or more, or two rules disagree */
};

/* One student. Strings belong to the roster; "" when the roster has none. */
typedef struct sw_student {
    const char *name;              /* as shown: the name cell, else "First Last" */
    const char *words;             /* the name folded (lower case, accents off), words
                                    * in given-name order, one space apart */
    const char *ids[SW_ROSTER_IDS]; /* normalised ids (lower case, alphanumerics, no
                                    * leading zeros when all digits) */
    int nids;
    const char *email;             /* lower case; "" when none */
    long line;                     /* the roster line it came from */
} sw_student;

/* A Gradescope export's submission folder and who submitted it. */
typedef struct sw_roster_gs {
    const char *folder;                     /* "submission_123456" */
    const char *who[SW_ROSTER_GROUP_MAX];   /* submitters' names as the metadata gives them */
    int student[SW_ROSTER_GROUP_MAX];       /* their roster index, or SW_ROSTER_NONE/AMBIGUOUS */
    int n;
    long line;                              /* the metadata line of the folder */
} sw_roster_gs;

typedef struct sw_roster_block sw_roster_block;

typedef struct sw_roster {
    sw_student *students;
    int n;
    sw_roster_gs *gs;     /* from sw_roster_read_gradescope; NULL until then */
    int ngs;
    long skipped;         /* rows left out: staff (a role column), Canvas's "Points Possible" */
    sw_roster_block *pool; /* the strings */
} sw_roster;

/* Read a roster CSV (RFC 4180; comma, semicolon or tab, from the header
 * row; UTF-8, a BOM allowed) into r. The header names the columns, any case:
 * "name" (or "student", "full name"; a "Last, First" cell is understood),
 * or "first name" and "last name" (also "first"/"last", "given name",
 * "surname"); optional ids ("id", "sid", "student id", "id number", "sis
 * user id", ...), "email", and "role" (rows whose role is not a student's
 * are skipped). 0, or SW_EINVAL / SW_EIO / SW_ENOMEM with err
 * "FILE:LINE: what is wrong"; r is then empty (still free it). */
int sw_roster_read(const char *path, sw_roster *r, char *err, size_t errlen);
/* The same from bytes in memory; name is used in messages. */
int sw_roster_parse(const char *name, const char *text, size_t len, sw_roster *r, char *err,
                    size_t errlen);
/* Release what r holds (r may be zeroed or half read). */
void sw_roster_free(sw_roster *r);

/* Read a Gradescope export's submission_metadata.yml: each
 * "submission_ID" folder's submitters (name, sid, email), each resolved to
 * a roster student by sid, else email, else name. Replaces earlier
 * metadata. 0 or an error as sw_roster_read's. */
int sw_roster_read_gradescope(sw_roster *r, const char *path, char *err, size_t errlen);
/* The same from bytes in memory. */
int sw_roster_parse_gradescope(sw_roster *r, const char *name, const char *text, size_t len,
                               char *err, size_t errlen);

/* The student a submission belongs to, from its path relative to the
 * submissions directory ("submission_123/euler.c",
 * "smithjohn_late_4711_99_euler.c", "John Smith_12_assignsubmission_file_/
 * euler.c", "s1234567_euler.trace"). The outermost folder or file name that
 * names a student decides. Returns the index, or SW_ROSTER_NONE or
 * SW_ROSTER_AMBIGUOUS; why (may be NULL) gets one line: the rule that
 * matched, or why none did. For a group submission, the first member. */
int sw_roster_match(const sw_roster *r, const char *relpath, char *why, size_t whylen);
/* The same, every member of a group submission into out (max >= 1):
 * returns how many (>= 1), or SW_ROSTER_NONE / SW_ROSTER_AMBIGUOUS. */
int sw_roster_match_all(const sw_roster *r, const char *relpath, int *out, int max, char *why,
                        size_t whylen);

/* What a file's self-declared student ("# student:") says, against the
 * student the roster matched it to. */
typedef enum sw_roster_claim {
    SW_CLAIM_NONE = 0,  /* nothing declared */
    SW_CLAIM_SELF,      /* it names the matched student (name, part of it, id or email) */
    SW_CLAIM_OTHER,     /* it names someone else on the roster: report, never believe */
    SW_CLAIM_UNKNOWN    /* it names nobody on the roster */
} sw_roster_claim;

/* Check declared against student (an index, or negative when the file
 * matched nobody). For SW_CLAIM_OTHER, *other (may be NULL) is the student
 * it names. why (may be NULL) gets one line for the report. */
sw_roster_claim sw_roster_check_claim(const sw_roster *r, int student, const char *declared,
                                      int *other, char *why, size_t whylen);

/* A name folded for comparison into out (always NUL-terminated): lower
 * case, Latin accents and combining marks removed (é and e + U+0301 both
 * give e; ß gives ss, æ ae, ø o), everything but letters and digits dropped.
 * Returns the length. */
size_t sw_roster_fold(const char *text, size_t len, char *out, size_t outlen);

/* The same Latin letters with their case and everything else kept, into
 * out (always NUL-terminated): "Émilie du Châtelet" gives "Emilie du
 * Chatelet", "Straße" "Strasse"; combining marks dropped, other text
 * copied. For file names made from names the roster compares folded.
 * Returns the length. */
size_t sw_roster_fold_latin(const char *text, size_t len, char *out, size_t outlen);

#endif
