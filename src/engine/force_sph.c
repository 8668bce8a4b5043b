/* Smoothed-particle hydrodynamics in 2-D after Müller, Charypar and Gross
 * (2003), in a box. With kernel radius h and each neighbour b of a within h:
 *   density   ρ_a = Σ_b m_b W6(x_a - x_b)          (self included)
 *   pressure  p_a = stiff·max(ρ_a - rho0, 0)       (the sound speed c = √stiff)
 *   force     f_a = -Σ_b m_a m_b (p_a/ρ_a² + p_b/ρ_b²) ∇Wspiky(x_a - x_b)
 *                   + nu·rho0 Σ_b m_a m_b (v_b - v_a)/(ρ_a ρ_b) ∇²Wvisc(|x_a - x_b|)
 * The pressure term is Monaghan's symmetric form; Müller's (p_a + p_b)/
 * (2 ρ_a ρ_b) is its half where densities agree, and holds a column at rest
 * only at twice the hydrostatic pressure.
 * with the 2-D kernels W6 = 4/(π h⁸)(h² - r²)³, ∇Wspiky = -C (h - r)² d/r
 * (C = 30/(π h⁵), or as the scene renormalises it: fo->grad), ∇²Wvisc =
 * 40/(π h⁵)(h - r). Each pair's term is symmetric in a and b, so
 * f_b gets exactly -f_a: Newton's third law pair by pair, momentum changed
 * only by gravity and the walls. Walls x = 0, x = box_w and y = 0 push a
 * particle within `zone` of them with acceleration 4·stiff/h²·(zone - dist)
 * and hold it there (no slip) with a damping -(2c/h)·v.
 * Neighbours come from a Verlet list: every pair within (1 + skin) h, found
 * in a uniform grid (a cell list, counting sort, O(n)) of cells at least
 * half that wide over the particles' bounding box, put in each particle's
 * row in ascending order by a second counting sort, kept across
 * evaluations and built again once a particle has moved skin/2 (then no
 * pair within h can be missing from it). Each particle's sums (density,
 * force) run over its neighbours in ascending index order, whatever found
 * them (the list, a list of another skin, the grid): the same bits,
 * deterministic; the force pass takes the pairs the density pass kept. Invariant: an evaluation
 * allocates nothing (all is sized when the force is added).
 * The Jacobian it gives is each particle's own estimate (pairs 0): the walls,
 * and for the pressure and the viscosity each neighbour counted twice, as
 * in the stiffest mode of a lattice, neighbours moving against each other. */
#include "engine/forces.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "util/num.h"

typedef struct sph_work {
    int n, ncap;        /* particles, most cells */
    double *rho, *press; /* density; p/ρ², the pressure's share in each pair's term */
    int *cell, *start, *order; /* each particle's cell; cell c's particles are order[start[c] .. start[c + 1]) */
    double x0, y0, cs;  /* the grid's corner and cell size */
    int nx, ny;
    double skin;        /* the list's reach beyond h, in units of h */
    double *xb;         /* the positions the list was built at */
    double *r2;         /* n: one row's kept pairs' squared distances */
    int *ls, *lb;       /* the list: a's candidates b > a, ascending, are lb[ls[a] .. ls[a + 1]) */
    int *ks, *kb;       /* while listed, the pairs within h the density pass kept: a's are kb[ks[a] .. ks[a + 1]) */
    long lcap;          /* room in lb, and so in kb (the kept are some of the list's) */
    int listed;         /* 1: the list holds every pair within (1 + skin) h of xb */
    int *scratch;       /* n ints: one particle's candidates as they are gathered */
    long visited;       /* distances computed by the last evaluation */
    long builds;        /* lists built so far */
} sph_work;

/* The list's reach beyond h (a Verlet list's skin), in units of h, and the
 * room for its candidates, on average a particle: a lattice of h =
 * 2 spacings has 6 to 9 pairs within h a particle (each counted once) and
 * 21 within 1.8 h; more (a fluid squeezed far past its rest density) and
 * the evaluation gathers its neighbours from the grid as it goes. A wider
 * skin is more candidates an evaluation and fewer builds: the dam of 1e4
 * at 0.5 ms builds its list every 3.8 steps over its first second at 0.5
 * h, every 5.8 at 0.8 h, every 9.4 at 1.3 h (docs/performance.md). */
#define SKIN 0.8
#define REBUILD 0.49 /* of the skin: a move this long rebuilds the list (half, less a margin for rounding) */
#define LIST_EACH 40

