#!/bin/sh
# A gradebook nobody else can touch (issue 21). Output paths are checked
# before anything is graded (exit 2, one line, nothing graded, nothing
# left); every entry of the submissions directory gets a row (FIFO, socket,
# links in and out and to the assignment, subdirectory, .txt, no extension,
# hidden); links are never followed; CSV cells are inert in a spreadsheet
# and names are escaped on the terminal; --csv and --results work on
# /dev/stdout through a pipe; numeric options say their range; the
# grader's limits are named as the grader's; an interrupted or killed
# grade, check --plugin X.c or try leaves no temporary directory; a hostile
# lesson progress file costs a warning, not a hang.
. "$(dirname "$0")/lib.sh"
needs_jail
json="$ROOT/tests/e2e/json.awk"
TMPDIR="$WORK/tmp"
export TMPDIR
mkdir "$TMPDIR"
temp_none() { ! ls "$TMPDIR" | grep -q '^stepwise-'; }
temp_made() { ls "$TMPDIR" | grep -q '^stepwise-'; }
no_temp_left() { # WHAT: no stepwise-* directory in TMPDIR (the watcher may take a moment)
    wait_until 30 temp_none || fail "$1 left $(ls "$TMPDIR")"
}

"$SW" record spring --steps 20 -o ref.trace 2>/dev/null || fail "cannot record the assignment"
mkdir class elsewhere
cp ref.trace class/alice.trace
cp ref.trace elsewhere/bob.trace
# A name a spreadsheet would run, and a file name holding an escape sequence.
{ echo '# stepwise trace 1'; echo '# student: =HYPERLINK("http://evil","pass")'; sed -n '2,$p' ref.trace; } \
    > class/formula.trace
esc=$(printf 'x\033[2Jfake.trace')
cp ref.trace "class/$esc"
ln -s ../elsewhere/bob.trace class/zed.trace        # out of the directory
ln -s ../ref.trace class/answer.trace               # to the assignment
ln -s alice.trace class/alias.trace                 # inside: refused too
ln ref.trace class/hardlink.trace 2>/dev/null || cp ref.trace class/hardlink.trace
mkfifo class/pipe.trace
mkdir class/folder
cp ref.trace class/right.txt                        # a correct trace, badly named
echo notes > class/README
cp ref.trace class/.hidden.trace
sock=0
if command -v python3 >/dev/null 2>&1 &&
   python3 -c "import socket; socket.socket(socket.AF_UNIX).bind('class/sock.trace')" 2>/dev/null; then
    sock=1
fi

