/* Rosters: the CSV reader (quoting, separators, BOM, the header's names,
 * rows left out, one-line errors with their line), folding names, and
 * matching submission paths to students by the rules of Gradescope, Canvas,
 * Moodle and plain prefixes, with ambiguity named and self-declared names
 * checked, not believed. */
#include <check.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "grade/roster.h"
#include "stepwise/base.h"
#include "util/utf8.h"

static sw_roster parse_ok(const char *text)
{
    sw_roster r;
    char err[SW_ERRLEN] = "";
    int rc = sw_roster_parse("r.csv", text, strlen(text), &r, err, sizeof err);
    ck_assert_msg(rc == SW_OK, "refused: %s", err);
    return r;
}

/* The error for text, which must be refused. */
static const char *parse_err(const char *text, size_t len)
{
    static char err[SW_ERRLEN];
    sw_roster r;
    err[0] = '\0';
    int rc = sw_roster_parse("r.csv", text, len, &r, err, sizeof err);
    ck_assert_msg(rc != SW_OK, "accepted: %.60s", text);
    ck_assert_int_eq(r.n, 0);
    ck_assert_ptr_null(strchr(err, '\n'));
    sw_roster_free(&r);
    return err;
}

#define ERR_HAS(text, want) do { \
    const char *e_ = parse_err(text, strlen(text)); \
    ck_assert_msg(strstr(e_, want) != NULL, "error '%s' lacks '%s'", e_, want); \
} while (0)

/* ---- reading ------------------------------------------------------------------ */

START_TEST(csv_quoting_and_separators)
{
    /* RFC 4180: quoted cells with the separator, doubled quotes, CRLF, a
     * BOM; trailing empty cells; blank lines. */
    sw_roster r = parse_ok("\xEF\xBB\xBFName,ID,Email\r\n"
                           "\"Smith, John\",00123,John.Smith@Uni.edu\r\n"
                           "\r\n"
                           "\"Ann \"\"Nan\"\" Lee\",s-77,,\r\n"
                           "Zoë Brontë,9,zb@uni.edu");
    ck_assert_int_eq(r.n, 3);
    ck_assert_str_eq(r.students[0].name, "John Smith"); /* "Last, First" turned round */
    ck_assert_str_eq(r.students[0].words, "john smith");
    ck_assert_str_eq(r.students[0].ids[0], "123");      /* leading zeros dropped */
    ck_assert_str_eq(r.students[0].email, "john.smith@uni.edu");
    ck_assert_int_eq(r.students[0].line, 2);
    ck_assert_str_eq(r.students[1].name, "Ann \"Nan\" Lee");
    ck_assert_str_eq(r.students[1].words, "ann nan lee");
    ck_assert_str_eq(r.students[1].ids[0], "s77");
    ck_assert_int_eq(r.students[1].line, 4);
    ck_assert_str_eq(r.students[2].words, "zoe bronte");
    sw_roster_free(&r);

    /* A semicolon file (Excel in many locales) and a tab-separated one. */
    r = parse_ok("first name;last name;student id\nJosé;García López;42\n");
    ck_assert_int_eq(r.n, 1);
    ck_assert_str_eq(r.students[0].name, "José García López");
    ck_assert_str_eq(r.students[0].words, "jose garcia lopez");
    sw_roster_free(&r);
    r = parse_ok("Surname\tGiven name\tE-mail\nOkafor\tChidi\tco@x.org\n");
    ck_assert_str_eq(r.students[0].name, "Chidi Okafor");
    ck_assert_str_eq(r.students[0].email, "co@x.org");
    sw_roster_free(&r);
}
END_TEST

