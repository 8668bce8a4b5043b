/* Softened mutual gravity (Plummer), every pair by direct sum:
 *   f_i = -Σ_j G m_i m_j (x_i - x_j) / (|x_i - x_j|² + ε²)^(3/2),
 *   V = -Σ_{i<j} G m_i m_j / √(|x_i - x_j|² + ε²).
 * ε keeps a close pass finite (stars are not points at this resolution).
 * Parameters: mu = G, soft = ε. */
#include "engine/forces.h"

#include <math.h>
#include <stdio.h>

static void mutual_add(const sw_particles *p, const sw_force *fo, const double *x, const double *v, double *f)
{
    (void)v;
    double e2 = fo->soft * fo->soft;
    for (int i = 0; i < p->n; i++) /* each pair once, both ends at once: the lecture's loop */
        for (int j = i + 1; j < p->n; j++) {
            double dx = x[2 * i] - x[2 * j], dy = x[2 * i + 1] - x[2 * j + 1], q2 = dx * dx + dy * dy + e2;
            double s = fo->mu * p->mass[i] * p->mass[j] / (q2 * sqrt(q2));
            f[2 * i] -= s * dx;
            f[2 * i + 1] -= s * dy;
            f[2 * j] += s * dx;
            f[2 * j + 1] += s * dy;
        }
}

static void mutual_potential(const sw_particles *p, const sw_force *fo, const double *x, double *e)
{
    double e2 = fo->soft * fo->soft;
    for (int i = 0; i < p->n; i++)
        for (int j = i + 1; j < p->n; j++) {
            double dx = x[2 * i] - x[2 * j], dy = x[2 * i + 1] - x[2 * j + 1];
            *e -= fo->mu * p->mass[i] * p->mass[j] / sqrt(dx * dx + dy * dy + e2);
        }
}

static long mutual_pairs(const sw_particles *p, const sw_force *fo, int *reach)
{
    (void)fo;
    *reach = p->n - 1;
    return (long)p->n * (p->n - 1) / 2;
}

static void mutual_blocks(const sw_particles *p, const sw_force *fo, const double *x, const double *v,
                          swp_blocks *out)
{
    (void)v;
    double e2 = fo->soft * fo->soft;
    for (int i = 0; i < p->n; i++)
        for (int j = i + 1; j < p->n; j++, out->n++) {
            double *k = out->pair + 8 * out->n;
            out->a[out->n] = i;
            out->b[out->n] = j;
            swp_inverse_square_block(fo->mu * p->mass[i] * p->mass[j], x[2 * i] - x[2 * j],
                                     x[2 * i + 1] - x[2 * j + 1], e2, k);
            k[4] = k[5] = k[6] = k[7] = 0;
        }
}

static void mutual_values(const sw_force *fo, char *buf, size_t len)
{
    snprintf(buf, len, "G = %g, soft = %g", fo->mu, fo->soft);
}

const swp_force_type swp_mutual = {
    .name = "mutual gravity",
    .formula = "f_i = -sum_j G m_i m_j d/(|d|^2 + soft^2)^(3/2), d = x_i - x_j",
    .values = mutual_values,
    .add = mutual_add,
    .potential = mutual_potential,
    .term = "mutual gravity potential",
    .term_formula = "- G m_i m_j/√(r² + ε²)",
    .pairs = mutual_pairs,
    .blocks = mutual_blocks,
};
