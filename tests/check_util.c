/* util/: UTF-8, escaping untrusted text (bidirectional controls and other
 * invisible formatting), name lists, NAME=VALUE, output files written the Unix way,
 * inputs opened without blocking; and lesson progress, the writer with
 * concurrent users (app/progress.c). */
#include <check.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "app/progress.h"
#include "stepwise/base.h"
#include "util/escape.h"
#include "util/fds.h"
#include "util/infile.h"
#include "util/kv.h"
#include "util/names.h"
#include "util/outfile.h"
#include "util/utf8.h"

static char tmpdir[64];

static void make_tmpdir(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/sw_util_XXXXXX");
    ck_assert_ptr_nonnull(mkdtemp(tmpdir));
}

static void remove_tmpdir(void)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpdir);
    ck_assert_int_eq(system(cmd), 0);
}

/* Entries in tmpdir (. and .. not counted). */
static int entries(void)
{
    char cmd[256], path[96];
    snprintf(path, sizeof path, "%s.count", tmpdir);
    snprintf(cmd, sizeof cmd, "ls -A '%s' | wc -l > '%s'", tmpdir, path);
    ck_assert_int_eq(system(cmd), 0);
    FILE *f = fopen(path, "r");
    int n = -1;
    ck_assert_int_eq(fscanf(f, "%d", &n), 1);
    fclose(f);
    remove(path);
    return n;
}

static void write_text(const char *path, const char *text)
{
    sw_outfile o;
    char err[SW_ERRLEN];
    ck_assert_msg(sw_outfile_open(&o, path, err, sizeof err) == SW_OK, "%s", err);
    fputs(text, o.f);
    ck_assert_msg(sw_outfile_commit(&o, err, sizeof err) == SW_OK, "%s", err);
}

static void read_text(const char *path, char *buf, size_t len)
{
    FILE *f = fopen(path, "r");
    ck_assert_ptr_nonnull(f);
    size_t n = fread(buf, 1, len - 1, f);
    buf[n] = '\0';
    fclose(f);
}

START_TEST(utf8)
{
    size_t len;
    uint32_t cp;
    const unsigned char e_acute[] = { 0xC3, 0xA9 }, overlong[] = { 0xC0, 0xAF }, cut[] = { 0xE2, 0x89 };
    const unsigned char surrogate[] = { 0xED, 0xA0, 0x80 };
    ck_assert_int_eq(sw_utf8_check(e_acute, 2, &len, &cp), SW_UTF8_OK);
    ck_assert_uint_eq(len, 2);
    ck_assert_uint_eq(cp, 0xE9);
    ck_assert_int_eq(sw_utf8_check(overlong, 2, &len, &cp), SW_UTF8_BAD_LEAD);
    ck_assert_int_eq(sw_utf8_check(cut, 2, &len, &cp), SW_UTF8_CUT);
    ck_assert_int_eq(sw_utf8_check(surrogate, 3, &len, &cp), SW_UTF8_BAD_RANGE);
    ck_assert_uint_eq(sw_utf8_count("\xCE\x94t = 1", 7), 6);      /* Δt = 1 */
    ck_assert_uint_eq(sw_utf8_clip("a\xCE\x94", 3, 2), 1);         /* never half of Δ */
    const unsigned char *p = (const unsigned char *)"\xE2\x9C\x93x";
    ck_assert_uint_eq(sw_utf8_next(&p), 0x2713);
    ck_assert_uint_eq(sw_utf8_next(&p), 'x');
}
END_TEST

/* ---- escaping invisible formatting -------------------------------------------------------- */

/* text with cp between 'a' and 'b', and what sw_escape must make of it */
static void around(uint32_t cp, char *text, char *want, int escaped)
{
    char bytes[4];
    int n = sw_utf8_encode(cp, bytes);
    char *t = text, *w = want;
    *t++ = 'a';
    *w++ = 'a';
    for (int i = 0; i < n; i++) {
        *t++ = bytes[i];
        if (escaped)
            w += sprintf(w, "\\x%02x", (unsigned char)bytes[i]);
        else
            *w++ = bytes[i];
    }
    *t++ = 'b';
    *w++ = 'b';
    *t = *w = '\0';
}

