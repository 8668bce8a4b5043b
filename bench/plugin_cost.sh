#!/bin/bash
# What one honest plugin costs to grade with its order and stability
# measured (issue 35's goal: at most 1 s CPU and 2 s wall on an idle
# machine): `check --plugin` of an honest RK4 (tests/hostile/honest-rk4.c,
# built once) on the chain, RUNS times jailed and RUNS times with
# --no-sandbox, interleaved; each run's wall time and CPU time (user +
# system of every process, the plugin's host included), then the medians.
# bash for its `time` (children included: each waits for its own).
#
# usage: bash bench/plugin_cost.sh [STEPWISE] [RUNS]
set -u
SW=$(cd "$(dirname "${1:-./stepwise}")" && pwd)/$(basename "${1:-./stepwise}")
RUNS=${2:-5}
root=$(cd "$(dirname "$0")/.." && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
sed "s/@NAME@/honest-rk4/" "$root/tests/hostile/honest-rk4.c" > "$dir/rk4.c"
${CC:-cc} -std=c11 -O2 -shared -fPIC -I"$root/include" -o "$dir/rk4.so" "$dir/rk4.c" || exit 1
TIMEFORMAT="%R %U %S"
on_wall="" on_cpu="" off_wall="" off_cpu=""
for r in $(seq "$RUNS"); do
    for mode in on off; do
        flag=""; [ $mode = off ] && flag=--no-sandbox
        t=$( { time "$SW" check $flag --plugin "$dir/rk4.so" --reference rk4 --scene chain >/dev/null 2>&1; } 2>&1 )
        set -- $t
        cpu=$(echo "$2 $3" | awk '{ printf "%.3f", $1 + $2 }')
        echo "run $r $mode: $1 s wall, $cpu s CPU"
        if [ $mode = on ]; then on_wall="$on_wall $1"; on_cpu="$on_cpu $cpu"; else off_wall="$off_wall $1"; off_cpu="$off_cpu $cpu"; fi
    done
done
median() { echo "$@" | tr ' ' '\n' | grep . | sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
echo "one honest RK4, order and stability measured: median $(median $on_wall) s wall, $(median $on_cpu) s CPU jailed; $(median $off_wall) s wall, $(median $off_cpu) s CPU with --no-sandbox"
