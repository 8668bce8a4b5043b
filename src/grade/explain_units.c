/* The explainer's look at units: a column, or a family of columns (x*, y*,
 * vx*, vy*, t, energy), that is the assignment's times 10, 100 or 1000, or
 * divided by them, at every examined value: positions written in cm, times
 * in ms. Invariant: named only when every other column matches as it is,
 * so the units are the whole story of the failure. */
#include "grade/explain_int.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "stepwise/stepwise.h"

/* A change of unit is an exact multiplication: a value printed ×100 is the
 * reference to rounding (1e-16), and a run made in cm throughout drifts
 * from the scaled reference by rounding only (about 1e-13 over the 400
 * rows examined). 1e-9 relative, the default grading tolerance, leaves
 * three orders for that, and no wrong method stays within 1e-9 of a
 * constant multiple of the right one at every value of a column. At 0 a
 * factor shows nothing: there the column's absolute tolerance decides. */
#define UNIT_RTOL 1e-9

static const double factors[] = { 10, 100, 1000, 0.1, 0.01, 0.001 };
#define NFACTORS ((int)(sizeof factors / sizeof factors[0]))

/* The quantities a column can hold, each with its SI unit. */
enum { Q_TIME, Q_POSITION, Q_VELOCITY, Q_ENERGY, NQ };
static const char *const quantity_noun[NQ] = { "times", "positions", "velocities", "energies" };
static const char *const quantity_unit[NQ] = { "s", "m", "m/s", "J" };

/* The column families, in trace order: t, x, y, vx, vy, energy. */
enum { F_T, F_X, F_Y, F_VX, F_VY, F_ENERGY, NF };
static const char *const family_name[NF] = { "t", "x", "y", "vx", "vy", "energy" };
static const int family_quantity[NF] = { Q_TIME, Q_POSITION, Q_POSITION, Q_VELOCITY, Q_VELOCITY,
                                         Q_ENERGY };

typedef struct units {
    const xpl_rows *tr, *ref;
    const sw_check_tol *tol;
    const sw_system *sys;
    int per, has_energy;
    double *fac;      /* per column: 1 when right as it is, else the factor */
    char *said;       /* per column: already in the message */
} units;

static int family_of(const units *u, int c)
{
    if (c == 1)
        return F_T;
    if (u->has_energy && c == u->tr->ncols - 1)
        return F_ENERGY;
    return F_X + (c - 2) % u->per;
}

/* Whether column c, divided by f, passes: UNIT_RTOL relative, the column's
 * own absolute tolerance (values at 0). need_nonzero: at least one value
 * of the assignment's away from 0, without which no factor shows. */
static int scaled_by(const units *u, int c, double f, double rtol, int need_nonzero)
{
    const sw_check_tol *tol = u->tol;
    double atol = tol->col_atol ? tol->col_atol[c] : tol->atol, ae, re, ratio;
    int nonzero = 0;
    for (int i = 0; i < u->tr->n; i++) {
        double want = xpl_row(u->ref, i)[c], got = xpl_row(u->tr, i)[c];
        if (!sw_check_value(want, got / f, rtol, atol, &ae, &re, &ratio))
            return 0;
        nonzero += fabs(want) > atol;
    }
    return nonzero > 0 || !need_nonzero;
}

/* "cm" for positions ×100: only the prefixes people write (c, m, k). */
static const char *prefix_of(double f)
{
    return f == 100 ? "c" : f == 1000 ? "m" : f == 0.001 ? "k" : NULL;
}

/* Append to buf (len bytes, used so far); a full buffer stays full. */
static size_t add(char *buf, size_t len, size_t used, const char *text)
{
    if (used + 1 >= len)
        return used;
    int n = snprintf(buf + used, len - used, "%s", text);
    return n < 0 || (size_t)n >= len - used ? len - 1 : used + (size_t)n;
}

/* "x* and y*", "x0", "vx2 and vy2": the columns of quantity q off by f,
 * a family as "x*" when all its columns are (at 0 any factor holds) and it
 * has more than one. Marks them said. */
