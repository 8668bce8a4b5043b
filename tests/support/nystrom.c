/* Nyström order conditions and a long double stepper (nystrom.h).
 *
 * For x'' = f(x) the Taylor series of the true x(θh) and of the stages
 * X_i = x0 + c_i h v0 + h² Σ_j A_ij f(X_j) are sums over the same
 * elementary differentials: f^(m+k)(x0) applied to m copies of v0 and to k
 * terms h² ∫∫ (a smaller one). Each is a tree: a root (f) with m leaves (v0,
 * weight θ for the truth, c_i for a stage) and k branches (a double
 * integral for the truth, Σ_j A_ij for a stage) to subtrees. Its size ρ is
 * the root + m + Σ (1 + ρ_k), and it enters f(x(θh)) with h^(ρ-1). The
 * truth's weight is κ θ^(ρ-1) with κ = Π_k κ_k/(ρ_k (ρ_k + 1)); a stage's
 * Φ_i = c_i^m Π_k Σ_j A_ij Φ_j(subtree k). The combinatorial factors are
 * the same on both sides, so a method has order p when, for every tree,
 *     Σ BX_i Φ_i = κ/(ρ (ρ + 1))   for ρ ≤ p - 1   (x1: h² h^(ρ-1))
 *     Σ BV_i Φ_i = κ/ρ             for ρ ≤ p       (v1: h h^(ρ-1)).
 * The trees are generated here, every multiset of branches once. */
#include "nystrom.h"

#include <math.h>

enum { MAX_TREES = 2048 };
static const nys_tableau *tab;
static int ntrees, rho[MAX_TREES], overflow;
static long double kappa[MAX_TREES], phi[MAX_TREES][NYS_MAX_S], branch[MAX_TREES][NYS_MAX_S];

static void add_tree(int size, long double k, const long double prod[NYS_MAX_S])
{
    if (ntrees == MAX_TREES) {
        overflow = 1;
        return;
    }
    int t = ntrees++, s = tab->s;
    rho[t] = size;
    kappa[t] = k;
    for (int i = 0; i < s; i++)
        phi[t][i] = prod[i];
    for (int i = 0; i < s; i++) {
        long double b = 0;
        for (int j = 0; j < s; j++)
            b += tab->a[i][j] * phi[t][j];
        branch[t][i] = b;
    }
}

/* Trees of size `size`: branches to trees from index `from` on (so each
 * multiset once) while `left` nodes remain; the rest are leaves. */
static void grow(int size, int left, int from, int below, long double k, const long double prod[NYS_MAX_S])
{
    int s = tab->s;
    long double leaves[NYS_MAX_S];
    for (int i = 0; i < s; i++)
        leaves[i] = prod[i] * powl(tab->c[i], left);
    add_tree(size, k, leaves);
    for (int t = from; t < below; t++) {
        if (1 + rho[t] > left)
            continue;
        long double next[NYS_MAX_S];
        for (int i = 0; i < s; i++)
            next[i] = prod[i] * branch[t][i];
        grow(size, left - 1 - rho[t], t, below, k * kappa[t] / (rho[t] * (rho[t] + 1.0L)), next);
    }
}

int nys_make_trees(const nys_tableau *tb, int max_rho, int count[NYS_MAX_RHO + 1])
{
    long double one[NYS_MAX_S];
    for (int i = 0; i < NYS_MAX_S; i++)
        one[i] = 1;
    tab = tb;
    ntrees = overflow = 0;
    for (int size = 1; size <= max_rho; size++) {
        int below = ntrees; /* only smaller trees can be branches */
        grow(size, size - 1, 0, below, 1.0L, one);
    }
    for (int r = 0; r <= NYS_MAX_RHO; r++)
        count[r] = 0;
    for (int t = 0; t < ntrees; t++)
        count[rho[t]]++;
    return overflow ? -1 : 0;
}

long double nys_residual(const long double *w, int velocity, int lo, int hi)
{
    long double worst = 0;
    for (int t = 0; t < ntrees; t++) {
        if (rho[t] < lo || rho[t] > hi)
            continue;
        long double s = 0;
        for (int i = 0; i < tab->s; i++)
            s += w[i] * phi[t][i];
        long double want = velocity ? kappa[t] / rho[t] : kappa[t] / (rho[t] * (rho[t] + 1.0L));
        worst = fmaxl(worst, fabsl(s - want));
    }
    return worst;
}

long double nys_row_sums(const nys_tableau *tb)
{
    long double worst = 0;
    for (int i = 0; i < tb->s; i++) {
        long double s = 0;
        for (int j = 0; j < tb->s; j++)
            s += tb->a[i][j];
        worst = fmaxl(worst, fabsl(s - tb->c[i] * tb->c[i] / 2));
    }
    return worst;
}

void nys_steps(const nys_tableau *tb, nys_accel *f, const long double *wx, const long double *wv, long double h,
               long n, long double y[4])
{
    for (long step = 0; step < n; step++) {
        long double a[NYS_MAX_S][2], X[2];
        for (int i = 0; i < tb->s; i++) {
            for (int c = 0; c < 2; c++) {
                long double sum = 0;
                for (int j = 0; j < i; j++)
                    sum += tb->a[i][j] * a[j][c];
                X[c] = y[c] + tb->c[i] * h * y[2 + c] + h * h * sum;
            }
            f(X, a[i]);
        }
        for (int c = 0; c < 2; c++) {
            long double sx = 0, sv = 0;
            for (int i = 0; i < tb->s; i++)
                sx += wx[i] * a[i][c], sv += wv[i] * a[i][c];
            y[c] += h * y[2 + c] + h * h * sx;
            y[2 + c] += h * sv;
        }
    }
}
