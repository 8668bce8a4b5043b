#!/bin/sh
# Pictures that show their point at 80x24 (issue 25), as a student sees
# them: on lesson 5 page 3 the stability region's marks move at every
# halving of dt and the axes stay put, each drawn on its side of the
# region's edge line (X past it, * on the shading), as the line under the
# picture says; on lesson 6 page 5 RK4's marks climb the imaginary axis
# and pass its edge line only at dt = 0.04, drawn X there; on lesson 6 page 4 the
# work-precision plot shows Euler (its marker, or named under the plot)
# and RK4's point of the page's table (about 500 evaluations, error 3e-7)
# beside the page's text, before and after the answer; the projectile's
# dashed line is labelled as its launch height, not a ground, and the ball
# flies on below it. Each prints what it measured.
. "$(dirname "$0")/lib.sh"
tmux_start 80 24
mkdir -p "$WORK/state/stepwise"

# The picture's columns (the lesson pane starts at column 41).
picture() { screen | cut -c1-39; }

# 1. Lesson 5 page 3 in the C locale (ASCII shading, so that columns are
#    characters): the marks' cells, and the axis row and the origin's column.
printf '05-springs.lesson 2\n' > "$WORK/state/stepwise/progress"
type_cmd "LC_ALL=C XDG_STATE_HOME=$WORK/state $STEPWISE lesson 5"
wait_for 'Springs, damping, stiffness +\(page 3/7\)' || fail "lesson 5 did not open on page 3"
keys s
wait_for 'scale \+-0.62 fixed' || fail "s did not show the region with its scale said"
# "ROW:COL" of every mark (X or *) in the region's rows (down to the line
# under the picture, which starts "in "), the axis, the numbers under it
marks() { picture | awk '/^in [:|*X-]/ { exit } NR >= 2 { for (i = 1; i <= length($0); i++) { ch = substr($0, i, 1)
    if (ch == "X" || ch == "*") printf "%d:%d ", NR, i } }'; }
axis() { picture | awk '/^-+\+/ { row = NR } END { print row }'; }
ticks() { picture | grep -E '^ *-0\.[0-9] +-0\.[0-9]' | sed 's/ *$//'; }
# the mark's side of the edge line (#) in its row: "outside" when the nearest
# region glyph on each side is the line or none, "inside" when the inside (:)
# is next to it; the first mark's row is read
side() { picture | awk '/^in [:|*X-]/ { exit } NR >= 2 { for (i = 1; i <= length($0); i++) { ch = substr($0, i, 1)
    if (ch == "X" || ch == "*") { l = substr($0, 1, i - 1); r = substr($0, i + 1); gsub(/[^:#]/, "", l); gsub(/[^:#]/, "", r)
        ll = substr(l, length(l), 1); rr = substr(r, 1, 1)
        print (ll != ":" && rr != ":") ? "outside" : (substr($0, i - 1, 1) == ":" || substr($0, i + 1, 1) == ":") ? "inside" : "on the line"
        exit } } }'; }
# the line under the picture: the edge's column, the mark's, what it says
gauge() { picture | awk '/^in [:|*X-]/ { print index($0, "|") " " (index($0, "X") ? index($0, "X") : index($0, "*")) " " $NF; exit }'; }
prev_marks=$(marks); prev_axis=$(axis); prev_ticks=$(ticks)
set -- $(gauge); edge=$1 prev_pos=$2
echo "dt=0.005: marks $prev_marks axis row $prev_axis; under it: edge column $1, mark column $2, $3"
[ -n "$prev_marks" ] || fail "no marks on the region view"
[ -n "$prev_ticks" ] || fail "no numbers under the picture"
# (the ratio's sign is × where the locale shows it, ? where it does not)
case $3 in 5?edge | 5×edge) ;; *) false ;; esac && [ "$2" -gt "$1" ] || fail "at dt=0.005 the line under the picture does not show the mark out, 5×edge"
[ "$(side)" = outside ] || fail "at dt=0.005 the mark is not drawn outside the edge line (#)"
for dt in 0.0025 0.00125 0.000625; do
    keys -
    wait_for "euler  dt=$dt " || fail "- did not halve dt to $dt"
    m=$(marks); ax=$(axis)
    set -- $(gauge)
    echo "dt=$dt: marks $m axis row $ax; in the picture: $(side), edge line #; under it: edge column $1, mark column $2, $3"
    [ -n "$m" ] || fail "no marks at dt=$dt"
    [ "$m" != "$prev_marks" ] || fail "the marks did not move when dt halved to $dt ($m)"
    [ "$ax" = "$prev_axis" ] || fail "the axis moved from row $prev_axis to $ax at dt=$dt"
    [ "$(ticks)" = "$prev_ticks" ] || fail "the scale's numbers changed at dt=$dt: [$(ticks)] was [$prev_ticks]"
    [ "$1" = "$edge" ] || fail "the edge moved on the line under the picture at dt=$dt"
    [ "$2" -lt "$prev_pos" ] || fail "the mark did not move towards the origin on its ray at dt=$dt"
    case $dt in
        0.000625) [ "$2" -lt "$1" ] && case $3 in 0.625?edge | 0.625×edge) ;; *) false ;; esac &&
            [ "$(side)" = inside ] ||
            fail "at dt=$dt the mark is not shown inside, 0.625×edge, on the shading" ;;
        *) [ "$2" -gt "$1" ] && [ "$(side)" = outside ] || fail "at dt=$dt the mark is not shown outside, past the edge line" ;;
    esac
    prev_marks=$m prev_pos=$2