START_TEST(csv_exports_of_the_platforms)
{
    /* Gradescope's roster: staff rows are left out by their role. */
    sw_roster r = parse_ok("First Name,Last Name,SID,Email,Role,Sections\n"
                           "Ada,Lovelace,1815,ada@uni.edu,Student,\n"
                           "Alan,Turing,,turing@uni.edu,Instructor,\n"
                           "Grace,Hopper,1906,grace@uni.edu,STUDENT,A\n");
    ck_assert_int_eq(r.n, 2);
    ck_assert_int_eq(r.skipped, 1);
    ck_assert_str_eq(r.students[1].name, "Grace Hopper");
    sw_roster_free(&r);

    /* Canvas's gradebook: "Last, First", three ids, a "Points Possible" row. */
    r = parse_ok("Student,ID,SIS User ID,SIS Login ID,Section,HW1 (123)\n"
                 "    Points Possible,,,,,10\n"
                 "\"Lovelace, Ada\",4711,u1815,ada,CS 1,9\n");
    ck_assert_int_eq(r.n, 1);
    ck_assert_int_eq(r.skipped, 1);
    ck_assert_int_eq(r.students[0].nids, 3);
    ck_assert_str_eq(r.students[0].ids[0], "4711");
    ck_assert_str_eq(r.students[0].ids[2], "ada");
    sw_roster_free(&r);

    /* Moodle's export. */
    r = parse_ok("First name,Surname,ID number,Institution,Department,Email address\n"
                 "Émile,Zola,E-1840,,,emile@x.fr\n");
    ck_assert_str_eq(r.students[0].words, "emile zola");
    ck_assert_str_eq(r.students[0].ids[0], "e1840");
    sw_roster_free(&r);
}
END_TEST

START_TEST(csv_errors_name_the_line)
{
    ERR_HAS("", "r.csv:1: empty");
    ERR_HAS("id,email\n1,a@b.c\n", "r.csv:1: no name column");
    ERR_HAS("first name,id\nAda,1\n", "no name column");
    ERR_HAS("name,id\n", "no students");
    ERR_HAS("name,id\nAda,1\n\"Bob,2\nCarl,3\n", "r.csv:3: a quoted cell opened on this line runs past its end");
    ERR_HAS("name,id\nAda,1\n\"Bob", "r.csv:3: a quoted cell opened on this line is never closed");
    ERR_HAS("name,id\n\"Ada\" L,1\n", "r.csv:2: text after a quoted cell");
    ERR_HAS("name,id\nAda,1\nSmith, John,2\n", "r.csv:3: 3 cells, but the header has 2");
    ERR_HAS("name,id\nAda,1\nBob,1\n", "r.csv:3: id 1 is also line 2's");
    ERR_HAS("name,id\nAda,007\nBob,7\n", "id 7 is also line 2's");
    ERR_HAS("name,email\nAda,A@x.org\nBob,a@X.org\n", "r.csv:3: email a@x.org is also line 2's");
    ERR_HAS("name,email\nAda,ada.x.org\n", "r.csv:2: 'ada.x.org' is not an email address");
    ERR_HAS("name,id\nAda,1\n,2\n", "r.csv:3: no name on this row");
    ERR_HAS("name,id\n---,2\n", "has no letters or digits");
    ERR_HAS("name,Name\nAda,Ada\n", "columns 1 ('name') and 2 ('Name') say the same thing");
    ERR_HAS("name,id,sid,student id,sis user id\nAda,1,2,3,4\n", "more than 3 id columns");
    ERR_HAS("name,id\nAda,1\nJos\xe9,2\n", "r.csv:3: not UTF-8");
    ERR_HAS("name,id\nAda,1\nBob\x01,2\n", "r.csv:3: a cell holds a control character");
    ERR_HAS("name,id\nAda,1\n\"Bob\nLee\",2\n", "r.csv:3: a quoted cell opened on this line runs past");
    const char nul[] = "name,id\nA\0da,1\n";
    const char *e = parse_err(nul, sizeof nul - 1);
    ck_assert_msg(strstr(e, "r.csv:2: a NUL byte") != NULL, "%s", e);

    char big[600];
    snprintf(big, sizeof big, "name\n%0300d\n", 0);
    ERR_HAS(big, "r.csv:2: a cell longer than 256 bytes");
    char wide[400] = "name";
    for (int i = 0; i < 70; i++)
        strcat(wide, ",x");
    ERR_HAS(wide, "more than 64 cells in a row");
}
END_TEST

