/* The zip writer: local header + data per entry, then the central
 * directory and its end record; little-endian fields written byte by byte,
 * so the archive is the same on every host. Times are fixed (1980-01-01),
 * so the same inputs give the same bytes. */
#include "util/zip.h"

#include <stdlib.h>
#include <string.h>

#include "stepwise/base.h"

uint32_t sw_crc32(uint32_t crc, const void *data, size_t len)
{
    /* Reflected polynomial 0xEDB88320, bit by bit: a bundle is a few MB. */
    const unsigned char *p = data;
    crc = ~crc;
    for (size_t i = 0; i < len; i++) {
        crc ^= p[i];
        for (int k = 0; k < 8; k++)
            crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

static void put16(FILE *f, unsigned v)
{
    fputc((int)(v & 0xff), f);
    fputc((int)((v >> 8) & 0xff), f);
}

static void put32(FILE *f, uint32_t v)
{
    put16(f, v & 0xffff);
    put16(f, v >> 16);
}

enum { DOS_TIME = 0, DOS_DATE = (0 << 9) | (1 << 5) | 1, /* 1980-01-01 00:00 */
       VERSION_NEEDED = 10, VERSION_MADE = (3 << 8) | 20 /* Unix, 2.0 */ };

void sw_zip_begin(sw_zip *z, FILE *f)
{
    memset(z, 0, sizeof *z);
    z->f = f;
}

static int name_ok(const char *name)
{
    size_t len = strlen(name);
    if (len == 0 || len > 1023 || name[0] == '/' || name[len - 1] == '/')
        return 0;
    for (const char *s = name; *s; s++)
        if (*s == '\\' || (unsigned char)*s < 0x20)
            return 0;
    return strcmp(name, "..") != 0 && strncmp(name, "../", 3) != 0 && !strstr(name, "/../") &&
           !(len >= 3 && strcmp(name + len - 3, "/..") == 0);
}

int sw_zip_add(sw_zip *z, const char *name, const void *data, size_t len, unsigned mode,
               char *err, size_t errlen)
{
    if (!name_ok(name)) {
        snprintf(err, errlen, "zip: the name '%.60s' is not allowed (relative, no '..', at most "
                 "1023 bytes)", name);
        return SW_EINVAL;
    }
    if (len > 0xfffffffeu || z->offset + len + 1100 > 0xfffffffeu || z->n == 65535) {
        snprintf(err, errlen, "zip: '%.60s' does not fit: a bundle holds at most 65535 files and "
                 "4 GiB", name);
        return SW_EINVAL;
    }
    if (z->n == z->cap) {
        int cap = z->cap ? 2 * z->cap : 64;
        sw_zip_entry *e = realloc(z->entries, (size_t)cap * sizeof *e);
        if (!e) {
            snprintf(err, errlen, "zip: out of memory");
            return SW_ENOMEM;
        }
        z->entries = e;
        z->cap = cap;
    }
    sw_zip_entry *e = &z->entries[z->n];
    e->name = strdup(name);
    if (!e->name) {
        snprintf(err, errlen, "zip: out of memory");
        return SW_ENOMEM;
    }
    e->crc = sw_crc32(0, data, len);
    e->size = (uint32_t)len;
    e->offset = (uint32_t)z->offset;
    e->mode = mode & 07777;
    z->n++;
    size_t name_len = strlen(name);
    put32(z->f, 0x04034b50);        /* local file header */
    put16(z->f, VERSION_NEEDED);
    put16(z->f, 0);                 /* flags */
    put16(z->f, 0);                 /* stored */
    put16(z->f, DOS_TIME);
    put16(z->f, DOS_DATE);
    put32(z->f, e->crc);
    put32(z->f, e->size);           /* compressed = uncompressed */
    put32(z->f, e->size);
    put16(z->f, (unsigned)name_len);
    put16(z->f, 0);                 /* extra field */
    fwrite(name, 1, name_len, z->f);
    if (len)
        fwrite(data, 1, len, z->f);
    z->offset += 30 + name_len + len;
    return SW_OK;
}

void sw_zip_free(sw_zip *z)
{
    for (int i = 0; i < z->n; i++)
        free(z->entries[i].name);
    free(z->entries);
    z->entries = NULL;
    z->n = z->cap = 0;
}

int sw_zip_end(sw_zip *z, char *err, size_t errlen)
{
    uint64_t start = z->offset, size = 0;
    for (int i = 0; i < z->n; i++) {
        const sw_zip_entry *e = &z->entries[i];
        size_t name_len = strlen(e->name);
        put32(z->f, 0x02014b50);    /* central directory header */
        put16(z->f, VERSION_MADE);
        put16(z->f, VERSION_NEEDED);
        put16(z->f, 0);
        put16(z->f, 0);
        put16(z->f, DOS_TIME);
        put16(z->f, DOS_DATE);
        put32(z->f, e->crc);
        put32(z->f, e->size);
        put32(z->f, e->size);
        put16(z->f, (unsigned)name_len);
        put16(z->f, 0);             /* extra */
        put16(z->f, 0);             /* comment */
        put16(z->f, 0);             /* disk */
        put16(z->f, 0);             /* internal attributes */
        put32(z->f, (uint32_t)(0100000u | e->mode) << 16); /* S_IFREG | mode, Unix style */
        put32(z->f, e->offset);
        fwrite(e->name, 1, name_len, z->f);
        size += 46 + name_len;
    }
    put32(z->f, 0x06054b50);        /* end of central directory */
    put16(z->f, 0);
    put16(z->f, 0);
    put16(z->f, (unsigned)z->n);
    put16(z->f, (unsigned)z->n);
    put32(z->f, (uint32_t)size);
    put32(z->f, (uint32_t)start);
    put16(z->f, 0);
    sw_zip_free(z);
    if (ferror(z->f)) {
        snprintf(err, errlen, "zip: a write failed");
        return SW_EIO;
    }
    return SW_OK;
}
