# What every end-to-end test shares; each test starts with
#     . "$(dirname "$0")/lib.sh"
# and gets: STEPWISE and SW (the binary, absolute), ROOT (the repository),
# WORK (also dir and work: a scratch directory, removed on exit, and the
# current directory), fail MESSAGE, and the tmux helpers below for tests
# that drive stepwise as a student would. Needs only POSIX sh and coreutils
# (no procps: processes are found through /proc).
set -u
STEPWISE=${STEPWISE:?set STEPWISE to the stepwise binary}
SW=$STEPWISE
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
root=$ROOT
WORK=$(mktemp -d)
dir=$WORK
work=$WORK
SESSION="sw-e2e-$$"
TMUX_STARTED=0
TMUX_N=0
# Every tmux session a test starts has a server of its own (socket
# sw-e2e-PID-N): a server whose last session has gone is still shutting down
# for a moment, and a new session sent to its socket then fails with "server
# exited unexpectedly". No test touches the user's own sessions, and a
# session gets this environment.
tmux() { command tmux -L "$SESSION-$TMUX_N" "$@"; }
# tmux_next: leave the current server (killed) for a fresh one.
tmux_next() {
    tmux kill-server 2>/dev/null
    TMUX_N=$((TMUX_N + 1))
}
tmux_cleanup() {
    n=0
    while [ $n -le $TMUX_N ]; do
        command tmux -L "$SESSION-$n" kill-server 2>/dev/null
        rm -f "${TMUX_TMPDIR:-/tmp}/tmux-$(id -u)/$SESSION-$n"
        n=$((n + 1))
    done
}
trap 'tmux_cleanup; rm -rf "$WORK"' EXIT
cd "$WORK" || exit 1

# needs_jail: a test that runs students' plugins calls this first. Where no
# jail can be built (user namespaces refused and not root: a container run
# as an ordinary user), it says in one line that it is skipped and why and
# exits 77, which run.sh counts as skipped, never as passed.
needs_jail() {
    if ! why=$("$SW" autograder --probe 2>&1); then
        echo "skip: $(basename "$0" .sh): no jail for plugins can be built here: $why"
        exit 77
    fi
}

# build_dir: the build directory $SW was made in, for a test that reads
# the objects: SW_BUILD, else the binary's own directory where its objects
# are beside it (make sanitize's build/san), else build/ (the binary at the top).
build_dir() {
    if [ -n "${SW_BUILD:-}" ]; then
        echo "$SW_BUILD"
    elif [ -f "$(dirname "$SW")/src/main.o" ]; then
        dirname "$SW"
    else
        echo "$ROOT/build"
    fi
}

fail() {
    echo "FAIL: $*"
    if [ "$TMUX_STARTED" = 1 ]; then
        echo "--- screen:"
        tmux capture-pane -p -t "$SESSION" 2>/dev/null
    fi
    exit 1
}

# A 120x40 tmux session (tmux_start COLS ROWS: another size) running a plain sh with the prompt "PROMPT$ ", in
# the C.UTF-8 locale (built into glibc, so present on a fresh Debian too):
# the UI's ✓, ✗ and Braille need a UTF-8 terminal, whatever the caller's locale.
tmux_start() {
    tmux_next
    TMUX_STARTED=1
    LANG=C.UTF-8 LC_ALL=C.UTF-8 tmux -u new-session -d -s "$SESSION" -x "${1:-120}" -y "${2:-40}" -c "$WORK" \
        "env LANG=C.UTF-8 LC_ALL=C.UTF-8 PS1='PROMPT\$ ' TERM=xterm-256color sh" || fail "cannot start tmux"
    wait_for 'PROMPT\$' || fail "no shell prompt"
}

screen() { tmux capture-pane -p -t "$SESSION"; }

. "$ROOT/tests/e2e/wait.sh"   # wait_until

screen_has() { screen | grep -Eq -- "$1"; }
# The same for the shell's text after a program ended, its wrapped lines
# joined: a message that names the binary's path wraps where the checkout
# lies deep (wait_for_text PATTERN [LIMIT]).
text_has() { tmux capture-pane -p -J -t "$SESSION" | grep -Eq -- "$1"; }
wait_for_text() { wait_until "${2:-30}" text_has "$1"; }

# wait_for REGEX [SECONDS]: poll the screen until it matches.
wait_for() { wait_until "${2:-30}" screen_has "$1"; }

keys() { tmux send-keys -t "$SESSION" "$@"; }

# run CMD in the shell (typed, as a student would)
type_cmd() { keys "$1" Enter; }

# Down in the lesson pane (at most 6 presses) until the screen shows ERE $1:
# the text scrolls, and a question folded under it opens at its end.
read_down_to() {
    for _ in 1 2 3 4 5 6; do
        screen_has "$1" && return 0
        keys Down
        sleep 0.3
    done
    screen_has "$1"
}

# child_of PID: the first process whose parent is PID (from /proc/*/stat:
# after the parenthesised name come the state, then the parent's pid).
child_of() {
    parent=$1
    for stat in /proc/[0-9]*/stat; do
        { read -r line < "$stat"; } 2>/dev/null || continue
        rest=${line##*) }
        set -- $rest
        [ "${2:-}" = "$parent" ] || continue
        p=${stat#/proc/}
        echo "${p%/stat}"
        return 0
    done
}

# The pid of the stepwise process under the pane's shell.
app_pid() {
    child_of "$(tmux display -p -t "$SESSION" '#{pane_pid}')"
}

# Wait until no stepwise runs under the pane's shell (a sanitizer build may
# take a moment at exit), so that what is typed next goes to the shell.
no_app() { [ -z "$(app_pid)" ]; }
wait_exit() {
    wait_until 30 no_app || fail "stepwise still running after $1"
}

# After the program has gone: the prompt is back, and the terminal is sane.
check_terminal_sane() {
    wait_exit "$1"
    keys "clear" Enter
    wait_for 'PROMPT\$' || fail "no prompt after $1"
    # the marker is computed by the shell, so the typed command line cannot match it
    type_cmd "stty -a | tr ' ;' '\n\n' | grep -E '^-?(icanon|echo|isig)$' | tr '\n' ' '; echo STTY-\$((40+2))"
    # the answer is read from the capture that shows it (a later one may
    # come after the shell repainted, on a loaded machine)
    stty_line() { s=$(screen | grep -E 'icanon.*STTY-42$' | tail -1); [ -n "$s" ]; }
    wait_until 30 stty_line || fail "stty did not answer after $1"
    case "$s" in
        *-icanon*|*-echo\ *|*-isig*) fail "terminal left raw after $1: $s" ;;
    esac
    echo "$s" | grep -q 'icanon' || fail "no stty line after $1"
    # the cursor and echo work: typed text shows up
    type_cmd "echo typed-ok-$1"
    wait_for "^typed-ok-$1" || fail "echo does not work after $1"
}
