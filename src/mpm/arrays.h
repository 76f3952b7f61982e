/* arrays.h - the large arrays of the particles and the grid, each placed
 * at its own offset within a 4 KiB page (internal).
 *
 * Why: the step reads and writes element q of a dozen particle arrays and
 * node i of a dozen nodal arrays together. Arrays this large come from
 * mmap, page-aligned plus malloc's 16-byte header, so element q of every
 * array has the same address modulo 4096: the same set of the L1 cache
 * (8 ways for 12 and more lines) and a store to one array seems to alias
 * a load from the next (the processor's 4 KiB check). Where the arrays
 * landed depended on what the process had freed before - measured
 * 2026-12-03: the gas-filled membrane at 10^5 particles stepped at 23.0 M
 * particle-steps/s in a fresh process and 27.7 with the arrays on the
 * heap (docs/performance.md "Where the arrays lie"). Here array k starts
 * k * LM_ARR_STAGGER bytes into a page, whatever malloc does. Each array
 * is a block of its own (freed alone), so arrays may trade places, as the
 * step's nodal sums made ahead do with the grid's. The layout changes no
 * value: same bits. */
#ifndef LAMINA_ARRAYS_H
#define LAMINA_ARRAYS_H

#include <stddef.h>

/* 128 bytes (two cache lines) between neighbours: 32 arrays fill a page's
 * offsets without two on one line. */
#define LM_ARR_STAGGER 128

/* n elements of `size` bytes starting k * LM_ARR_STAGGER bytes (modulo
 * 4096) into a page; zeroed when `zero`. NULL when out of memory or n *
 * size overflows. */
void *lm_arr_alloc(size_t n, size_t size, int k, int zero);
/* `a` (old_n elements; NULL: none) grown to n elements at the same page
 * offset, its contents kept (the rest unset); NULL with `a` untouched on
 * failure. */
void *lm_arr_grow(void *a, size_t old_n, size_t n, size_t size, int k);
/* Frees an array of lm_arr_alloc / lm_arr_grow (NULL: nothing). */
void lm_arr_free(void *a);

#endif
