/* Fuzz entry points: each takes arbitrary bytes and must never crash, hang
 * or leak. libFuzzer drives them (tests/fuzz/fuzz_*.c, `make fuzz`), and
 * the unit suite replays every file under tests/fuzz/NAME/ through them, so
 * seeds and past crashes stay regression tests. Each returns 1 when it
 * accepted the input whole, 0 when it refused it (-1: out of memory), and
 * tests/data/fuzz_verdicts.txt pins that verdict for every corpus file. */
#ifndef SW_FUZZ_TARGETS_H
#define SW_FUZZ_TARGETS_H

#include <stddef.h>
#include <stdint.h>

/* The lesson parser on the bytes as a lesson file. */
int sw_fuzz_lesson(const uint8_t *data, size_t len);
/* The trace reader on the bytes as a trace file (metadata, header, rows). */
int sw_fuzz_trace(const uint8_t *data, size_t len);
/* The --set PARAM=VALUE and number parsers: first byte picks the scene. */
int sw_fuzz_parse(const uint8_t *data, size_t len);
/* The rasteriser: canvas size, mode and view from the bytes, then points,
 * marks and lines at any doubles (NaN, infinities, huge), a density pass,
 * and a scene drawn at a fuzzed state. 1 when the view was accepted. */
int sw_fuzz_canvas(const uint8_t *data, size_t len);
/* The lesson runner: a lesson file up to the first 0xFF byte, then keys
 * pressed on its pages with time advancing. 1 when the lesson ran. */
int sw_fuzz_runner(const uint8_t *data, size_t len);
/* The check path: a trace read, its run rebuilt from its metadata (small
 * runs only) and compared row by row. 1 when the trace passes. */
int sw_fuzz_check(const uint8_t *data, size_t len);
/* The plugin sandbox's channel, the grader's side: the first byte picks the
 * system (dim 1..16, 0..3 work vectors), the rest is what a plugin's
 * process sends back for one step. 1 when it is a valid step. */
int sw_fuzz_channel(const uint8_t *data, size_t len);

/* The roster reader: the bytes up to the first 0xFF as a roster CSV, the
 * rest as Gradescope's submission_metadata.yml and, line by line, as
 * submission paths; every student's name, words and ids matched as paths
 * too, and each student's own words must be their own claim. 1 when the
 * roster was read. */
int sw_fuzz_roster(const uint8_t *data, size_t len);
/* The gradebook reader (regrading): the bytes as a CSV; when read, every
 * row written again through sw_csv_field and read back must give the same
 * cells, and writing those again the same bytes. 1 when it was read. */
int sw_fuzz_gradebook(const uint8_t *data, size_t len);
/* Source similarity: the bytes up to the first 0xFF and the rest as two C
 * sources (then the rest as the base), compared with each other and with
 * themselves (which must score 1); the bytes as rows of two traces too.
 * 1 when both sources were compared. */
int sw_fuzz_similar(const uint8_t *data, size_t len);

#endif
