# Verner's "most efficient" 8(7) and 9(8) pairs for src/engine/vern.c, from
# jacobwilliams/rklib's src/rklib_variable_steps.f90 (its rkv87e and
# rkv98e: Verner's digits, 40 of them): checks the row sums and every order
# condition at 50 digits, then writes src/engine/vern_tableau.h (the
# numbers) and src/engine/vern_body.h (each pair's trial step, its stages
# written out as dop853.c writes its own).
#
# Why groups: the pair's matrix reaches 123 and its weights 31.7, in
# entries of opposite signs on stages whose nodes nearly coincide (stages
# 4 and 7: 0.160 and 0.155; 5 and 6; 8 to 11: 0.90 to 0.94). Each
# coefficient rounded to double alone leaves the order conditions 1e-13
# from true (an adaptive run at rtol 1e-13 then stalls: its error stuck
# near 1e-9, its evaluations 19 times dop853's). Within a group G of one
# row (or of b or e) the sum is written as
#     S k_m + sum_{j in G, j != m} a_j (k_j - k_m),   S = sum_{j in G} a_j,
# m the entry of largest size, S rounded from its exact value: the large
# entries' rounding then meets only the small differences k_j - k_m, and
# the conditions hold to 5e-15 (printed below). The table stores S in
# place of a_m. The 9(8) pair's coefficients reach 35.9 but rounded one by
# one leave its conditions within 1.3e-16: no groups.  Usage: python3 bench/vern_gen.py rklib_variable_steps.f90
import re, sys, itertools
from mpmath import mp, mpf
mp.dps = 50
src = open(sys.argv[1]).read()
S, GROUPS = 13, ()  # the pair at hand: stages, groups (0-based stages)

def parse(name):
    body = src[src.index('module procedure ' + name):src.index('end procedure ' + name)]
    return {m.group(1): m.group(2) for m in
            re.finditer(r'parameter\s*::\s*(\w+)\s*=\s*([-+]?[\d.]+(?:e[-+]?\d+)?)_wp', body)}

def tableau(name, s):
    A = [[mpf(0)] * s for _ in range(s)]
    c, b, bh = [mpf(0)] * s, [mpf(0)] * s, [mpf(0)] * s
    for k, x in parse(name).items():
        if k[0] == 'a':
            c[int(k[1:]) - 1] = mpf(x)
        elif k[0] == 'b':
            d = k[1:]
            i, j = (int(d[0]), int(d[1])) if len(d) == 2 else (int(d[:2]), int(d[2])) if len(d) == 3 \
                else (int(d[:2]), int(d[2:]))
            A[i - 1][j - 1] = mpf(x)
        elif k[0] == 'c':
            b[int(k[1:]) - 1] = mpf(x)
        elif k[0] == 'd':
            bh[int(k[1:]) - 1] = mpf(x)
    for i in range(1, s):  # the last nodes are written t + h in the source
        if c[i] == 0:
            c[i] = mpf(1)
    return A, c, b, bh

def trees(n):
    if n == 1:
        return [()]
    out = set()
    def parts(n, maxp):
        if n == 0:
            yield []
            return
        for p in range(min(n, maxp), 0, -1):
            for rest in parts(n - p, p):
                yield [p] + rest
    for part in parts(n - 1, n - 1):
        for combo in itertools.product(*[trees(p) for p in part]):
            out.add(tuple(sorted(combo)))
    return sorted(out)

def order(t): return 1 + sum(order(u) for u in t)
def gamma(t):
    g = order(t)
    for u in t:
        g *= gamma(u)
    return g

def residuals(A, w, target, nmax):
    memo = {}
    def phi(t):
        if t not in memo:
            v = [mpf(1)] * S
            for u in t:
                pu = phi(u)
                v = [v[i] * sum(A[i][j] * pu[j] for j in range(S)) for i in range(S)]
            memo[t] = v
        return memo[t]
    return [max(abs(sum(w[i] * x for i, x in enumerate(phi(t))) - target(t)) for t in trees(n))
            for n in range(1, nmax + 1)]

