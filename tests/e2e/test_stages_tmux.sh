#!/bin/sh
# The stage view (issue 25) on the screen a student sees at 80x24: k draws
# one step stage by stage; at the last stage RK4's picture holds its four
# numbered stage points and midpoint's two; lesson 6's page "Inside one
# step" opens on it. Each waits for the screen, never for time.
. "$(dirname "$0")/lib.sh"
tmux_start 80 24

# The stage points on the picture: lone digits (between blanks, line
# glyphs, the dotted line or the true path ') in the first $1 columns of the rows between
# the title and the status block (which starts with "o vortex").
points() {
    screen | awk -v w="$1" 'NR == 1 { next } /^o vortex  / { exit } {
        s = " " substr($0, 1, w) " "
        for (i = 2; i < length(s); i++) {
            c = substr(s, i, 1)
            if (c ~ /[1-9]/ && index(" -.\\/|\047", substr(s, i - 1, 1)) && index(" -.\\/|\047", substr(s, i + 1, 1))) seen[c] = 1
        }
    } END { n = 0; for (c in seen) n++; print n }'
}

# 1. play: rk4 at dt = 1 on one particle, then midpoint
type_cmd "$STEPWISE play vortex --set n=1 -i rk4 --dt 1"
wait_for 'vortex +rk4 +dt=1 ' || fail "play vortex did not start"
keys k
wait_for '\[1 of 5: k next, Esc closes\]' || fail "k did not open the stage view at k1"
screen | grep -q 'PAUSED' || fail "the run is not paused under the stage view"
screen | grep -q '> k1 = f(t, y)' || fail "k1's formula line is not lit"
keys k k k
wait_for '\[4 of 5: k next' || fail "three more k did not reach k4"
screen | grep -q '> k4 = f(t + h, y + h\*k3)' || fail "k4's formula line is not lit"
keys k
wait_for '\[5 of 5: k closes' || fail "k did not draw the step itself"
n=$(points 48)
echo "rk4: $n stage points drawn"
[ "$n" -eq 4 ] || fail "rk4's stage view draws $n stage points, not 4"
keys Escape
wait_for 'stage view closed' || fail "Esc did not close the stage view"
keys 3
wait_for 'vortex +midpoint +dt=1 ' || fail "3 did not pick midpoint"
keys k k k
wait_for '\[3 of 3: k closes' || fail "midpoint's stage view did not reach its last stage"
n=$(points 48)
echo "midpoint: $n stage points drawn"
[ "$n" -eq 2 ] || fail "midpoint's stage view draws $n stage points, not 2"
keys k
wait_for 'stage view closed' || fail "k after the last stage did not close the view"
keys 7
wait_for 'vortex +implicit-euler' || fail "7 did not pick implicit-euler"
keys k
wait_for 'stages: not drawn for implicit-euler' || fail "implicit-euler's stages did not say why not"
keys q
wait_for 'PROMPT\$ *$' || fail "q did not quit"

# 2. lesson 6's page, resumed there (six pages done)
mkdir -p "$WORK/state/stepwise"
printf '06-runge-kutta.lesson 6\n' > "$WORK/state/stepwise/progress"
type_cmd "XDG_STATE_HOME=$WORK/state STEPWISE_LESSONS=$ROOT/lessons $STEPWISE lesson 6"
wait_for 'Inside one step' || fail "lesson 6 did not open on 'Inside one step'"
keys k k k k k
wait_for '\[5 of 5: k closes' || fail "the page's stage view did not reach the step"
n=$(points 39)
echo "lesson 6, rk4: $n stage points drawn"
[ "$n" -eq 4 ] || fail "the page's rk4 stage view draws $n stage points, not 4"
read_down_to 'Where does RK4 take its last slope' || fail "the page's question is hidden"
keys q
wait_for 'PROMPT\$ *$' || fail "q did not quit the lesson"
echo "ok: the stage view at 80x24"
