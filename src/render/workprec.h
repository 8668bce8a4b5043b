/* The work-precision plot as text: the grid (testable on its own) and the
 * overlay that frames it with a title, a legend and notes. */
#ifndef SW_RENDER_WORKPREC_H
#define SW_RENDER_WORKPREC_H

#include "measure/bench.h"

/* At most this many "i under j" pairs are named under the plot. */
#define SW_WORKPREC_PAIRS 64

/* The series whose points share a cell of the grid, in the order of the
 * series (the first methods of the table, euler first, lead): series
 * under[k]'s point shares a cell with series over[k]'s (the cell shows '&'). */
typedef struct sw_workprec_overlap {
    int n;
    int under[SW_WORKPREC_PAIRS], over[SW_WORKPREC_PAIRS];
} sw_workprec_overlap;

/* The log-log plot of report r (x: evaluations or seconds, SW_BENCH_X_*)
 * into a grid of rows × cols characters (rows plot rows, then the x axis
 * and its labels; g holds (rows + 2) × cols bytes): each series' marker on
 * its points, dots between them, '&' where points of two series share a
 * cell (the pairs in *ov, may be NULL). 0 when there is no point to plot. */
int sw_workprec_grid(const sw_bench_report *r, int xaxis, char *g, int rows, int cols, sw_workprec_overlap *ov);

#endif
