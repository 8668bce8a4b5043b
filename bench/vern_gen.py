# Verner's "most efficient" 8(7) pair for src/engine/vern8.c, from
# jacobwilliams/rklib's src/rklib_variable_steps.f90 (its rkv87e: Verner's
# digits, 40 of them): checks the row sums and every order condition at 50
# digits, then writes src/engine/vern8_tableau.h (the numbers) and
# src/engine/vern8_body.h (the stage loops).
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
# place of a_m.  Usage: python3 bench/vern_gen.py rklib_variable_steps.f90
import re, sys, itertools
from mpmath import mp, mpf
mp.dps = 50
src = open(sys.argv[1]).read()
S = 13
GROUPS = ((3, 6), (4, 5), (7, 8, 9, 10), (11, 12))  # 0-based stages

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

A, c, b, bh = tableau('rkv87e', S)
e = [b[i] - bh[i] for i in range(S)]
print('rkv87e: row sums |c_i - sum_j a_ij| max', mp.nstr(max(abs(c[i] - sum(A[i])) for i in range(S)), 3))
one = lambda t: mpf(1) / gamma(t)
zero = lambda t: mpf(0)
print('  exact b, orders 1-9:', ' '.join(mp.nstr(r, 2) for r in residuals(A, b, one, 9)))
print('  exact bhat, orders 1-8:', ' '.join(mp.nstr(r, 2) for r in residuals(A, bh, one, 8)))
dA = [[mpf(float(x)) for x in row] for row in A]
print('  each rounded, b:', ' '.join(mp.nstr(r, 2) for r in residuals(dA, [mpf(float(x)) for x in b], one, 8)))
print('  each rounded, e:', ' '.join(mp.nstr(r, 2) for r in residuals(dA, [mpf(float(x)) for x in e], zero, 7)))
gA = [effective(row) for row in A]
print('  grouped, b:', ' '.join(mp.nstr(r, 2) for r in residuals(gA, effective(b), one, 8)))
print('  grouped, e:', ' '.join(mp.nstr(r, 2) for r in residuals(gA, effective(e), zero, 7)))

def lit(x): return mp.nstr(x, 25, strip_zeros=False) if x != 0 else '0'

def row_c(name, w):
    st, _ = grouped(w)
    return f'{{ ' + ', '.join(f'[{j}] = {lit(st[j])}' for j in range(S) if w[j] != 0) + ' }'

with open('src/engine/vern8_tableau.h', 'w') as out:
    out.write('''/* Generated by bench/vern_gen.py: do not edit. Private to the engine: the
 * tableau of Verner's "most efficient" 8(7) pair, RKV87.IIa (J. H. Verner,
 * Jim Verner's Refuge for Runge-Kutta Pairs, https://www.sfu.ca/~jverner/:
 * RKV87.IIa.Efficient.000000282866.081208), his 40 digits as
 * jacobwilliams/rklib transcribes them (rkv87e), checked at 50 digits
 * (every order condition of b to 8 and of b - e to 7), written here to 25.
 * C: the nodes; A: the matrix; B: the 8th-order weights; E: b minus the
 * embedded 7th-order weights. In each of A's rows, in B and in E, the
 * entries on stages {4, 7}, {5, 6}, {8, 9, 10, 11} and {12, 13} (nodes
 * close together) form a group: the group's largest entry m is stored as
 * the group's sum S, and vern8.c forms S k_m + sum a_j (k_j - k_m) (see
 * the script). Indices from 0. */
#ifndef SW_ENGINE_VERN8_TABLEAU_H
#define SW_ENGINE_VERN8_TABLEAU_H

''')
    out.write('static const double V8_C[13] = { ' + ', '.join(lit(x) for x in c) + ' };\n')
    out.write('static const double V8_A[13][13] = {\n')
    for i in range(1, S):
        out.write(f'    [{i}] = {row_c("", A[i])},\n')
    out.write('};\n')
    out.write('static const double V8_B[13] = ' + row_c('', b) + ';\n')
    out.write('static const double V8_E[13] = ' + row_c('', e) + ';\n')
    out.write('/* The groups: entry j of a row is summed as a_j (k_j - k_m), m = the\n'
              ' * row\'s M[j], where M[j] != j; as S k_j where M[j] = j (vern8_body.h writes\n'
              ' * the same sums out; the lecture form reads these). */\n')
    def marks(w):
        _, bases = grouped(w)
        base_of = {j: m for m, idx in bases.values() for j in idx}
        return '{ ' + ', '.join(str(base_of.get(j, j)) for j in range(S)) + ' }'
    out.write('static const unsigned char V8_A_M[13][13] = {\n')
    for i in range(1, S):
        out.write(f'    [{i}] = {marks(A[i])},\n')
    out.write('};\n')
    out.write('static const unsigned char V8_B_M[13] = ' + marks(b) + ';\n')
    out.write('static const unsigned char V8_E_M[13] = ' + marks(e) + ';\n\n#endif\n')

def combo(tag, w, k):
    """C text of sum_j w_j k_j, grouped: the stored table's entries."""
    _, bases = grouped(w)
    base_of = {j: m for m, idx in bases.values() for j in idx}
    terms = []
    for j in range(S):
        if w[j] == 0:
            continue
        m = base_of.get(j, j)
        if j == m:
            terms.append(f'{tag}[{j}] * {k(j)}')
        else:
            terms.append(f'{tag}[{j}] * ({k(j)} - {k(m)})')
    return ' + '.join(terms)

kk = lambda j: f'k{j + 1}[i]'
out = ['/* Generated by bench/vern_gen.py: do not edit. The stages of vern8.c, each',
       ' * row\'s sum as vern8_tableau.h groups it. */']
for i in range(1, S):
    out.append(f'    for (i = 0; i < n; i++)')
    out.append(f'        yt[i] = y[i] + h * ({combo(f"V8_A[{i}]", A[i], kk)});')
    out.append(f'    sw_eval_with(&f, t + V8_C[{i}] * h, n, yt, k{i + 1});')
out.append('#define V8_BK (' + combo('V8_B', b, kk) + ')')
out.append('#define V8_EK (' + combo('V8_E', e, kk) + ')')
with open('src/engine/vern8_body.h', 'w') as f:
    f.write('\n'.join(out) + '\n')