/* Every family Trojan Source (CVE-2021-42574) and name spoofing use: each
 * code point escaped as all its bytes, in \xNN, whatever function shows it. */
START_TEST(escape_invisible_families)
{
    static const struct { uint32_t lo, hi; const char *what; } families[] = {
        { 0x061C, 0x061C, "Arabic letter mark" },
        { 0x180E, 0x180E, "Mongolian vowel separator" },
        { 0x200B, 0x200D, "zero-width space, non-joiner, joiner" },
        { 0x200E, 0x200F, "left-to-right and right-to-left marks" },
        { 0x2028, 0x2029, "line and paragraph separators" },
        { 0x202A, 0x202E, "embeddings, pop, overrides (U+202E: RLO)" },
        { 0x2060, 0x2064, "word joiner, invisible operators" },
        { 0x2066, 0x2069, "isolates (LRI, RLI, FSI, PDI)" },
        { 0x206A, 0x206F, "deprecated format characters" },
        { 0xFEFF, 0xFEFF, "zero-width no-break space (BOM)" },
        { 0xFFF9, 0xFFFB, "interlinear annotation" },
        { 0xE0000, 0xE007F, "tag characters (hidden ASCII)" },
    };
    char text[16], want[64], out[64], kept[64];
    for (size_t f = 0; f < sizeof families / sizeof families[0]; f++)
        for (uint32_t cp = families[f].lo; cp <= families[f].hi; cp++) {
            ck_assert_msg(sw_utf8_invisible(cp), "U+%04X (%s)", (unsigned)cp, families[f].what);
            around(cp, text, want, 1);
            sw_escape(text, 100, out, sizeof out);
            ck_assert_msg(strcmp(out, want) == 0, "U+%04X (%s): '%s', not '%s'", (unsigned)cp,
                          families[f].what, out, want);
            sw_escape_kept(text, 100, kept, sizeof kept);
            ck_assert_str_eq(kept, want);
            /* in place, for a whole message */
            memcpy(kept, text, strlen(text) + 1);
            sw_escape_message(kept, sizeof kept);
            ck_assert_str_eq(kept, want);
            /* and escaping the escaped text again changes nothing */
            sw_escape_kept(want, 100, kept, sizeof kept);
            ck_assert_str_eq(kept, want);
        }
    /* a label that reads "RK4 password" backwards: nothing of it raw, all of it readable */
    char label[128];
    sw_escape("RK4 \u202Edrowssap\u202C \u2066x\u2069 zero\u200Bwidth", 100, label, sizeof label);
    ck_assert_str_eq(label, "RK4 \\xe2\\x80\\xaedrowssap\\xe2\\x80\\xac \\xe2\\x81\\xa6x\\xe2\\x81\\xa9 "
                          "zero\\xe2\\x80\\x8bwidth");
}
END_TEST

/* The characters beside each family are ordinary text, and ordinary UTF-8
 * (accents, Greek, CJK, emoji with a skin tone) comes out as it went in. */
START_TEST(escape_keeps_text)
{
    static const uint32_t beside[] = { 0x061B, 0x061D, 0x180D, 0x180F, 0x200A, 0x2010, 0x2027, 0x202F,
                                       0x205F, 0x2070, 0xFEFC, 0xFFF8, 0xFFFC, 0xDFFFF, 0xE0080,
                                       0x00E9, 0x03A9, 0x65E5, 0x1F600 };
    char text[16], want[64], out[64];
    for (size_t i = 0; i < sizeof beside / sizeof beside[0]; i++) {
        ck_assert_msg(!sw_utf8_invisible(beside[i]), "U+%04X", (unsigned)beside[i]);
        around(beside[i], text, want, 0);
        sw_escape(text, 100, out, sizeof out);
        ck_assert_msg(strcmp(out, text) == 0, "U+%04X changed to '%s'", (unsigned)beside[i], out);
    }
    static const char *const plain[] = {
        "café crème, naïve façade",
        "Ελληνικά: Δt, ω·Δt < 2",
        "日本語の説明、中文说明、한국어",
        "rk4 😀 🚀 👍🏽 ✓ ✗ ⠿",
        "Runge–Kutta “classical” (4th) — ok",
    };
    char big[256];
    for (size_t i = 0; i < sizeof plain / sizeof plain[0]; i++) {
        sw_escape(plain[i], 200, big, sizeof big);
        ck_assert_str_eq(big, plain[i]);
        sw_escape_kept(plain[i], 200, big, sizeof big);
        ck_assert_str_eq(big, plain[i]);
        memcpy(big, plain[i], strlen(plain[i]) + 1);
        sw_escape_message(big, sizeof big);
        ck_assert_str_eq(big, plain[i]);
    }
    /* the widths still add up: kept text keeps its cells, escapes are ASCII */
    sw_escape("日本\u202E", 100, out, sizeof out);
    ck_assert_str_eq(out, "日本\\xe2\\x80\\xae");
    ck_assert_uint_eq(sw_utf8_columns(out, strlen(out)), 4 + 12);
}
END_TEST

