#!/bin/sh
# The picture shows what the lessons say (issue 13), checked on the screen a
# student sees: Euler's vortex grows on a fixed camera; compare restarts
# every method together, so RK4 keeps its own energy; the phase view shows
# Euler leaving the exact ellipse and Verlet staying on it; the stability
# region shows the chain's modes leaving RK4's region when the meter says
# they grow. Each prints the figures it measured.
. "$(dirname "$0")/lib.sh"
tmux_start

# The scene rows of a capture: everything above the status block (whose
# first line starts with the main run's glyph and the scene's name).
# (the row just above it is the picture's legend, "o euler  .:- crowded": left out)
scene_rows() { screen | awk -v s="$1" '$0 ~ "^o " s "  " { exit } NR > 1 { print prev } { prev = $0 }'; }

# The horizontal extent (in columns) of the characters in set $1 on stdin.
extent() {
    awk -v set="$1" '{ n = length($0); for (i = 1; i <= n; i++) if (index(set, substr($0, i, 1))) {
        if (lo == "" || i < lo) lo = i; if (i > hi) hi = i } } END { print (hi == "" ? 0 : hi - lo + 1) }'
}

# 1. Euler on the vortex, default camera: the outer ring's width on screen
#    grows over one turn (radius x1.0025^63 = 1.17 at dt = 0.05).
type_cmd "$STEPWISE play vortex -i euler --speed 4"
wait_for 'vortex +euler +dt=0\.05 ' || fail "play vortex did not start"
# the start, whenever the screen is first read: paused, then reset to t = 0
keys ' '
wait_for 'PAUSED' || fail "space did not pause the vortex"
keys r
wait_for 'vortex +euler +dt=0\.05 +t=0\.000 ' || fail "r did not reset the vortex to t = 0"
w0=$(scene_rows vortex | extent o)
# one turn in single steps (t = 126 x 0.05 = 6.3), whatever the machine's speed
keys $(i=0; while [ $i -lt 126 ]; do printf '. '; i=$((i + 1)); done)
wait_for 'vortex +euler +dt=0\.05 +t=6\.300 +steps 126 ' || fail "126 single steps did not reach t = 6.3"
w1=$(scene_rows vortex | extent o)
echo "vortex, euler, one turn: outer ring $w0 -> $w1 columns"
[ "$w0" -gt 20 ] || fail "the ring at the start is only $w0 columns wide"
[ "$w1" -ge $((w0 * 11 / 10)) ] || fail "the ring did not grow on screen over a turn: $w0 -> $w1 columns"
keys q
wait_for 'PROMPT\$ *$' || fail "q did not quit"

# 2. Compare on the orbit after 30 Euler steps: every method restarts at
#    t = 0, so RK4's energy drift is its own (under 0.1 %).
type_cmd "$STEPWISE play orbit -i euler"
wait_for 'orbit +euler' || fail "play orbit did not start"
keys ' '
wait_for 'PAUSED' || fail "space did not pause the orbit"
keys r
i=0; while [ $i -lt 30 ]; do keys .; i=$((i + 1)); done
wait_for 'steps 30 ' || fail "30 single steps were not taken"
keys c
wait_for 'vs +rk4' || fail "c did not start compare"
keys ' '
wait_for 'orbit +euler +dt=0\.01 +t=[1-9][0-9]*\.' || fail "compare did not run"
drift=$(screen | sed -n 's/.*vs  rk4 .*energy \([-+][0-9.e+-]*\)%.*/\1/p' | head -1)
echo "orbit, compare after 30 euler steps: rk4 energy drift $drift %"
[ -n "$drift" ] || fail "no energy on rk4's status line"
awk -v d="$drift" 'BEGIN { exit !(d < 0.1 && d > -0.1) }' || fail "rk4's energy drift is $drift %, not its own"
screen | grep -Eq 'vs +rk4 .*steps [0-9]' || fail "rk4 has no step count"
keys q
wait_for 'PROMPT\$ *$' || fail "q did not quit"

