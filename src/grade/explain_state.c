/* The explainer's look at what a trace says about the scene itself rather
 * than the method: its initial state (row 0) against the assignment's, and
 * its energy column against the formulas a student could have written,
 * recomputed from the trace's own positions and velocities. Invariant: a
 * formula is named only when it reproduces every examined energy value
 * within the energy column's grading tolerance. */
#include "grade/explain_int.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine/forces.h"
#include "grade/assignment.h"
#include "stepwise/stepwise.h"

static double col_rtol(const sw_check_tol *tol, int c)
{
    return tol->col_rtol ? tol->col_rtol[c] : tol->rtol;
}

static double col_atol(const sw_check_tol *tol, int c)
{
    return tol->col_atol ? tol->col_atol[c] : tol->atol;
}

static int ignored(const sw_check_tol *tol, int c) { return tol->ignore && tol->ignore[c]; }

/* The state y (ode->dim doubles) that row gives, columns in canonical order. */
static void state_of_row(const sw_system *sys, const double *row, double *y)
{
    int n = sys->n, per = sw_trace_per_particle(sys);
    for (int i = 0; i < n; i++) {
        y[2 * i] = row[2 + per * i];
        y[2 * i + 1] = row[3 + per * i];
        if (per == 4) {
            y[2 * n + 2 * i] = row[4 + per * i];
            y[2 * n + 2 * i + 1] = row[5 + per * i];
        }
    }
}

/* ---- the initial state ---------------------------------------------------- */

int xpl_initial_state(const xpl_rows *tr, const xpl_rows *ref, const sw_run_desc *d,
                      const sw_check_tol *tol, sw_explanation *out)
{
    int ncols = tr->ncols, ecol = d->scene->energy ? ncols - 1 : -1, first = -1, second = -1,
        count = 0;
    const double *got = xpl_row(tr, 0), *want = xpl_row(ref, 0);
    double ae, re, ratio;
    for (int c = 2; c < ncols; c++) {
        if (c == ecol || ignored(tol, c) ||
            sw_check_value(want[c], got[c], col_rtol(tol, c), col_atol(tol, c), &ae, &re, &ratio))
            continue;
        count++;
        if (first >= 0 && second < 0)
            second = c;
        if (first < 0)
            first = c;
    }
    if (count == 0)
        return 0;
    sw_system sys;
    char err[SW_ERRLEN];
    if (sw_system_build(&sys, d->scene, d->p, err, sizeof err) != SW_OK)
        return 0;
    char name[32], yours[40], theirs[40], others[200] = "", after[120] = "";
    sw_trace_colname(&sys, first, name, sizeof name);
    sw_fmt_shortest(yours, sizeof yours, got[first]);
    sw_fmt_shortest(theirs, sizeof theirs, want[first]);
    int per = sw_trace_per_particle(&sys), particle = (first - 2) / per;
    const char *noun = sys.kind == SW_SYS_FLOW ? "point" : "particle";
    /* Two particles' same coordinate exchanged (the plucked bead one off):
     * say so, it is the likelier story than two wrong values. */
    if (count == 2 && (second - first) % per == 0 &&
        sw_check_value(want[second], got[first], col_rtol(tol, first), col_atol(tol, first), &ae, &re, &ratio) &&
        sw_check_value(want[first], got[second], col_rtol(tol, second), col_atol(tol, second), &ae, &re, &ratio)) {
        char name2[32], yours2[40];
        int other = (second - 2) / per;
        sw_trace_colname(&sys, second, name2, sizeof name2);
        sw_fmt_shortest(yours2, sizeof yours2, got[second]);
        snprintf(others, sizeof others, ", and %s %d with %s = %s in yours: %s %d's and %s %d's "
                 "values are exchanged%s", noun, other, name2, yours2, noun, particle, noun, other,
                 other - particle == 1 ? " (an index off by one?)" : "");
    } else if (count > 1)
        snprintf(others, sizeof others, " (and %d other value%s)", count - 1, count > 2 ? "s" : "");
    /* Were the steps right from the student's own start? */
    double *y0 = malloc((size_t)sys.ode->dim * sizeof *y0);
    xpl_rows again = { malloc((size_t)tr->n * (size_t)ncols * sizeof(double)), NULL, 0, ncols };
    double worst;
    if (y0 && again.v) {
        state_of_row(&sys, got, y0);
        again.n = xpl_run_rows(d, d->method, d->p, d->dt, y0, tr->n, &again);
        if (again.n == tr->n && xpl_rows_match(tr, &again, tr->n, tol, -1, 1.0, &worst)) {
            char how[40];
            xpl_agree(how, sizeof how, worst);
            snprintf(after, sizeof after, "; from your initial state on, your steps match %s %s",
                     d->method->name, how);
        }
    }
    free(y0);
    free(again.v);
    snprintf(out->kind, sizeof out->kind, "initial-state");
    if (snprintf(out->message, sizeof out->message, "your initial state is not the assignment's: "
                 "%s %d starts with %s = %s in yours, %s in the assignment's%s; docs/scenes.md, '%s', "
                 "gives every %s's initial state%s",
                 noun, particle, name, yours, theirs, others, d->scene->name, noun, after) < 0)
        out->message[0] = '\0'; /* a long one is cut: its start says what differs */
    sw_system_free(&sys);
    return 1;
}