/* One block: the header, then rho, press, xb, r2 (n, n, 2n, n doubles), then
 * cell, order, scratch (n each), start (ncap + 1), ls and ks (n + 1 each),
 * lb and kb; the system frees it. */
static void *sph_work_new(int n)
{
    int ncap = 4 * n + 64;
    size_t head = (sizeof(sph_work) + 15) & ~(size_t)15, lcap = (size_t)LIST_EACH * n;
    char *block = calloc(1, head + (size_t)5 * n * sizeof(double) +
                                ((size_t)3 * n + ncap + 1 + 2 * ((size_t)n + 1) + 2 * lcap) * sizeof(int));
    if (!block)
        return NULL;
    sph_work *w = (sph_work *)block;
    w->n = n;
    w->ncap = ncap;
    w->skin = SKIN;
    w->rho = (double *)(block + head);
    w->press = w->rho + n;
    w->xb = w->press + n;
    w->r2 = w->xb + 2 * (size_t)n;
    w->cell = (int *)(w->r2 + n);
    w->order = w->cell + n;
    w->scratch = w->order + n;
    w->start = w->scratch + n;
    w->ls = w->start + ncap + 1;
    w->ks = w->ls + n + 1;
    w->lb = w->ks + n + 1;
    w->kb = w->lb + lcap;
    w->lcap = (long)lcap;
    return w;
}

/* The cell list: cells at least h wide over the bounding box, doubled until
 * there are at most ncap of them. 0, or -1 when a position is not finite. */
static int grid(sph_work *w, int n, const double *x, double h)
{
    double x0 = x[0], x1 = x[0], y0 = x[1], y1 = x[1];
    for (int i = 1; i < n; i++) {
        x0 = fmin(x0, x[2 * i]), x1 = fmax(x1, x[2 * i]);
        y0 = fmin(y0, x[2 * i + 1]), y1 = fmax(y1, x[2 * i + 1]);
    }
    if (!isfinite(x0 + x1 + y0 + y1))
        return -1;
    double cs = h;
    while ((floor((x1 - x0) / cs) + 1) * (floor((y1 - y0) / cs) + 1) > w->ncap)
        cs *= 2;
    w->x0 = x0, w->y0 = y0, w->cs = cs;
    w->nx = (int)floor((x1 - x0) / cs) + 1;
    w->ny = (int)floor((y1 - y0) / cs) + 1;
    int ncell = w->nx * w->ny;
    for (int c = 0; c <= ncell; c++)
        w->start[c] = 0;
    for (int i = 0; i < n; i++) {
        int cx = (int)((x[2 * i] - x0) / cs), cy = (int)((x[2 * i + 1] - y0) / cs);
        cx = cx < w->nx ? cx : w->nx - 1;
        cy = cy < w->ny ? cy : w->ny - 1;
        w->cell[i] = cy * w->nx + cx;
        w->start[w->cell[i] + 1]++;
    }
    for (int c = 0; c < ncell; c++)
        w->start[c + 1] += w->start[c];
    for (int i = 0; i < n; i++) /* stable: each cell's particles in index order */
        w->order[w->start[w->cell[i]]++] = i;
    for (int c = ncell; c > 0; c--)
        w->start[c] = w->start[c - 1];
    w->start[0] = 0;
    return 0;
}

/* Every pair (a, b) within h once, cell by cell: each cell with itself
 * (b after a) and with its right, upper-left, upper and upper-right
 * neighbours. visit(a, b, dx, dy, r², ctx). The candidates (pairs whose
 * distance it computes) are counted in w->visited: about 20 a particle at
 * the lattice's density, whatever n (the cells are h wide). Inline, so
 * each caller's visit is compiled into its loop. */
typedef void pair_fn(int a, int b, double dx, double dy, double r2, void *ctx);

