#!/bin/sh
# Each part of a plugin homework runs in a host of its own (red team 3,
# F2): what a plugin keeps in static memory in one part never reaches the
# next. A plugin that remembered a hidden part's system (its dimension
# and dt) wrote it into the next part's state, and the visible part's
# feedback ("column x0: expected ..., got 8010") showed it. This one is
# an honest RK4 while it sees one system only; once it has stepped one
# system and then meets another (another dimension), it writes what it
# remembers into y. Graded with a hidden gyre first and a visible chain
# after, it must pass both parts, and no feedback may show the code.
. "$(dirname "$0")/lib.sh"
needs_jail
cheat="$ROOT/tests/data/cheat"
mkdir class
{
    cat "$cheat/common.h"
    cat <<'C'
static int first_dim;
static double first_h;
static int carry(sw_ode *ode, double t, double *y, double h, double *work)
{
    if (!first_dim) {
        first_dim = ode->dim;
        first_h = h;
    }
    int rc = rk4(ode, t, y, h, work);
    if (ode->dim != first_dim)
        y[0] = 1000.0 * first_dim + 100.0 * first_h + 0.25; /* the earlier system, told */
    return rc;
}
CHEATER("carry", carry)
C
} > class/carry.c
cat > hw.txt <<'A'
# stepwise assignment 1
# kind: plugin
# integrator: rk4
# steps: 50
# points x* y*: 2
# part gyre
# scene: gyre
# param n: 4
# dt: 0.1
# visibility: hidden
# part chain
# scene: chain
# param n: 3
# dt: 0.01
A
"$SW" grade --assignment hw.txt --csv g.csv --feedback fb class > g.out 2>&1; rc=$?
[ $rc -eq 0 ] || fail "grade exited $rc: $(cat g.out g.csv fb/carry.txt)"
score=$(grep '^carry,class/carry.c,' g.csv | awk -F, '{ print $(NF-2) "/" $(NF-1) }')
[ "$score" = 4/4 ] || fail "a part saw the one before it: $score $(cat g.csv fb/carry.txt)"
grep -q '8010' fb/carry.txt g.csv && fail "the hidden part's dimension and dt reached the feedback: $(cat fb/carry.txt)"
exit 0
