/* Private to the engine: the RODAS4 tableau, for rosenbrock.c and for the
 * test of its order conditions and stability function. */
#ifndef SW_ENGINE_RODAS_TABLEAU_H
#define SW_ENGINE_RODAS_TABLEAU_H

/* RODAS4 (E. Hairer & G. Wanner, Solving Ordinary Differential Equations II,
 * 2nd ed., Springer 1996, Sections IV.7 and VI.4; the coefficient set
 * METH = 1 of subroutine ROCOE in Hairer's rodas.f, 16 digits), in Hairer's transformed
 * variables: with γ the diagonal, stage i solves
 *     (I/(γh) - J) k_i = f(t + α_i h, y0 + Σ_j a_ij k_j) + Σ_j (c_ij/h) k_j + d_i h ∂f/∂t,
 * y1 = y0 + Σ m_i k_i, and the embedded order-3 solution is y1 - k_6 (so the
 * error estimate is k_6). Stiffly accurate: a_6j = m_j (j < 6), so y1 is the
 * last stage's point plus its k; L-stable. tests/check_rosenbrock.c maps the
 * coefficients back to the standard form (α_ij, γ_ij) and checks the order
 * conditions of order 4 for y1 and 3 for y1 - k_6, α_i and d_i as row sums,
 * and the stability function. Zero entries are written out: a row i uses
 * j < i only. */
#define SW_RODAS_STAGES 6
static const double SW_RODAS_GAMMA = 0.25;
static const double SW_RODAS_ALPHA[SW_RODAS_STAGES] = { 0.0, 0.386, 0.21, 0.63, 1.0, 1.0 };
static const double SW_RODAS_D[SW_RODAS_STAGES] = { 0.25, -0.1043, 0.1035, -0.3620000000000023e-01, 0.0, 0.0 };
static const double SW_RODAS_A[SW_RODAS_STAGES][SW_RODAS_STAGES] = {
    { 0 },
    { 0.1544000000000000e+01 },
    { 0.9466785280815826e+00, 0.2557011698983284e+00 },
    { 0.3314825187068521e+01, 0.2896124015972201e+01, 0.9986419139977817e+00 },
    { 0.1221224509226641e+01, 0.6019134481288629e+01, 0.1253708332932087e+02, -0.6878860361058950e+00 },
    { 0.1221224509226641e+01, 0.6019134481288629e+01, 0.1253708332932087e+02, -0.6878860361058950e+00, 1.0 },
};
static const double SW_RODAS_C[SW_RODAS_STAGES][SW_RODAS_STAGES] = {
    { 0 },
    { -0.5668800000000000e+01 },
    { -0.2430093356833875e+01, -0.2063599157091915e+00 },
    { -0.1073529058151375e+00, -0.9594562251023355e+01, -0.2047028614809616e+02 },
    { 0.7496443313967647e+01, -0.1024680431464352e+02, -0.3399990352819905e+02, 0.1170890893206160e+02 },
    { 0.8083246795921522e+01, -0.7981132988064893e+01, -0.3152159432874371e+02, 0.1631930543123136e+02,
      -0.6058818238834054e+01 },
};
/* y1 = y0 + Σ m_i k_i: the last row of A with 1 for the last stage. */
static const double SW_RODAS_M[SW_RODAS_STAGES] = {
    0.1221224509226641e+01, 0.6019134481288629e+01, 0.1253708332932087e+02, -0.6878860361058950e+00, 1.0, 1.0,
};

#endif