static inline void each_pair(sph_work *w, const double *x, double h, pair_fn *visit, void *ctx)
{
    static const int step[4][2] = { { 1, 0 }, { -1, 1 }, { 0, 1 }, { 1, 1 } };
    double h2 = h * h;
    long visited = 0;
    for (int cy = 0; cy < w->ny; cy++)
        for (int cx = 0; cx < w->nx; cx++) {
            int c = cy * w->nx + cx;
            for (int ia = w->start[c]; ia < w->start[c + 1]; ia++) {
                int a = w->order[ia];
                for (int s = -1; s < 4; s++) {
                    int ox = s < 0 ? cx : cx + step[s][0], oy = s < 0 ? cy : cy + step[s][1];
                    if (ox < 0 || ox >= w->nx || oy >= w->ny)
                        continue;
                    int o = oy * w->nx + ox, ib0 = s < 0 ? ia + 1 : w->start[o];
                    visited += w->start[o + 1] - ib0;
                    for (int ib = ib0; ib < w->start[o + 1]; ib++) {
                        int b = w->order[ib];
                        double dx = x[2 * a] - x[2 * b], dy = x[2 * a + 1] - x[2 * b + 1], r2 = dx * dx + dy * dy;
                        if (r2 < h2)
                            visit(a, b, dx, dy, r2, ctx);
                    }
                }
            }
        }
    w->visited = visited;
}

/* The cells on each side a search within √r2max must look at. */
static int span(const sph_work *w, double r2max)
{
    int k = 1;
    while ((double)k * w->cs * ((double)k * w->cs) < r2max)
        k++;
    return k;
}

/* a's neighbours b > a within √r2max of it, in ascending order, into out:
 * their count (the fallback when the list does not fit). The candidates
 * whose distance it computes are added to *visited. Each cell's
 * particles are in index order, so each merges in from the top. */
static int gather(const sph_work *w, const double *x, int a, double r2max, int *out, long *visited)
{
    int cx = w->cell[a] % w->nx, cy = w->cell[a] / w->nx, k = 0, s = span(w, r2max);
    long seen = 0;
    for (int oy = cy > s ? cy - s : 0; oy <= cy + s && oy < w->ny; oy++)
        for (int ox = cx > s ? cx - s : 0; ox <= cx + s && ox < w->nx; ox++) {
            int o = oy * w->nx + ox, ib = w->start[o], end = w->start[o + 1];
            for (int hi = end; ib < hi;) { /* the first b > a: the run is ascending */
                int mid = ib + (hi - ib) / 2;
                if (w->order[mid] <= a)
                    ib = mid + 1;
                else
                    hi = mid;
            }
            seen += end - ib;
            for (; ib < end; ib++) {
                int b = w->order[ib];
                double dx = x[2 * a] - x[2 * b], dy = x[2 * a + 1] - x[2 * b + 1];
                if (dx * dx + dy * dy < r2max) {
                    int j = k++;
                    for (; j > 0 && out[j - 1] > b; j--)
                        out[j] = out[j - 1];
                    out[j] = b;
                }
            }
        }
    *visited += seen;
    return k;
}

/* The list at x: every pair within (1 + skin) h, a's partners b > a in
 * ascending order, by a counting sort: each b's partners a < b are found
 * first (in cells half the reach wide, a 5 × 5 block of them; each cell's
 * run is ascending, so it stops at b) into kb, each a counted; then, b by
 * b in ascending order, each b is put in its partners' rows, which so fill
 * in ascending order. 0; 1 when it did not fit (w->listed 0: the grid is
 * left for the evaluation to gather from); -1 when a position is not
 * finite. */
static int build(sph_work *w, int n, const double *x, double h)
{
    double reach = (1 + w->skin) * h, r2max = reach * reach;
    w->listed = 0;
    if (grid(w, n, x, reach / 2) != 0)
        return -1;
    int s = span(w, r2max), *tb = w->ks, *t = w->kb, *cnt = w->ls, *pos = w->scratch;
    long m = 0, seen = 0;
    for (int a = 0; a <= n; a++)
        cnt[a] = 0;
    for (int b = 0; b < n; b++) {
        int cx = w->cell[b] % w->nx, cy = w->cell[b] / w->nx;
        double xb = x[2 * b], yb = x[2 * b + 1];
        tb[b] = (int)m;
        for (int oy = cy > s ? cy - s : 0; oy <= cy + s && oy < w->ny; oy++) {
            int row = oy * w->nx;
            for (int ox = cx > s ? cx - s : 0; ox <= cx + s && ox < w->nx; ox++) {
                int ia = w->start[row + ox], end = w->start[row + ox + 1];
                for (; ia < end; ia++) {
                    int a = w->order[ia];
                    if (a >= b)
                        break;
                    seen++;
                    double dx = x[2 * a] - xb, dy = x[2 * a + 1] - yb;
                    int in = dx * dx + dy * dy < r2max; /* no branch on it: some 60 % are in */
                    if (m == w->lcap) {
                        if (!in)
                            continue;
                        w->visited += seen;
                        return 1;
                    }
                    t[m] = a;
                    m += in;
                    cnt[a + 1] += in;
                }
            }
        }
    }
    tb[n] = (int)m;
    w->visited += seen;
    for (int a = 0; a < n; a++) {
        cnt[a + 1] += cnt[a]; /* cnt is ls: a's row starts at ls[a] */
        pos[a] = cnt[a];
    }
    for (int b = 0; b < n; b++)
        for (int j = tb[b]; j < tb[b + 1]; j++)
            w->lb[pos[t[j]]++] = b;
    for (int i = 0; i < 2 * n; i++)
        w->xb[i] = x[i];
    w->listed = 1;
    w->builds++;
    return 0;
}

