#!/bin/sh
# Instructions per particle-step of the generic stepper and of the hand-fused
# loop (bench_base.c), counted by callgrind, which counts the same on every
# run where times on a shared machine do not. Each figure is the difference
# between two runs of the count probe at K1 and K2 steps, divided by
# (K2 - K1)·n, so building the system and loading the program drop out.
# The copies counted are those the loader picks on this machine (AVX2 where
# present). Usage: sh bench/instructions.sh [BENCH_BINARY]
set -eu
bin=${1:-build/bench_engine}
command -v valgrind >/dev/null 2>&1 || { echo "instructions.sh: needs valgrind (apt-get install valgrind)" >&2; exit 2; }
out=$(mktemp)
trap 'rm -f "$out"' EXIT
count() { # scene n method steps base|generic
    valgrind --tool=callgrind --callgrind-out-file="$out" "$bin" --count-probe "$@" >/dev/null 2>&1
    awk '/^summary:/ { print $2 }' "$out"
}
printf '%-18s %-6s %10s %10s %7s\n' problem method generic hand-fused ratio
for row in "chain 1000 euler 20 120" "chain 1000 rk4 20 120" "vortex 100000 euler 5 25" "vortex 100000 rk4 5 25"; do
    set -- $row
    g1=$(count "$1" "$2" "$3" "$4" generic); g2=$(count "$1" "$2" "$3" "$5" generic)
    b1=$(count "$1" "$2" "$3" "$4" base); b2=$(count "$1" "$2" "$3" "$5" base)
    awk -v s="$1 n = $2" -v m="$3" -v g1="$g1" -v g2="$g2" -v b1="$b1" -v b2="$b2" -v k=$(($5 - $4)) -v n="$2" \
        'BEGIN { g = (g2 - g1) / (k * n); b = (b2 - b1) / (k * n); printf "%-18s %-6s %10.1f %10.1f %7.2f\n", s, m, g, b, g / b }'
done
# The implicit and Rosenbrock steps against rk4 on the chain (issue 41's
# targets at n = 1000: linear-implicit-euler <= 4, implicit-euler and
# implicit-midpoint <= 5, rodas4 <= 10): instructions per particle-step
# of the generic stepper, the difference between K1 and K2 steps as above.
gcount() { # n method k1 k2
    c1=$(count chain "$1" "$2" "$3" generic); c2=$(count chain "$1" "$2" "$4" generic)
    awk -v c1="$c1" -v c2="$c2" -v k=$(($4 - $3)) -v n="$1" 'BEGIN { printf "%.1f", (c2 - c1) / (k * n) }'
}
printf '\n%-18s %-22s %10s %7s\n' problem method generic "x rk4"
for row in "1000 5 25" "10 200 2200"; do
    set -- $row
    rk4=$(gcount "$1" rk4 "$2" "$3")
    for m in rk4 linear-implicit-euler implicit-euler implicit-midpoint rodas4; do
        if [ "$m" = rk4 ]; then g=$rk4; else g=$(gcount "$1" "$m" "$2" "$3"); fi
        awk -v s="chain n = $1" -v m="$m" -v g="$g" -v r="$rk4" \
            'BEGIN { printf "%-18s %-22s %10.1f %7.2f\n", s, m, g, g / r }'
    done
done
# Instructions per call of the particle derivative, as the methods call it
# (the small-system path where it applies) and through the generic passes,
# at the scene's start: the difference between 2000 and 12000 calls.
dcount() { # scene setting calls small|generic
    valgrind --tool=callgrind --callgrind-out-file="$out" "$bin" --deriv-probe "$@" >/dev/null 2>&1
    awk '/^summary:/ { print $2 }' "$out"
}
printf '\n%-24s %10s %10s\n' "derivative" "as called" generic
for row in "orbit e=0.9" "orbit e=0.5" "spring c=0.5" "projectile drag=0.1" "chain n=10" "chain n=100"; do
    set -- $row
    s1=$(dcount "$1" "$2" 2000 small); s2=$(dcount "$1" "$2" 12000 small)
    g1=$(dcount "$1" "$2" 2000 generic); g2=$(dcount "$1" "$2" 12000 generic)
    awk -v s="$1 $2" -v s1="$s1" -v s2="$s2" -v g1="$g1" -v g2="$g2" \
        'BEGIN { printf "%-24s %10.1f %10.1f\n", s, (s2 - s1) / 10000, (g2 - g1) / 10000 }'
done
