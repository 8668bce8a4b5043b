#!/bin/sh
# The stability-region view is computed from the method's own one-step map,
# so a student's plugin gets its own region: examples/euler_plugin.c (forward
# Euler, sandboxed) shows Euler's disc and the same marks and growth as the
# built-in euler, at a step where the spring is inside the region and at
# one where it is outside.
. "$(dirname "$0")/lib.sh"
needs_jail
cc -std=c11 -O2 -Wall -Wextra -Werror -shared -fPIC -I"$ROOT/include" -o plugin.so \
    "$ROOT/examples/euler_plugin.c" 2>cc.err || fail "cannot build the plugin: $(cat cc.err)"

# The last frame's picture and legend, once the region is shaded whole: a
# plugin's region fills in over frames within a wall-clock budget each, so
# how many frames that takes depends on the machine. Run longer until no
# "shading" line is left (the limit is for a hung plugin only).
region() {
    frames=40 end=$(( $(date +%s) + 300 ))
    while :; do
        "$STEPWISE" play spring "$@" --view region --frames $frames --ascii --size 80x24 > frames.txt || return 1
        tail -24 frames.txt | head -20 > last.txt
        grep -q 'shading' last.txt || { cat last.txt; return 0; }
        [ "$(date +%s)" -lt "$end" ] || { cat last.txt; return 0; }
        frames=$((frames * 2))
    done
}
shaded() { tr -cd ':' | wc -c; }

for dt in 0.02 0.32; do
    region -i euler --dt $dt > builtin.txt || fail "play -i euler --view region failed"
    region --plugin plugin.so -i student-euler --dt $dt > plugin.txt || fail "play with the plugin failed"
    grep -q 'shading' plugin.txt && fail "the plugin's region was not shaded in 5 minutes"
    wb=$(sed -n 's/.*worst x\([0-9.]*\)\/step.*/\1/p' builtin.txt)
    wp=$(sed -n 's/.*worst x\([0-9.]*\)\/step.*/\1/p' plugin.txt)
    sb=$(shaded < builtin.txt) sp=$(shaded < plugin.txt)
    echo "dt=$dt: worst growth euler x$wb, plugin x$wp; shaded cells $sb and $sp"
    [ -n "$wb" ] && [ "$wb" = "$wp" ] || fail "the plugin's marks grow x$wp per step, euler's x$wb"
    [ "$sb" -gt 20 ] || fail "euler's region is not shaded ($sb cells)"
    # the plugin's grid is two cells wide: its edge may differ by a cell per row
    diff=$((sb > sp ? sb - sp : sp - sb))
    [ $diff -le $((sb / 10 + 17)) ] || fail "the plugin's region ($sp cells) is not euler's ($sb cells)"
    if [ $dt = 0.02 ]; then
        grep -q 'all inside' plugin.txt || fail "at dt=0.02 the plugin's marks are not inside: $(cat plugin.txt)"
    else
        grep -q 'X 2 outside' plugin.txt || fail "at dt=0.32 the plugin's marks are not outside: $(cat plugin.txt)"
    fi
done
echo ok