/* 1 when some particle moved skin/2 or more (less a margin for rounding)
 * since the list was built, or is not finite: a pair within h now may
 * then have been beyond (1 + skin) h then. */
static int moved(const sph_work *w, int n, const double *x, double h)
{
    double lim = REBUILD * w->skin * h, lim2 = lim * lim;
    int out = 0;
    for (int i = 0; i < n; i++) {
        double dx = x[2 * i] - w->xb[2 * i], dy = x[2 * i + 1] - w->xb[2 * i + 1];
        out |= !(dx * dx + dy * dy < lim2);
    }
    return out;
}

/* C of ∇Wspiky = -C (h - r)² d/r. */
static double spiky(const sw_force *fo)
{
    double h = fo->h;
    return fo->grad > 0 ? fo->grad : 30.0 / (SW_PI * h * h * h * h * h);
}

typedef struct sph_ctx {
    const sw_particles *p;
    const sw_force *fo;
    sph_work *w;
    const double *x, *v;
    double *f;
    double h2, w6, spiky, visc; /* h², 4/(π h⁸), the spiky gradient's C, π h⁵: the kernels' constants */
} sph_ctx;

/* a's density terms from its candidates b (ascending, all > a) within h:
 * ρ_a and ρ_b both get the pair's term, so every density sums its
 * neighbours in ascending order whatever found them. The pairs within h
 * are first put in keep (room for k; it may be cand itself: each is
 * written at or before the candidate it came from), their squared
 * distances in w->r2, with no branch, then summed: a candidate's test is
 * no guess for the branch predictor (about a third of the list's are
 * within h). Their count. */
static int density_row(sph_ctx *c, int a, const int *cand, int k, int *keep)
{
    const double *x = c->x, *mass = c->p->mass;
    double *rho = c->w->rho, *r2 = c->w->r2, h2 = c->h2, w6 = c->w6, xa = x[2 * a], ya = x[2 * a + 1], ma = mass[a], ra = rho[a];
    int kept = 0;
    for (int j = 0; j < k; j++) {
        int b = cand[j];
        double dx = xa - x[2 * b], dy = ya - x[2 * b + 1], d2 = dx * dx + dy * dy;
        keep[kept] = b;
        r2[kept] = d2;
        kept += d2 < h2;
    }
    for (int j = 0; j < kept; j++) {
        int b = keep[j];
        double q = h2 - r2[j], t = w6 * q * q * q;
        ra += mass[b] * t; /* b > a: ρ_a is not among the ρ_b */
        rho[b] += ma * t;
    }
    rho[a] = ra;
    return kept;
}

/* a's pair forces from its neighbours b (ascending, all > a, all within h:
 * the density pass kept them, or gather found them, by the same test): f_a
 * gets each pair's term and f_b its negative, so every force sums its
 * neighbours in ascending order too; no push when they sit at one point. */
static void force_row(const sph_ctx *c, int a, const int *cand, int k)
{
    const sw_force *fo = c->fo;
    const double *x = c->x, *v = c->v, *rho = c->w->rho, *press = c->w->press, *mass = c->p->mass;
    double *f = c->f, h = fo->h, nvisc = fo->nu * fo->rho0 * 40.0 / c->visc, spk = c->spiky;
    double xa = x[2 * a], ya = x[2 * a + 1], vxa = v[2 * a], vya = v[2 * a + 1], ma = mass[a], rhoa = rho[a],
           pa = press[a], fxa = f[2 * a], fya = f[2 * a + 1];
    for (int j = 0; j < k; j++) {
        int b = cand[j];
        double dx = xa - x[2 * b], dy = ya - x[2 * b + 1], r = sqrt(dx * dx + dy * dy);
        if (!(r > 0))
            continue;
        double mm = ma * mass[b], mm_rr = mm / (rhoa * rho[b]), hr = h - r;
        /* -(p_a/ρ_a² + p_b/ρ_b²) ∇Wspiky = (p_a/ρ_a² + p_b/ρ_b²) 30/(π h⁵)(h - r)² d/r */
        double push = mm * (pa + press[b]) * spk * hr * hr / r;
        double visc = mm_rr * nvisc * hr;
        double fx = push * dx + visc * (v[2 * b] - vxa), fy = push * dy + visc * (v[2 * b + 1] - vya);
        fxa += fx, fya += fy; /* b > a: f_a is not among the f_b */
        f[2 * b] -= fx, f[2 * b + 1] -= fy;
    }
    f[2 * a] = fxa, f[2 * a + 1] = fya;
}