/* A cut (by the output buffer or by max) falls between characters: never
 * inside the escapes of one invisible character ("\xe2" alone would read
 * as a broken byte), always marked "...", always NUL-terminated in outlen. */
START_TEST(escape_invisible_cut)
{
    const char *text = "ab\u202Ecd";               /* a b e2 80 ae c d */
    const char *full = "ab\\xe2\\x80\\xaecd";     /* 16 bytes */
    char out[64];
    /* by the buffer: the 12 bytes of the escape go whole or not at all */
    for (size_t outlen = 1; outlen <= 24; outlen++) {
        memset(out, 'Z', sizeof out);
        sw_escape(text, 100, out, outlen);
        size_t len = strnlen(out, outlen);
        ck_assert_msg(len < outlen, "outlen %zu: not terminated", outlen);
        ck_assert_msg(out[outlen] == 'Z', "outlen %zu: wrote past outlen", outlen);
        const char *want = outlen > 16 ? full : outlen >= 6 ? "ab..." : outlen >= 5 ? "a..." : outlen >= 4 ? "..."
                         : outlen == 3 ? "ab" : outlen == 2 ? "a" : ""; /* no room for a mark */
        ck_assert_msg(strcmp(out, want) == 0, "outlen %zu: '%s', not '%s'", outlen, out, want);
    }
    /* the same with a four-byte tag character (U+E0041, a hidden 'A') */
    sw_escape("x\U000E0041y", 100, out, 19);
    ck_assert_str_eq(out, "x\\xf3\\xa0\\x81\\x81y");
    sw_escape("x\U000E0041y", 100, out, 18);
    ck_assert_str_eq(out, "x...");
    /* a cut after the whole escape keeps it */
    sw_escape("ab\u202Ecdefgh", 100, out, 18);
    ck_assert_str_eq(out, "ab\\xe2\\x80\\xae...");
    /* by max, inside the character: the part read is not shown as bytes */
    sw_escape(text, 3, out, sizeof out);
    ck_assert_str_eq(out, "ab...");
    sw_escape(text, 4, out, sizeof out);
    ck_assert_str_eq(out, "ab...");
    sw_escape(text, 5, out, sizeof out);
    ck_assert_str_eq(out, "ab\\xe2\\x80\\xae...");
    sw_escape("x\U000E0041y", 3, out, sizeof out);
    ck_assert_str_eq(out, "x...");
    sw_escape("aé", 2, out, sizeof out);             /* ordinary text too: no "\xc3" */
    ck_assert_str_eq(out, "a...");
    sw_escape("日本語", 4, out, sizeof out);
    ck_assert_str_eq(out, "日...");
    /* text that was never whole is still escaped byte by byte */
    sw_escape("a\xe2\x80", 100, out, sizeof out);
    ck_assert_str_eq(out, "a\\xe2\\x80");
    sw_escape("\x80\x80\x80\x80", 2, out, sizeof out);
    ck_assert_str_eq(out, "\\x80\\x80...");
    /* a message cut in place: no half escape either, and terminated */
    char msg[16];
    snprintf(msg, sizeof msg, "%s", "ab\u202Ecdefgh");
    sw_escape_message(msg, sizeof msg);
    ck_assert_str_eq(msg, "ab...");
    /* whatever the input and the size, no raw byte of such a character */
    const char *hostile = "\u202E\u2066\u200B\u2069\u202C\uFEFF\u061C";
    for (size_t outlen = 1; outlen <= 96; outlen++)
        for (size_t max = 0; max <= strlen(hostile) + 1; max++) {
            char o[96];
            sw_escape(hostile, max, o, outlen);
            ck_assert(strlen(o) < outlen);
            for (size_t i = 0; o[i]; i++)
                ck_assert_msg((unsigned char)o[i] >= 0x20 && (unsigned char)o[i] < 0x7f,
                              "outlen %zu max %zu: byte %zu is 0x%02x", outlen, max, i,
                              (unsigned char)o[i]);
            /* escapes come in whole characters: the bytes they stand for decode */
            unsigned char bytes[32];
            size_t nb = 0;
            for (const char *q = o; (q = strstr(q, "\\x")) != NULL && nb < sizeof bytes; q += 4)
                bytes[nb++] = (unsigned char)strtoul((char[3]){ q[2], q[3], 0 }, NULL, 16);
            for (size_t i = 0, len; i < nb; i += len) {
                uint32_t cp;
                ck_assert_msg(sw_utf8_check(bytes + i, nb - i, &len, &cp) == SW_UTF8_OK &&
                              sw_utf8_invisible(cp), "outlen %zu max %zu: '%s'", outlen, max, o);
            }
        }
}
END_TEST

