/* The stability region along one mark's ray: how far from the origin the
 * ray through a mark Δt·λ stays in the region (its edge), and the line
 * under the picture that shows the mark against that edge on a log scale.
 * Near the origin a lightly damped mode's ray runs almost along the edge
 * of the region, so in the plane "just outside" and "just inside" look
 * the same; along the ray the distance is the mark's |Δt·λ| over the
 * edge's, which halves with Δt: each halving moves the mark one notch. */
#include "render/region.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

double sw_region_growth(sw_truth_work *w, const sw_integrator *m, int order, double x, double y)
{
    sw_spectrum sp;
    memset(&sp, 0, sizeof sp);
    sp.order = order;
    sp.n = 1;
    sp.complete = 1;
    sp.mode[0] = (sw_mode){ x, y, x, -y };
    sp.largest = hypot(x, y);
    return sw_truth_growth_with(w, m, &sp, 1.0, NULL);
}

/* Below this the step is taken as stable at every r (a mark this close to
 * the origin is the free motion the meter calls neutral), above the far
 * end as stable on the whole ray (an implicit method). */
#define RAY_NEAR 1e-9
#define RAY_FAR 100.0

double sw_region_edge_on_ray(sw_truth_work *w, const sw_integrator *m, int order, double ux, double uy)
{
    double norm = hypot(ux, uy);
    if (!(norm > 0))
        return INFINITY;
    ux /= norm;
    uy /= norm;
#define UNSTABLE(r) (!(sw_region_growth(w, m, order, (r) * ux, (r) * uy) <= 1 + SW_TRUTH_NEUTRAL))
    if (UNSTABLE(RAY_NEAR))
        return 0;
    double lo = RAY_NEAR, hi = 0;
    for (double r = RAY_NEAR * 1.25; r <= RAY_FAR; r *= 1.25) {
        if (UNSTABLE(r)) {
            hi = r;
            break;
        }
        lo = r;
    }
    if (hi == 0)
        return INFINITY;
    /* the first unstable point to a part in 1e-9 (the gauge shows two figures) */
    while (hi - lo > 1e-9 * hi) {
        double mid = 0.5 * (lo + hi);
        if (UNSTABLE(mid))
            hi = mid;
        else
            lo = mid;
    }
#undef UNSTABLE
    return lo;
}

void sw_region_gauge(char *out, size_t len, int width, double ratio, int grows)
{
    /* "in ::::::|----- out 5×edge": the edge in the middle of the bar, each
     * factor 2 of the ratio `notch` columns, the inside shaded as the
     * picture shades it */
    char tail[32];
    if (ratio == 0 || isinf(ratio)) {
        /* no edge to measure against: said, not drawn */
        snprintf(out, len, "%s", ratio == 0 ? "its ray has no edge: always in" : "its ray's edge is 0: always out");
        return;
    }
    snprintf(tail, sizeof tail, " %.3g×edge", ratio); /* (the mark's distance: that many times the edge's) */
    /* the tail's room is fixed, so that the bar (and its edge) stays put
     * while the ratio's figures change */
    int bar = width - 3 - 4 - 14;
    if (bar > 41)
        bar = 41;
    if (bar < 9 || len < (size_t)width + 1) {
        snprintf(out, len, "mark/edge on its ray:%s", tail);
        return;
    }
    if (bar % 2 == 0)
        bar--;
    int mid = bar / 2, notch = mid >= 9 ? 3 : 2, pos;
    double p = mid + notch * log2(ratio);
    pos = p < 0 ? 0 : p > bar - 1 ? bar - 1 : (int)lround(p);
    char line[128];
    int n = snprintf(line, sizeof line, "in ");
    for (int k = 0; k < bar; k++) {
        char ch = k < mid ? ':' : k == mid ? '|' : '-';
        if (k == pos)
            ch = grows ? 'X' : '*';
        line[n++] = ch;
    }
    snprintf(line + n, sizeof line - (size_t)n, " out%s", tail);
    snprintf(out, len, "%s", line);
}