/* The walls' acceleration on coordinate value u, dist = u - wall (sign:
 * +1 pushes up/right), and its stiffness. */
static double wall_push(const sw_force *fo, double dist)
{
    return dist < fo->zone ? 4.0 * fo->stiff / (fo->h * fo->h) * (fo->zone - dist) : 0.0;
}

/* Within `zone` of a wall: pushed out, and held (no slip) by a damping
 * 2c/h, the wall spring's own rate. */
static int in_zone(const sw_force *fo, const double *xi)
{
    return xi[0] <= fo->zone || fo->box_w - xi[0] <= fo->zone || xi[1] <= fo->zone;
}

/* Neighbours from the list while no particle has moved skin/2 since it was
 * built (then built again); where the list does not fit, gathered from the
 * grid as the passes go. Every sum runs over the neighbours in ascending
 * order either way: the same bits. */
static void sph_add(const sw_particles *p, const sw_force *fo, const double *x, const double *v, double *f)
{
    sph_work *w = fo->work;
    int n = p->n;
    w->visited = 0;
    if (!w->listed || moved(w, n, x, fo->h))
        if (build(w, n, x, fo->h) < 0)
            return; /* a position went non-finite: the sim reports the blow-up */
    double h2 = fo->h * fo->h, w0 = 4.0 / (SW_PI * h2); /* W6(0) = 4/(π h²) */
    for (int i = 0; i < n; i++)
        w->rho[i] = p->mass[i] * w0;
    sph_ctx c = { p, fo, w, x, v, f, h2, 4.0 / (SW_PI * h2 * h2 * h2 * h2), spiky(fo),
                  SW_PI * (fo->h * fo->h * fo->h * fo->h * fo->h) };
    w->ks[0] = 0;
    for (int a = 0; a < n; a++)
        if (w->listed) {
            int k = w->ls[a + 1] - w->ls[a];
            w->visited += k;
            w->ks[a + 1] = w->ks[a] + density_row(&c, a, w->lb + w->ls[a], k, w->kb + w->ks[a]);
        } else {
            density_row(&c, a, w->scratch, gather(w, x, a, h2, w->scratch, &w->visited), w->scratch);
        }
    for (int i = 0; i < n; i++) {
        double pressure = w->rho[i] > fo->rho0 ? fo->stiff * (w->rho[i] - fo->rho0) : 0.0;
        w->press[i] = pressure / (w->rho[i] * w->rho[i]);
    }
    for (int a = 0; a < n; a++)
        if (w->listed)
            force_row(&c, a, w->kb + w->ks[a], w->ks[a + 1] - w->ks[a]);
        else
            force_row(&c, a, w->scratch, gather(w, x, a, h2, w->scratch, &w->visited));
    double grip = 2.0 * sqrt(fo->stiff) / fo->h;
    for (int i = 0; i < n; i++) {
        double at = in_zone(fo, x + 2 * i) ? grip : 0.0;
        f[2 * i] += p->mass[i] * ((wall_push(fo, x[2 * i]) - wall_push(fo, fo->box_w - x[2 * i])) - at * v[2 * i]);
        f[2 * i + 1] += p->mass[i] * (wall_push(fo, x[2 * i + 1]) - at * v[2 * i + 1]);
    }
}

static long sph_pairs(const sw_particles *p, const sw_force *fo, int *reach)
{
    (void)p, (void)fo;
    *reach = 0;
    return 0;
}

/* Each particle's own estimate: twice the sum over its neighbours of the
 * pressure's stiffness 2·stiff·m²/rho0²·∇Wspiky ∇W6ᵀ (the density each pair
 * changes, through p_a and p_b, as the pressure's linearisation at rest gives it) and of the
 * viscosity's damping; the walls' stiffness within their zone. */