START_TEST(csv_bounds_and_files)
{
    /* 10 000 students read; one more is refused, on its line. */
    size_t cap = 10002 * 24;
    char *text = malloc(cap);
    ck_assert_ptr_nonnull(text);
    size_t n = (size_t)snprintf(text, cap, "name,id\n");
    for (int i = 0; i < SW_ROSTER_MAX; i++)
        n += (size_t)snprintf(text + n, cap - n, "Student %d,%d\n", i, i);
    sw_roster r;
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_roster_parse("big.csv", text, n, &r, err, sizeof err), SW_OK);
    ck_assert_int_eq(r.n, SW_ROSTER_MAX);
    char why[SW_ERRLEN];
    ck_assert_int_eq(sw_roster_match(&r, "9999_euler.c", why, sizeof why), 9999);
    sw_roster_free(&r);
    n += (size_t)snprintf(text + n, cap - n, "One More,x1\n");
    ck_assert_int_ne(sw_roster_parse("big.csv", text, n, &r, err, sizeof err), SW_OK);
    ck_assert_str_eq(err, "big.csv:10002: more than 10000 students");
    free(text);

    /* From a file; a missing file and a directory are one-line errors. */
    char path[] = "/tmp/sw_roster_XXXXXX";
    int fd = mkstemp(path);
    ck_assert_int_ge(fd, 0);
    const char body[] = "name,email\nAda Lovelace,ada@uni.edu\n";
    ck_assert_int_eq(write(fd, body, sizeof body - 1), (ssize_t)(sizeof body - 1));
    close(fd);
    ck_assert_int_eq(sw_roster_read(path, &r, err, sizeof err), SW_OK);
    ck_assert_int_eq(r.n, 1);
    sw_roster_free(&r);
    unlink(path);
    ck_assert_int_eq(sw_roster_read(path, &r, err, sizeof err), SW_EIO);
    ck_assert_msg(strstr(err, ":1: cannot open: No such file") != NULL, "%s", err);
    ck_assert_int_eq(sw_roster_read("/tmp", &r, err, sizeof err), SW_EINVAL);
    ck_assert_str_eq(err, "/tmp:1: is a directory, not a roster");
    sw_roster_free(&r); /* a failed read leaves r empty and freeable */
}
END_TEST

START_TEST(folding_names)
{
    char out[64];
    ck_assert_int_eq(sw_roster_fold("José García-López", strlen("José García-López"), out, sizeof out), 15);
    ck_assert_str_eq(out, "josegarcialopez");
    sw_roster_fold("Jose\xCC\x81", 6, out, sizeof out); /* NFD: e + combining acute */
    ck_assert_str_eq(out, "jose");
    sw_roster_fold("Jos\xE9", 4, out, sizeof out);       /* Latin-1 byte */
    ck_assert_str_eq(out, "jose");
    sw_roster_fold("Straße Ærø Øyvind Łukasz Œuvre", 40, out, sizeof out);
    ck_assert_str_eq(out, "strasseaerooyvindlukaszoeuvre");
    sw_roster_fold("O'Brien_Smith.2", 15, out, sizeof out);
    ck_assert_str_eq(out, "obriensmith2");
    sw_roster_fold("ΣΩΚΡΑΤΗΣ", 16, out, sizeof out);     /* Greek capitals lowered */
    ck_assert_str_eq(out, "σωκρατησ");
    ck_assert_int_eq(sw_roster_fold("abcdef", 6, out, 4), 3); /* cut, NUL-terminated */
    ck_assert_str_eq(out, "abc");
}
END_TEST

/* File names from names (grade --feedback) fold as the roster does, case
 * kept: every Latin letter the roster folds gives the same letters, only
 * its capital kept, so a file's name and a roster match agree. */
