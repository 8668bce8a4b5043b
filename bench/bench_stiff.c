/* Stiff problems: stepwise's rodas4 against SUNDIALS CVODE's BDF at equal
 * accuracy (issue 27). The same problems (stiff-spring at k = 1e6, a
 * damped chain of k = 1e6 springs, built by the scene catalog) and the same
 * derivative (CVODE calls the system's own sw_ode, through a permutation to
 * one particle's x, y, vx, vy side by side, so its Jacobian is banded);
 * CVODE with its dense (stiff-spring) or band (chain) direct solver and its
 * difference-quotient Jacobian. For each error target, each method's
 * loosest rtol = atol reaching it, then paired, interleaved timed runs.
 * CVODE is used only here, when `make bench` found its headers. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "bench_common.h"
#include "stepwise/sim.h"

#ifdef SW_HAVE_CVODE
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_version.h>
#include <sunlinsol/sunlinsol_band.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_band.h>
#include <sunmatrix/sunmatrix_dense.h>
#endif

typedef struct stiff_problem {
    const char *label;
    const sw_scene *sc;
    double p[SW_MAX_PARAMS];
    double T;
    int dim;
    double *ref, *y, *ya, *fa; /* ya, fa: the derivative's [x | v] layout, for CVODE */
    sw_system sys;
} stiff_problem;

/* rodas4 (or the reference method) to T at rtol = atol = tol; state into pb->y. */
static int sw_run(stiff_problem *pb, const char *method, double tol, double *seconds, long *evals)
{
    char err[SW_ERRLEN];
    sw_sim s;
    if (sw_sim_init(&s, pb->sc, pb->p, sw_integrator_find(method), pb->T, err, sizeof err) != SW_OK)
        return -1;
    sw_sim_set_tolerances(&s, tol, tol);
    double t0 = now_seconds();
    int blown = sw_sim_run_until(&s, pb->T);
    *seconds = now_seconds() - t0;
    *evals = sw_sim_evals(&s);
    memcpy(pb->y, s.sys.y, (size_t)pb->dim * sizeof *pb->y);
    sw_sim_free(&s);
    return blown ? -1 : 0;
}

#ifdef SW_HAVE_CVODE
/* CVODE's state u holds particle i's x, y, vx, vy at 4i..4i+3; the
 * system's y = [x | v]. A spring between neighbours then couples entries at
 * most 7 apart: the band. */
static void to_particles(int dim, const double *y, double *u)
{
    int h = dim / 2;
    for (int i = 0; i < h / 2; i++) {
        u[4 * i] = y[2 * i], u[4 * i + 1] = y[2 * i + 1];
        u[4 * i + 2] = y[h + 2 * i], u[4 * i + 3] = y[h + 2 * i + 1];
    }
}

static void from_particles(int dim, const double *u, double *y)
{
    int h = dim / 2;
    for (int i = 0; i < h / 2; i++) {
        y[2 * i] = u[4 * i], y[2 * i + 1] = u[4 * i + 1];
        y[h + 2 * i] = u[4 * i + 2], y[h + 2 * i + 1] = u[4 * i + 3];
    }
}

static int cv_deriv(sunrealtype t, N_Vector u, N_Vector du, void *user)
{
    stiff_problem *pb = user;
    from_particles(pb->dim, N_VGetArrayPointer(u), pb->ya);
    pb->sys.ode->deriv(pb->sys.ode->ctx, t, pb->ya, pb->fa);
    to_particles(pb->dim, pb->fa, N_VGetArrayPointer(du));
    return 0;
}

/* CVODE BDF to T at rtol = atol = tol, band solver when banded (else
 * dense); state into pb->y; evaluations: the right-hand side's and the
 * difference-quotient Jacobian's. Setup is outside the timed part. */