static int name_columns(const units *u, int q, double f, char *buf, size_t len)
{
    int names = 0, ncols = u->tr->ncols;
    size_t used = 0;
    buf[0] = '\0';
    for (int fam = 0; fam < NF; fam++) {
        if (family_quantity[fam] != q)
            continue;
        int members = 0, off = 0, whole = 1;
        for (int c = 1; c < ncols; c++) {
            if (family_of(u, c) != fam)
                continue;
            members++;
            off += u->fac[c] == f;
            whole &= u->fac[c] == f || (u->fac[c] == 1 && scaled_by(u, c, f, UNIT_RTOL, 0));
        }
        if (!off)
            continue;
        if (whole && members > 1) {
            used = add(buf, len, used, names++ ? " and " : "");
            used = add(buf, len, used, family_name[fam]);
            used = add(buf, len, used, "*");
        }
        for (int c = 1; c < ncols; c++) {
            if (family_of(u, c) != fam || u->fac[c] != f)
                continue;
            u->said[c] = 1;
            if (whole && members > 1)
                continue;
            char col[32];
            sw_trace_colname(u->sys, c, col, sizeof col);
            used = add(buf, len, used, names++ ? " and " : "");
            used = add(buf, len, used, col);
        }
    }
    return names;
}

int xpl_units(const xpl_rows *tr, const xpl_rows *ref, const sw_run_desc *d,
              const sw_check_tol *tol, sw_explanation *out)
{
    int ncols = tr->ncols, found = 0, scaled = 0;
    if (tr->n <= 0 || ref->n < tr->n)
        return 0;
    sw_system sys;
    char err[SW_ERRLEN];
    if (sw_system_build(&sys, d->scene, d->p, err, sizeof err) != SW_OK)
        return 0;
    units u = { tr, ref, tol, &sys, sw_trace_per_particle(&sys), d->scene->energy != NULL,
                malloc((size_t)ncols * sizeof(double)), calloc((size_t)ncols, 1) };
    if (!u.fac || !u.said)
        goto done;
    /* Each column right as it is (the grading tolerances), or right divided
     * by one factor; one column neither and it is not (only) units. */
    for (int c = 1; c < ncols; c++) {
        double rtol = tol->col_rtol ? tol->col_rtol[c] : tol->rtol;
        u.fac[c] = 1;
        if ((tol->ignore && tol->ignore[c]) || scaled_by(&u, c, 1, rtol, 0))
            continue;
        u.fac[c] = 0;
        for (int k = 0; k < NFACTORS && u.fac[c] == 0; k++)
            if (scaled_by(&u, c, factors[k], UNIT_RTOL, 1))
                u.fac[c] = factors[k];
        if (u.fac[c] == 0)
            goto done;
        scaled++;
    }
    if (!scaled)
        goto done;
    /* One sentence per quantity and factor, in column order. */
    size_t used = 0, len = sizeof out->message;
    for (int c = 1; c < ncols; c++) {
        if (u.fac[c] == 1 || u.said[c])
            continue;
        double f = u.fac[c];
        int q = family_quantity[family_of(&u, c)];
        char cols[160], sentence[320], unit[40];
        int names = name_columns(&u, q, f, cols, sizeof cols);
        const char *prefix = prefix_of(f);
        if (prefix)
            snprintf(unit, sizeof unit, " in %s%s instead of %s?", prefix, quantity_unit[q],
                     quantity_unit[q]);
        else
            snprintf(unit, sizeof unit, " in another unit?");
        snprintf(sentence, sizeof sentence, "%s%s %s %s%g%s the reference at every step: %s%s",
                 used ? "; " : "", cols, names > 1 ? "are" : "is", f >= 1 ? "" : "1/",
                 f >= 1 ? f : 1 / f, f >= 1 ? " times" : " of", quantity_noun[q], unit);
        used = add(out->message, len, used, sentence);
    }
    snprintf(out->kind, sizeof out->kind, "units");
    out->agreement = NAN;
    found = 1;
done:
    free(u.fac);
    free(u.said);
    sw_system_free(&sys);
    return found;
}