START_TEST(folding_names_for_files)
{
    char out[96];
    sw_roster_fold_latin("Henri Poincaré", strlen("Henri Poincaré"), out, sizeof out);
    ck_assert_str_eq(out, "Henri Poincare");
    sw_roster_fold_latin("Émilie du Châtelet", strlen("Émilie du Châtelet"), out, sizeof out);
    ck_assert_str_eq(out, "Emilie du Chatelet");
    const char *many = "Straße Ærø Øyvind Łukasz Œuvre Ĳssel Ŋ Ÿves Žofie ĸ";
    sw_roster_fold_latin(many, strlen(many), out, sizeof out);
    ck_assert_str_eq(out, "Strasse Aero Oyvind Lukasz Oeuvre Ijssel N Yves Zofie k");
    sw_roster_fold_latin("Jose\xCC\x81 Jos\xE9", 11, out, sizeof out); /* NFD; a Latin-1 byte */
    ck_assert_str_eq(out, "Jose Jose");
    sw_roster_fold_latin("O'Brien_Σ 3×4", strlen("O'Brien_Σ 3×4"), out, sizeof out);
    ck_assert_str_eq(out, "O'Brien_Σ 34");                 /* the rest kept, × dropped as the roster does */
    ck_assert_int_eq(sw_roster_fold_latin("abcdef", 6, out, 4), 3);
    ck_assert_str_eq(out, "abc");
    /* Each letter of U+00C0..U+017F: lower-cased, the same as the roster's fold. */
    for (uint32_t cp = 0xC0; cp < 0x180; cp++) {
        char in[4], latin[8], roster[8];
        int n = sw_utf8_encode(cp, in);
        sw_roster_fold(in, (size_t)n, roster, sizeof roster);
        size_t k = sw_roster_fold_latin(in, (size_t)n, latin, sizeof latin);
        for (size_t i = 0; i < k; i++)
            latin[i] = (char)(latin[i] >= 'A' && latin[i] <= 'Z' ? latin[i] - 'A' + 'a' : latin[i]);
        ck_assert_msg(strcmp(latin, roster) == 0, "U+%04X: '%s' for files, '%s' in the roster",
                      (unsigned)cp, latin, roster);
    }
}
END_TEST

/* ---- matching ----------------------------------------------------------------- */

static const char class_csv[] =
    "Name,ID,SIS User ID,Email\n"
    "\"Smith, John\",4711,s1001,jsmith@uni.edu\n"          /* 0 */
    "José García López,4712,s1002,jgarcia@uni.edu\n"     /* 1 */
    "Ann Lee,4713,s1003,ann.lee@uni.edu\n"               /* 2 */
    "Ann Leeds,4714,s1004,aleeds@uni.edu\n"              /* 3 */
    "Wei Zhang,4715,s1005,wzhang@uni.edu\n"              /* 4 */
    "Wei Zhang,4716,s1006,wzhang2@uni.edu\n"             /* 5: the same name */
    "Zoë Brontë,4717,s1007,zoe@uni.edu\n";               /* 6 */

static int match(const sw_roster *r, const char *path, char *why)
{
    return sw_roster_match(r, path, why, SW_ERRLEN);
}

#define MATCHES(path, want, why_has) do { \
    char w_[SW_ERRLEN]; \
    int got_ = match(&r, path, w_); \
    ck_assert_msg(got_ == (want), "%s: got %d, want %d (%s)", path, got_, (want), w_); \
    ck_assert_msg(strstr(w_, why_has) != NULL, "%s: why '%s' lacks '%s'", path, w_, why_has); \
} while (0)

