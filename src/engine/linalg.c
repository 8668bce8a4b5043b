/* Small linear algebra for the implicit methods and the stability theory:
 * dense and banded LU with partial pivoting (correct on indefinite and
 * non-symmetric matrices, where conjugate gradients fail), and the
 * eigenvalues of a real matrix by balancing, Hessenberg reduction and
 * Francis's double-shift QR (after EISPACK's balanc, elmhes and hqr).
 * Invariant: nothing allocates; every array comes from the caller. */
#include "engine/linalg.h"

#include <math.h>
#include <string.h>

int sw_dense_factor(int n, double *a, int *perm)
{
    for (int col = 0; col < n; col++) {
        int piv = col;
        for (int i = col + 1; i < n; i++)
            if (fabs(a[i * n + col]) > fabs(a[piv * n + col]))
                piv = i;
        double p = a[piv * n + col];
        perm[col] = piv;
        if (!(fabs(p) > 0) || !isfinite(p))
            return -1;
        /* Swap only from this column on: each multiplier stays where it
         * was made, beside the row of b it acts on at that column. */
        if (piv != col)
            for (int j = col; j < n; j++) {
                double tmp = a[col * n + j];
                a[col * n + j] = a[piv * n + j];
                a[piv * n + j] = tmp;
            }
        for (int i = col + 1; i < n; i++) {
            double f = a[i * n + col] / p;
            a[i * n + col] = f; /* L below the diagonal; 0 where nothing was eliminated */
            if (f == 0)
                continue;
            for (int j = col + 1; j < n; j++)
                a[i * n + j] -= f * a[col * n + j];
        }
    }
    return 0;
}

/* The same operations on b, in the same order, as elimination with b
 * carried along: each row interchange, then b_i -= l_ic·b_c (skipped where
 * l_ic = 0), then back substitution. */
void sw_dense_lu_solve(int n, const double *a, const int *perm, double *b)
{
    for (int col = 0; col < n; col++) {
        int piv = perm[col];
        if (piv != col) {
            double tmp = b[col];
            b[col] = b[piv];
            b[piv] = tmp;
        }
        for (int i = col + 1; i < n; i++) {
            double f = a[i * n + col];
            if (f != 0)
                b[i] -= f * b[col];
        }
    }
    for (int i = n - 1; i >= 0; i--) {
        double acc = b[i];
        for (int j = i + 1; j < n; j++)
            acc -= a[i * n + j] * b[j];
        b[i] = acc / a[i * n + i];
    }
}

int sw_dense_solve(int n, double *a, double *b)
{
    for (int col = 0; col < n; col++) {
        int piv = col;
        for (int i = col + 1; i < n; i++)
            if (fabs(a[i * n + col]) > fabs(a[piv * n + col]))
                piv = i;
        double p = a[piv * n + col];
        if (!(fabs(p) > 0) || !isfinite(p))
            return -1;
        if (piv != col) {
            for (int j = 0; j < n; j++) {
                double tmp = a[col * n + j];
                a[col * n + j] = a[piv * n + j];
                a[piv * n + j] = tmp;
            }
            double tmp = b[col];
            b[col] = b[piv];
            b[piv] = tmp;
        }
        for (int i = col + 1; i < n; i++) {
            double f = a[i * n + col] / p;
            if (f == 0)
                continue;
            for (int j = col; j < n; j++)
                a[i * n + j] -= f * a[col * n + j];
            b[i] -= f * b[col];
        }
    }
    for (int i = n - 1; i >= 0; i--) {
        double acc = b[i];
        for (int j = i + 1; j < n; j++)
            acc -= a[i * n + j] * b[j];
        b[i] = acc / a[i * n + i];
    }
    return 0;
}

/* ---- band matrices ------------------------------------------------------ */

#define BAND(b, i, j) ((b)->a[((b)->kl + (b)->ku + (i) - (j)) + (size_t)(j) * (size_t)(b)->ld])

size_t sw_band_doubles(int n, int kl, int ku) { return (size_t)(2 * kl + ku + 1) * (size_t)n; }

