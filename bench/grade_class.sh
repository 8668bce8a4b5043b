#!/bin/sh
# The cost of the sandbox on a class: N submissions, half traces (recorded
# with stepwise: correct) and half plugins (C sources of an honest RK4 step,
# each a little different so every one is compiled), against an rk4
# assignment on the chain that pays for the measured order and stability
# (so every plugin is also measured), graded with and without the jail,
# RUNS times each, interleaved. Prints each run's wall time and the
# medians and their ratio. With COMPARE=jobs, the jailed class is graded
# with -j 1 and with -j 2 instead (the gradebooks compared byte for byte).
#
# usage: [COMPARE=jobs] sh bench/grade_class.sh [STEPWISE] [N] [RUNS]
set -u
SW=$(cd "$(dirname "${1:-./stepwise}")" && pwd)/$(basename "${1:-./stepwise}")
N=${2:-120}
RUNS=${3:-3}
root=$(cd "$(dirname "$0")/.." && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir" || exit 1
mkdir class
cat > assignment.txt <<'A'
# stepwise assignment 1
# title: RK4 on a chain, measured
# scene: chain
# param n: 4
# integrator: rk4
# dt: 0.005
# steps: 400
# points x* y*: 4
# points order: 1
# points stability: 1
A
"$SW" record chain --set n=4 -i rk4 --dt 0.005 --steps 400 -o ref.trace >/dev/null || exit 1
i=0
while [ $i -lt $((N / 2)) ]; do
    sed "s/^# scene/# student: Trace $i\n# scene/" ref.trace > class/t$i.trace
    sed -e "s/@NAME@/student-$i/" "$root/tests/hostile/honest-rk4.c" > class/p$i.c
    i=$((i + 1))
done
export STEPWISE_INCLUDE="$root/include"
now() { date +%s.%N; }
on="" off=""
r=0
while [ $r -lt "$RUNS" ]; do
    for mode in on off; do
        flag=""; [ $mode = off ] && flag=--no-sandbox
        if [ "${COMPARE:-}" = jobs ]; then
            flag="-j 2 --csv j2.csv"; [ $mode = off ] && flag="-j 1 --csv j1.csv"
        fi
        t0=$(now)
        "$SW" grade --assignment assignment.txt --fresh $flag class >/dev/null 2>&1
        rc=$?
        t1=$(now)
        s=$(echo "$t1 - $t0" | bc)
        echo "run $r ${COMPARE:-sandbox} $mode: $s s (exit $rc)"
        [ $mode = on ] && on="$on $s" || off="$off $s"
    done
    r=$((r + 1))
done
median() { echo "$@" | tr ' ' '\n' | grep . | sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
mon=$(median $on); moff=$(median $off)
if [ "${COMPARE:-}" = jobs ]; then
    cmp -s j1.csv j2.csv && same="identical" || same="DIFFERENT"
    echo "class of $N ($((N / 2)) traces, $((N / 2)) plugins from source), jailed: median $mon s with -j 2, $moff s with -j 1, ratio $(echo "scale=2; $mon / $moff" | bc); gradebooks $same"
    exit 0
fi
echo "class of $N ($((N / 2)) traces, $((N / 2)) plugins from source): median $mon s jailed, $moff s without the jail, ratio $(echo "scale=2; $mon / $moff" | bc)"