START_TEST(match_plain_prefixes)
{
    sw_roster r = parse_ok(class_csv);
    MATCHES("s1001_euler.trace", 0, "file name 's1001' is the id of John Smith (roster line 2)");
    MATCHES("4712.trace", 1, "id of José García López");
    MATCHES("jsmith_rk4.c", 0, "is the email of John Smith");
    MATCHES("jsmith@uni.edu.trace", 0, "email");
    MATCHES("John_Smith.c", 0, "is the name of John Smith");
    MATCHES("smith-john-hw3.csv", 0, "'smith-john' is the name");   /* last name first */
    MATCHES("Jose Garcia Lopez - rk4.c", 1, "name");                 /* accents off */
    MATCHES("garcia_lopez_jose/rk4.c", 1, "folder name 'garcia_lopez_jose'");
    MATCHES("ann_leeds_euler.c", 3, "Ann Leeds");    /* longest prefix first: not Ann Lee */
    MATCHES("ann-lee.trace", 2, "Ann Lee");
    MATCHES("ZOE_BRONTE.trace", 6, "Zoë Brontë");
    MATCHES("./hw3/ann.lee/euler.c", 2, "folder name 'ann.lee' is the email");
    /* Outermost decides: a student's folder may hold files named anything. */
    MATCHES("s1003/john_smith.c", 2, "folder name 's1003'");
    MATCHES("euler.c", SW_ROSTER_NONE, "no folder or file name in 'euler.c'");
    MATCHES("johnsmithrk4.c", SW_ROSTER_NONE, "no folder");           /* no delimiter */
    sw_roster_free(&r);
}
END_TEST

START_TEST(match_ambiguity_is_named)
{
    sw_roster r = parse_ok(class_csv);
    MATCHES("wei_zhang_euler.c", SW_ROSTER_AMBIGUOUS,
            "'wei_zhang' fits Wei Zhang (roster line 6) and Wei Zhang (roster line 7); rename "
            "the file with the id");
    /* An ambiguous folder is settled by a file name inside it... */
    MATCHES("Wei Zhang/s1006_rk4.c", 5, "settles");
    /* ...but not by one naming somebody else. */
    MATCHES("Wei Zhang/s1001_rk4.c", SW_ROSTER_AMBIGUOUS, "and file name 's1001'");
    MATCHES("wei_zhang_s1005.c", 4, "'wei_zhang' fits 2 students; the id or email in it is Wei "
            "Zhang (roster line 6)");
    MATCHES("wei_zhang_wzhang2.c", 5, "the id or email in it is Wei Zhang (roster line 7)");
    sw_roster_free(&r);
}
END_TEST

START_TEST(match_canvas_downloads)
{
    sw_roster r = parse_ok(class_csv);
    /* <lastfirst>_[late_]<user id>_<file id>_<original name>; resubmissions get -1. */
    MATCHES("smithjohn_4711_99817_euler.c", 0, "Canvas name: id 4711 and the name is John Smith");
    MATCHES("smithjohn_late_4711_99817_euler-1.c", 0, "Canvas name: id 4711");
    MATCHES("garcialopezjose_4712_5_rk4.c", 1, "Canvas");
    /* A user id the roster lacks: the name decides. */
    MATCHES("leeann_900001_5_x.c", 2, "Canvas name: 'leeann' is Ann Lee");
    /* The id decides even when the name changed (a preferred name). */
    MATCHES("smithjonathan_4711_5_x.c", 0, "Canvas name: id 4711 is John Smith");
    /* The id and the name disagree: nobody is guessed. */
    MATCHES("leeann_4711_5_x.c", SW_ROSTER_AMBIGUOUS,
            "id 4711 is John Smith (roster line 2) but 'leeann' is Ann Lee (roster line 4)");
    /* The older form "last--first[-late]_id_file_name", and a text entry. */
    MATCHES("smith--john-late_4711_5_x.c", 0, "Canvas");
    MATCHES("smithjohn_4711_text.html", 0, "Canvas");
    /* Nobody: the why says what was looked for. */
    MATCHES("doejane_123_5_x.c", SW_ROSTER_NONE,
            "Canvas name 'doejane' (id 123): no roster student has that name or id");
    sw_roster_free(&r);
}
END_TEST

START_TEST(match_moodle_downloads)
{
    sw_roster r = parse_ok(class_csv);
    MATCHES("John Smith_55_assignsubmission_file_/euler.c", 0, "Moodle name: 'John Smith' is John Smith");
    MATCHES("José García López_56_assignsubmission_file_rk4.c", 1, "Moodle");
    MATCHES("Jose\xCC\x81 Garci\xCC\x81" "a Lo\xCC\x81pez_56_assignsubmission_file_rk4.c", 1,
            "Moodle"); /* a Mac's NFD file name */
    MATCHES("García López José_56_assignsubmission_onlinetext_onlinetext.html", 1, "Moodle");
    MATCHES("Participant 9913_9913_assignsubmission_file_x.c", SW_ROSTER_NONE,
            "Moodle name 'Participant 9913' (id 9913)"); /* blind marking */
    sw_roster_free(&r);
}
END_TEST