static int cv_run(stiff_problem *pb, int banded, double tol, double *seconds, long *evals)
{
    SUNContext ctx;
    if (SUNContext_Create(NULL, &ctx) != 0)
        return -1;
    N_Vector u = N_VNew_Serial(pb->dim, ctx);
    void *mem = CVodeCreate(CV_BDF, ctx);
    SUNMatrix A = banded ? SUNBandMatrix(pb->dim, 7, 7, ctx) : SUNDenseMatrix(pb->dim, pb->dim, ctx);
    SUNLinearSolver ls = banded ? SUNLinSol_Band(u, A, ctx) : SUNLinSol_Dense(u, A, ctx);
    int rc = -1;
    if (u && mem && A && ls) {
        sw_system fresh;
        char err[SW_ERRLEN];
        if (sw_system_build(&fresh, pb->sc, pb->p, err, sizeof err) == SW_OK) {
            to_particles(pb->dim, fresh.y, N_VGetArrayPointer(u));
            sw_system_free(&fresh);
            rc = 0;
        }
        if (rc == 0 && (CVodeInit(mem, cv_deriv, 0.0, u) != CV_SUCCESS ||
                        CVodeSStolerances(mem, tol, tol) != CV_SUCCESS || CVodeSetUserData(mem, pb) != CV_SUCCESS ||
                        CVodeSetLinearSolver(mem, ls, A) != CV_SUCCESS ||
                        CVodeSetMaxNumSteps(mem, 10000000) != CV_SUCCESS ||
                        CVodeSetStopTime(mem, pb->T) != CV_SUCCESS))
            rc = -1;
    }
    if (rc == 0) {
        sunrealtype t = 0;
        double t0 = now_seconds();
        rc = CVode(mem, pb->T, u, &t, CV_NORMAL) < 0 ? -1 : 0;
        *seconds = now_seconds() - t0;
        long nfe = 0, nfe_ls = 0;
        CVodeGetNumRhsEvals(mem, &nfe);
        CVodeGetNumLinRhsEvals(mem, &nfe_ls);
        *evals = nfe + nfe_ls;
        from_particles(pb->dim, N_VGetArrayPointer(u), pb->y);
    }
    SUNLinSolFree(ls);
    SUNMatDestroy(A);
    CVodeFree(&mem);
    N_VDestroy(u);
    SUNContext_Free(&ctx);
    return rc;
}
#endif

/* One run by library: 0 stepwise's rodas4, 1 CVODE. */
static int run(stiff_problem *pb, int lib, double tol, double *error, double *seconds, long *evals)
{
    int rc = -1;
    if (lib == 0)
        rc = sw_run(pb, "rodas4", tol, seconds, evals);
#ifdef SW_HAVE_CVODE
    else
        rc = cv_run(pb, pb->dim > 8, tol, seconds, evals);
#endif
    *error = rc == 0 ? bench_max_diff(pb->dim, pb->y, pb->ref) : INFINITY;
    return rc;
}

/* The loosest tolerance reaching target: from 100·target down by quarter
 * decades, then bisected in log tol to 1/32 decade (as bench_peer.c). */
static double search(stiff_problem *pb, int lib, double target)
{
    double e, sec;
    long ev;
    int k;
    for (k = 0; k <= 40; k++) {
        double tol = 100.0 * target * pow(10.0, -0.25 * k);
        if (tol < 1e-13)
            return NAN;
        if (run(pb, lib, tol, &e, &sec, &ev) == 0 && e <= target)
            break;
    }
    if (k > 40)
        return NAN;
    double hit = 100.0 * target * pow(10.0, -0.25 * k), miss = hit * pow(10.0, 0.25);
    for (int b = 0; k > 0 && b < 3; b++) {
        double mid = sqrt(hit * miss);
        if (run(pb, lib, mid, &e, &sec, &ev) == 0 && e <= target)
            hit = mid;
        else
            miss = mid;
    }
    return hit;
}

static void problem_free(stiff_problem *pb)
{
    free(pb->ref), free(pb->y), free(pb->ya), free(pb->fa);
    if (pb->sys.ode)
        sw_system_free(&pb->sys);
    memset(pb, 0, sizeof *pb);
}

/* Build scene with its assignments (NUL-separated); the reference is dop853
 * at rtol = atol = 1e-13, and CVODE at 1e-12 bounds its error. */
static int problem_init(stiff_problem *pb, const char *label, const char *scene, const char *set, double T)
{
    char err[SW_ERRLEN];
    memset(pb, 0, sizeof *pb);
    pb->label = label;
    pb->sc = sw_scene_find(scene);
    sw_scene_defaults(pb->sc, pb->p);
    for (const char *a = set; *a; a += strlen(a) + 1)
        if (sw_scene_set(pb->sc, pb->p, a, err, sizeof err) != SW_OK)
            return -1;
    if (sw_system_build(&pb->sys, pb->sc, pb->p, err, sizeof err) != SW_OK)
        return -1;
    pb->T = T;
    pb->dim = pb->sys.ode->dim;
    size_t bytes = (size_t)pb->dim * sizeof(double);
    pb->ref = malloc(bytes), pb->y = malloc(bytes), pb->ya = malloc(bytes), pb->fa = malloc(bytes);
    if (!pb->ref || !pb->y || !pb->ya || !pb->fa)
        return -1;
    double sec;
    long ev;
    if (sw_run(pb, "dop853", 1e-13, &sec, &ev) != 0)
        return -1;
    memcpy(pb->ref, pb->y, bytes);
    double check = NAN;
#ifdef SW_HAVE_CVODE
    run(pb, 1, 1e-12, &check, &sec, &ev);
#endif
    printf("  %s, T = %g, state %d: reference dop853 at 1e-13; CVODE at 1e-12 lies %.1e from it\n", label, T, pb->dim,
           check);
    return 0;
}