def grouped(w):
    """w's entries with each group's largest replaced by the group's sum:
    (stored values, bases {group: m})."""
    st, bases = list(w), {}
    for g in GROUPS:
        idx = [j for j in g if w[j] != 0]
        if len(idx) > 1:
            m = max(idx, key=lambda j: abs(w[j]))
            st[m] = sum(w[j] for j in idx)
            bases[g] = (m, idx)
    return st, bases

def effective(w):
    """The weights a double run applies: each stored value rounded, a
    group's base the rounded sum less the others' rounded entries."""
    st, bases = grouped(w)
    eff = [mpf(float(x)) for x in st]
    for m, idx in bases.values():
        eff[m] = mpf(float(st[m])) - sum(mpf(float(w[j])) for j in idx if j != m)
    return eff

one = lambda t: mpf(1) / gamma(t)
zero = lambda t: mpf(0)

def lit(x): return mp.nstr(x, 25, strip_zeros=False) if x != 0 else '0'

def row_c(w):
    st, _ = grouped(w)
    return '{ ' + ', '.join(f'[{j}] = {lit(st[j])}' for j in range(S) if w[j] != 0) + ' }'

def marks(w):
    _, bases = grouped(w)
    base_of = {j: m for m, idx in bases.values() for j in idx}
    return '{ ' + ', '.join(str(base_of.get(j, j)) for j in range(S)) + ' }'

def combo(tag, w):
    """C text of sum_j w_j k_j, grouped: the stored table's entries."""
    _, bases = grouped(w)
    base_of = {j: m for m, idx in bases.values() for j in idx}
    terms = []
    for j in range(S):
        if w[j] == 0:
            continue
        m = base_of.get(j, j)
        terms.append(f'{tag}[{j}] * k{j + 1}[i]' if j == m else f'{tag}[{j}] * (k{j + 1}[i] - k{m + 1}[i])')
    return ' + '.join(terms)