static const char gs_yml[] =
    "---\n"
    "submission_216975964:\n"
    "  :submitters:\n"
    "  - :name: John Smith\n"
    "    :sid: 's1001'\n"
    "    :email: jsmith@uni.edu\n"
    "  - :name: \"Zo\\u00EB Bront\\u00EB\"\n"
    "    :sid: ''\n"
    "    :email: zoe@uni.edu\n"
    "  :created_at: 2023-12-02 02:52:07.938335000 Z\n"
    "  :score: 0.0\n"
    "  :history:\n"
    "  - :submitters: []\n"
    "    :id: 217383000\n"
    "submission_216996427:\n"
    "  :submitters:\n"
    "  - :name: Someone Else\n"
    "    :sid: '99999'\n"
    "    :email: else@uni.edu\n"
    "submission_216996428:\n"
    "  :submitters:\n"
    "  - :name: Ann Lee\n"
    "    :sid: ''\n"
    "    :email: ''\n";

START_TEST(match_gradescope_exports)
{
    sw_roster r = parse_ok(class_csv);
    /* Before the metadata is read, the folder says where to look. */
    MATCHES("submission_216975964/euler.c", SW_ROSTER_NONE, "submission_metadata.yml");
    char err[SW_ERRLEN];
    ck_assert_int_eq(sw_roster_parse_gradescope(&r, "meta.yml", gs_yml, sizeof gs_yml - 1, err,
                                                sizeof err), SW_OK);
    ck_assert_int_eq(r.ngs, 3);
    ck_assert_str_eq(r.gs[0].who[1], "Zoë Brontë"); /* \u escapes decoded */
    /* A group: both members, by sid and by email. */
    int who[4];
    char why[SW_ERRLEN];
    ck_assert_int_eq(sw_roster_match_all(&r, "submission_216975964/euler.c", who, 4, why,
                                         sizeof why), 2);
    ck_assert_int_eq(who[0], 0);
    ck_assert_int_eq(who[1], 6);
    ck_assert_msg(strstr(why, "a group of 2, first John Smith") != NULL, "%s", why);
    MATCHES("submission_216996428/x/rk4.c", 2, "Gradescope's submission_216996428: Ann Lee");
    MATCHES("submission_216996427/rk4.c", SW_ROSTER_NONE, "submitted by Someone Else, who is not on the roster");
    MATCHES("submission_1/rk4.c", SW_ROSTER_NONE, "not in submission_metadata.yml");

    /* Metadata errors name their line. */
    ck_assert_int_ne(sw_roster_parse_gradescope(&r, "m.yml", "a: 1\n", 5, err, sizeof err), SW_OK);
    ck_assert_msg(strstr(err, "m.yml:1: no 'submission_ID:' entries") != NULL, "%s", err);
    const char twice[] = "submission_1:\n  :submitters: []\nsubmission_1:\n";
    ck_assert_int_ne(sw_roster_parse_gradescope(&r, "m.yml", twice, sizeof twice - 1, err, sizeof err), SW_OK);
    ck_assert_str_eq(err, "m.yml:3: submission_1 appears twice (first on line 1)");
    ck_assert_ptr_null(r.gs); /* a failed read drops the old metadata too */
    sw_roster_free(&r);
}
END_TEST

