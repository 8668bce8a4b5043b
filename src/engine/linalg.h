/* Private to the engine and the layers above it: the small dense and banded
 * linear algebra the implicit methods and the stability theory need. Row-
 * major matrices of doubles; nothing here allocates. */
#ifndef SW_ENGINE_LINALG_H
#define SW_ENGINE_LINALG_H

#include <stddef.h>

/* Solve a·x = b in place for an n×n row-major matrix a (destroyed: its LU
 * factors) by Gaussian elimination with partial pivoting; b becomes x.
 * Returns 0, or -1 when a is singular to working precision (a pivot is zero
 * or not finite). */
int sw_dense_solve(int n, double *a, double *b);
/* The same elimination kept for later right-hand sides: a becomes its LU
 * factors (L's multipliers below the diagonal), perm[c] the row swapped
 * with row c at column c. 0, or -1 when singular (as sw_dense_solve). */
int sw_dense_factor(int n, double *a, int *perm);
/* Solve with those factors, b becoming x: the same numbers, bit for bit, as
 * sw_dense_solve on the unfactored matrix. */
void sw_dense_lu_solve(int n, const double *a, const int *perm, double *b);

/* A band matrix with kl sub- and ku super-diagonals in LAPACK's factored
 * layout: row i, column j (|i - j| within the band) lives at
 * band[(kl + ku + i - j) + j·ld], ld = 2·kl + ku + 1 (the extra kl rows take
 * the fill-in of row interchanges). */
typedef struct sw_band {
    int n, kl, ku, ld;
    double *a;       /* ld·n doubles, owned by the caller */
    int *piv;        /* n pivot rows, owned by the caller */
    int fill;        /* after sw_band_factor: super-diagonals of U that row interchanges
                        filled, ku to kl + ku (beyond them U is zero) */
    int straight;    /* after sw_band_factor: the columns before the first row
                        interchange (n: none) */
} sw_band;

/* Doubles and ints a band of this shape needs. */
size_t sw_band_doubles(int n, int kl, int ku);
/* Point b at caller storage and zero it. */
void sw_band_init(sw_band *b, int n, int kl, int ku, double *a, int *piv);
/* Point b at caller storage, left as it is: the caller zeroes each column
 * (b->ld doubles from b->a + j·b->ld) before it writes into it. */
void sw_band_shape(sw_band *b, int n, int kl, int ku, double *a, int *piv);
/* Add v to entry (i, j), which must lie in the band. */
void sw_band_add(sw_band *b, int i, int j, double v);
/* Factor in place (LU with partial pivoting, as LAPACK's dgbtf2); 0 or -1
 * when singular to working precision. */
int sw_band_factor(sw_band *b);
/* Solve with the factors: x overwrites rhs. */
void sw_band_solve(const sw_band *b, double *rhs);

/* Eigenvalues of the n×n row-major real matrix a (destroyed) by reduction
 * to Hessenberg form and the shifted QR algorithm (EISPACK's hqr): the
 * real parts into re, imaginary parts into im (conjugate pairs adjacent,
 * positive imaginary part first). Returns 0, or -1 when QR did not
 * converge within 30·n iterations. */
int sw_eigenvalues(int n, double *a, double *re, double *im);

/* Spectral radius of a small n×n matrix (copied, not destroyed); NaN when
 * the eigenvalues do not converge or an entry is not finite. n <= 16. */
double sw_spectral_radius(int n, const double *a);

#endif