done
keys q
check_terminal_sane region

# 1b. Lesson 6 page 5 (RK4's region, undamped: the marks on the imaginary
#     axis): doubling dt from 0.005 to 0.04 the marks climb the axis; the
#     edge line (#) crosses it at 2.83i; at 0.02 the upper mark is at or
#     below the line's top row there, at 0.04 above it, drawn X.
printf '06-runge-kutta.lesson 4\n' > "$WORK/state/stepwise/progress"
type_cmd "LC_ALL=C XDG_STATE_HOME=$WORK/state $STEPWISE lesson 6"
wait_for "RK4's region" || fail "lesson 6 did not open on RK4's region"
keys s
wait_for 'scale \+-[0-9.]+ fixed' || fail "s did not show RK4's region"
# "MARKROW LINEROW GLYPH": the upper mark's row and glyph, the top row of
# the edge line in the three columns round the mark's
rk4_rows() { picture | awk '/^in [:|*X-]/ { exit } NR >= 2 { line[NR] = $0
    if (!mr) for (i = 1; i <= length($0); i++) { ch = substr($0, i, 1); if (ch == "X" || ch == "*") { mr = NR; mc = i; g = ch == "X" ? "X" : "star"; break } } }
    END { for (r = 2; r in line; r++) { s = substr(line[r], mc - 1, 3); if (index(s, "#")) { print mr " " r " " g; exit } } }'; }
for dt in 0.01 0.02 0.04; do
    keys +
    wait_for "rk4  dt=$dt " || fail "+ did not double dt to $dt"
    set -- $(rk4_rows)
    echo "rk4 at dt=$dt: upper mark row $1 ($3), edge line's top row on the axis $2"
    [ -n "${3:-}" ] || fail "no mark or no edge line on RK4's region at dt=$dt"
    case $dt in
        0.04) [ "$1" -lt "$2" ] && [ "$3" = X ] || fail "at dt=0.04 the mark is not drawn past the edge line, X" ;;
        *) [ "$1" -ge "$2" ] && [ "$3" = star ] || fail "at dt=$dt the mark is not drawn inside the edge line" ;;
    esac
done
keys q
check_terminal_sane region-rk4