START_TEST(match_hostile_paths)
{
    sw_roster r = parse_ok(class_csv);
    char why[SW_ERRLEN], longpath[5000];
    const char *paths[] = { "", "/", "//", "..", "../../etc/passwd", ".", "\x1b[2J_4711.c",
                            "\xff\xfe\xfd", "_", "__4711__", "submission_", "submission_x/y",
                            "a_1_assignsubmission_", "_1_assignsubmission_file_x", "x\\y\\4711.c" };
    for (size_t i = 0; i < sizeof paths / sizeof paths[0]; i++) {
        int got = match(&r, paths[i], why);
        ck_assert_int_ge(got, SW_ROSTER_AMBIGUOUS);
        ck_assert_ptr_null(strchr(why, '\n'));
        ck_assert_ptr_null(strchr(why, '\x1b')); /* escaped for the terminal */
    }
    ck_assert_int_eq(match(&r, "x\\y\\4711.c", why), 0); /* a Windows zip's separators */
    memset(longpath, 'a', sizeof longpath - 1);
    longpath[sizeof longpath - 1] = '\0';
    ck_assert_int_eq(match(&r, longpath, why), SW_ROSTER_NONE);
    for (size_t i = 0; i + 1 < sizeof longpath; i += 2)
        longpath[i] = '/';
    ck_assert_int_eq(match(&r, longpath, why), SW_ROSTER_NONE);
    ck_assert_int_eq(sw_roster_match(&r, NULL, NULL, 0), SW_ROSTER_NONE);
    sw_roster_free(&r);
    sw_roster empty = { 0 };
    ck_assert_int_eq(sw_roster_match(&empty, "4711.c", why, sizeof why), SW_ROSTER_NONE);
    ck_assert_str_eq(why, "the roster is empty");
}
END_TEST

START_TEST(claims_are_checked_not_believed)
{
    sw_roster r = parse_ok(class_csv);
    char why[SW_ERRLEN];
    int other;
    ck_assert_int_eq(sw_roster_check_claim(&r, 0, NULL, &other, why, sizeof why), SW_CLAIM_NONE);
    ck_assert_int_eq(sw_roster_check_claim(&r, 0, "  ", &other, why, sizeof why), SW_CLAIM_NONE);
    ck_assert_int_eq(sw_roster_check_claim(&r, 0, "John Smith", &other, why, sizeof why), SW_CLAIM_SELF);
    ck_assert_int_eq(sw_roster_check_claim(&r, 0, "smith, john", &other, why, sizeof why), SW_CLAIM_SELF);
    ck_assert_int_eq(sw_roster_check_claim(&r, 0, "John", &other, why, sizeof why), SW_CLAIM_SELF);
    ck_assert_int_eq(sw_roster_check_claim(&r, 0, "John Q. Smith", &other, why, sizeof why),
                     SW_CLAIM_SELF); /* a middle initial added */
    ck_assert_int_eq(sw_roster_check_claim(&r, 0, "Johnny", &other, why, sizeof why), SW_CLAIM_UNKNOWN);
    ck_assert_str_eq(why, "'# student: Johnny' is nobody on the roster");
    ck_assert_int_eq(sw_roster_check_claim(&r, 0, "s1001", &other, why, sizeof why), SW_CLAIM_SELF);
    ck_assert_int_eq(sw_roster_check_claim(&r, 0, "JSmith@uni.edu", &other, why, sizeof why), SW_CLAIM_SELF);
    ck_assert_int_eq(sw_roster_check_claim(&r, 1, "Jose Garcia", &other, why, sizeof why), SW_CLAIM_SELF);
    /* A classmate's name: reported with who it names. */
    ck_assert_int_eq(sw_roster_check_claim(&r, 0, "Ann Lee", &other, why, sizeof why), SW_CLAIM_OTHER);
    ck_assert_int_eq(other, 2);
    ck_assert_str_eq(why, "'# student: Ann Lee' names Ann Lee (roster line 4), but the file is "
                          "John Smith (roster line 2)'s: not believed");
    ck_assert_int_eq(sw_roster_check_claim(&r, 0, "4717", &other, why, sizeof why), SW_CLAIM_OTHER);
    ck_assert_int_eq(other, 6);
    /* A file that matched nobody cannot make itself somebody's. */
    ck_assert_int_eq(sw_roster_check_claim(&r, SW_ROSTER_NONE, "Ann Lee", &other, why, sizeof why),
                     SW_CLAIM_OTHER);
    ck_assert_msg(strstr(why, "the file's name matched nobody: not believed") != NULL, "%s", why);
    ck_assert_int_eq(sw_roster_check_claim(&r, 0, "Johnny \x1b[31m", &other, why, sizeof why),
                     SW_CLAIM_UNKNOWN);
    ck_assert_ptr_null(strchr(why, '\x1b'));
    sw_roster_free(&r);
}
END_TEST

