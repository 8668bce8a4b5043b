/* RODAS4's stage arithmetic (rosenbrock.c), one pass over the state a
 * stage, with the tableau's row made a constant so that the loop has no
 * inner loop and vectorises: the same operations in the same order as the
 * plain loops of reference_implicit.c. */
#include "engine/rosenbrock.h"

#include <stdint.h>
#include <string.h>

#include "engine/clones.h"

/* One pass of a stage's arithmetic, with the tableau's row fixed at each
 * call (terms and with_ft are constants where it is inlined, so the loop
 * over i has no inner loop and vectorises):
 *     out_i = base_i + Σ_{j<terms} coef_j·k_j,i                (scale 0)
 *     out_i = scale·((base_i + dh·ft_i) + Σ_{j<terms} coef_j·k_j,i)   (with_ft 1)
 *     out_i = scale·((base_i + 0.0) + Σ_{j<terms} coef_j·k_j,i)       (with_ft 2)
 * the sums taken in the lecture form's order, j rising, so the bits are
 * its bits. out is never one of the vectors read. */
SW_INLINE void stage_pass(int n, int terms, int with_ft, double *restrict out, const double *restrict base,
                          double dh, const double *restrict ft, double scale, const double *coef,
                          const double *const *k)
{
    const double *restrict k0 = k[0], *restrict k1 = k[1], *restrict k2 = k[2], *restrict k3 = k[3],
                 *restrict k4 = k[4];
    (void)dh, (void)ft; /* with_ft 2 reads neither */
    double c0 = terms > 0 ? coef[0] : 0, c1 = terms > 1 ? coef[1] : 0, c2 = terms > 2 ? coef[2] : 0,
           c3 = terms > 3 ? coef[3] : 0, c4 = terms > 4 ? coef[4] : 0;
    for (int i = 0; i < n; i++) {
        double sum = base[i];
        if (with_ft == 1)
            sum += dh * ft[i];
        else if (with_ft == 2)
            sum += 0.0; /* dh·ft_i with ft_i = +0: a -0 becomes +0 */
        if (terms > 0)
            sum += c0 * k0[i];
        if (terms > 1)
            sum += c1 * k1[i];
        if (terms > 2)
            sum += c2 * k2[i];
        if (terms > 3)
            sum += c3 * k3[i];
        if (terms > 4)
            sum += c4 * k4[i];
        out[i] = with_ft != 0 ? scale * sum : sum;
    }
}

/* stage_pass with the number of terms made a constant, one copy each. */
SW_CLONES void swr_stage_combine(int n, int terms, int with_ft, double *restrict out,
                                    const double *restrict base, double dh, const double *restrict ft,
                                    double scale, const double *coef, const double *const *k)
{
    switch (terms * 3 + with_ft) {
    case 0: stage_pass(n, 0, 0, out, base, dh, ft, scale, coef, k); break;
    case 1: stage_pass(n, 0, 1, out, base, dh, ft, scale, coef, k); break;
    case 2: stage_pass(n, 0, 2, out, base, dh, ft, scale, coef, k); break;
    case 3: stage_pass(n, 1, 0, out, base, dh, ft, scale, coef, k); break;
    case 4: stage_pass(n, 1, 1, out, base, dh, ft, scale, coef, k); break;
    case 5: stage_pass(n, 1, 2, out, base, dh, ft, scale, coef, k); break;
    case 6: stage_pass(n, 2, 0, out, base, dh, ft, scale, coef, k); break;
    case 7: stage_pass(n, 2, 1, out, base, dh, ft, scale, coef, k); break;
    case 8: stage_pass(n, 2, 2, out, base, dh, ft, scale, coef, k); break;
    case 9: stage_pass(n, 3, 0, out, base, dh, ft, scale, coef, k); break;
    case 10: stage_pass(n, 3, 1, out, base, dh, ft, scale, coef, k); break;
    case 11: stage_pass(n, 3, 2, out, base, dh, ft, scale, coef, k); break;
    case 12: stage_pass(n, 4, 0, out, base, dh, ft, scale, coef, k); break;
    case 13: stage_pass(n, 4, 1, out, base, dh, ft, scale, coef, k); break;
    case 14: stage_pass(n, 4, 2, out, base, dh, ft, scale, coef, k); break;
    case 15: stage_pass(n, 5, 0, out, base, dh, ft, scale, coef, k); break;
    case 16: stage_pass(n, 5, 1, out, base, dh, ft, scale, coef, k); break;
    case 17: stage_pass(n, 5, 2, out, base, dh, ft, scale, coef, k); break;
    }
}

/* 1 when every v_i is finite (no exponent field all ones): the test in
 * integer lanes, an OR over the components, no branch a component. */
SW_CLONES int swr_all_finite(int n, const double *v)
{
    const uint64_t exponent = 0x7FF0000000000000ULL;
    uint64_t over = 0;
    for (int i = 0; i < n; i++) {
        uint64_t bits;
        memcpy(&bits, v + i, sizeof bits);
        over |= (bits & exponent) + 0x0010000000000000ULL; /* carries out of the field only when it is full */
    }
    return (over >> 63) == 0 ? 1 : 0;
}

/* The second stage's point, out_i = base_i + coef·k_i, with base copied
 * into keep in the same pass (the controller's copy of y0, taken where y0
 * is read anyway; SW_ONE_PASS keeps the copy in it). */
SW_CLONES SW_ONE_PASS void swr_stage_point_keep(int n, double *restrict out, double *restrict keep, const double *restrict base,
                                    double coef, const double *restrict k)
{
    for (int i = 0; i < n; i++) {
        double b = base[i];
        keep[i] = b;
        out[i] = b + coef * k[i];
    }
}