typedef struct block_ctx { const sw_particles *p; const sw_force *fo; double *diag; } block_ctx;

static void block_pair(int a, int b, double dx, double dy, double r2, void *ctx)
{
    block_ctx *c = ctx;
    const sw_force *fo = c->fo;
    double h = fo->h, h2 = h * h, r = sqrt(r2), h5 = h2 * h2 * h;
    if (!(r > 0))
        return;
    double m = c->p->mass[a], q = h2 - r2;
    double gs = spiky(fo) * (h - r) * (h - r) / r, g6 = 24.0 / (SW_PI * h2 * h2 * h2 * h2) * q * q;
    double k = 4.0 * fo->stiff * m * m / (fo->rho0 * fo->rho0) * gs * g6; /* 2 · (p_a + p_b)/ρ0² */
    double dmp = 2.0 * fo->nu * m / fo->rho0 * 40.0 / (SW_PI * h5) * (h - r);
    double blk[4] = { k * dx * dx, k * dx * dy, k * dy * dx, k * dy * dy };
    int who[2] = { a, b };
    for (int s = 0; s < 2; s++) {
        double *d = c->diag + 8 * who[s], mass = c->p->mass[who[s]];
        for (int e = 0; e < 4; e++)
            d[e] -= mass * blk[e];
        d[4] -= mass * dmp;
        d[7] -= mass * dmp;
    }
}

static void sph_blocks(const sw_particles *p, const sw_force *fo, const double *x, const double *v,
                       swp_blocks *out)
{
    (void)v;
    sph_work *w = fo->work;
    if (grid(w, p->n, x, fo->h) != 0)
        return;
    block_ctx c = { p, fo, out->diag };
    each_pair(w, x, fo->h, block_pair, &c);
    double kw = 4.0 * fo->stiff / (fo->h * fo->h);
    for (int i = 0; i < p->n; i++) {
        double *d = out->diag + 8 * i;
        if (x[2 * i] <= fo->zone || fo->box_w - x[2 * i] <= fo->zone)
            d[0] -= p->mass[i] * kw;
        if (x[2 * i + 1] <= fo->zone)
            d[3] -= p->mass[i] * kw;
        if (in_zone(fo, x + 2 * i)) {
            d[4] -= p->mass[i] * 2.0 * sqrt(fo->stiff) / fo->h;
            d[7] -= p->mass[i] * 2.0 * sqrt(fo->stiff) / fo->h;
        }
    }
}

static void sph_values(const sw_force *fo, char *buf, size_t len)
{
    snprintf(buf, len, "h = %g, rho0 = %g, stiff = %g (c = %g), nu = %g, box width %g", fo->h, fo->rho0, fo->stiff,
             sqrt(fo->stiff), fo->nu, fo->box_w);
}

long swp_sph_visited(const sw_force *fo)
{
    const sph_work *w = fo->work;
    return w ? w->visited : 0;
}

long swp_sph_builds(const sw_force *fo)
{
    const sph_work *w = fo->work;
    return w ? w->builds : 0;
}

double swp_sph_skin(const sw_force *fo, double *rebuild)
{
    const sph_work *w = fo->work;
    double skin = w ? w->skin : SKIN;
    *rebuild = REBUILD * skin;
    return skin;
}

int swp_sph_row(const sw_force *fo, int a, const int **row)
{
    const sph_work *w = fo->work;
    if (!w || !w->listed || a < 0 || a >= w->n)
        return -1;
    *row = w->lb + w->ls[a];
    return w->ls[a + 1] - w->ls[a];
}

void swp_sph_set_skin(const sw_force *fo, double skin)
{
    sph_work *w = fo->work;
    if (w) {
        w->skin = skin > 0 ? skin : 0;
        w->listed = 0;
    }
}

static int sph_uses_velocity(const sw_force *fo) { return fo->nu != 0; }

const swp_force_type swp_sph = {
    .name = "sph",
    .formula = "f_a = -sum_b m_a m_b (p_a/rho_a^2 + p_b/rho_b^2) grad W_spiky + nu rho0 sum_b m_a m_b (v_b - v_a)/"
               "(rho_a rho_b) lap W_visc; p = stiff max(rho - rho0, 0)",
    .values = sph_values,
    .add = sph_add,
    .pairs = sph_pairs,
    .blocks = sph_blocks,
    .work_new = sph_work_new,
    .uses_velocity = sph_uses_velocity,
};