/* Fitting text to terminal cells (grade's table) and to a message's room
 * after a whole word (the sandbox's reasons, the table's last column). */
START_TEST(escape_fit_cells_and_words)
{
    char out[128];
    /* By cells, not bytes: é is two bytes and one cell, 日 three and two. */
    sw_escape_fit("Henri Poincaré", 0, 20, 0, out, sizeof out);
    ck_assert_str_eq(out, "Henri Poincaré");
    sw_escape_fit("Émilie du Châtelet Lebrun", 0, 20, 0, out, sizeof out);
    ck_assert_str_eq(out, "Émilie du Châtele...");
    ck_assert_uint_eq(sw_utf8_columns(out, strlen(out)), 20);
    sw_escape_fit("日本語のテキスト", 0, 9, 0, out, sizeof out);
    ck_assert_str_eq(out, "日本語...");
    sw_escape_fit("日本語のテキスト", 0, 10, 0, out, sizeof out); /* no half of a wide one */
    ck_assert_str_eq(out, "日本語...");
    /* An escape counts its four cells and is never cut. */
    sw_escape_fit("x\033[2Jfake.trace", 0, 8, 0, out, sizeof out);
    ck_assert_str_eq(out, "x\\x1b...");
    sw_escape_fit("x\033[2Jfake.trace", 0, 7, 0, out, sizeof out);
    ck_assert_str_eq(out, "x...");
    /* After a whole word, the punctuation left hanging dropped. */
    const char *why = "the sandbox could not be set up: unshare(CLONE_NEWUSER | CLONE_NEWNS) failed "
                      "(Operation not permitted); it needs Linux user namespaces";
    sw_escape_fit(why, 1, SIZE_MAX, 1, out, 101);
    ck_assert_str_eq(out, "the sandbox could not be set up: unshare(CLONE_NEWUSER | CLONE_NEWNS) failed "
                          "(Operation not...");
    sw_escape_fit(why, 1, SIZE_MAX, 1, out, 107);
    ck_assert_str_eq(out, "the sandbox could not be set up: unshare(CLONE_NEWUSER | CLONE_NEWNS) failed "
                          "(Operation not permitted)...");
    sw_escape_fit("first part; second part", 0, 15, 1, out, sizeof out);
    ck_assert_str_eq(out, "first part...");
    /* A cut just before a space keeps the word it ends. */
    sw_escape_fit("abc defgh ijk", 0, 12, 1, out, sizeof out);
    ck_assert_str_eq(out, "abc defgh...");
    /* No word ends in the room's second half (a path): cut between characters. */
    sw_escape_fit("see /a/very/long/path/without/spaces", 0, 20, 1, out, sizeof out);
    ck_assert_str_eq(out, "see /a/very/long/...");
    /* Text that fits is left as it is, and the bytes bound too. */
    char whole[256];
    sw_escape_fit(why, 1, SIZE_MAX, 1, whole, sizeof whole);
    ck_assert_str_eq(whole, why);
    sw_escape_fit("abcdef", 0, SIZE_MAX, 1, out, 5);
    ck_assert_str_eq(out, "a...");
    for (size_t outlen = 1; outlen < 40; outlen++)
        for (size_t cells = 0; cells < 40; cells++) {
            char o[64];
            memset(o, 'Z', sizeof o);
            sw_escape_fit("Zoë Brontë, 日本, and a \x1b word", 0, cells, (int)(cells % 2), o, outlen);
            ck_assert(strnlen(o, outlen) < outlen && o[outlen] == 'Z');
            ck_assert_msg(sw_utf8_columns(o, strlen(o)) <= cells || outlen < 4 || cells < 3,
                          "cells %zu outlen %zu: '%s'", cells, outlen, o);
        }
}
END_TEST

