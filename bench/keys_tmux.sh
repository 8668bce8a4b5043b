#!/bin/bash
# The picture's longest stall after each key, from outside (issue 41: "no
# key (w, k, c, +, -, ;) stops the picture for more than 100 ms at
# n = 1e5"). Opens `stepwise play SCENE --set n=100000` in tmux, waits
# until it has run half a second, presses the key (and space after the
# keys that pause the run: k, c, +, -, ; leave it paused by design, so
# space runs it on, in the same write as the key), then reads the
# status line's `t=` with `tmux capture-pane` as fast as the shell can for
# WINDOW seconds. The gap is the longest time the `t=` field went without
# changing from the key on: the first change after the key, and between
# changes after it; the row "none" presses nothing: the picture's own
# longest gap over the window at that load. t= moves in whole steps, so
# at speed 1 a gap is at least the run's dt (printed: `+` doubles it, to
# 100 ms on the vortex). A measurement, not a test: the sampling interval
# (one capture-pane, a few ms; its median is printed) bounds its
# resolution, and the machine's load (printed) shifts it. `make bench`
# runs it; no test asserts a time.
#
# usage: bash bench/keys_tmux.sh [STEPWISE] [REPEATS] [WINDOW] [SCENES]
set -u
SW=$(cd "$(dirname "${1:-./stepwise}")" && pwd)/$(basename "${1:-./stepwise}")
REPEATS=${2:-3}
WINDOW=${3:-3}
SCENES=${4:-chain vortex}
command -v tmux >/dev/null 2>&1 || { echo "keys_tmux: skipped (no tmux)"; exit 0; }
session=swkeys$$
trap 'tmux kill-session -t "$session" 2>/dev/null' EXIT

# The main run's t= on the screen now, or "" (not shown).
t_now() {
    local screen
    screen=$(tmux capture-pane -p -t "$session" 2>/dev/null)
    [[ $screen =~ \ t=([0-9.]+) ]] && echo "${BASH_REMATCH[1]}"
}

# Wait (up to 60 s, a condition polled) until t= shows a value above $1.
wait_running() {
    local t
    for _ in $(seq 600); do
        t=$(t_now)
        [ -n "$t" ] && awk -v t="$t" -v m="$1" 'BEGIN { exit !(t > m) }' && return 0
        sleep 0.1
    done
    return 1
}


# One run: prints "GAP_MS SAMPLE_MS" (the longest gap, the median sampling
# interval, the run's dt after the key in ms: the floor of the gap at
# speed 1, as t= moves in whole steps), or "- - -" when it did not start.
one_run() {
    local scene=$1 key=$2 start t last now prev gap=0 change end intervals="" step
    tmux kill-session -t "$session" 2>/dev/null
    tmux new -d -s "$session" -x 100 -y 30 "'$SW' play $scene --set n=100000"
    wait_running 0.5 || { echo "- - -"; return; } # play starts running
    last=$(t_now)
    case $key in
    none) ;; # the picture's own gaps, for comparison
    w) tmux send-keys -t "$session" -l -- "$key" ;;
    *) tmux send-keys -t "$session" -l -- "$key " ;; # the key, then space: run on
    esac
    start=${EPOCHREALTIME/./}
    change=$start prev=$start end=$((start + WINDOW * 1000000))
    while :; do
        now=${EPOCHREALTIME/./}
        [ "$now" -gt "$end" ] && break
        t=$(t_now)
        intervals="$intervals $((now - prev))"
        prev=$now
        if [ -n "$t" ] && [ "$t" != "$last" ]; then
            [ $((now - change)) -gt "$gap" ] && gap=$((now - change))
            change=$now last=$t
        fi
    done
    [ $((end - change)) -gt "$gap" ] && gap=$((end - change)) # still at the window's end
    # the run's step after the key: at speed 1, t= moves once per dt of wall time at the most
    step=$(tmux capture-pane -p -t "$session" | grep -o ' dt=[0-9.e+-]*' | head -1 | cut -d= -f2)
    tmux send-keys -t "$session" -l q
    for _ in $(seq 100); do # gone (and the server with it) before the next one starts
        tmux has-session -t "$session" 2>/dev/null || break
        sleep 0.1
    done
    echo "$((gap / 1000)) $(echo "$intervals" | median | awk '{ printf "%.1f", $1 / 1e3 }') $(awk -v d="${step:-0}" 'BEGIN { printf "%g", 1e3 * d }')"
}

median() { tr ' ' '\n' | grep -v '^$' | sort -n | awk '{ v[NR] = $1 } END { print NR ? v[int((NR + 1) / 2)] : "-" }'; }
worst() { tr ' ' '\n' | grep -v '^$' | sort -n | tail -1; }

echo "keys at n = 1e5 in tmux (100x30): the longest time t= stood still from the key on, over ${WINDOW} s;"
echo "median of $REPEATS runs, the worst beside it; sampling interval (one capture-pane) median; the run's"
echo "dt after the key (at speed 1 t= moves once a step: a gap of dt is the run's own pace, not a stall)."
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "past dt: the gap less the run's dt, the time the picture stood still beyond its own pace (judged)."
printf "  %-7s %-4s %8s %8s %10s %8s %8s  %s\n" scene key "gap ms" worst "sample ms" "dt ms" "past dt" "<=100ms"
for scene in $SCENES; do
    for key in none w k c + - ';'; do
        gaps="" samples="" step=-
        for _ in $(seq "$REPEATS"); do
            set -- $(one_run "$scene" "$key")
            [ "$1" = - ] && continue
            gaps="$gaps $1" samples="$samples $2" step=$3
        done
        g=$(echo "$gaps" | median) past=-
        [ "$g" != - ] && past=$(awk -v g="$g" -v d="$step" 'BEGIN { p = g - (d == "-" ? 0 : d); printf "%d", (p > 0 ? p : 0) }')
        printf "  %-7s %-4s %8s %8s %10s %8s %8s  %s\n" "$scene" "$key" "$g" "$(echo "$gaps" | worst)" \
            "$(echo "$samples" | median)" "$step" "$past" "$( [ "$past" != - ] && [ "$past" -le 100 ] && echo yes || echo NO)"
    done
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
