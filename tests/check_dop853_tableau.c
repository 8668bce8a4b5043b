/* dop853's tableau against the theory of Runge-Kutta methods (Butcher):
 * a method has order p when, for every rooted tree t with at most p nodes,
 * Σ b_i Φ_i(t) = 1/γ(t), with Φ_i(•) = 1, Φ_i([t1 .. tm]) = Π_k Σ_j a_ij
 * Φ_j(t_k) and γ(t) = |t| Π γ(t_k). The trees are generated here, not
 * listed: 200 of them up to order 8 (1, 1, 2, 4, 9, 20, 48, 115), 286 more
 * of order 9. The 8th-order weights must meet all 200 and miss some of
 * order 9; the embedded 5th-order weights (b - ER) all 17 up to order 5,
 * the 3rd-order ones (BHH) the 4 up to order 3. Tolerance: the conditions
 * are sums of up to a few hundred products of coefficients as large as
 * 40, each rounded to double, so they hold to about 1e-13 of the sum of
 * the products' magnitudes; 64 ε of that scale is allowed. An order-9
 * miss is anything beyond 1e-6. */
#include <check.h>
#include <float.h>
#include <math.h>
#include <string.h>

#include "engine/dop853_tableau.h"

enum { S = 12, MAX_TREES = 486, MAX_ORDER = 9 };

static double A[S][S], C[S];

static void tableau(void)
{
    static const struct { int i, j; double a; } entries[] = {
        { 1, 0, DP8_A2_1 },   { 2, 0, DP8_A3_1 },   { 2, 1, DP8_A3_2 },   { 3, 0, DP8_A4_1 },   { 3, 2, DP8_A4_3 },
        { 4, 0, DP8_A5_1 },   { 4, 2, DP8_A5_3 },   { 4, 3, DP8_A5_4 },   { 5, 0, DP8_A6_1 },   { 5, 3, DP8_A6_4 },
        { 5, 4, DP8_A6_5 },   { 6, 0, DP8_A7_1 },   { 6, 3, DP8_A7_4 },   { 6, 4, DP8_A7_5 },   { 6, 5, DP8_A7_6 },
        { 7, 0, DP8_A8_1 },   { 7, 3, DP8_A8_4 },   { 7, 4, DP8_A8_5 },   { 7, 5, DP8_A8_6 },   { 7, 6, DP8_A8_7 },
        { 8, 0, DP8_A9_1 },   { 8, 3, DP8_A9_4 },   { 8, 4, DP8_A9_5 },   { 8, 5, DP8_A9_6 },   { 8, 6, DP8_A9_7 },
        { 8, 7, DP8_A9_8 },   { 9, 0, DP8_A10_1 },  { 9, 3, DP8_A10_4 },  { 9, 4, DP8_A10_5 },  { 9, 5, DP8_A10_6 },
        { 9, 6, DP8_A10_7 },  { 9, 7, DP8_A10_8 },  { 9, 8, DP8_A10_9 },  { 10, 0, DP8_A11_1 }, { 10, 3, DP8_A11_4 },
        { 10, 4, DP8_A11_5 }, { 10, 5, DP8_A11_6 }, { 10, 6, DP8_A11_7 }, { 10, 7, DP8_A11_8 }, { 10, 8, DP8_A11_9 },
        { 10, 9, DP8_A11_10 }, { 11, 0, DP8_A12_1 }, { 11, 3, DP8_A12_4 }, { 11, 4, DP8_A12_5 }, { 11, 5, DP8_A12_6 },
        { 11, 6, DP8_A12_7 }, { 11, 7, DP8_A12_8 }, { 11, 8, DP8_A12_9 }, { 11, 9, DP8_A12_10 },
        { 11, 10, DP8_A12_11 },
    };
    memset(A, 0, sizeof A);
    for (size_t e = 0; e < sizeof entries / sizeof entries[0]; e++)
        A[entries[e].i][entries[e].j] = entries[e].a;
    const double c[S] = { 0, DP8_C2, DP8_C3, DP8_C4, DP8_C5, DP8_C6, DP8_C7, DP8_C8, DP8_C9, DP8_C10, DP8_C11, 1 };
    memcpy(C, c, sizeof C);
}

/* The trees: order, γ, Φ_i, and g_i = Σ_j a_ij Φ_j (what a parent multiplies by). */
static int ntrees, order[MAX_TREES];
static double gam[MAX_TREES], phi[MAX_TREES][S], g[MAX_TREES][S];
/* the same over the coefficients' magnitudes: the scale of rounding errors */
static double phi_abs[MAX_TREES][S], g_abs[MAX_TREES][S];

static void add_tree(int n, double gprod, const double prod[S], const double prod_abs[S])
{
    ck_assert_int_lt(ntrees, MAX_TREES);
    int t = ntrees++;
    order[t] = n;
    gam[t] = n * gprod;
    memcpy(phi[t], prod, sizeof phi[t]);
    memcpy(phi_abs[t], prod_abs, sizeof phi_abs[t]);
    for (int i = 0; i < S; i++) {
        g[t][i] = g_abs[t][i] = 0;
        for (int j = 0; j < S; j++) {
            g[t][i] += A[i][j] * prod[j];
            g_abs[t][i] += fabs(A[i][j]) * prod_abs[j];
        }
    }
}