static const char *word_at(const void *ctx, int i) { return ((const char *const *)ctx)[i]; }

START_TEST(names)
{
    const char *const words[] = { "euler", "rk4", "verlet" };
    char buf[64], tiny[8];
    ck_assert_uint_eq(sw_names_join(buf, sizeof buf, word_at, words, 3), strlen("euler, rk4, verlet"));
    ck_assert_str_eq(buf, "euler, rk4, verlet");
    sw_names_join(tiny, sizeof tiny, word_at, words, 3); /* bounded, terminated */
    ck_assert_str_eq(tiny, "euler, ");
    ck_assert_str_eq(sw_names_nearest("rk-4", word_at, words, 3), "rk4");
    ck_assert_ptr_null(sw_names_nearest("midpoint", word_at, words, 3));
    ck_assert_int_eq(sw_names_distance("kitten", "sitting"), 3);
}
END_TEST

START_TEST(kv_pairs)
{
    const char *s = "k = 5\tm=2 c=";
    sw_kv kv;
    ck_assert_int_eq(sw_kv_next(s, strlen(s), 0, &kv), 1);
    ck_assert_int_eq((int)kv.name_len, 1);
    ck_assert_int_eq(s[kv.value_at], '5');
    ck_assert_int_eq(sw_kv_next(s, strlen(s), kv.end, &kv), 1);
    ck_assert_int_eq(s[kv.name_at], 'm');
    ck_assert_int_eq(sw_kv_next(s, strlen(s), kv.end, &kv), 1);
    ck_assert_int_eq((int)kv.value_len, 0);
    ck_assert_int_eq(sw_kv_next(s, strlen(s), kv.end, &kv), 0);
    ck_assert_int_eq(sw_kv_next("k", 1, 0, &kv), -1);
}
END_TEST

/* A new file gets 0666 less the umask; rewriting keeps an existing mode;
 * until commit the name holds the old contents; abort leaves nothing. */
