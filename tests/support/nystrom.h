/* Nyström methods for x'' = f(x) in long double, for the tests of rkn and
 * rkn12 (tests/check_rkn.c, tests/check_rkn12.c): their order conditions,
 * tree by tree, and an independent stepper. A tableau is given as its
 * nodes c and matrix A (stage i: X_i = x0 + c_i h v0 + h² Σ_j A_ij a_j). */
#ifndef SW_TESTS_NYSTROM_H
#define SW_TESTS_NYSTROM_H

enum { NYS_MAX_S = 17, NYS_MAX_RHO = 12 };

typedef struct nys_tableau {
    int s;
    long double c[NYS_MAX_S], a[NYS_MAX_S][NYS_MAX_S];
} nys_tableau;

/* Generate every tree of size 1 .. max_rho for the tableau; count[r] gets
 * the number of size r. Returns 0, or -1 when they do not fit. */
int nys_make_trees(const nys_tableau *tb, int max_rho, int count[NYS_MAX_RHO + 1]);

/* The largest residual, over the trees of size lo .. hi made last, of the
 * x conditions (velocity 0: Σ w_i Φ_i = κ/(ρ(ρ + 1))) or the v conditions
 * (velocity 1: Σ w_i Φ_i = κ/ρ) of the weights w. */
long double nys_residual(const long double *w, int velocity, int lo, int hi);

/* The largest |Σ_j A_ij - c_i²/2| over the stages. */
long double nys_row_sums(const nys_tableau *tb);

typedef void nys_accel(const long double x[2], long double a[2]);

/* n steps of h of the method (tableau, weights wx, wv) on one particle in
 * the plane: y = (x, v). */
void nys_steps(const nys_tableau *tb, nys_accel *f, const long double *wx, const long double *wv, long double h,
               long n, long double y[4]);

#endif