/* The class of issue 22: a roster of 10, 8 submissions in the names three
 * platforms and students use, one claiming a classmate; 2 missing. */
START_TEST(a_class_with_missing_students)
{
    sw_roster r = parse_ok("First Name,Last Name,SID,Email\n"
                           "Ada,Lovelace,1,ada@u.edu\nAlan,Turing,2,alan@u.edu\n"
                           "Grace,Hopper,3,grace@u.edu\nEdsger,Dijkstra,4,ewd@u.edu\n"
                           "Barbara,Liskov,5,liskov@u.edu\nDonald,Knuth,6,knuth@u.edu\n"
                           "Frances,Allen,7,fran@u.edu\nJohn,Backus,8,backus@u.edu\n"
                           "Katherine,Johnson,9,kj@u.edu\nNiklaus,Wirth,10,wirth@u.edu\n");
    const char *files[] = { "lovelaceada_late_1_55_euler.c", "Alan Turing_2_assignsubmission_file_/rk4.c",
                            "3_rk4.trace", "ewd_euler.trace", "liskov-barbara.trace",
                            "donald_knuth/rk4.c", "allen_frances_rk4.c", "kj.trace" };
    const char *declared[] = { "", "", "Grace Hopper", "", "Ada Lovelace", "", "", "" };
    int seen[10] = { 0 }, claims_other = 0;
    for (int i = 0; i < 8; i++) {
        char why[SW_ERRLEN];
        int s = sw_roster_match(&r, files[i], why, sizeof why);
        ck_assert_msg(s >= 0, "%s: %s", files[i], why);
        seen[s]++;
        int other;
        if (sw_roster_check_claim(&r, s, declared[i], &other, why, sizeof why) == SW_CLAIM_OTHER) {
            claims_other++;
            ck_assert_int_eq(other, 0); /* Barbara's trace says it is Ada's */
            ck_assert_int_eq(s, 4);
        }
    }
    int missing[10], nmissing = 0;
    for (int i = 0; i < r.n; i++)
        if (!seen[i])
            missing[nmissing++] = i;
    ck_assert_int_eq(nmissing, 2);
    ck_assert_str_eq(r.students[missing[0]].name, "John Backus");
    ck_assert_str_eq(r.students[missing[1]].name, "Niklaus Wirth");
    ck_assert_int_eq(claims_other, 1);
    sw_roster_free(&r);
}
END_TEST

Suite *make_roster_suite(void);
Suite *make_roster_suite(void)
{
    Suite *s = suite_create("roster");
    TCase *tc = tcase_create("read");
    tcase_add_test(tc, csv_quoting_and_separators);
    tcase_add_test(tc, csv_exports_of_the_platforms);
    tcase_add_test(tc, csv_errors_name_the_line);
    tcase_add_test(tc, csv_bounds_and_files);
    tcase_add_test(tc, folding_names);
    tcase_add_test(tc, folding_names_for_files);
    suite_add_tcase(s, tc);
    tc = tcase_create("match");
    tcase_add_test(tc, match_plain_prefixes);
    tcase_add_test(tc, match_ambiguity_is_named);
    tcase_add_test(tc, match_canvas_downloads);
    tcase_add_test(tc, match_moodle_downloads);
    tcase_add_test(tc, match_gradescope_exports);
    tcase_add_test(tc, match_hostile_paths);
    tcase_add_test(tc, claims_are_checked_not_believed);
    tcase_add_test(tc, a_class_with_missing_students);
    suite_add_tcase(s, tc);
    return s;
}
