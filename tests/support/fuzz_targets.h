/* Fuzz entry points: each takes arbitrary bytes and must never crash, hang
 * or leak. libFuzzer drives them (tests/fuzz/fuzz_*.c, `make fuzz`), and
 * the unit suite replays every file under tests/fuzz/NAME/ through them, so
 * seeds and past crashes stay regression tests. */
#ifndef SW_FUZZ_TARGETS_H
#define SW_FUZZ_TARGETS_H

#include <stddef.h>
#include <stdint.h>

/* The lesson parser on the bytes as a lesson file. */
void sw_fuzz_lesson(const uint8_t *data, size_t len);
/* The trace reader on the bytes as a trace file (metadata, header, rows). */
void sw_fuzz_trace(const uint8_t *data, size_t len);
/* The --set PARAM=VALUE and number parsers: first byte picks the scene. */
void sw_fuzz_parse(const uint8_t *data, size_t len);

#endif
