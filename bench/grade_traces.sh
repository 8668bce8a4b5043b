#!/bin/sh
# Grading at the speed of reading (issue 26): the CPU time (user + system,
# the grader and every process it starts) of `stepwise grade` on a class of
# N passing traces, RUNS times; prints each run and the median. Two
# classes: the spring's 300 steps (26 KB a trace) and the 10-bead chain's
# 2000 rk4 steps (1.7 MB a trace, 44 columns), where reading is the work.
#
# usage: sh bench/grade_traces.sh [STEPWISE] [N] [RUNS]
set -u
SW=$(cd "$(dirname "${1:-./stepwise}")" && pwd)/$(basename "${1:-./stepwise}")
N=${2:-100}
RUNS=${3:-5}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir" || exit 1
median() { echo "$@" | tr ' ' '\n' | grep . | sort -g | awk '{a[NR] = $1} END {print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2}'; }
# "0m1.250s" -> 1.250
secs() { echo "$1" | awk -Fm '{sub(/s$/, "", $2); print $1 * 60 + $2}'; }
class() { # NAME SCENE INTEGRATOR DT STEPS
    mkdir -p "$1"
    printf '# stepwise assignment 1\n# title: %s\n# scene: %s\n# integrator: %s\n# dt: %s\n# steps: %s\n' \
        "$1" "$2" "$3" "$4" "$5" > "$1.assignment"
    "$SW" record "$2" -i "$3" --dt "$4" --steps "$5" -o "$1.ref" >/dev/null 2>&1 || exit 1
    i=0
    while [ $i -lt "$N" ]; do
        sed "s/^# scene/# student: Trace $i\n# scene/" "$1.ref" > "$1/t$i.trace"
        i=$((i + 1))
    done
    bytes=$(wc -c < "$1.ref")
    all=""
    r=0
    while [ $r -lt "$RUNS" ]; do
        # `times` prints the shell's own times, then its children's.
        t=$( ("$SW" grade --assignment "$1.assignment" --fresh "$1" >/dev/null 2>&1; echo "exit $?" >&2; times) 2>"$1.exit" | tail -1)
        grep -q "exit 0" "$1.exit" || { echo "grade $1: not every trace passed"; exit 1; }
        cpu=$(echo "$(secs "${t% *}") + $(secs "${t#* }")" | bc)
        all="$all $cpu"
        r=$((r + 1))
    done
    echo "$N passing traces, $1 ($bytes bytes each): CPU s per run:$all; median $(median $all) s"
}
class spring spring euler 0.01 300
class chain chain rk4 0.01 2000
