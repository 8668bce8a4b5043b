#!/bin/sh
# A terminal that goes away under a running lesson (the window closed, the
# pane or session killed, the pty's master closed) ends stepwise within a
# second, using little CPU on the way, with exit status 129 (a hangup),
# also when a parent swallowed the SIGHUP (`trap '' HUP`, as `make run` or
# a wrapper script may) and when no SIGHUP is sent at all (a process in its
# own session: only EOF/EIO on the terminal tells).
. "$(dirname "$0")/lib.sh"
command -v setsid >/dev/null || { echo "setsid (util-linux) is needed"; exit 1; }
# (tmux gives a new session the server's environment: passed explicitly below)
XDG_STATE_HOME="$WORK/state"
HZ=$(getconf CLK_TCK 2>/dev/null || echo 100)

# cpu_ticks PID: user + system time so far, in clock ticks (/proc/PID/stat
# fields 14 and 15, counted after the parenthesised name).
cpu_ticks() {
    { read -r line < "/proc/$1/stat"; } 2>/dev/null || { echo 0; return; }
    rest=${line##*) }
    set -- $rest
    echo $(( ${12} + ${13} ))
}

now_ms() { date +%s%3N; }
gone() { [ ! -d "/proc/$1" ]; }

# find_app: the pid of our stepwise process (its command line names the binary and "lesson").
find_app() {
    for c in /proc/[0-9]*/cmdline; do
        cmd=$( { tr '\0' ' ' < "$c"; } 2>/dev/null) || continue
        case "$cmd" in "$STEPWISE lesson"*|"$STEPWISE "|"$STEPWISE") p=${c#/proc/}; echo "${p%/cmdline}"; return ;; esac
    done
}

# found_app: 0 when our stepwise runs (its pid in $pid).
found_app() { pid=$(find_app); [ -n "$pid" ]; }
# pane_shows SESSION REGEX: the pane's text matches.
pane_shows() { tmux capture-pane -p -t "$1" 2>/dev/null | grep -Eq -- "$2"; }
# waiting PID: the process sleeps (in its input poll: the UI is up).
waiting() {
    { read -r line < "/proc/$1/stat"; } 2>/dev/null || return 1
    case "${line##*) }" in S*) return 0 ;; esac
    return 1
}

# vanish NAME HOW WRAP KEYS SHOWN ARGS: start `stepwise ARGS` in a fresh tmux
# session under `sh -c` (WRAP "setsid -w" to give it a session of its own),
# wait until it has drawn, type KEYS and wait until the pane shows SHOWN (a
# regex), kill the pane or session (HOW), and check how fast and how
# cheaply it ends.
vanish() {
    name=$1 how=$2 wrap=$3 typed=$4 shown=$5; shift 5
    rm -f rc times
    s="sw-gone-$$-$name"
    tmux_next
    LANG=C.UTF-8 LC_ALL=C.UTF-8 tmux -u new-session -d -s "$s" -x 120 -y 40 -c "$WORK" \
        "env TERM=xterm-256color LANG=C.UTF-8 XDG_STATE_HOME='$XDG_STATE_HOME' sh -c 'trap \"\" HUP; $wrap \"$STEPWISE\" $*; echo \$? > rc; times > times'" \
        || fail "$name: cannot start tmux"
    pid=""
    wait_until 60 found_app || { tmux kill-session -t "$s" 2>/dev/null; fail "$name: stepwise did not start"; }
    wait_until 60 pane_shows "$s" '[^[:space:]]' || fail "$name: stepwise drew nothing"
    [ -z "$typed" ] || tmux send-keys -t "$s" $typed
    wait_until 60 pane_shows "$s" "$shown" || fail "$name: the pane never showed '$shown'"
    before=$(cpu_ticks "$pid")
    start=$(now_ms)
    if [ "$how" = pane ]; then tmux kill-pane -t "$s"; else tmux kill-session -t "$s"; fi
    # a condition with a generous guard: a stepwise that survives its
    # terminal (a busy loop on a dead tty) is still there after 30 s
    wait_until 30 gone "$pid"
    took=$(( $(now_ms) - start ))
    if [ -d "/proc/$pid" ]; then
        spent=$(( $(cpu_ticks "$pid") - before ))
        kill -KILL "$pid" 2>/dev/null
        fail "$name: stepwise still runs ${took} ms after its terminal went away ($spent ticks of CPU since)"
    fi
    wait_until 30 test -s times
    [ -s rc ] && [ -s times ] || fail "$name: the wrapping shell did not record the exit"
    # times: the shell's user and system time, then its children's
    total=$(sed -n 2p times | awk '{ n = 0; for (i = 1; i <= 2; i++) { split($i, a, /[ms]/); n += a[1] * 60 + a[2] } print int(n * 1000) }')
    after=$(( total - before * 1000 / HZ ))
    echo "$name: gone ${took} ms after the terminal, exit $(cat rc), CPU after: ${after} ms (total ${total} ms)"
    [ "$took" -lt 1000 ] || fail "$name: took ${took} ms to end, expected under 1 s"
    [ "$(cat rc)" = 129 ] || fail "$name: exit status $(cat rc), expected 129 (128 + SIGHUP)"
    # measured by ticks (10 ms): what it used since the kill, startup excluded
    [ "$after" -lt 300 ] || fail "$name: used ${after} ms of CPU after the terminal went away"
}

vanish lesson-session session "" "" 'page 1' lesson 1
vanish lesson-pane pane "" "" 'page 1' lesson 1
vanish lesson-own-session session "setsid -w" "" 'page 1' lesson 1
vanish menu-own-session pane "setsid -w" "" '[^[:space:]]' ""
# a page completed before the terminal went is kept: lesson 2's first page
# asks for five steps (.), and its progress is saved
vanish lesson-progress session "setsid -w" ". . . . ." 'page done' lesson 2
grep -q '^02-euler.lesson 1$' "$XDG_STATE_HOME/stepwise/progress" || fail "the completed page was not saved"

# A pty whose master is closed under it (script(1) killed outright).
if command -v script >/dev/null; then
    rm -f rc times
    # script's input: a FIFO held open here, so it never sees end of file
    mkfifo in && exec 3<>in
    env TERM=xterm-256color XDG_STATE_HOME="$XDG_STATE_HOME" script -qfec "sh -c 'trap \"\" HUP; setsid -w \"$STEPWISE\" lesson 1; echo \$? > rc; times > times'" /dev/null <in >/dev/null 2>&1 &
    pid=""
    wait_until 60 found_app || fail "pty: stepwise did not start under script"
    wait_until 60 waiting "$pid" || fail "pty: stepwise never waited for input"
    spid=""
    for c in /proc/[0-9]*/cmdline; do
        case "$( { tr '\0' ' ' < "$c"; } 2>/dev/null)" in script\ -qfec*) p=${c#/proc/}; spid=${p%/cmdline} ;; esac
    done
    [ -n "$spid" ] || fail "pty: no script process"
    start=$(now_ms)
    kill -KILL "$spid"
    wait_until 30 gone "$pid"
    took=$(( $(now_ms) - start ))
    [ -d "/proc/$pid" ] && { kill -KILL "$pid"; fail "pty: stepwise still runs ${took} ms after its pty closed"; }
    wait_until 30 test -s rc
    echo "pty: gone ${took} ms after the master closed, exit $(cat rc 2>/dev/null)"
    [ "$(cat rc 2>/dev/null)" = 129 ] || fail "pty: exit status $(cat rc 2>/dev/null), expected 129"
fi
echo ok
