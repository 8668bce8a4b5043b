/* A zip archive writer, just enough for Gradescope's autograder bundle:
 * stored entries (no compression), each with its CRC-32 and Unix mode, then
 * the central directory (PKWARE APPNOTE 6.3, sections 4.3 and 4.4).
 * Invariant: at most 65535 entries, each under 4 GiB (no zip64). */
#ifndef SW_UTIL_ZIP_H
#define SW_UTIL_ZIP_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* CRC-32 (ISO-HDLC, as zip and gzip): crc of the bytes so far (0 to start)
 * updated with len more. "123456789" gives 0xCBF43926. */
uint32_t sw_crc32(uint32_t crc, const void *data, size_t len);

typedef struct sw_zip_entry {
    char *name;
    uint32_t crc, size, offset;
    unsigned mode;                 /* Unix permission bits, e.g. 0755 */
} sw_zip_entry;

typedef struct sw_zip {
    FILE *f;                       /* written in order; not closed here */
    sw_zip_entry *entries;
    int n, cap;
    uint64_t offset;               /* bytes written so far */
} sw_zip;

/* Start an archive on f. */
void sw_zip_begin(sw_zip *z, FILE *f);
/* Add a file: name (relative, '/'-separated, no "..", at most 1023
 * bytes), its bytes and its Unix mode. 0, SW_EINVAL (a name or size not
 * allowed, too many entries) or SW_ENOMEM, with err filled. */
int sw_zip_add(sw_zip *z, const char *name, const void *data, size_t len, unsigned mode,
               char *err, size_t errlen);
/* Write the central directory and free the entries. 0, or SW_EIO when a
 * write failed (checked with ferror). */
int sw_zip_end(sw_zip *z, char *err, size_t errlen);
/* Free the entries without writing (an abandoned archive). */
void sw_zip_free(sw_zip *z);

#endif
