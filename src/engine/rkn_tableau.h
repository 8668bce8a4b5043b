/* Private to the engine: the RKN6(4)6FM tableau, for rkn.c and for the test
 * of its order conditions (tests/check_rkn.c), written once as exact
 * fractions so that the test checks the very numbers the method uses. */
#ifndef SW_ENGINE_RKN_TABLEAU_H
#define SW_ENGINE_RKN_TABLEAU_H

/* Dormand, El-Mikkawy & Prince, "Families of Runge-Kutta-Nyström
 * formulae", IMA J. Numer. Anal. 7 (1987) 235-250: RKN6(4)6FM for
 * x'' = f(t, x), 6 stages, FSAL. Transcribed from the tableau as
 * OrdinaryDiffEq.jl's DPRKN6FM gives it (src/tableaus/rkn_tableaus.jl),
 * and checked against the order conditions by tests/check_rkn.c, not
 * trusted. The stages are
 *     X_i = x0 + c_i h v0 + h² Σ_j A_ij a_j,   a_i = f(t0 + c_i h, X_i),
 * the solution x1 = x0 + h v0 + h² Σ BX_i a_i, v1 = v0 + h Σ BV_i a_i
 * (order 6), the embedded one with EX_i = BX_i - B̂X_i, EV_i = BV_i - B̂V_i
 * (order 4; its weights are zero on stage 6 in x and equal BV_6 in v).
 * Row 6 of A is BX and c_6 = 1, so X_6 = x1: a_6 is the next step's a_1.
 * X(NAME, numerator, denominator). */
#define SW_RKN_TABLEAU(X)                                                                                   \
    X(C2, 1, 10) X(C3, 3, 10) X(C4, 7, 10) X(C5, 17, 25)                                                    \
    X(A21, 1, 200)                                                                                          \
    X(A31, -1, 2200) X(A32, 1, 22)                                                                          \
    X(A41, 637, 6600) X(A42, -7, 110) X(A43, 7, 33)                                                         \
    X(A51, 225437, 1968750) X(A52, -30073, 281250) X(A53, 65569, 281250) X(A54, -9367, 984375)              \
    X(BX1, 151, 2142) X(BX2, 5, 116) X(BX3, 385, 1368) X(BX4, 55, 168) X(BX5, -6250, 28101)                 \
    X(BV1, 151, 2142) X(BV2, 25, 522) X(BV3, 275, 684) X(BV4, 275, 252) X(BV5, -78125, 112404)              \
    X(BV6, 1, 12)                                                                                           \
    X(HX1, 1349, 157500) X(HX2, 7873, 50000) X(HX3, 192199, 900000) X(HX4, 521683, 2100000)                 \
    X(HX5, -16, 125)                                                                                        \
    X(HV1, 1349, 157500) X(HV2, 7873, 45000) X(HV3, 27457, 90000) X(HV4, 521683, 630000) X(HV5, -2, 5)

#endif
