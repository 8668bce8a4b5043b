/* Private to the explainer's files (explain*.c): the rows held in memory,
 * running a variant into rows, comparing rows with the grading tolerances,
 * and the finders each file supplies. Invariant: a finder names a mistake
 * only when the run (or formula) it stands for matches every examined value. */
#ifndef SW_GRADE_EXPLAIN_INT_H
#define SW_GRADE_EXPLAIN_INT_H

#include <stddef.h>

#include "grade/explain.h"

/* n rows of ncols values in the canonical column order (step, t, state...,
 * energy), with the file line of each (NULL or 0 for a run). */
typedef struct xpl_rows {
    double *v;
    long *line;
    int n, ncols;
} xpl_rows;

static inline double *xpl_row(const xpl_rows *r, int i)
{
    return r->v + (size_t)i * (size_t)r->ncols;
}

/* Up to max rows of d's run under method m with parameters p and step dt
 * (from the initial state y0 when not NULL) into out (already sized);
 * returns the rows made, or -1 when the run cannot start or has other
 * columns. */
int xpl_run_rows(const sw_run_desc *d, const sw_integrator *m, const double *p, double dt,
                 const double *y0, int max, xpl_rows *out);

/* Whether every value of the first n rows of a and b passes tol (column
 * skip left out, -1 none; each tolerance multiplied by widen); *worst is
 * the largest relative difference over the values compared. */
int xpl_rows_match(const xpl_rows *a, const xpl_rows *b, int n, const sw_check_tol *tol,
                   int skip, double widen, double *worst);

/* "exactly" or "to 3e-16", for an agreement. */
void xpl_agree(char *buf, size_t len, double worst);

/* Units (explain_units.c): when every column of tr matches ref as it is
 * or divided by one factor of 10, 100 or 1000 (or multiplied), and one at
 * least does not match as it is, 1 with *out naming the columns, the
 * factor and the unit it suggests; 0 otherwise. */
int xpl_units(const xpl_rows *tr, const xpl_rows *ref, const sw_run_desc *d,
              const sw_check_tol *tol, sw_explanation *out);

/* The initial state (explain_state.c): when row 0 of tr differs from ref's
 * in a state column, 1 with *out naming the first value, the particle and
 * the scene's section of docs/scenes.md; 0 when row 0 matches. */
int xpl_initial_state(const xpl_rows *tr, const xpl_rows *ref, const sw_run_desc *d,
                      const sw_check_tol *tol, sw_explanation *out);

/* The energy column (explain_state.c): when every state column matches ref
 * and the energy column does not, 1 with *out naming the formula that
 * reproduces it from the trace's own state (a sign flipped, a term missing
 * or without its ½), or saying only the energy differs; 0 otherwise. */
int xpl_energy(const xpl_rows *tr, const xpl_rows *ref, const sw_run_desc *d,
               const sw_check_tol *tol, sw_explanation *out);

#endif