/* Children for a root of order n: a multiset of trees of total order
 * `left`, taken with non-increasing index (each multiset once), from the
 * trees below `below` (all of order less than n). */
static void children(int n, int left, int below, double gprod, const double prod[S], const double prod_abs[S])
{
    if (left == 0) {
        add_tree(n, gprod, prod, prod_abs);
        return;
    }
    for (int u = below - 1; u >= 0; u--) {
        if (order[u] > left)
            continue;
        double next[S], next_abs[S];
        for (int i = 0; i < S; i++) {
            next[i] = prod[i] * g[u][i];
            next_abs[i] = prod_abs[i] * g_abs[u][i];
        }
        children(n, left - order[u], u + 1, gprod * gam[u], next, next_abs);
    }
}

static void make_trees(void)
{
    tableau();
    ntrees = 0;
    double one[S];
    for (int i = 0; i < S; i++)
        one[i] = 1.0;
    for (int n = 1; n <= MAX_ORDER; n++) {
        int before = ntrees;
        children(n, n - 1, before, 1.0, one, one);
    }
}

/* Σ b_i Φ_i(t) - 1/γ(t), and its scale Σ |b_i| |Φ|_i(t) + 1/γ(t). */
static double residual(const double b[S], int t, double *scale)
{
    double s = 0, m = 1.0 / gam[t];
    for (int i = 0; i < S; i++) {
        s += b[i] * phi[t][i];
        m += fabs(b[i]) * phi_abs[t][i];
    }
    *scale = m;
    return s - 1.0 / gam[t];
}

/* The number of trees up to order p whose condition weights b miss. */
static int misses(const double b[S], int p, double *worst)
{
    int bad = 0;
    *worst = 0;
    for (int t = 0; t < ntrees && order[t] <= p; t++) {
        double scale, r = residual(b, t, &scale);
        *worst = fmax(*worst, fabs(r) / scale);
        if (!(fabs(r) <= 64 * DBL_EPSILON * scale))
            bad++;
    }
    return bad;
}

static const double B8[S] = { DP8_B1, 0, 0, 0, 0, DP8_B6, DP8_B7, DP8_B8, DP8_B9, DP8_B10, DP8_B11, DP8_B12 };

START_TEST(trees_counted)
{
    make_trees();
    const int per_order[MAX_ORDER + 1] = { 0, 1, 1, 2, 4, 9, 20, 48, 115, 286 };
    int count[MAX_ORDER + 1] = { 0 };
    for (int t = 0; t < ntrees; t++)
        count[order[t]]++;
    for (int n = 1; n <= MAX_ORDER; n++)
        ck_assert_int_eq(count[n], per_order[n]);
    /* the simplest: the bushy tree of order n is Σ b_i c_i^(n-1) = 1/n (c_i = Σ_j a_ij) */
    for (int i = 0; i < S; i++) {
        double row = 0;
        for (int j = 0; j < S; j++)
            row += A[i][j];
        ck_assert_msg(fabs(row - C[i]) <= 1e-14, "row %d sums to %.17g, c = %.17g", i + 1, row, C[i]);
    }
}
END_TEST

START_TEST(order_eight_exactly)
{
    make_trees();
    double worst;
    ck_assert_msg(misses(B8, 8, &worst) == 0, "the 8th-order weights miss a condition (worst %.3g)", worst);
    int ninth = 0;
    for (int t = 0; t < ntrees; t++) {
        double scale, r = residual(B8, t, &scale);
        if (order[t] == 9 && fabs(r) > 1e-6)
            ninth++;
    }
    ck_assert_msg(ninth > 0, "every order-9 condition holds: the method would be of order 9");
}
END_TEST

START_TEST(embedded_orders)
{
    make_trees();
    double b5[S], b3[S] = { DP8_BHH1, 0, 0, 0, 0, 0, 0, 0, DP8_BHH9, 0, 0, DP8_BHH12 }, worst;
    const double er[S] = { DP8_ER1, 0, 0, 0, 0, DP8_ER6, DP8_ER7, DP8_ER8, DP8_ER9, DP8_ER10, DP8_ER11, DP8_ER12 };
    for (int i = 0; i < S; i++)
        b5[i] = B8[i] - er[i];
    ck_assert_msg(misses(b5, 5, &worst) == 0, "b - ER misses an order-5 condition (worst %.3g)", worst);
    ck_assert_msg(misses(b3, 3, &worst) == 0, "BHH misses an order-3 condition (worst %.3g)", worst);
}
END_TEST

Suite *make_dop853_tableau_suite(void);
Suite *make_dop853_tableau_suite(void)
{
    Suite *s = suite_create("dop853_tableau");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, trees_counted);
    tcase_add_test(tc, order_eight_exactly);
    tcase_add_test(tc, embedded_orders);
    suite_add_tcase(s, tc);
    return s;
}