# 2. Lesson 6 page 4: the plot in the picture's place, the page's text beside it.
printf '06-runge-kutta.lesson 3\n' > "$WORK/state/stepwise/progress"
type_cmd "XDG_STATE_HOME=$WORK/state $STEPWISE lesson 6"
wait_for 'Runge-Kutta: midpoint and RK4 +\(4/[0-9]+\)' || fail "lesson 6 did not open on page 4"
keys w
wait_for 'error vs evaluations' 60 || fail "w did not show the work-precision plot"
wait_for 'for one turn of the' || fail "the plot hides the page's text"
# Euler: its marker 1 in the plot, or the cells it shares named
if picture | sed -n '2,12p' | cut -c7- | grep -q 1; then
    echo "euler: its marker is in the plot"
else
    picture | grep -Eq 'shared cell, top one shown: .*(over 1|over euler)' || fail "euler is neither drawn nor named in a shared cell"
    echo "euler: in shared cells, named: $(picture | grep 'shared cell')"
fi
# RK4's table point: ~500 evaluations (log10 2.7 between the 1e2 and 1e3
# labels), error 3e-7 (between the rows labelled 1e-5 and 1e-8, ±1 row)
found=$(picture | awk '
    /^ *1e-?[0-9]+\|/ { lab = $0; sub(/\|.*/, "", lab); gsub(/ /, "", lab); e = substr(lab, 3) + 0; erow[e] = NR }
    /^ *\+\+?-/ { axisrow = NR }
    { line[NR] = $0 }
    END {
        xl = line[axisrow + 1]
        c2 = index(xl, "1e2") + 1; c3 = index(xl, "1e3") + 1
        if (c2 <= 1 || c3 <= 1) { print "nolabels"; exit }
        x = c2 + 0.7 * (c3 - c2)
        top = -1; bot = -1
        for (e in erow) { if (e + 0 >= -6.5 && (top < 0 || erow[e] > top)) top = erow[e]
                          if (e + 0 <= -6.5 && (bot < 0 || erow[e] < bot)) bot = erow[e] }
        if (top < 0) top = 2; if (bot < 0) bot = axisrow - 1
        for (r = top - 1; r <= bot + 1; r++) for (c = int(x) - 1; c <= int(x) + 2; c++) {
            ch = substr(line[r], c, 1); if (ch == "5") { print "row " r " col " c " (" ch ")"; exit } }
        print "none near column " x " rows " top ".." bot }')
echo "rk4 at ~500 evaluations, error 3e-7: $found"
case $found in row*) ;; *) fail "RK4's point of the table is not on the plot: $found" ;; esac
keys B
wait_for 'Done: press n' || fail "the answer was not taken"
screen | grep -q 'error vs evaluations' || fail "the plot closed when the question was answered"
# (the pane shows its end, the answer's feedback, its title on top)
screen | grep -q 'Error against cost' && screen | grep -q 'B) ' || fail "after the answer the plot hides the page's text"
keys q
check_terminal_sane workprec

# 3. The projectile: the dashed line is the launch height, and the ball,
#    with no ground, flies on below it (its row under the line, or an
#    arrow at the bottom edge).
type_cmd "$STEPWISE play projectile --until 2.5"
wait_for 'stopped at the stop time t = 2\.5' || fail "play projectile did not stop at t = 2.5"
screen | grep -q 'launch height (no ground' || fail "the launch line is not labelled as the launch height"
screen | grep -q 'launch kinetic energy, 62.5 J' || fail "the energy change's reference is not said"
line=$(screen | awk '/^-----+$/ { print NR; exit }')
ball=$(screen | awk '/^o projectile/ { exit } /(^| )o( |$)|v[0-9]/ { r = NR } END { print r }')
echo "projectile at t = 2.5: launch line row $line, ball (or its arrow) row $ball"
[ -n "$line" ] && [ -n "$ball" ] && [ "$ball" -gt "$line" ] || fail "the ball is not shown below the launch line"
keys q
check_terminal_sane projectile
echo ok