START_TEST(outfile_regular)
{
    make_tmpdir();
    char path[128], text[64], err[SW_ERRLEN];
    struct stat st;
    snprintf(path, sizeof path, "%s/out.csv", tmpdir);
    mode_t old = umask(022);
    write_text(path, "one\n");
    ck_assert_int_eq(stat(path, &st), 0);
    ck_assert_int_eq(st.st_mode & 0777, 0644);
    ck_assert_int_eq(chmod(path, 0600), 0);
    sw_outfile o;
    ck_assert_int_eq(sw_outfile_open(&o, path, err, sizeof err), SW_OK);
    fputs("two\n", o.f);
    fflush(o.f);
    read_text(path, text, sizeof text);
    ck_assert_str_eq(text, "one\n");
    ck_assert_int_eq(entries(), 2); /* the file and its temporary */
    ck_assert_int_eq(sw_outfile_commit(&o, err, sizeof err), SW_OK);
    read_text(path, text, sizeof text);
    ck_assert_str_eq(text, "two\n");
    ck_assert_int_eq(stat(path, &st), 0);
    ck_assert_int_eq(st.st_mode & 0777, 0600);
    ck_assert_int_eq(sw_outfile_open(&o, path, err, sizeof err), SW_OK);
    fputs("three\n", o.f);
    sw_outfile_abort(&o);
    sw_outfile_abort(&o); /* twice is harmless */
    read_text(path, text, sizeof text);
    ck_assert_str_eq(text, "two\n");
    ck_assert_int_eq(entries(), 1);
    umask(old);
    /* A directory is refused; a missing directory cannot hold a file. */
    ck_assert_int_eq(sw_outfile_open(&o, tmpdir, err, sizeof err), SW_EINVAL);
    ck_assert_ptr_nonnull(strstr(err, "is a directory"));
    snprintf(path, sizeof path, "%s/no/such.csv", tmpdir);
    ck_assert_int_eq(sw_outfile_open(&o, path, err, sizeof err), SW_EIO);
    ck_assert_int_eq(sw_outfile_check(path, err, sizeof err), SW_EIO);
    ck_assert_ptr_nonnull(strstr(err, "cannot create"));
    ck_assert_int_eq(entries(), 1);
    remove_tmpdir();
}
END_TEST

/* A symbolic link is followed: the target gets the contents, the link
 * stays a link (also a dangling one, whose target is created). */
START_TEST(outfile_symlink)
{
    make_tmpdir();
    char target[128], link[128], text[64];
    struct stat st;
    snprintf(target, sizeof target, "%s/target.trace", tmpdir);
    snprintf(link, sizeof link, "%s/link.trace", tmpdir);
    ck_assert_int_eq(symlink("target.trace", link), 0);
    write_text(link, "via link\n");
    ck_assert_int_eq(lstat(link, &st), 0);
    ck_assert(S_ISLNK(st.st_mode));
    read_text(target, text, sizeof text);
    ck_assert_str_eq(text, "via link\n");
    write_text(link, "again\n");
    ck_assert_int_eq(lstat(link, &st), 0);
    ck_assert(S_ISLNK(st.st_mode));
    read_text(target, text, sizeof text);
    ck_assert_str_eq(text, "again\n");
    ck_assert_int_eq(entries(), 2);
    remove_tmpdir();
}
END_TEST

