/* Private to the engine and the layers above it: what the engine knows of
 * each force kind, one descriptor per kind in its own file (force_*.c) and
 * one table (forces.c). The derivative, the energy, the implicit solve and
 * the stability theory ask the descriptor; none of them re-derives a force.
 * Adding a kind: its descriptor file (fields named), its extern below, its
 * line in forces.c, its enum value (and parameters) in
 * include/stepwise/particles.h — docs/architecture.md. */
#ifndef SW_ENGINE_FORCES_H
#define SW_ENGINE_FORCES_H

#include "stepwise/particles.h"

/* The Jacobian of the forces as 2x2 blocks (row-major: xx, xy, yx, yy).
 * diag: 8 per particle, ∂f_i/∂x_i then ∂f_i/∂v_i, added to. pairs: a force
 * that joins particles a and b as f_a = g(x_a - x_b, v_a - v_b), f_b = -g
 * (b < 0: a fixed point, no f_b) writes pair j = n++ as a[j], b[j] and 8
 * doubles at pair + 8j: ∂g/∂d, then ∂g/∂(dv). The caller makes room for
 * every pair the forces count (pairs below). */
typedef struct swp_blocks {
    double *diag;
    int *a, *b;
    double *pair;
    long n;
} swp_blocks;

typedef struct swp_force_type {
    const char *name;
    const char *formula;  /* the force on particle i, as docs/scenes.md writes it */
    /* Its parameters' values, "G = 1, soft = 0.1", into buf. */
    void (*values)(const sw_force *fo, char *buf, size_t len);
    /* f (2n) += the force on every particle at positions x, velocities v.
     * (Springs, gravity and drag are also compiled into particles_deriv.c's
     * fused loops, which must give these numbers: tests/check_derivative.c.) */
    void (*add)(const sw_particles *p, const sw_force *fo, const double *x, const double *v, double *f);
    /* *e += its potential energy at x, term by term in particle or
     * spring order; NULL: it stores none (drag). */
    void (*potential)(const sw_particles *p, const sw_force *fo, const double *x, double *e);
    /* A bound on |the potential it adds at x - the exact one|, where it
     * approximates it (a tree's far cells); NULL hook: it is exact. */
    double (*potential_error)(const sw_particles *p, const sw_force *fo, const double *x);
    /* The potential as the explainer names it: "spring potential", its
     * formula, and whether the formula has a ½ (a slip forgets it). */
    const char *term, *term_formula;
    int term_half;
    /* The pairs it writes into swp_blocks (0: it acts on each particle
     * alone) and, in *reach, the largest |a - b| among them. */
    long (*pairs)(const sw_particles *p, const sw_force *fo, int *reach);
    /* Its Jacobian at (x, v) into out. */
    void (*blocks)(const sw_particles *p, const sw_force *fo, const double *x, const double *v, swp_blocks *out);
    /* 1 when blocks never writes out->diag (pair blocks alone, or none:
     * springs, gravity); 0 (the default): it may. The implicit solve then
     * knows a particle's own blocks stay zero and skips them. */
    int pairs_only;
    /* Its workspace for n particles, kept between evaluations (fo->work,
     * freed by the system), or NULL when out of memory; NULL hook: it keeps
     * none. */
    void *(*work_new)(int n);
    /* 1 when the force, with these parameters, depends on velocities (drag,
     * a damped spring); NULL hook: it never does. Runge-Kutta-Nyström
     * methods (rkn) refuse a system where one does. */
    int (*uses_velocity)(const sw_force *fo);
} swp_force_type;

extern const swp_force_type swp_gravity, swp_drag, swp_springs, swp_central, swp_mutual, swp_tree,
    swp_heat, swp_sph;

/* The descriptor of a kind; NULL for a value that is not a kind. */
const swp_force_type *swp_force_type_of(sw_force_kind kind);

/* Size fo->work for p's n particles when the force is added, through its
 * descriptor's work_new: 0 or SW_ENOMEM. The system frees fo->work.
 * Evaluations then allocate nothing. */
int swp_force_prepare(const sw_particles *p, sw_force *fo);

/* The 2x2 block -s·(I/q³ - 3 d dᵀ/q⁵), q² = dx² + dy² + soft²: the
 * Jacobian of f = -s·d/q³ (central attraction, softened gravity); zero
 * where q = 0. */
void swp_inverse_square_block(double s, double dx, double dy, double soft2, double blk[4]);

/* The candidate pairs (pairs of particles whose distance it computed: the
 * grid's neighbouring cells' when it built its neighbour list, the list's
 * otherwise) of an SPH force's last evaluation: a count, for the O(n)
 * test; 0 before the first. */
long swp_sph_visited(const sw_force *fo);

/* The neighbour lists an SPH force has built so far. */
long swp_sph_builds(const sw_force *fo);

/* Its list's skin (reach beyond h, in units of h; 0: built at every
 * evaluation that moved a particle), the next list built afresh. The
 * results do not depend on it, to the bit: tests/check_water.c. */
void swp_sph_set_skin(const sw_force *fo, double skin);

/* Its skin (in units of h) and, in *rebuild, the move that rebuilds the
 * list (in units of h). */
double swp_sph_skin(const sw_force *fo, double *rebuild);

/* Particle a's row of its neighbour list (its partners b > a within
 * (1 + skin) h of where the list was built, ascending) into *row, and
 * their count; -1 while no list is held (before the first evaluation,
 * after a skin is set, or when the list did not fit). */
int swp_sph_row(const sw_force *fo, int a, const int **row);

#endif