# 3. The phase view on the undamped spring: Euler's path leaves the exact
#    ellipse outward, Verlet's stays within a band around it.
for m in euler verlet; do
    type_cmd "$STEPWISE play spring --set c=0 -i $m --speed 2"
    wait_for "spring +$m" || fail "play spring -i $m did not start"
    keys ' '
    wait_for PAUSED || fail "space did not pause"
    keys r v
    wait_for 'phase: stretch' || fail "v did not open the phase view"
    # the exact ellipse, whole from the start (the path will cover it)
    exact=$(scene_rows spring | sed '1d;$d' | extent "'")
    keys ' '
    wait_for 't=(1[0-9]|[2-9][0-9])\.' 120 || fail "the spring did not run 10 s"
    keys ' '
    wait_for PAUSED || fail "space did not pause"
    # (the axis's name at its end, "stretch 0.75 >", is not a path)
    path=$(scene_rows spring | sed '1d;$d' | sed 's/[a-z][a-z ]* [-0-9.e+]* >//' | extent ".o<>")
    echo "spring, $m, phase view at t >= 10: exact ellipse $exact columns, path $path columns"
    [ "$exact" -gt 20 ] || fail "no exact ellipse on the phase view ($exact columns)"
    if [ $m = euler ]; then
        [ "$path" -gt $((exact + 4)) ] || fail "euler's path ($path) does not leave the ellipse ($exact)"
    else
        # (the paths are drawn over the exact orbit, so a path on it hides it)
        [ "$path" -ge 1 ] && [ "$path" -le $((exact + 2)) ] ||
            fail "verlet's path ($path) is not within a band of the ellipse ($exact)"
    fi
    keys q
    wait_for 'PROMPT\$ *$' || fail "q did not quit"
done

# 4. The stability region of RK4 with the chain's modes: + until the meter
#    says GROWS puts a mark outside the shaded region.
type_cmd "$STEPWISE play chain -i rk4"
wait_for 'chain +rk4' || fail "play chain did not start"
keys s
wait_for 'stability region of rk4' || fail "s did not open the region view"
wait_for 'all inside' || fail "at the default dt the modes are not all inside"
presses=0
chain_dt() { screen | sed -n 's/.*chain  rk4  dt=\([0-9.e-]*\) .*/\1/p' | head -1; }
dt_changed() { [ "$(chain_dt)" != "$1" ]; }
while ! screen | grep -q 'GROWS'; do
    [ $presses -lt 12 ] || fail "12 presses of + and the meter never said GROWS"
    was=$(chain_dt)
    keys +
    wait_until 30 dt_changed "$was" || fail "+ did not change dt from $was"
    wait_for 'all inside|GROWS|outside' || fail "the meter did not answer at dt=$(chain_dt)"
    presses=$((presses + 1))
done
wait_for 'X [0-9]+ outside' || fail "the meter says GROWS but the region view marks nothing outside"
dt=$(screen | sed -n 's/.*chain  rk4  dt=\([0-9.e-]*\) .*/\1/p' | head -1)
# an X mark whose neighbour (left, right, above or below) is unshaded
outside=$(scene_rows chain | awk '
    { row[NR] = $0 }
    END { for (r = 2; r < NR; r++) { n = length(row[r]); for (i = 1; i <= n; i++) if (substr(row[r], i, 1) == "X") {
        l = substr(row[r], i - 1, 1); rr = substr(row[r], i + 1, 1); u = substr(row[r - 1], i, 1); d = substr(row[r + 1], i, 1)
        if (l == " " || rr == " " || u == " " || u == "" || d == " " || d == "") c++ } } print c + 0 }')
echo "chain, rk4: GROWS after $presses presses of + (dt=$dt); $outside X marks beside unshaded cells"
[ "$outside" -ge 1 ] || fail "no X mark lies outside the drawn region"
keys q
wait_for 'PROMPT\$ *$' || fail "q did not quit"
check_terminal_sane picture
echo ok