void sw_band_shape(sw_band *b, int n, int kl, int ku, double *a, int *piv)
{
    b->n = n;
    b->kl = kl;
    b->ku = ku;
    b->ld = 2 * kl + ku + 1;
    b->a = a;
    b->piv = piv;
    b->fill = kl + ku;
    b->straight = 0;
}

void sw_band_init(sw_band *b, int n, int kl, int ku, double *a, int *piv)
{
    sw_band_shape(b, n, kl, ku, a, piv);
    memset(a, 0, sw_band_doubles(n, kl, ku) * sizeof *a);
}

void sw_band_add(sw_band *b, int i, int j, double v) { BAND(b, i, j) += v; }

static int imin(int a, int b) { return a < b ? a : b; }
static int imax(int a, int b) { return a > b ? a : b; }

/* Gaussian elimination with partial pivoting within the band; a row
 * interchange widens U to kl + ku super-diagonals (the fill-in rows).
 * Column c is contiguous in storage, entry (i, c) at a[c·ld + kv + i - c],
 * so every inner loop runs down one column. */
int sw_band_factor(sw_band *b)
{
    int n = b->n, kl = b->kl, kv = b->kl + b->ku, ld = b->ld, ju = 0, fill = b->ku, straight = n;
    int *piv = b->piv;
    for (int j = 0; j < n; j++) {
        double *col = b->a + (size_t)j * (size_t)ld + kv; /* col[t]: entry (j + t, j) */
        int km = n - 1 - j < kl ? n - 1 - j : kl, jp = 0;
        double best = fabs(col[0]);
        if (km == 3) { /* the loop below, written out (a chain's band) */
            double a1 = fabs(col[1]), a2 = fabs(col[2]), a3 = fabs(col[3]);
            if (a1 > best)
                best = a1, jp = 1;
            if (a2 > best)
                best = a2, jp = 2;
            if (a3 > best)
                best = a3, jp = 3;
        } else {
            for (int t = 1; t <= km; t++)
                if (fabs(col[t]) > best) {
                    best = fabs(col[t]);
                    jp = t;
                }
        }
        piv[j] = j + jp;
        if (!(best > 0) || !isfinite(best)) {
            b->fill = fill;
            return -1;
        }
        int reach = j + kv - kl + jp < n - 1 ? j + kv - kl + jp : n - 1; /* j + ku + jp */
        ju = reach > ju ? reach : ju;
        fill = ju - j > fill ? ju - j : fill;
        if (jp != 0) {
            straight = straight < j ? straight : j;
            for (int c = j; c <= ju; c++) {
                double *cc = b->a + (size_t)c * (size_t)ld + kv + j - c; /* cc[t]: entry (j + t, c) */
                double tmp = cc[jp];
                cc[jp] = cc[0];
                cc[0] = tmp;
            }
        }
        double inv = 1.0 / col[0];
        if (km == 3) { /* a chain's band written out, as in sw_band_solve */
            double l1 = col[1] * inv, l2 = col[2] * inv, l3 = col[3] * inv;
            col[1] = l1;
            col[2] = l2;
            col[3] = l3;
            if (ju == j + 3) { /* no interchange widened U here: the three
                                  columns of the loop below, written out */
                double *c1 = col + (ld - 1), *c2 = c1 + (ld - 1), *c3 = c2 + (ld - 1);
                double u1 = c1[0], u2 = c2[0], u3 = c3[0];
                if (u1 != 0) {
                    c1[1] -= l1 * u1;
                    c1[2] -= l2 * u1;
                    c1[3] -= l3 * u1;
                }
                if (u2 != 0) {
                    c2[1] -= l1 * u2;
                    c2[2] -= l2 * u2;
                    c2[3] -= l3 * u2;
                }
                if (u3 != 0) {
                    c3[1] -= l1 * u3;
                    c3[2] -= l2 * u3;
                    c3[3] -= l3 * u3;
                }
                continue;
            }
            /* column c's entries from row j down start at col + (c - j)·(ld - 1) */
            for (int c = j + 1; c <= ju; c++) {
                double *cc = b->a + (size_t)c * (size_t)ld + kv + j - c;
                double u = cc[0];
                if (u != 0) {
                    cc[1] -= l1 * u;
                    cc[2] -= l2 * u;
                    cc[3] -= l3 * u;
                }
            }
            continue;
        }
        for (int t = 1; t <= km; t++)
            col[t] *= inv;
        for (int c = j + 1; c <= ju; c++) {
            double *cc = b->a + (size_t)c * (size_t)ld + kv + j - c;
            double u = cc[0];
            if (u != 0)
                for (int t = 1; t <= km; t++)
                    cc[t] -= col[t] * u;
        }
    }
    b->fill = fill;
    b->straight = straight;
    return 0;
}