/* A 251-byte name works: the temporary's name is cut to fit NAME_MAX. */
START_TEST(outfile_long_name)
{
    make_tmpdir();
    char path[512], name[252];
    memset(name, 'n', 251);
    name[251] = '\0';
    snprintf(path, sizeof path, "%s/%s", tmpdir, name);
    sw_outfile o;
    char err[SW_ERRLEN];
    ck_assert_msg(sw_outfile_open(&o, path, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_uint_le(strlen(strrchr(o.tmp, '/') + 1), 255);
    fputs("x\n", o.f);
    ck_assert_msg(sw_outfile_commit(&o, err, sizeof err) == SW_OK, "%s", err);
    ck_assert_int_eq(access(path, F_OK), 0);
    ck_assert_int_eq(entries(), 1);
    remove_tmpdir();
}
END_TEST

/* Devices and FIFOs are written in place: a device stays a device, a
 * FIFO's reader gets the bytes, and a write error (/dev/full) is one.
 * (/dev/zero, which takes writes like /dev/null, stands for every device:
 * on a shared machine another program's bug may have replaced /dev/null.) */
START_TEST(outfile_devices)
{
    sw_outfile o;
    char err[SW_ERRLEN];
    struct stat st;
    ck_assert_int_eq(sw_outfile_open(&o, "/dev/zero", err, sizeof err), SW_OK);
    ck_assert(o.direct);
    ck_assert_str_eq(o.tmp, "");
    fputs("gone\n", o.f);
    ck_assert_int_eq(sw_outfile_commit(&o, err, sizeof err), SW_OK);
    ck_assert_int_eq(stat("/dev/zero", &st), 0);
    ck_assert(S_ISCHR(st.st_mode));
    if (access("/dev/full", W_OK) == 0) {
        ck_assert_int_eq(sw_outfile_open(&o, "/dev/full", err, sizeof err), SW_OK);
        fputs("no room\n", o.f);
        ck_assert_int_eq(sw_outfile_commit(&o, err, sizeof err), SW_EIO);
        ck_assert_ptr_nonnull(strstr(err, "cannot write '/dev/full'"));
    }
    make_tmpdir();
    char fifo[128], text[32];
    snprintf(fifo, sizeof fifo, "%s/pipe", tmpdir);
    ck_assert_int_eq(mkfifo(fifo, 0600), 0);
    int rd = open(fifo, O_RDONLY | O_NONBLOCK); /* a reader, so the writer's open does not wait */
    ck_assert_int_ge(rd, 0);
    ck_assert_int_eq(sw_outfile_open(&o, fifo, err, sizeof err), SW_OK);
    ck_assert(o.direct);
    fputs("streamed\n", o.f);
    ck_assert_int_eq(sw_outfile_commit(&o, err, sizeof err), SW_OK);
    ssize_t n = read(rd, text, sizeof text - 1);
    ck_assert_int_eq(n, 9);
    text[n] = '\0';
    ck_assert_str_eq(text, "streamed\n");
    close(rd);
    ck_assert_int_eq(stat(fifo, &st), 0);
    ck_assert(S_ISFIFO(st.st_mode));
    remove_tmpdir();
}
END_TEST

/* Inputs: a FIFO without a writer, a directory and a device are refused at
 * once, never waited on; a regular file reads whole, or is too large. */
START_TEST(infile_never_blocks)
{
    make_tmpdir();
    char fifo[128], file[128];
    struct stat st;
    const char *what;
    snprintf(fifo, sizeof fifo, "%s/pipe", tmpdir);
    ck_assert_int_eq(mkfifo(fifo, 0600), 0);
    ck_assert_int_eq(sw_infile_open(fifo, &st, &what), -1);
    ck_assert_str_eq(what, "a FIFO");
    ck_assert_int_eq(sw_infile_open(tmpdir, &st, &what), -1);
    ck_assert_str_eq(what, "a directory");
    ck_assert_int_eq(sw_infile_open("/dev/zero", &st, &what), -1);
    ck_assert_str_eq(what, "a device");
    snprintf(file, sizeof file, "%s/missing", tmpdir);
    ck_assert_int_eq(sw_infile_open(file, &st, &what), -1);
    ck_assert_ptr_null(what);
    ck_assert_int_eq(errno, ENOENT);
    snprintf(file, sizeof file, "%s/text", tmpdir);
    write_text(file, "0123456789");
    int fd = sw_infile_open(file, &st, &what);
    ck_assert_int_ge(fd, 0);
    char *buf;
    size_t len;
    ck_assert_int_eq(sw_infile_read(fd, 10, &buf, &len), 0);
    ck_assert_uint_eq(len, 10);
    ck_assert_str_eq(buf, "0123456789");
    free(buf);
    ck_assert_int_eq(lseek(fd, 0, SEEK_SET), 0);
    ck_assert_int_eq(sw_infile_read(fd, 9, &buf, &len), 1);
    close(fd);
    remove_tmpdir();
}
END_TEST

/* Progress: names with spaces are saved; a state directory that is a file
 * is an error with a reason; two processes saving 300 updates each at once
 * lose none (the lock serialises read-merge-write). */
START_TEST(progress)
{
    make_tmpdir();
    char state[128], err[SW_ERRLEN];
    snprintf(state, sizeof state, "%s/state", tmpdir);
    setenv("XDG_STATE_HOME", state, 1);
    ck_assert_int_eq(sw_progress_check(err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_progress_set("my lesson.lesson", 3, err, sizeof err), SW_OK);
    ck_assert_int_eq(sw_progress_get("my lesson.lesson"), 3);
    ck_assert_int_eq(sw_progress_get("my"), 0);
    ck_assert_int_eq(sw_progress_set("my lesson.lesson", 2, err, sizeof err), SW_OK); /* never lowers */
    ck_assert_int_eq(sw_progress_get("my lesson.lesson"), 3);
    ck_assert_int_eq(sw_progress_set("two\nlines", 1, err, sizeof err), SW_EINVAL);

    pid_t kids[2];
    for (int k = 0; k < 2; k++) {
        kids[k] = fork();
        ck_assert_int_ge(kids[k], 0);
        if (kids[k] == 0) {
            char name[32], e[SW_ERRLEN];
            for (int i = 0; i < 300; i++) {
                snprintf(name, sizeof name, "%c-%d.lesson", 'a' + k, i);
                if (sw_progress_set(name, 1 + i % 5, e, sizeof e) != SW_OK)
                    _exit(1);
            }
            _exit(0);
        }
    }
    for (int k = 0; k < 2; k++) {
        int status;
        ck_assert_int_eq(waitpid(kids[k], &status, 0), kids[k]);
        ck_assert(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    }
    int kept = 0;
    for (int k = 0; k < 2; k++)
        for (int i = 0; i < 300; i++) {
            char name[32];
            snprintf(name, sizeof name, "%c-%d.lesson", 'a' + k, i);
            kept += sw_progress_get(name) == 1 + i % 5;
        }
    ck_assert_int_eq(kept, 600);
    ck_assert_int_eq(sw_progress_get("my lesson.lesson"), 3);

    char file[160];
    snprintf(file, sizeof file, "%s/plain-file", tmpdir);
    write_text(file, "");
    setenv("XDG_STATE_HOME", file, 1);
    ck_assert_int_eq(sw_progress_set("x.lesson", 1, err, sizeof err), SW_EIO);
    ck_assert_ptr_nonnull(strstr(err, "Not a directory"));
    ck_assert_int_eq(sw_progress_check(err, sizeof err), SW_EIO);
    unsetenv("XDG_STATE_HOME");
    remove_tmpdir();
}
END_TEST


/* Each way of closing inherited descriptors, in a child: descriptors
 * spread from 3 to 900 are open; after the call only 0-2 (below `from`)
 * and the kept ones are. */
START_TEST(close_fds)
{
    for (int way = 0; way <= 3; way++) {
        pid_t pid = fork();
        ck_assert_int_ge(pid, 0);
        if (pid == 0) {
            static const int spread[] = { 3, 4, 5, 7, 8, 40, 41, 300, 899, 900 };
            for (size_t i = 0; i < sizeof spread / sizeof spread[0]; i++)
                if (dup2(2, spread[i]) != spread[i])
                    _exit(10);
            int keep[] = { 41, 5, 900 };
            if (way == 3)
                sw_close_fds(4, keep, 3);
            else if (sw_close_fds_by(way, 4, keep, 3) != 0)
                _exit(11);
            for (int fd = 3; fd <= 1000; fd++) { /* 0-2: whatever the runner left */
                int open_now = fcntl(fd, F_GETFD) != -1;
                int want = fd == 3 || fd == 5 || fd == 41 || fd == 900;
                if (open_now != want)
                    _exit(20 + fd % 200);
            }
            _exit(0);
        }
        int status;
        ck_assert_int_eq(waitpid(pid, &status, 0), pid);
        ck_assert_msg(WIFEXITED(status) && WEXITSTATUS(status) == 0, "way %d: status %d", way,
                      WEXITSTATUS(status));
    }
}
END_TEST

Suite *make_util_suite(void);
Suite *make_util_suite(void)
{
    Suite *s = suite_create("util");
    TCase *tc = tcase_create("util");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, utf8);
    tcase_add_test(tc, escape_invisible_families);
    tcase_add_test(tc, escape_keeps_text);
    tcase_add_test(tc, escape_invisible_cut);
    tcase_add_test(tc, escape_fit_cells_and_words);
    tcase_add_test(tc, names);
    tcase_add_test(tc, kv_pairs);
    tcase_add_test(tc, outfile_regular);
    tcase_add_test(tc, outfile_symlink);
    tcase_add_test(tc, outfile_long_name);
    tcase_add_test(tc, outfile_devices);
    tcase_add_test(tc, infile_never_blocks);
    tcase_add_test(tc, progress);
    tcase_add_test(tc, close_fds);
    suite_add_tcase(s, tc);
    return s;
}