/* ---- the energy formula --------------------------------------------------- */

/* The terms of docs/scenes.md's energy, in the order messages name them:
 * the kinetic energy, then each force kind's potential (term 1 + kind;
 * a kind that stores none, drag, has no name and is never present). */
enum { KINETIC, NTERMS = 1 + SW_FORCE_KINDS };

static const char *term_name(int k)
{
    return k == KINETIC ? "kinetic energy" : swp_force_type_of((sw_force_kind)(k - 1))->term;
}

static const char *term_formula(int k)
{
    return k == KINETIC ? "½ m|v|²" : swp_force_type_of((sw_force_kind)(k - 1))->term_formula;
}

static int has_half(int k)
{
    return k == KINETIC || swp_force_type_of((sw_force_kind)(k - 1))->term_half;
}

/* Coefficients a slip gives: a term kept, left out, with its sign flipped,
 * or (a ½ forgotten) doubled. */
static const double slips[] = { 1, 0, -1, 2 };

/* Each term of sw_particles_energy at y into e. */
static void energy_terms(const sw_particles *p, const double *y, double e[NTERMS])
{
    int n2 = 2 * p->n;
    const double *x = y, *v = y + n2;
    memset(e, 0, NTERMS * sizeof *e);
    for (int i = 0; i < p->n; i++)
        e[KINETIC] += 0.5 * p->mass[i] * (v[2 * i] * v[2 * i] + v[2 * i + 1] * v[2 * i + 1]);
    for (int k = 0; k < p->nforces; k++) { /* each term as the engine sums it */
        const sw_force *fo = &p->forces[k];
        const swp_force_type *type = swp_force_type_of(fo->kind);
        if (type->potential)
            type->potential(p, fo, x, &e[1 + fo->kind]);
    }
}

/* Whether coefficients coef reproduce the energy column of every row. */
static int formula_matches(const double *terms, const xpl_rows *tr, int ecol, const double *coef,
                           const sw_check_tol *tol, double *worst)
{
    *worst = 0;
    for (int i = 0; i < tr->n; i++) {
        double e = 0, ae, re, ratio;
        for (int k = 0; k < NTERMS; k++)
            e += coef[k] * terms[i * NTERMS + k];
        if (!sw_check_value(e, xpl_row(tr, i)[ecol], col_rtol(tol, ecol), col_atol(tol, ecol),
                            &ae, &re, &ratio))
            return 0;
        *worst = re > *worst ? re : *worst;
    }
    return 1;
}

/* "kinetic minus spring potential" */
static void say_formula(const double *coef, const int *present, char *buf, size_t len)
{
    size_t used = 0;
    buf[0] = 0;
    for (int k = 0; k < NTERMS && used < len; k++) {
        if (!present[k] || coef[k] == 0)
            continue;
        const char *join = coef[k] < 0 ? (used ? " minus " : "minus ") : used ? " plus " : "";
        used += (size_t)snprintf(buf + used, len - used, "%s%s%s", join,
                                 fabs(coef[k]) == 2 ? "twice the " : "", term_name(k));
    }
}

/* "the spring potential has the wrong sign; the gravity potential is missing" */
static void say_slips(const double *coef, const int *present, char *buf, size_t len)
{
    size_t used = 0;
    buf[0] = 0;
    for (int k = 0; k < NTERMS && used < len; k++) {
        if (!present[k] || coef[k] == 1)
            continue;
        const char *what = coef[k] == 0 ? "is missing" : coef[k] < 0 ? "has the wrong sign"
                                                                     : "lacks its ½";
        used += (size_t)snprintf(buf + used, len - used, "%sthe %s %s", used ? "; " : "",
                                 term_name(k), what);
    }
}