/* A chain's band (kl = 3) forward, from row 0 while no row was
 * interchanged (the factorisation's b->straight): the rows still being updated ride in registers (through
 * memory, each update waited for the store of the last). Every x_i gets
 * the same updates in the same order as in sw_band_solve's loop. Returns
 * the row where that loop takes over (an interchange, or the last rows). */
static int forward_chain(const sw_band *b, double *x)
{
    int n = b->n, ld = b->ld, j = 0;
    if (n < 4)
        return 0;
    int end = b->straight < n - 3 ? b->straight : n - 3;
    const double *col = b->a + b->kl + b->ku; /* column j's diagonal */
    double q0 = x[0], q1 = x[1], q2 = x[2]; /* x_j, x_j+1, x_j+2 as updated so far */
    for (; j < end; j++, col += ld) {
        double xj = q0;
        x[j] = xj;
        q0 = q1 - col[1] * xj;
        q1 = q2 - col[2] * xj;
        q2 = x[j + 3] - col[3] * xj;
    }
    x[j] = q0;
    x[j + 1] = q1;
    x[j + 2] = q2;
    return j;
}

/* The back substitution on a band whose U has three super-diagonals (no
 * interchange widened it), from the last row down while x_j is finite, the
 * same way: the same operations in the same order. Returns the row where
 * sw_band_solve's loop takes over (-1: done). */
static int back_chain(const sw_band *b, double *x)
{
    int n = b->n, kv = b->kl + b->ku, ld = b->ld, j = n - 1;
    if (n < 4)
        return j;
    const double *col = b->a + (size_t)j * (size_t)ld + kv; /* column j's diagonal */
    double p0 = x[j], p1 = x[j - 1], p2 = x[j - 2]; /* x_j, x_j-1, x_j-2 as updated so far */
    for (; j >= 3; j--, col -= ld) {
        double xj = p0 / col[0];
        if (!isfinite(xj))
            break;
        x[j] = xj;
        p0 = p1 - col[-1] * xj;
        p1 = p2 - col[-2] * xj;
        p2 = x[j - 3] - col[-3] * xj;
    }
    x[j] = p0;
    x[j - 1] = p1;
    x[j - 2] = p2;
    return j;
}

void sw_band_solve(const sw_band *b, double *x)
{
    int n = b->n, kl = b->kl, kv = b->kl + b->ku, ld = b->ld;
    for (int j = kl == 3 ? forward_chain(b, x) : 0; j < n - 1; j++) {
        const double *col = b->a + (size_t)j * (size_t)ld + kv; /* col[t]: entry (j + t, j) */
        int lm = imin(kl, n - 1 - j), l = b->piv[j];
        if (l != j) {
            double tmp = x[l];
            x[l] = x[j];
            x[j] = tmp;
        }
        double xj = x[j];
        for (int t = 1; t <= lm; t++)
            x[j + t] -= col[t] * xj;
    }
    /* Above row j - fill, column j of U is zero: there the updates are
     * x_i -= 0·x_j, which change nothing while x_j is finite. */
    int fill = imin(b->fill, kv);
    for (int j = fill == 3 ? back_chain(b, x) : n - 1; j >= 0; j--) {
        const double *col = b->a + (size_t)j * (size_t)ld + kv; /* col[-k]: entry (j - k, j) */
        x[j] /= col[0];
        double xj = x[j];
        int from = imax(0, j - (isfinite(xj) ? fill : kv));
        for (int i = from; i < j; i++)
            x[i] -= col[i - j] * xj;
    }
}

/* ---- eigenvalues -------------------------------------------------------- */

/* 1-based access into a row-major n×n matrix, as EISPACK writes it. */
#define A(i, j) a[((i) - 1) * n + ((j) - 1)]

