/* Private to the engine and the layers above it: SW_CLONES marks a hot
 * loop's function to be compiled twice on x86-64 Linux — for AVX2 (4
 * doubles a vector) and for the baseline (SSE2, 2) — the loader picking one
 * for the machine. Both do the same IEEE operations in the same order (no
 * FMA: AVX2 alone does not include it, and ISO C mode does not contract),
 * so results are the same bits on every machine; only the speed differs.
 * -DSW_NO_CLONES turns it off; clang (14) gets none: its clones of a
 * function called from another file left the plain name undefined. */
#ifndef SW_ENGINE_CLONES_H
#define SW_ENGINE_CLONES_H

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__linux__) && !defined(SW_NO_CLONES)
#define SW_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define SW_CLONES
#endif

/* A loop that copies or clears one array while it computes another: GCC
 * would split the copy or clear out into a call to memcpy or memset (a
 * second pass, and `rep movsb`/`rep stosb` for long arrays, which callgrind
 * counts a byte at a time); SW_ONE_PASS asks it not to, for one function. */
#if defined(__GNUC__) && !defined(__clang__)
#define SW_ONE_PASS __attribute__((optimize("no-tree-loop-distribute-patterns")))
#else
#define SW_ONE_PASS
#endif

/* A hot helper inlined into each clone that calls it: compiled for each
 * target with its caller, and called without a dispatch. */
#define SW_INLINE static inline __attribute__((always_inline))

#endif