# --- outputs refused before anything is graded ----------------------------------
refuse() { # WANT ARGS...: exit 2, one line with WANT, nothing on stdout, nothing made
    want=$1; shift
    timeout 120 "$SW" grade --assignment ref.trace "$@" class >out 2>err; rc=$?
    [ "$rc" -eq 2 ] || fail "grade $*: exit $rc, want 2: $(cat out err)"
    [ "$(wc -l < err)" -eq 1 ] || fail "grade $*: stderr is not one line: $(cat err)"
    grep -qF -- "$want" err || fail "grade $*: stderr lacks '$want': $(cat err)"
    [ -s out ] && fail "grade $*: graded before refusing: $(cat out)"
    ls class/*.tmp.* elsewhere/*.tmp.* ./*.tmp.* >/dev/null 2>&1 && fail "grade $*: left a temporary"
    [ -z "$(ls "$TMPDIR")" ] || fail "grade $*: made $(ls "$TMPDIR")"
    return 0
}
refuse "is the assignment" --csv ref.trace
refuse "is one of the submissions" --csv class/alice.trace
refuse "is one of the submissions" --results class/zed.trace   # a link among them
refuse "is one of the submissions" --csv class/pipe.trace
refuse "is inside the submissions directory" --csv class/grades.csv
refuse "is inside the submissions directory" --results elsewhere/../class/r.json
ln -s class classlink
refuse "is inside the submissions directory" --csv classlink/grades.csv
ln -s class/new.csv sneaky.csv
refuse "is inside the submissions directory" --csv sneaky.csv
refuse "cannot create 'nodir/g.csv'" --csv nodir/g.csv
refuse "is a directory" --csv elsewhere
refuse "cannot create '/proc/self/g.csv'" --csv /proc/self/g.csv
refuse "both write to 'g.csv'" --csv g.csv --results g.csv
refuse "both write to 'standard output'" --csv - --results /dev/stdout
if [ "$(id -u)" -ne 0 ]; then   # root writes anywhere
    mkdir ro && chmod 500 ro
    refuse "cannot create 'ro/g.csv'" --csv ro/g.csv
fi
[ -e ref.trace ] && cmp -s ref.trace class/alice.trace || fail "a refused run touched a file"

# --- every entry gets a row --------------------------------------------------------
timeout 300 "$SW" grade --assignment ref.trace --csv g.csv --results r.json class >out 2>err; rc=$?
[ "$rc" -eq 1 ] || fail "grade the class: exit $rc, want 1 (entries skipped): $(cat out err)"
[ -s err ] && fail "grade wrote to stderr: $(cat err)"
tr -d '\r' < g.csv > rows
entries=$(ls -A class | wc -l)
[ "$(($(wc -l < rows) - 1))" -eq "$entries" ] || fail "$entries entries, $(($(wc -l < rows) - 1)) rows: $(cat rows)"
row() { # FILE VERDICT MESSAGE-REGEX
    grep -F ",class/$1,$2," rows | grep -Eq -- "$3" || fail "no '$2' row for $1 saying '$3': $(grep -F "class/$1," rows)"
}
row alice.trace pass ''
row zed.trace skipped "symbolic link to '../elsewhere/bob.trace', outside the submissions directory"
row answer.trace skipped 'symbolic link to the assignment'
row alias.trace skipped "symbolic link to 'alice.trace'"
row hardlink.trace skipped 'the assignment itself'
row pipe.trace skipped 'a FIFO \(named pipe\), not a regular file'
row folder skipped 'a directory'
row right.txt skipped 'not a submission: a \.txt file; traces end in \.trace or \.csv, plugins in \.so or \.c'
row README skipped 'a file without an extension'
row .hidden.trace skipped 'a hidden file'
[ "$sock" = 1 ] && row sock.trace skipped 'a socket'
grep -q "^\"'=HYPERLINK(\"\"http://evil\"\",\"\"pass\"\")\",class/formula.trace,pass," rows \
    || fail "the formula is not neutralised: $(grep formula rows)"
grep -q '^x\\x1b\[2Jfake,class/x\\x1b\[2Jfake.trace,' rows || fail "the escape is not escaped: $(grep fake rows)"
awk '{ sub(/^"/, ""); c = substr($0, 1, 1) } c == "=" || c == "+" || c == "-" || c == "@" { bad = 1; print }
     END { exit bad }' rows || fail "a cell starts like a formula"
LC_ALL=C grep -q "$(printf '\033')" out g.csv r.json && fail "an escape byte reached the table, CSV or JSON"
grep -q 'x\\x1b\[2Jfake' out || fail "the table does not show the escaped name: $(cat out)"
grep -q '^grading 3 submissions against ref.trace .*; [0-9]* other entries not graded' out || fail "heading: $(head -1 out)"
grep -q "other entries not graded, in .*the limits per submission" out || fail "totals: $(tail -1 out)"
awk -f "$json" r.json > fields || fail "results.json is not JSON"
# The class's figure: the homework's points (two checks, header and values)
# and the mean of the three traces, which all pass; skipped entries are no
# submissions and do not count.
grep -qx "max_score=2" fields || fail "results.json max_score: $(grep max_score fields)"
grep -qx 'score=2' fields || fail "results.json score: $(grep '^score' fields)"
grep -q '^tests\[[0-9]*\]\.output=skipped: not graded: a symbolic link to the assignment$' fields \
    || fail "a skipped entry's output: $(grep answer fields)"
cmp -s ref.trace elsewhere/bob.trace || fail "the link's target changed"

# Named on the command line (a shell glob): the same rules, links refused.
timeout 300 "$SW" grade --assignment ref.trace class/alice.trace class/zed.trace class/right.txt >out 2>&1; rc=$?
[ "$rc" -eq 1 ] || fail "grade named files: exit $rc: $(cat out)"
grep -q 'zed.trace .*skipped .*symbolic link' out && grep -q 'right.txt .*skipped' out \
    || fail "named files: $(cat out)"

# --- reports on standard output ------------------------------------------------------
timeout 300 "$SW" grade --assignment ref.trace --csv /dev/stdout class 2>err | cat > piped.csv
tr -d '\r' < piped.csv | cmp -s - rows || fail "--csv /dev/stdout through a pipe: $(head -3 piped.csv)"
grep -q '^grading 3 submissions' err || fail "the table did not move to stderr: $(head -2 err)"
timeout 300 "$SW" grade --assignment ref.trace --results /dev/stdout class 2>/dev/null | cat > piped.json
# The totals carry the wall time: the same run may take 0.1 s or 0.2 s.
untimed() { sed 's/ in [0-9.]* s;/ in T s;/' "$1"; }
awk -f "$json" piped.json > pfields && untimed fields > f1 && untimed pfields > f2 && cmp -s f1 f2 ||
    fail "--results /dev/stdout through a pipe: $(diff fields pfields)"
timeout 300 "$SW" grade --assignment ref.trace --csv - class 2>/dev/null > file.csv
tr -d '\r' < file.csv | cmp -s - rows || fail "--csv - into a file"
timeout 300 "$SW" grade --assignment ref.trace --csv /dev/null --results /dev/null class >/dev/null 2>&1
[ $? -eq 1 ] || fail "--csv /dev/null"

# --- numeric options: the range in the message ----------------------------------------
bad_number() { # OPTION VALUE WANT
    "$SW" grade --assignment ref.trace "$1" "$2" class >out 2>err; rc=$?
    [ "$rc" -eq 2 ] && [ ! -s out ] && [ "$(wc -l < err)" -eq 1 ] && grep -qF -- "$3" err \
        || fail "grade $1 $2: exit $rc, want 2 with '$3': $(cat out err)"
}
# --worker is how grade starts a plugin's worker again as a program, never
# an option: without its mark in the environment, or with the mark but no
# channel (a socket) on descriptor 3, it is refused in one line.
for mark in "" 1; do
    STEPWISE_GRADE_WORKER=$mark "$SW" grade --worker 1 build class/alice.trace 0 0 "" --assignment ref.trace \
        >out 2>err 3>/dev/null; rc=$?
    [ "$rc" -eq 2 ] && [ ! -s out ] && [ "$(wc -l < err)" -eq 1 ] &&
        grep -qF -- "--worker is how grade starts a plugin's worker, not an option" err ||
        fail "grade --worker (mark '$mark'): exit $rc, want 2 and the refusal: $(cat out err)"
done
# A worker whose record cannot be sent (the grader gone, its channel
# closed) ends with status 1, which the grader records as the worker's
# end, not 0 as if it had reported (issue 39). Here a plugin's worker,
# started as grade starts it, gets a trace assignment (so it sends a
# "wrong kind" record at once) on a socket whose other end is closed;
# with the other end open it sends its record and ends 0.
if command -v python3 >/dev/null 2>&1; then
    for peer in closed open; do
        got=$(python3 - "$SW" "$peer" <<'EOF'
import os, socket, sys
sw, peer = sys.argv[1], sys.argv[2]
mine, theirs = socket.socketpair()
if peer == "closed":
    mine.close()
pid = os.fork()
if pid == 0:
    os.dup2(theirs.fileno(), 3)
    env = dict(os.environ, STEPWISE_GRADE_WORKER="1")
    out = os.open(os.devnull, os.O_WRONLY)
    os.dup2(out, 1)
    os.dup2(out, 2)
    os.execve(sw, [sw, "grade", "--worker", "0", ".", "sub.c", "0", "0", "", "--assignment", "ref.trace"], env)
theirs.close()
received = 0
if peer == "open":
    while True:
        part = mine.recv(65536)
        if not part:
            break
        received += len(part)
_, status = os.waitpid(pid, 0)
print(os.waitstatus_to_exitcode(status), received)
EOF
        ) || fail "the worker's channel harness failed"
        case $peer in
        closed) [ "${got% *}" = 1 ] || fail "a worker whose record cannot be sent: status and bytes '$got', want status 1" ;;
        open) [ "${got% *}" = 0 ] && [ "${got#* }" -gt 0 ] ||
            fail "a worker with its channel open: status and bytes '$got', want status 0 and its record" ;;
        esac
    done
else
    echo "skip: a worker's failed write: no python3 to give it a closed channel"
fi
bad_number --cpu 1e308 "--cpu must be between 0.1 and 3600 seconds"
bad_number --cpu nan "--cpu must be between 0.1 and 3600 seconds"
bad_number --cpu inf "--cpu must be between 0.1 and 3600 seconds"
bad_number --wall 0 "--wall must be between 0.1 and 86400 seconds"
bad_number --memory 1e9 "--memory must be between 64 and 65536 MiB"
bad_number --output 1 "--output must be between 4 and 1048576 KiB"
bad_number --plugin-timeout -1 "--plugin-timeout must be between 0.01 and 3600 seconds"
bad_number --rtol 2 "--rtol must be between 1e-16 and 1"
bad_number --atol 1e999 "--atol must be between 1e-300 and 1000000"

# --- the grader's limits are the grader's ----------------------------------------------
mkdir plugins
cp "$ROOT/examples/euler_plugin.c" plugins/mine.c
timeout 300 "$SW" grade --assignment ref.trace --output 4 plugins >out 2>&1
grep -q "mine.c .*error .*the compiler reached the grader's --output limit of 4 KiB while building it" out \
    || fail "--output 4: $(cat out)"
grep -q 'does not compile' out && fail "--output 4 blamed on the student: $(cat out)"
no_temp_left "grade --output 4"

# --- interrupted and killed: no temporary directory left -------------------------------
cat > plugins/loop.c <<'C'
#include <stepwise/integrator.h>
static int step(sw_ode *ode, double t, double *y, double h, double *work)
{
    (void)ode; (void)t; (void)y; (void)h; (void)work;
    for (volatile int spin = 1; spin;) { }
    return 0;
}
static const sw_plugin info = { .abi = SW_PLUGIN_ABI, .name = "loop", .label = "loops",
    .order = 1, .evals = 1, .work_vectors = 1, .step = step };
const sw_plugin *sw_plugin_info(void);
const sw_plugin *sw_plugin_info(void) { return &info; }
C
# stop N SIGNAL COMMAND...: start it, wait until it has made its directory,
# signal it; in the background, with a TMPDIR of its own (tmp-N), so that
# the cases run side by side (each holds a second before its signal)
stops=""
stop() {
    n=$1 sig=$2; shift 2
    (
        TMPDIR=$WORK/tmp-$n
        mkdir "$TMPDIR" || exit 1
        STEPWISE_PLUGIN_TIMEOUT=60 "$@" >/dev/null 2>&1 &
        pid=$!
        wait_until 30 temp_made
        sleep 1   # into the build or the run (either must leave nothing: not a race the test needs to win)
        kill -s "$sig" "$pid" 2>/dev/null
        wait "$pid" 2>/dev/null
        no_temp_left "$sig to $*"
    ) > "stop-$n.log" 2>&1 &
    stops="$stops $n:$!"
}
stop 1 INT "$SW" grade --assignment ref.trace plugins
stop 2 TERM "$SW" grade --assignment ref.trace plugins
stop 3 KILL "$SW" grade --assignment ref.trace plugins
stop 4 TERM "$SW" check --plugin plugins/loop.c --reference euler --scene spring
stop 5 KILL "$SW" check --plugin plugins/loop.c --reference euler --scene spring
stop 6 TERM "$SW" try plugins/loop.c --no-play
stop 7 KILL "$SW" try plugins/loop.c --no-play
if env --default-signal=INT true 2>/dev/null; then   # a background job's SIGINT is ignored otherwise
    stop 8 INT env --default-signal=INT "$SW" check --plugin plugins/loop.c --reference euler --scene spring
    stop 9 INT env --default-signal=INT "$SW" try plugins/loop.c --no-play
fi
for np in $stops; do
    wait "${np#*:}" || { cat "stop-${np%%:*}.log"; fail "a stopped command left its temporary directory (above)"; }
done
"$SW" check --plugin plugins/mine.c --reference euler --scene spring >/dev/null 2>&1
no_temp_left "check --plugin X.c"

# --- the lesson progress file: a warning, not a hang --------------------------------------
mkdir -p state/stepwise
progress=state/stepwise/progress
for kind in fifo zero sparse; do
    rm -f "$progress"
    case $kind in
        fifo) mkfifo "$progress" ;;
        zero) ln -s /dev/zero "$progress" ;;
        sparse) truncate -s 2G "$progress" ;;
    esac
    # a FIFO read would block, a 2 GiB file take long: timeout (a hang's
    # guard, 124) would end it, and the exit status would not be 2
    XDG_STATE_HOME="$WORK/state" timeout 120 "$SW" lesson 1 </dev/null >out 2>err; rc=$?
    [ "$rc" -eq 2 ] || fail "lesson with a $kind progress file: exit $rc: $(cat err)"
    grep -q "^stepwise: warning: the progress file '.*progress' is .*; lessons start from their first page" err \
        || fail "no warning for a $kind progress file: $(cat err)"
    grep -q 'lessons need a terminal' err || fail "$kind: $(cat err)"
done
rm -f "$progress"
echo ok