/* Balance rows and columns by powers of two (exact), so that badly scaled
 * matrices (a spring of stiffness 1e9 beside a unit mass) lose no accuracy. */
static void balance(int n, double *a)
{
    const double radix = 2.0, sqrdx = radix * radix;
    int done = 0;
    for (int sweep = 0; !done && sweep < 100; sweep++) {
        done = 1;
        for (int i = 1; i <= n; i++) {
            double r = 0, c = 0;
            for (int j = 1; j <= n; j++)
                if (j != i) {
                    c += fabs(A(j, i));
                    r += fabs(A(i, j));
                }
            if (c == 0 || r == 0)
                continue;
            double g = r / radix, f = 1, s = c + r;
            while (c < g) {
                f *= radix;
                c *= sqrdx;
            }
            g = r * radix;
            while (c > g) {
                f /= radix;
                c /= sqrdx;
            }
            if ((c + r) / f < 0.95 * s) {
                done = 0;
                g = 1 / f;
                for (int j = 1; j <= n; j++)
                    A(i, j) *= g;
                for (int j = 1; j <= n; j++)
                    A(j, i) *= f;
            }
        }
    }
}

/* Reduce to upper Hessenberg form by stabilised elementary similarity
 * transformations, then clear what lies below the sub-diagonal. */
static void hessenberg(int n, double *a)
{
    for (int m = 2; m < n; m++) {
        double x = 0;
        int i = m;
        for (int j = m; j <= n; j++)
            if (fabs(A(j, m - 1)) > fabs(x)) {
                x = A(j, m - 1);
                i = j;
            }
        if (i != m) {
            for (int j = m - 1; j <= n; j++) {
                double t = A(i, j);
                A(i, j) = A(m, j);
                A(m, j) = t;
            }
            for (int j = 1; j <= n; j++) {
                double t = A(j, i);
                A(j, i) = A(j, m);
                A(j, m) = t;
            }
        }
        if (x != 0)
            for (i = m + 1; i <= n; i++) {
                double y = A(i, m - 1);
                if (y == 0)
                    continue;
                y /= x;
                A(i, m - 1) = y;
                for (int j = m; j <= n; j++)
                    A(i, j) -= y * A(m, j);
                for (int j = 1; j <= n; j++)
                    A(j, m) += y * A(j, i);
            }
    }
    for (int i = 3; i <= n; i++)
        for (int j = 1; j < i - 1; j++)
            A(i, j) = 0;
}

static double sign_of(double a, double b) { return b >= 0 ? fabs(a) : -fabs(a); }

/* Eigenvalues of an upper Hessenberg matrix by the double-shift QR
 * algorithm with exceptional shifts (hqr); eigenvalue k (1-based, as the
 * algorithm counts) goes to wr[k - 1], wi[k - 1]. */