static void say_energy(const int *present, char *buf, size_t len)
{
    size_t used = (size_t)snprintf(buf, len, "energy =");
    for (int k = 0; k < NTERMS && used < len; k++)
        if (present[k])
            used += (size_t)snprintf(buf + used, len - used, "%s %s",
                                     used > 8 && term_formula(k)[0] != '-' ? " +" : "",
                                     term_formula(k));
}

int xpl_energy(const xpl_rows *tr, const xpl_rows *ref, const sw_run_desc *d,
               const sw_check_tol *tol, sw_explanation *out)
{
    int ncols = tr->ncols, ecol = ncols - 1;
    double worst;
    if (!d->scene->energy || ignored(tol, ecol) || tr->n > ref->n ||
        !xpl_rows_match(tr, ref, tr->n, tol, ecol, 1.0, &worst))
        return 0;
    sw_system sys;
    char err[SW_ERRLEN];
    if (sw_system_build(&sys, d->scene, d->p, err, sizeof err) != SW_OK)
        return 0;
    int found = 0, present[NTERMS] = { 1 }, first_bad = -1;
    double *terms = malloc((size_t)tr->n * NTERMS * sizeof *terms);
    double *y = malloc((size_t)sys.ode->dim * sizeof *y);
    if (sys.kind != SW_SYS_PARTICLES || !terms || !y)
        goto done;
    /* A term is there when it is non-zero in some examined row: a slip in
     * a term that is 0 throughout cannot be told apart. */
    for (int i = 0; i < tr->n; i++) {
        state_of_row(&sys, xpl_row(tr, i), y);
        energy_terms(&sys.particles, y, terms + (size_t)i * NTERMS);
        for (int k = 0; k < NTERMS; k++)
            present[k] |= terms[(size_t)i * NTERMS + k] != 0;
        double ae, re, ratio;
        if (first_bad < 0 && !sw_check_value(xpl_row(ref, i)[ecol], xpl_row(tr, i)[ecol],
                                             col_rtol(tol, ecol), col_atol(tol, ecol), &ae, &re, &ratio))
            first_bad = i;
    }
    if (first_bad < 0)
        goto done;
    char formula[160], fix[200], energy[120];
    say_energy(present, energy, sizeof energy);
    /* Every slip of every present term, fewest slips first. */
    int nslip = (int)(sizeof slips / sizeof slips[0]), combos = 1;
    for (int k = 0; k < NTERMS; k++)
        combos *= present[k] ? nslip : 1;
    for (int want = 1; want <= NTERMS && !found; want++)
        for (int c = 1; c < combos && !found; c++) {
            double coef[NTERMS];
            int code = c, changed = 0, kept = 0, ok = 1;
            for (int k = 0; k < NTERMS; k++) {
                int s = present[k] ? code % nslip : 0;
                code /= present[k] ? nslip : 1;
                coef[k] = present[k] ? slips[s] : 0;
                changed += present[k] && s != 0;
                kept += coef[k] != 0;
                ok &= !(coef[k] == 2 && !has_half(k));
            }
            if (changed != want || !kept || !ok ||
                !formula_matches(terms, tr, ecol, coef, tol, &worst))
                continue;
            char how[40];
            xpl_agree(how, sizeof how, worst);
            say_formula(coef, present, formula, sizeof formula);
            say_slips(coef, present, fix, sizeof fix);
            snprintf(out->kind, sizeof out->kind, "energy-formula");
            if (snprintf(out->message, sizeof out->message, "your positions and velocities match, but "
                         "your energy column is %s (recomputed from your own x and v, it matches %s): "
                         "%s; %s (docs/scenes.md, 'The two kinds of system')", formula, how, fix,
                         energy) < 0)
                out->message[0] = '\0'; /* a long one is cut: its start names the slip */
            out->agreement = worst;
            found = 1;
        }
    if (!found) {
        char yours[40], theirs[40];
        sw_fmt_shortest(yours, sizeof yours, xpl_row(tr, first_bad)[ecol]);
        sw_fmt_shortest(theirs, sizeof theirs, xpl_row(ref, first_bad)[ecol]);
        snprintf(out->kind, sizeof out->kind, "energy");
        snprintf(out->message, sizeof out->message, "your positions and velocities match, but "
                 "your energy column does not (step %.0f: yours %s, the assignment's %s), and no "
                 "flipped sign, missing term or missing ½ explains it: %s "
                 "(docs/scenes.md, 'The two kinds of system')", xpl_row(tr, first_bad)[0], yours,
                 theirs, energy);
        found = 1;
    }
done:
    free(terms);
    free(y);
    sw_system_free(&sys);
    return found;
}
