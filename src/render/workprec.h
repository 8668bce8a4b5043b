/* The work-precision plot as text: the grid (testable on its own) and the
 * overlay that frames it with a title, a legend and notes. */
#ifndef SW_RENDER_WORKPREC_H
#define SW_RENDER_WORKPREC_H

#include "measure/bench.h"

/* At most this many "i under j" pairs are named under the plot. */
#define SW_WORKPREC_PAIRS 64

/* The series whose points share a cell of the grid, ordered by under:
 * series under[k]'s point is covered by series over[k]'s (the cell shows
 * over's marker). clipped: points off the top of the error axis (drawn '^'
 * on the top edge); top: that axis' top decade (1e<top>). */
typedef struct sw_workprec_overlap {
    int n;
    int under[SW_WORKPREC_PAIRS], over[SW_WORKPREC_PAIRS];
    int clipped, top;
} sw_workprec_overlap;

/* The log-log plot of report r's series shown[0..nshown) (NULL: all; x:
 * evaluations or seconds, SW_BENCH_X_*) into a grid of rows × cols
 * characters (rows plot rows, then the x axis and its labels; g holds
 * (rows + 2) × cols bytes): each series' marker on its points, dots between
 * them; series with more points drawn first, so where two share a cell the
 * one with fewer shows (the pairs in *ov, may be NULL); errors above the
 * decade over r->scale as '^' on the top edge. 0 when there is no point. */
int sw_workprec_grid(const sw_bench_report *r, const int *shown, int nshown, int xaxis, char *g, int rows,
                     int cols, sw_workprec_overlap *ov);

#endif