def pair(name, T, s, p, q, groups, tab, body):
    global S, GROUPS
    S, GROUPS = s, groups
    A, c, b, bh = tableau(name, S)
    e = [b[i] - bh[i] for i in range(S)]
    print(f'{name}: row sums |c_i - sum_j a_ij| max', mp.nstr(max(abs(c[i] - sum(A[i])) for i in range(S)), 3))
    print(f'  exact b, orders 1-{p + 1}:', ' '.join(mp.nstr(r, 2) for r in residuals(A, b, one, p + 1)))
    print(f'  exact bhat, orders 1-{q + 1}:', ' '.join(mp.nstr(r, 2) for r in residuals(A, bh, one, q + 1)))
    dA = [[mpf(float(x)) for x in row] for row in A]
    print('  each rounded, b:', ' '.join(mp.nstr(r, 2) for r in residuals(dA, [mpf(float(x)) for x in b], one, p)))
    print('  each rounded, e:', ' '.join(mp.nstr(r, 2) for r in residuals(dA, [mpf(float(x)) for x in e], zero, q)))
    if GROUPS:
        gA = [effective(row) for row in A]
        print('  grouped, b:', ' '.join(mp.nstr(r, 2) for r in residuals(gA, effective(b), one, p)))
        print('  grouped, e:', ' '.join(mp.nstr(r, 2) for r in residuals(gA, effective(e), zero, q)))
    tab.write(f'/* {name}: {S} stages, order {p}, embedded order {q} */\n')
    tab.write(f'static const double {T}_C[{S}] = {{ ' + ', '.join(lit(x) for x in c) + ' };\n')
    tab.write(f'static const double {T}_A[{S}][{S}] = {{\n')
    for i in range(1, S):
        tab.write(f'    [{i}] = {row_c(A[i])},\n')
    tab.write('};\n')
    tab.write(f'static const double {T}_B[{S}] = ' + row_c(b) + ';\n')
    tab.write(f'static const double {T}_E[{S}] = ' + row_c(e) + ';\n')
    tab.write(f'static const unsigned char {T}_A_M[{S}][{S}] = {{\n')
    for i in range(1, S):
        tab.write(f'    [{i}] = {marks(A[i])},\n')
    tab.write('};\n')
    tab.write(f'static const unsigned char {T}_B_M[{S}] = ' + marks(b) + ';\n')
    tab.write(f'static const unsigned char {T}_E_M[{S}] = ' + marks(e) + ';\n')
    lo = T.lower()
    w = body.append
    w(f'/* {name}: k1 = f(t, y); y becomes the new state (the old one in saved), kn')
    w(' * its derivative, the error terms\' squares go into yt, their sum into sums. */')
    w(f'SW_CLONES static void {lo}_range(sw_ode *ode, double t, double *restrict y, double h, int n, unsigned elim,')
    w('                                double atol, double rtol, const double *restrict k1, '
      + ', '.join(f'double *restrict k{j}' for j in range(2, S + 1)) + ',')
    w('                                double *restrict kn, double *restrict yt, double *restrict saved, sw_trial_sums *sums)')
    w('{')
    w('    sw_evaluator f = sw_evaluator_of(ode);')
    w('    int i;')
    for i in range(1, S):
        w('    for (i = 0; i < n; i++)')
        w(f'        yt[i] = y[i] + h * ({combo(f"{T}_A[{i}]", A[i])});')
        w(f'    sw_eval_with(&f, t + {T}_C[{i}] * h, n, yt, k{i + 1});')
    w('    unsigned long long over = 0, add = sw_beyond_add(elim);')
    w('    for (i = 0; i < n; i++) {')
    w(f'        double y0 = y[i], y1 = y0 + h * ({combo(f"{T}_B", b)});')
    w('        double a0 = fabs(y0), a1 = fabs(y1);')
    w(f'        double e = h * ({combo(f"{T}_E", e)}) / (atol + rtol * (a1 > a0 ? a1 : a0));')
    w('        saved[i] = y0;')
    w('        y[i] = y1;')
    w('        over |= sw_beyond_bits(y1, add);')
    w('        yt[i] = e * e;')
    w('    }')
    w('    sums->err = sw_add_by4(sums->part[0], yt, n);')
    w('    sums->beyond |= sw_beyond_any(over);')
    w('    sw_eval_with(&f, t + h, n, y, kn);')
    w('}')
    w(f'#define {T}_KS(k) ' + ', '.join(f'k[{j}]' for j in range(S + 1)))

with open('src/engine/vern_tableau.h', 'w') as tab:
    tab.write('''/* Generated by bench/vern_gen.py: do not edit. Private to the engine: the
 * tableaus of Verner's "most efficient" pairs (J. H. Verner, Jim Verner's
 * Refuge for Runge-Kutta Pairs, https://www.sfu.ca/~jverner/):
 * RKV87.IIa.Efficient.000000282866.081208 (V8) and
 * RKV98.IIa.Efficient.000000349.081209 (V9), his 40 digits as
 * jacobwilliams/rklib transcribes them (rkv87e, rkv98e), checked at 50
 * digits (every order condition of b to its order and of the embedded
 * weights to theirs), written here to 25. C: the nodes; A: the matrix; B:
 * the higher order's weights; E: B minus the embedded order's. Indices
 * from 0. Groups (V8 only): in each of A's rows, in B and in E, the
 * entries on stages whose nodes nearly coincide form a group whose
 * largest entry m is stored as the group's sum S; the sum is formed as
 * S k_m + sum_j a_j (k_j - k_m), j the group's others, whose M[j] = m (M[j]
 * = j elsewhere): see the script. */
#ifndef SW_ENGINE_VERN_TABLEAU_H
#define SW_ENGINE_VERN_TABLEAU_H

''')
    body = ['/* Generated by bench/vern_gen.py: do not edit. The trial steps of vern.c,',
            ' * each sum as vern_tableau.h groups it. */']
    pair('rkv87e', 'V8', 13, 8, 7, ((3, 6), (4, 5), (7, 8, 9, 10), (11, 12)), tab, body)
    pair('rkv98e', 'V9', 16, 9, 8, (), tab, body)
    tab.write('\n#endif\n')
with open('src/engine/vern_body.h', 'w') as f:
    f.write('\n'.join(body) + '\n')