void bench_stiff(int repeats, int quick)
{
#ifdef SW_HAVE_CVODE
    printf("stiff problems: rodas4 against SUNDIALS %s CVODE (BDF, direct solver, difference-quotient "
           "Jacobian)\n", SUNDIALS_VERSION);
#else
    printf("stiff problems: CVODE not found (`make bench` installs libsundials-dev); rodas4 alone\n");
#endif
    printf("  error = largest |y - y_ref| over the state at T; each method's loosest rtol = atol reaching\n"
           "  it (to 1/32 decade); evaluations include CVODE's Jacobian difference quotients\n");
    static const struct { const char *label, *scene, *set; double T; } probs[] = {
        { "stiff-spring k=1e6", "stiff-spring", "k=1e6\0", 2.0 },
        { "chain n=10 k=1e6 c=100 g=9.81", "chain", "n=10\0k=1e6\0c=100\0g=9.81\0", 1.0 },
        { "chain n=100 k=1e6 c=100 g=9.81", "chain", "n=100\0k=1e6\0c=100\0g=9.81\0", 1.0 },
    };
    double targets[2] = { 1e-3, 1e-6 };
    int nprob = quick ? 1 : 3;
    if (repeats < 5)
        repeats = 5;
    char summary[8][320];
    int nsummary = 0;
    for (int w = 0; w < nprob; w++) {
        stiff_problem pb;
        if (problem_init(&pb, probs[w].label, probs[w].scene, probs[w].set, probs[w].T) != 0) {
            printf("  %s: could not be built\n", probs[w].label);
            problem_free(&pb);
            continue;
        }
        for (int e = 0; e < 2; e++) {
            double tol[2] = { search(&pb, 0, targets[e]), NAN };
#ifdef SW_HAVE_CVODE
            tol[1] = search(&pb, 1, targets[e]);
#endif
            double ta[MAX_REPEATS], tb[MAX_REPEATS], ratio[MAX_REPEATS], err[2] = { NAN, NAN };
            long ev[2] = { 0, 0 };
            for (int r = 0; r < repeats; r++) {
                run(&pb, 0, tol[0], &err[0], &ta[r], &ev[0]);
                tb[r] = NAN;
#ifdef SW_HAVE_CVODE
                run(&pb, 1, tol[1], &err[1], &tb[r], &ev[1]);
#endif
                ratio[r] = ta[r] / tb[r];
            }
            double am = median(ta, repeats), bm = median(tb, repeats), rm = median(ratio, repeats);
            double rmin = ratio[0], rmax = ratio[repeats - 1]; /* sorted by median() */
            printf("  %-32s error <= %.0e: rodas4 tol %.2g error %.2e %ld evals %.3f ms | CVODE tol %.2g "
                   "error %.2e %ld evals %.3f ms\n", pb.label, targets[e], tol[0], err[0], ev[0], am * 1e3,
                   tol[1], err[1], ev[1], bm * 1e3);
            fflush(stdout);
            if (nsummary < 8)
                snprintf(summary[nsummary++], sizeof summary[0],
                         "  | %s, error %.0e | %.3g (%ld) | %.3g (%ld) | %.2f (%.2f-%.2f) | %s |\n", pb.label,
                         targets[e], am * 1e3, ev[0], bm * 1e3, ev[1], rm, rmin, rmax,
                         rm <= 1.0 ? "met" : rm == rm ? "missed" : "-");
        }
        problem_free(&pb);
    }
    printf("\n  side by side: %d paired, interleaved runs; medians, ratio (min-max)\n"
           "  | problem | rodas4 ms (evals) | CVODE BDF ms (evals) | time ratio | goal <= 1 |\n"
           "  | --- | --- | --- | --- | --- |\n", repeats);
    for (int i = 0; i < nsummary; i++)
        printf("%s", summary[i]);
    printf("\n");
}