static int hqr(int n, double *a, double *wr, double *wi)
{
    double anorm = 0, t = 0;
    for (int i = 1; i <= n; i++)
        for (int j = imax(i - 1, 1); j <= n; j++)
            anorm += fabs(A(i, j));
    int nn = n, total = 0;
    while (nn >= 1) {
        int its = 0, l;
        do {
            for (l = nn; l >= 2; l--) {
                double s = fabs(A(l - 1, l - 1)) + fabs(A(l, l));
                if (s == 0)
                    s = anorm;
                if (fabs(A(l, l - 1)) + s == s) {
                    A(l, l - 1) = 0;
                    break;
                }
            }
            double x = A(nn, nn);
            if (l == nn) {
                wr[(nn) - 1] = x + t;
                wi[nn - 1] = 0;
                nn--;
            } else {
                double y = A(nn - 1, nn - 1), w = A(nn, nn - 1) * A(nn - 1, nn);
                if (l == nn - 1) {
                    double p = 0.5 * (y - x), q = p * p + w, z = sqrt(fabs(q));
                    x += t;
                    if (q >= 0) {
                        z = p + sign_of(z, p);
                        wr[(nn - 1) - 1] = wr[(nn) - 1] = x + z;
                        if (z != 0)
                            wr[(nn) - 1] = x - w / z;
                        wi[(nn - 1) - 1] = wi[(nn) - 1] = 0;
                    } else {
                        wr[(nn - 1) - 1] = wr[(nn) - 1] = x + p;
                        wi[(nn - 1) - 1] = z; /* positive imaginary part first */
                        wi[(nn) - 1] = -z;
                    }
                    nn -= 2;
                } else {
                    if (its == 30 || ++total > 30 * n)
                        return -1;
                    if (its == 10 || its == 20) { /* exceptional shift */
                        t += x;
                        for (int i = 1; i <= nn; i++)
                            A(i, i) -= x;
                        double s = fabs(A(nn, nn - 1)) + fabs(A(nn - 1, nn - 2));
                        y = x = 0.75 * s;
                        w = -0.4375 * s * s;
                    }
                    ++its;
                    int m;
                    double p = 0, q = 0, r = 0, z;
                    for (m = nn - 2; m >= l; m--) {
                        z = A(m, m);
                        r = x - z;
                        double s = y - z;
                        p = (r * s - w) / A(m + 1, m) + A(m, m + 1);
                        q = A(m + 1, m + 1) - z - r - s;
                        r = A(m + 2, m + 1);
                        s = fabs(p) + fabs(q) + fabs(r);
                        p /= s;
                        q /= s;
                        r /= s;
                        if (m == l)
                            break;
                        double u = fabs(A(m, m - 1)) * (fabs(q) + fabs(r));
                        double v = fabs(p) * (fabs(A(m - 1, m - 1)) + fabs(z) + fabs(A(m + 1, m + 1)));
                        if (u + v == v)
                            break;
                    }
                    for (int i = m + 2; i <= nn; i++) {
                        A(i, i - 2) = 0;
                        if (i != m + 2)
                            A(i, i - 3) = 0;
                    }
                    for (int k = m; k <= nn - 1; k++) {
                        if (k != m) {
                            p = A(k, k - 1);
                            q = A(k + 1, k - 1);
                            r = 0;
                            if (k != nn - 1)
                                r = A(k + 2, k - 1);
                            if ((x = fabs(p) + fabs(q) + fabs(r)) != 0) {
                                p /= x;
                                q /= x;
                                r /= x;
                            }
                        }
                        double s = sign_of(sqrt(p * p + q * q + r * r), p);
                        if (s == 0)
                            continue;
                        if (k == m) {
                            if (l != m)
                                A(k, k - 1) = -A(k, k - 1);
                        } else {
                            A(k, k - 1) = -s * x;
                        }
                        p += s;
                        x = p / s;
                        y = q / s;
                        z = r / s;
                        q /= p;
                        r /= p;
                        for (int j = k; j <= nn; j++) {
                            p = A(k, j) + q * A(k + 1, j);
                            if (k != nn - 1) {
                                p += r * A(k + 2, j);
                                A(k + 2, j) -= p * z;
                            }
                            A(k + 1, j) -= p * y;
                            A(k, j) -= p * x;
                        }
                        int mmin = nn < k + 3 ? nn : k + 3;
                        for (int i = l; i <= mmin; i++) {
                            p = x * A(i, k) + y * A(i, k + 1);
                            if (k != nn - 1) {
                                p += z * A(i, k + 2);
                                A(i, k + 2) -= p * r;
                            }
                            A(i, k + 1) -= p * q;
                            A(i, k) -= p;
                        }
                    }
                }
            }
        } while (l < nn - 1);
    }
    return 0;
}

#undef A

int sw_eigenvalues(int n, double *a, double *re, double *im)
{
    for (int i = 0; i < n * n; i++)
        if (!isfinite(a[i]))
            return -1;
    balance(n, a);
    hessenberg(n, a);
    return hqr(n, a, re, im);
}

double sw_spectral_radius(int n, const double *a)
{
    double m[16 * 16], re[16], im[16];
    if (n < 1 || n > 16)
        return NAN;
    memcpy(m, a, (size_t)n * (size_t)n * sizeof *m);
    if (sw_eigenvalues(n, m, re, im) != 0)
        return NAN;
    double rho = 0;
    for (int i = 0; i < n; i++)
        rho = fmax(rho, hypot(re[i], im[i]));
    return rho;
}
