#!/bin/sh
# e2e: long (run.sh starts it first)
# The hostile-submission suite (issue 21, "What it must show"). Submissions
# come from someone who wants a better grade or a classmate's worse one.
# tests/hostile/ holds one file per attack family (evil.h says how each
# makes its success visible). Seven classes, each with honest classmates
# (correct traces from `stepwise record`, a correct .c, a correct .so) —
# A forged results and attacks on processes, B and C one grader-killer each
# (kill-grader, stop-grader), D a compiler that never ends (inc-fifo), E
# the CPU, memory, disk, process and descriptor hogs, F attacks on files
# (reading, writing, the daemon, compile-time includes, crafted traces,
# directory tricks), G forge-ancestors (stops and kills the grader, forges
# its gradebook) — are graded at once, each with
#     stepwise grade --assignment A --cpu 2 --wall 40 --csv G --results R CLASS
# (D with grade's default wall-clock limit; A also with --feedback) and
# STEPWISE_PLUGIN_TIMEOUT=10:
# on a busy machine a watchdog must not stop an attack before it has run
# (which would pass for a defence); the limits under test decide.
# while check --plugin, try and record run hostile plugins; as root, at the
# same time as an unprivileged user (swhostile, made when missing), and as
# root in the jail of a user of its own (the container mode, where user
# namespaces are refused: STEPWISE_JAIL=uid); run as another user the suite
# runs once, as that user. Then:
#   (a) every entry of a class has a row; every hostile one fails (a pass
#       means its attack worked);
#   (b) every honest classmate passes and keeps a byte-identical file (so
#       do the assignment, the teacher's home and another class's files);
#   (c) the CSV and results.json are byte-identical 5 s after grade exits;
#       grade exits 1 (never killed, never stopped for good, never hung);
#   (d) no process a submission started outlives grade;
#   (e) no marker file of an attack is found outside a sandbox (this
#       test's directory, /tmp, /var/tmp, /dev/shm, $HOME), no connection
#       reached the test's listener, and grade and check leave nothing in
#       their TMPDIR;
#   (f) grade's stdout/stderr hold no raw control bytes and no forged rows,
#       nothing read from a secret reaches them or the gradebook, and no
#       CSV cell starts with = + - @ TAB or CR; no raw bidirectional or
#       zero-width character (U+202E, U+2066, U+200B, ...) reaches them,
#       the gradebook or the feedback files; no forged gradebook stands;
# and for check --plugin, try and record: a wrong plugin never exits 0 or
# prints PASS, stepwise never dies of a signal, prints no raw control byte
# nor bidirectional character, and nothing a plugin started survives.
# find-builtin is also checked on the chain and (ode->fast only) the
# vortex flow, as `check --plugin P --reference rk4 --scene S`.
# Every failure is one line, "FAIL: [as USER] WHAT: PROPERTY"; the suite
# goes on and exits 1 at the end. A resource hog that could not finish its
# attack in time on a very busy machine hands in NaN and gets a NOTE line
# ("inconclusive"), not a pass. Narrow it while working on one layer:
#     HOSTILE_ONLY="daemon network traces dirtricks"   families to include
#     HOSTILE_AS=root | user | container               one pass only (as root;
#                                                       container: the jail of a
#                                                       user of its own, STEPWISE_JAIL=uid)
#     HOSTILE_KEEP=1                                    keep the directory (its path is printed)
# Needs POSIX sh, coreutils, cc, and (as root) useradd and setpriv.
. "$(dirname "$0")/lib.sh"
needs_jail
H=$ROOT/tests/hostile
JSON=$ROOT/tests/e2e/json.awk
CPU=2           # the teacher's --cpu: cpu-hog must not get more
# Hang guards only (a grade normally takes 10-30 s, a check a second): a
# stopped grader is continued by the test, a compiler that blocks is ended
# by grade's own wall limit.
GRADE_LIMIT=180 # seconds before the test gives up on one grade
RUN_LIMIT=60    # ... on one check, try or record
AS=""
# One line per failure, also from subshells (a pipeline's loop, the
# background check part).
bad() {
    echo "FAIL: ${AS:+[as $AS] }$*"
    echo x >> "$WORK/failures"
}
now_ms() { echo $(($(date +%s%N) / 1000000)); }
T0=$(now_ms)
note() { echo "hostile: ${AS:+[as $AS] }$* ($((($(now_ms) - T0) / 1000)) s)"; }

PLUGINS="ctl-block ctor-seal find-builtin forge-fds forge-pidfd forge-procfd forge-stdout info-evil
         label-bidi label-escape network probe-forge ptrace-parent see-procs signal-probe vm-write"
HOGS="cpu-hog disk-fill fd-exhaust fork-bomb mem-hog"
FILERS="daemon read-others write-others"
INCS="inc-classmate inc-parent inc-passwd inc-secret inc-zero"
FAMILIES="$PLUGINS $HOGS $FILERS ctor-evil $INCS inc-fifo kill-grader stop-grader forge-ancestors"
# check --plugin takes these as .so (grade builds the .c ones); record and
# try the ones that reach stepwise's own process or output.
CHECK_PLUGINS="ctl-block ctor-evil ctor-seal find-builtin forge-ancestors forge-fds forge-pidfd forge-procfd
               forge-stdout label-bidi network probe-forge ptrace-parent read-others"
RECORD_PLUGINS="ctl-block forge-pidfd forge-procfd forge-stdout label-bidi probe-forge"
TRY_PLUGINS="ctl-block forge-procfd label-bidi probe-forge" # try always measures: 25 s under ASan
# check --plugin P --reference rk4 --scene SCENE, FAMILY:FIND_VIA:SCENE
# (find-builtin.c: 7 every way; 6 a system's fused rk4 alone, no table)
SCENE_CHECKS="find-builtin:7:chain find-builtin:6:vortex"
HONEST="alice.trace bob.c carol.so yves.c zoe.trace"

wanted() {
    [ -z "${HOSTILE_ONLY:-}" ] && return 0
    case " $HOSTILE_ONLY " in *" $1 "*) return 0 ;; esac
    return 1
}

# What a pass of each hostile entry means: its attack worked.
pass_means() {
    case $1 in
        read-others.c) echo "it read the assignment, classmates' files or the teacher's home" ;;
        see-procs.c) echo "it could see the grader's process in /proc" ;;
        signal-probe.c) echo "it could send the grader a signal" ;;
        ptrace-parent.c) echo "it could ptrace the grader" ;;
        vm-write.c) echo "it could write the grader's memory (process_vm_writev)" ;;
        forge-pidfd.c) echo "it took the grader's descriptors (pidfd_getfd), or its forged record was believed" ;;
        forge-fds.c) echo "a forged record written on its descriptors was believed" ;;
        network.c) echo "it reached the network (127.0.0.1 or an abstract socket)" ;;
        fork-bomb.c) echo "it held 64 processes or more" ;;
        fd-exhaust.c) echo "it held more than 4096 descriptors" ;;
        disk-fill.c) echo "it wrote 8 MiB or more of files" ;;
        mem-hog.c) echo "it held 1.25 GiB or more (the limit is 1024 MiB)" ;;
        cpu-hog.c) echo "it used more than --cpu $CPU s of CPU and was not stopped" ;;
        ctor-evil.so) echo "its constructor read others' files or reached the network" ;;
        ctor-seal.c) echo "its constructor's seccomp filter kept the seal from being installed (a file opened at a step)" ;;
        find-builtin.c) echo "it found stepwise's built-in rk4 (the integrator table or a fused step) in its memory and stepped with it" ;;
        forge-ancestors.c) echo "it stopped its ancestors, forged the gradebook and killed them, or lived on" ;;
        info-evil.c) echo "its sw_plugin_info() read the assignment or the teacher's home" ;;
        inc-classmate.c) echo "it was built from a classmate's file (#include \"bob.c\")" ;;
        inc-parent.c) echo "it was built from a file outside the submissions directory" ;;
        inc-secret.c) echo "it was built from the teacher's reference.h in \$HOME" ;;
        zed.trace | link-out.trace) echo "a link out of the submissions directory was followed" ;;
        *) echo "a hostile submission passed" ;;
    esac
}

# The number of raw control bytes in a file (not LF or TAB; not CR when $2 is 1).
controls() {
    keep='\n\t'
    [ "${2:-0}" = 1 ] && keep='\n\t\r'
    LC_ALL=C tr -d "$keep" < "$1" | LC_ALL=C tr -d '\040-\176\200-\377' | wc -c | tr -d ' '
}
# What forged text looks like (evil.h's evil_fake): a row for Mallory, a
# PASS line ending in SWEVIL:FAMILY.
FORGED='Mallory\|rk4 SWEVIL:'
# Raw bidirectional and zero-width characters (label-bidi.c): U+200B..U+200F,
# U+202A..U+202E, U+2066..U+2069 in UTF-8.
BIDI=$(printf '\342\200[\213-\217\252-\256]\\|\342\201[\246-\251]')
bidi() { LC_ALL=C grep -ac "$BIDI" "$1" 2>/dev/null; } # lines holding one
# A sanitizer build reports a crash this way (and exits 1, not by the signal).
SANITIZER='AddressSanitizer\|LeakSanitizer\|UndefinedBehaviorSanitizer\|runtime error:'
# The attacks whose SWEVIL:FAMILY text is in a file, on one line.
evil_texts() { grep -ao 'SWEVIL:[a-z0-9-]*' "$1" 2>/dev/null | sort -u | tr '\n' ' '; }

# ---- the machine ---------------------------------------------------------------

RUN=$(od -An -N3 -tx1 /dev/urandom | tr -d ' \n')
PIDNS=$(readlink /proc/self/ns/pid)
MYHOME=${HOME:-/nonexistent}
BIN=$WORK/bin
mkdir -p "$BIN" || fail "cannot make $BIN"
# A world-readable copy of the binary and the headers: the repository may
# sit under a directory the unprivileged user cannot enter.
# The plugin host goes beside it, where stepwise looks first.
cp "$STEPWISE" "$BIN/stepwise" && cp -R "$ROOT/include" "$BIN/include" || fail "cannot copy stepwise"
host=$(dirname "$STEPWISE")/stepwise-plugin-host
[ -x "$host" ] || host=$(dirname "$STEPWISE")/build/stepwise-plugin-host
cp "$host" "$BIN/stepwise-plugin-host" || fail "cannot copy the plugin host"
cc -std=c11 -O2 -o "$BIN/netwatch" "$H/netwatch.c" || fail "cannot build tests/hostile/netwatch.c"
# The container pass is reached the way Docker reaches it where this
# machine allows (root in a user namespace of its own that may make no
# other: tests/e2e/nouserns.c), else forced by the tests' switch.
NOUSERNS=""
if [ "$(id -u)" = 0 ] && cc -std=c11 -O2 -o "$BIN/nouserns" "$ROOT/tests/e2e/nouserns.c" 2>/dev/null &&
   "$BIN/nouserns" true 2>/dev/null; then
    NOUSERNS=$BIN/nouserns
fi
chmod -R a+rX "$BIN" && chmod 755 "$WORK" || fail "cannot open $WORK to other users"
SWB=$BIN/stepwise
"$BIN/netwatch" "$WORK/net.port" "$WORK/net.log" "swevil-net-$RUN" 600 &
NETPID=$!
i=0
while [ ! -s "$WORK/net.port" ] && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
PORT=$(cat "$WORK/net.port" 2>/dev/null) || fail "the listener did not start"

# The live processes of these tokens' attacks, "PID<TAB>NAME<TAB>COMMAND"
# (zombies are dead and left out): found by the name attacks give their
# processes (sw + token + family) and by a class's or a plugin directory's
# name in the command line.
survivors() { # TOKEN...
    pc="" pl=""
    for t in "$@"; do
        pc="$pc -e ^sw$t"
        pl="$pl -e swclas[s]-$t -e swchec[k]-$t"
    done
    # shellcheck disable=SC2086
    for f in $(grep -l $pc /proc/[0-9]*/comm 2>/dev/null) $(grep -la $pl /proc/[0-9]*/cmdline 2>/dev/null); do
        p=${f#/proc/}
        p=${p%/*}
        [ "$p" = $$ ] && continue
        { read -r st < "/proc/$p/stat"; } 2>/dev/null || continue
        st=${st##*) }
        [ "${st%% *}" = Z ] && continue
        { read -r comm < "/proc/$p/comm"; } 2>/dev/null || comm=?
        cmd=$(tr '\0' ' ' < "/proc/$p/cmdline" 2>/dev/null | cut -c1-160)
        printf '%s\t%s\t%s\n' "$p" "$comm" "$cmd"
    done | sort -u -k1,1n
}
# Which family a survivor belongs to: its name, or the submission in its command line.
survivor_family() { # NAME COMMAND
    c=${1#sw"$RUN"}
    if [ "$c" != "$1" ]; then
        c=${c#??}
        for f in $FAMILIES; do case $f in "$c"*) echo "$f"; return ;; esac; done
    fi
    s=$(printf '%s\n' "$2" | grep -o "swclass-$RUN[a-z]*/[^ ]*" | head -1)
    [ -n "$s" ] && { echo "${s##*/}"; return; }
    echo "a process of stepwise"
}
kill_survivors() { # TOKEN...
    for p in $(survivors "$@" | cut -f1); do
        kill -KILL "$p" 2>/dev/null
        kill -CONT "$p" 2>/dev/null
    done
}
report_survivors() { # CONTEXT TOKEN...
    what=$1
    shift
    survivors "$@" > "$BOOK/surv-$1"
    while IFS='	' read -r p comm cmd; do
        bad "$(survivor_family "$comm" "$cmd"): process $p ($comm: $(echo "$cmd" | cut -c1-90)) outlived $what"
    done < "$BOOK/surv-$1"
    kill_survivors "$@"
    i=0
    while [ -n "$(survivors "$@")" ] && [ $i -lt 20 ]; do sleep 0.1; i=$((i + 1)); done
}

# This run's marker files wherever the attacks may have put them.
markers() { # GLOB
    { find "$WORK" -name "swevil-$1*" 2>/dev/null
      find /tmp /var/tmp /dev/shm -maxdepth 2 -name "swevil-$1*" 2>/dev/null
      find "$MYHOME" -maxdepth 1 -name "swevil-$1*" 2>/dev/null
    } | sort -u
}
family_of_marker() { # swevil-TOKEN-FAMILY-WHAT
    rest=${1#swevil-????????-}
    best=""
    for f in $FAMILIES; do
        case $rest in "$f"*) [ ${#f} -gt ${#best} ] && best=$f ;; esac
    done
    echo "${best:-?}"
}
context_of_marker() { # swevil-TOKEN-...: the token's 7th character names its class
    t=${1#swevil-}
    t=${t%"${t#???????}"}
    case $t in *[klm]) echo "check, try and record" ;; *) echo "grading" ;; esac
}
report_markers() { # GLOB
    markers "$1" > "$BOOK/marks"
    while read -r m; do
        b=${m##*/}
        printf '%s|%s|%s\n' "$(family_of_marker "$b")" "$(context_of_marker "$b")" "$m"
    done < "$BOOK/marks" | awk -F'|' '{ k = $1 "|" $2; n[k]++; if (!(k in ex)) ex[k] = $3 }
        END { for (k in n) printf "%s|%d|%s\n", k, n[k], ex[k] }' | sort > "$BOOK/marks-by"
    while IFS='|' read -r f ctx n ex; do
        bad "$f: wrote $n file(s) outside a sandbox during $ctx, e.g. $ex"
    done < "$BOOK/marks-by"
    while read -r m; do rm -f "$m"; done < "$BOOK/marks"
    grep -a "swevil-$(echo "$1" | tr '?' '.')" "$WORK/net.log" 2>/dev/null | sort -u > "$BOOK/net"
    while read -r how who rest; do
        bad "$(family_of_marker "$who-x"): reached the network during $(context_of_marker "$who") ($how: $who $rest)"
    done < "$BOOK/net"
}

cleanup() {
    kill "$NETPID" 2>/dev/null
    kill_survivors "$RUN"
    markers "$RUN" | while read -r m; do rm -f "$m"; done
}
if [ -n "${HOSTILE_KEEP:-}" ]; then
    trap 'cleanup; echo "hostile: kept $WORK"' EXIT
else
    trap 'cleanup; tmux_cleanup; rm -rf "$WORK"' EXIT
fi
trap 'exit 130' INT TERM HUP

if [ "$(id -u)" = 0 ]; then
    MODES=${HOSTILE_AS:-root user container}
    case " $MODES " in
        *" user "*)
            command -v setpriv >/dev/null || fail "setpriv (util-linux) is needed to run as another user"
            id swhostile >/dev/null 2>&1 || useradd -M -r -s /bin/sh swhostile ||
                fail "cannot create the unprivileged user swhostile"
            ;;
    esac
else
    MODES=self
fi
# A pass whose user can build no jail (root can, but unprivileged user
# namespaces are refused: a chroot, a container) says so and is left out.
case " $MODES " in
    *" user "*)
        if ! why=$(setpriv --reuid=swhostile --regid="$(id -g swhostile)" --clear-groups -- \
                   env -i PATH="$PATH" "$SWB" autograder --probe 2>&1); then
            echo "skip: the pass as swhostile: no jail for plugins can be built for an unprivileged user here: $why"
            MODES=$(echo " $MODES " | sed 's/ user / /')
        fi
        ;;
esac

# runas MODE CMD...: CMD with a clean environment (HOME: the teacher's
# home; a 10 s plugin watchdog; TMPDIR: $RUN_TMPDIR when set), as root,
# as swhostile, or as the caller.
runas() {
    m=$1
    shift
    set -- env -i PATH="$PATH" HOME="$TH" LC_ALL=C STEPWISE_INCLUDE="$BIN/include" STEPWISE_PLUGIN_TIMEOUT=10 \
        ${RUN_TMPDIR:+TMPDIR="$RUN_TMPDIR"} \
        ${ASAN_OPTIONS:+ASAN_OPTIONS="$ASAN_OPTIONS"} ${UBSAN_OPTIONS:+UBSAN_OPTIONS="$UBSAN_OPTIONS"} \
        ${CC:+CC="$CC"} "$@"
    # container: as root, in the jail of a user of its own (what serves where
    # user namespaces are refused), reached as under Docker or forced
    if [ "$m" = container ]; then
        if [ -n "$NOUSERNS" ]; then set -- "$NOUSERNS" "$@"; else set -- env STEPWISE_JAIL=uid "$@"; fi
    fi
    if [ "$m" = user ]; then
        setpriv --reuid=swhostile --regid="$(id -g swhostile)" --clear-groups -- "$@"
    else
        "$@"
    fi
}

# A family's source as one file (evil.h pasted in), placeholders filled.
fill() { # TOKEN < SRC
    sed -e "s|@TOKEN@|$1|g" -e "s|@PORT@|$PORT|g" -e "s|@HOME@|$TH|g" -e "s|@CPU@|$CPU|g" \
        -e "s|@PIDNS@|$PIDNS|g"
}
gen() { # FAMILY TOKEN [FIRST-LINE]
    { [ -n "${3:-}" ] && printf '%s\n' "$3"
      awk -v f="$H/evil.h" '/^#include "evil.h"/ { while ((getline l < f) > 0) print l; close(f); next } { print }' \
          "$H/$1.c"; } | fill "$2"
}
build_so() { # FAMILY TOKEN OUT.so [FIRST-LINE]
    b=$BOOK/$(basename "$3" .so)-$2.c
    gen "$1" "$2" "${4:-}" > "$b" && cc -std=c11 -O2 -shared -fPIC -I"$BIN/include" -o "$3" "$b"
}
named() { # TRACE STUDENT: the trace with a "# student:" line
    { head -n 1 "$1"; printf '# student: %s\n' "$2"; tail -n +2 "$1"; }
}
# The protected files, "sha256 path" per line: every honest classmate,
# another class's work, the assignment and the teacher's home.
hashes() {
    { for c in "$D"/swclass-*; do
          for f in $HONEST; do echo "$c/$f"; done
      done
      echo "$D/outside/bob.trace"
      echo "$D/outside/solution.c"
      echo "$D/assignment.txt"
      echo "$TH/reference.h"
    } | while read -r f; do
        if [ -f "$f" ]; then h=$(sha256sum < "$f" | cut -c1-64); else h=missing; fi
        echo "$h $f"
    done
}
gb_hash() { # CLASS: the gradebook's state
    for f in "$D/grades-$1.csv" "$D/results-$1.json"; do
        if [ -f "$f" ]; then sha256sum < "$f" | cut -c1-16; else echo none; fi
    done | tr '\n' ' '
}
token_of() { # CLASS
    case $1 in A) echo "$TA" ;; B) echo "$TB" ;; C) echo "$TC" ;; D) echo "$TD" ;; E) echo "$TE" ;; F) echo "$TF" ;;
        G) echo "$TG" ;; esac
}
limits_of() { # CLASS: grade's limits (and A's feedback files)
    case $1 in D) echo "--cpu $CPU" ;; A) echo "--cpu $CPU --wall 40 --feedback feedback-A" ;; *) echo "--cpu $CPU --wall 40" ;; esac
}

# "PID TOKEN" for each stepwise process of these tokens that is stopped (state T).
stopped() { # TOKEN...
    for f in /proc/[0-9]*/stat; do
        { read -r st < "$f"; } 2>/dev/null || continue
        s=${st##*) }
        [ "${s%% *}" = T ] || continue
        p=${f#/proc/}
        p=${p%/stat}
        cmd=$(tr '\0' ' ' < "/proc/$p/cmdline" 2>/dev/null)
        for t in "$@"; do
            case $cmd in *stepwise*"swclass-$t"*) echo "$p $t" ;; esac
        done
    done
}

# Judge one run of check, try or record on a hostile plugin.
judge() { # WHAT RC OUT ERR WRONG(1: must not exit 0) [MS: how long it ran]
    case $2 in
        0) [ "$5" = 1 ] && bad "$1: exit 0: a wrong plugin passed" ;;
        1 | 2) ;;
        124 | 137)
            # timeout exits 137 too when stepwise was killed by someone else
            if [ "$2" = 137 ] && [ "${6:-$((RUN_LIMIT * 1000))}" -lt $((RUN_LIMIT * 1000)) ]; then
                bad "$1: stepwise was killed (SIGKILL) after $((${6:-0} / 1000)) s, not by the test: by its plugin?"
            else
                bad "$1: did not end within $RUN_LIMIT s"
            fi
            ;;
        *)
            if [ "$2" -gt 128 ]; then
                bad "$1: stepwise died of SIG$(kill -l $(($2 - 128)) 2>/dev/null) (exit $2)"
            else
                bad "$1: exit $2 (want 0, 1 or 2)"
            fi
            ;;
    esac
    if [ "$5" = 1 ] && grep -q 'PASS' "$3"; then
        bad "$1: printed PASS: $(grep -m1 'PASS' "$3" | LC_ALL=C tr -d '\000-\037' | cut -c1-100)"
    fi
    grep -aq "$SANITIZER" "$4" && bad "$1: stepwise failed under the sanitizer: $(grep -a -m1 "$SANITIZER" "$4" | cut -c1-120)"
    for s in "$3" "$4"; do
        w=stdout
        [ "$s" = "$4" ] && w=stderr
        n=$(controls "$s")
        [ "$n" -eq 0 ] || bad "$1: $n raw control bytes on $w (from: $(evil_texts "$s"))"
        grep -aq "$FORGED" "$s" && bad "$1: forged text on $w (from: $(evil_texts "$s"))"
        n=$(bidi "$s")
        [ "$n" -eq 0 ] || bad "$1: $n line(s) on $w hold raw bidirectional or zero-width characters (U+202E, U+2066, U+200B, ...)"
    done
}

# check --plugin, record and try on hostile plugins: worker W of N takes
# every Nth (in the background, while the classes are graded).
CHECK_WORKERS=3 # at most 3: check_token
# Each worker has a token of its own (k, l, m in the class's place): an
# attack on "every stepwise process of the run" must not reach another
# worker's runs.
check_token() { # W
    case $1 in 0) echo "${RUN}k$U" ;; 1) echo "${RUN}l$U" ;; *) echo "${RUN}m$U" ;; esac
}
check_part() { # W N
    TK=$(check_token "$1")
    CK=$D/swcheck-$TK
    k=0
    out=$BOOK/ck-out-$1
    err=$BOOK/ck-err-$1
    RUN_TMPDIR=$D/tmp-k$1
    for p in $CHECK_LIST; do
        k=$((k + 1))
        [ $((k % $2)) -eq "$1" ] || continue
        src=$CK/$p.so
        build_so "$p" "$TK" "$src" || { bad "cannot build $src"; continue; }
        [ "$M" = user ] && chown swhostile "$src"
        t0=$(now_ms)
        ( cd "$D" && runas "$M" timeout -k 5 "$RUN_LIMIT" "$SWB" check --plugin "$src" --assignment check-assignment.txt \
              --no-measure ) >"$out" 2>"$err"
        judge "check --plugin $p" $? "$out" "$err" 1 $(($(now_ms) - t0))
        case " $RECORD_PLUGINS " in
            *" $p "*)
                t0=$(now_ms)
                ( cd "$D" && runas "$M" timeout -k 5 "$RUN_LIMIT" "$SWB" record spring --plugin "$src" --set g=9.81 \
                      --dt 0.01 --steps 100 -o "$CK/rec-$p.trace" ) >"$out" 2>"$err"
                judge "record --plugin $p" $? "$out" "$err" 0 $(($(now_ms) - t0))
                n=$(bidi "$CK/rec-$p.trace")
                [ "${n:-0}" -eq 0 ] ||
                    bad "record --plugin $p: its trace holds raw bidirectional or zero-width characters ($n line(s))"
                ;;
        esac
        case " $TRY_PLUGINS " in
            *" $p "*)
                t0=$(now_ms)
                ( cd "$D" && runas "$M" timeout -k 5 "$RUN_LIMIT" "$SWB" try "$src" --reference rk4 --scene spring \
                      --set g=9.81 --no-play ) >"$out" 2>"$err"
                judge "try $p" $? "$out" "$err" 1 $(($(now_ms) - t0))
                ;;
        esac
    done
    # a plugin checked on a scene against a built-in method, measured too
    for c in $SCENE_CHECKS; do
        p=${c%%:*} v=${c#*:}
        scene=${v#*:} v=${v%%:*}
        wanted "$p" || continue
        k=$((k + 1))
        [ $((k % $2)) -eq "$1" ] || continue
        src=$CK/$p-$v-$scene.so
        build_so "$p" "$TK" "$src" "#define FIND_VIA $v" || { bad "cannot build $src"; continue; }
        [ "$M" = user ] && chown swhostile "$src"
        t0=$(now_ms)
        ( cd "$D" && runas "$M" timeout -k 5 "$RUN_LIMIT" "$SWB" check --plugin "$src" --reference rk4 \
              --scene "$scene" ) >"$out" 2>"$err"
        judge "check --plugin $p (FIND_VIA $v) --reference rk4 --scene $scene" $? "$out" "$err" 1 $(($(now_ms) - t0))
    done
}

# The rows of one class: (a), (b), (c)'s exit status, (f).
judge_class() { # CLASS
    X=$1
    T=$(token_of "$X")
    rc=$(cat "$BOOK/rc-$X" 2>/dev/null || echo "?")
    case $X in
        B) who=kill-grader ;; C) who=stop-grader ;; D) who=inc-fifo ;; G) who=forge-ancestors ;;
        *) who="class $X" ;;
    esac
    want=0
    grep -qvxF "$(printf '%s\n' $HONEST)" "$BOOK/entries-$X" && want=1
    eval "gend=\${END_$X:-0}"
    ran=$((gend - GRADES_START))
    case $rc in
        "$want") ;;
        137) # timeout's status for a grade killed by anyone
            if [ "$ran" -ge 0 ] && [ "$ran" -lt $((GRADE_LIMIT * 1000)) ]; then
                bad "$who: grade was killed (SIGKILL) after $((ran / 1000)) s, not by the test: nobody in the class gets a grade from it"
            else
                bad "$who: grade did not end within $GRADE_LIMIT s (the test killed it)"
            fi
            ;;
        124) bad "$who: grade did not end within $GRADE_LIMIT s (the test killed it)" ;;
        *)
            if [ "$rc" -gt 128 ] 2>/dev/null; then
                bad "$who: grade died of SIG$(kill -l $((rc - 128)) 2>/dev/null) (exit $rc)"
            else
                bad "$who: grade exited $rc, want $want"
            fi
            ;;
    esac
    grep -aq "$SANITIZER" "$BOOK/err-$X" &&
        bad "$who: grade failed under the sanitizer: $(grep -a -m1 "$SANITIZER" "$BOOK/err-$X" | cut -c1-120)"
    for s in "$BOOK/out-$X" "$BOOK/err-$X"; do
        w=stdout
        [ "$s" = "$BOOK/err-$X" ] && w=stderr
        n=$(controls "$s")
        [ "$n" -eq 0 ] || bad "class $X: grade's $w has $n raw control bytes (from: $(evil_texts "$s"))"
        grep -aq "$FORGED" "$s" && bad "class $X: forged rows on grade's $w (from: $(evil_texts "$s"))"
        n=$(bidi "$s")
        [ "$n" -eq 0 ] || bad "class $X: $n line(s) of grade's $w hold raw bidirectional or zero-width characters"
    done
    # a gradebook forged by a submission (forge-ancestors.c), as grade left it or now
    for f in "grades-$X.csv" "results-$X.json"; do
        if grep -aq 'SWEVIL:forge-ancestors' "$BOOK/$f" 2>/dev/null; then
            bad "forge-ancestors: the gradebook $f is its forgery (score 1000, Mallory's pass), not grade's"
        elif grep -aq 'SWEVIL:forge-ancestors' "$D/$f" 2>/dev/null; then
            bad "forge-ancestors: the gradebook $f was replaced by its forgery after grade exited"
        fi
    done
    for f in "$BOOK/grades-$X.csv" "$BOOK/results-$X.json" "$D/feedback-$X"/*; do
        [ -f "$f" ] || continue
        n=$(bidi "$f")
        [ "$n" -eq 0 ] || bad "class $X: $n line(s) of ${f#"$D"/} hold raw bidirectional or zero-width characters"
    done
    # judged: what grade wrote, copied when it exited (a daemon may change it later)
    csv=$BOOK/grades-$X.csv
    json=$BOOK/results-$X.json
    for f in "$BOOK/out-$X" "$BOOK/err-$X" "$json"; do # the CSV: row by row below
        [ -f "$f" ] || continue
        grep -aq "SWSECRET" "$f" && bad "class $X: the teacher's secret (SWSECRET) leaked into grade's ${f##*/}"
        grep -aq "root:x:0:" "$f" && bad "class $X: /etc/passwd leaked into grade's ${f##*/}"
    done
    if [ ! -f "$csv" ]; then
        bad "$who: no gradebook (grade exit $rc): nobody in the class gets a grade"
        return
    fi
    n=$(controls "$csv" 1)
    [ "$n" -eq 0 ] || bad "class $X: the CSV holds $n raw control bytes (from: $(evil_texts "$csv"))"
    if ! awk -f "$H/csv.awk" "$csv" > "$BOOK/rows-$X" 2>"$BOOK/csverr"; then
        bad "class $X: the CSV is not well formed: $(head -c 200 "$BOOK/csverr")"
        return
    fi
    LC_ALL=C awk -F'\t' '/[\001-\010\013-\037\177]/ { print $1 }' "$BOOK/rows-$X" > "$BOOK/ctl-$X"
    while read -r file; do
        bad "${file##*/}: its CSV row holds raw control bytes (escape sequences reach the gradebook)"
    done < "$BOOK/ctl-$X"
    grep -a 'SWSECRET\|root:x:0:' "$BOOK/rows-$X" | cut -f1 > "$BOOK/leak-$X"
    while read -r file; do
        bad "${file##*/}: its CSV row quotes a file it had no right to read (SWSECRET or root:x:0:)"
    done < "$BOOK/leak-$X"
    awk -v cells=1 -f "$H/csv.awk" "$csv" > "$BOOK/cells-$X" 2>/dev/null
    while IFS='	' read -r file col cell; do
        bad "${file##*/}: CSV $col cell starts with '$(printf '%s' "$cell" | cut -c1)', not neutralised (formula injection): $cell"
    done < "$BOOK/cells-$X"
    while read -r e; do
        r=$(awk -F'\t' -v f="swclass-$T/$e" '$1 == f' "$BOOK/rows-$X" | head -1)
        if [ -z "$r" ]; then
            bad "$e: no row in the gradebook (class $X): an entry dropped silently"
            continue
        fi
        v=$(printf '%s' "$r" | cut -f2)
        m=$(printf '%s' "$r" | cut -f4 | cut -c1-120)
        case " $HONEST " in
            *" $e "*)
                [ "$v" = pass ] || bad "honest $e (class $X): verdict '$v', want pass: $m"
                continue
                ;;
        esac
        case $v in
            pass) [ "$e" = correct.txt ] || bad "$e: passed: $(pass_means "$e")" ;;
            fail | error | skipped | limit) [ -n "$m" ] || bad "$e: verdict $v without a reason" ;;
            *) bad "$e: verdict '$v' is not pass, fail, error, skipped or limit" ;;
        esac
        # a hog that ran out of time before it could tell says so (it hands in NaN)
        case $e:$m in
            cpu-hog.c:*nan* | mem-hog.c:*nan* | cpu-hog.c:*non-finite* | mem-hog.c:*non-finite*)
                note "NOTE: $e inconclusive: the machine was too busy for the attack to finish" ;;
        esac
    done < "$BOOK/entries-$X"
    awk -F'\t' -v pre="swclass-$T/" '{ print substr($1, length(pre) + 1) }' "$BOOK/rows-$X" > "$BOOK/rowfiles-$X"
    while read -r e; do
        grep -qxF -- "$e" "$BOOK/entries-$X" ||
            bad "class $X: a row for '$e', which was not in the directory when grading began"
    done < "$BOOK/rowfiles-$X"
    # results.json: parses, and says what the CSV says
    if [ ! -f "$json" ]; then
        bad "class $X: no results.json"
    elif ! awk -f "$JSON" "$json" > "$BOOK/fields-$X" 2>/dev/null; then
        bad "class $X: results.json is not JSON"
    else
        # the class's figure: the mean of the rows that are submissions (the
        # CSV's score column), out of the homework's points (a homework of
        # either kind: the larger of a trace's and a plugin's maximum)
        passes=$(awk -F'\t' '$2 != "skipped" { s += $6; n++ } END { printf "%.15g", n ? s / n : 0 }' "$BOOK/rows-$X")
        rows=$(awk -F'\t' '$2 != "skipped" { print $7 }' "$BOOK/rows-$X" | sort -n | tail -1)
        got=$(sed -n 's/^score=//p' "$BOOK/fields-$X")
        awk -v a="$got" -v b="$passes" 'BEGIN { d = a - b; exit !(d < 1e-12 && d > -1e-12) }' &&
            grep -qx "max_score=${rows% }" "$BOOK/fields-$X" ||
            bad "class $X: results.json's score=$got $(grep '^max_score=' "$BOOK/fields-$X") differs from the CSV's mean $passes of ${rows% }"
    fi
}

# ---- one pass: as root, as swhostile, or as the caller --------------------------

suite() { # MODE LETTER
    M=$1 U=$2
    case $M in root) AS=root ;; user) AS=swhostile ;; container) AS="root, a user's jail" ;; *) AS=$(id -un) ;; esac
    D=$WORK/swrun-$RUN-$U
    BOOK=$WORK/book-$U
    TH=$D/home
    TA=${RUN}a$U TB=${RUN}b$U TC=${RUN}c$U TD=${RUN}d$U TE=${RUN}e$U TF=${RUN}f$U TG=${RUN}g$U
    mkdir -p "$D/home" "$D/outside" "$BOOK" || fail "cannot make $D"
    chmod 700 "$BOOK"

    # The assignment: the spring under gravity (2-D, nonlinear), rk4.
    printf '# stepwise assignment 1\n# title: hostile suite\n# scene: spring\n# param g: 9.81\n# integrator: rk4\n# dt: 0.01\n# steps: 100\n' \
        > "$D/assignment.txt"
    # check --plugin's own copy: write-others.c spoils the classes' one
    cp "$D/assignment.txt" "$D/check-assignment.txt"
    "$SWB" record spring -i rk4 --set g=9.81 --dt 0.01 --steps 100 -o "$BOOK/rk4.trace" 2>/dev/null &&
        "$SWB" record spring -i euler --set g=9.81 --dt 0.01 --steps 100 -o "$BOOK/euler.trace" 2>/dev/null ||
        fail "cannot record the honest traces"
    named "$BOOK/rk4.trace" "Alice Honest" > "$BOOK/alice.trace"
    named "$BOOK/rk4.trace" "Zoe Honest" > "$BOOK/zoe.trace"
    named "$BOOK/rk4.trace" "Bob Outside" > "$D/outside/bob.trace"
    named "$BOOK/rk4.trace" "Tom Txt" > "$BOOK/correct.trace"
    for s in bob yves carol; do sed "s/@NAME@/$s-rk4/g" "$H/honest-rk4.c" > "$BOOK/$s.c"; done
    sed "s/@NAME@/outside-rk4/g" "$H/honest-rk4.c" > "$D/outside/solution.c"
    cc -std=c11 -O2 -shared -fPIC -I"$BIN/include" -o "$BOOK/carol.so" "$BOOK/carol.c" || fail "cannot build carol.so"
    fill "$TA" < "$H/reference.h" > "$TH/reference.h"
    chmod 600 "$TH/reference.h"

    # The classes: A forgers and process attacks, B and C a grader-killer
    # each, D a compiler that never ends, E the hogs, F attacks on files,
    # G the forger of the gradebook that kills its ancestors.
    classes=""
    for X in A B C D E F G; do
        case $X in
            B) wanted kill-grader || continue ;;
            C) wanted stop-grader || continue ;;
            D) wanted inc-fifo || continue ;;
            E) for p in $HOGS; do wanted "$p" && break; done || continue ;;
            G) wanted forge-ancestors || continue ;;
        esac
        mkdir "$D/swclass-$(token_of $X)"
        for f in $HONEST; do cp "$BOOK/$f" "$D/swclass-$(token_of $X)/"; done
        classes="$classes $X"
    done
    CA=$D/swclass-$TA
    for p in $PLUGINS; do wanted "$p" && gen "$p" "$TA" > "$CA/$p.c"; done
    if wanted ctor-evil; then build_so ctor-evil "$TA" "$CA/ctor-evil.so" || fail "cannot build ctor-evil.so"; fi
    CF=$D/swclass-$TF
    for p in $FILERS; do wanted "$p" && gen "$p" "$TF" > "$CF/$p.c"; done
    for p in $INCS; do wanted "$p" && fill "$TF" < "$H/$p.c" > "$CF/$p.c"; done
    wanted traces && sh "$H/traces.sh" "$BOOK/euler.trace" "$CF"
    wanted dirtricks && sh "$H/dirtricks.sh" "$CF" "$TH/reference.h" "$BOOK/correct.trace"
    for p in $HOGS; do wanted "$p" && gen "$p" "$TE" > "$D/swclass-$TE/$p.c"; done
    wanted kill-grader && gen kill-grader "$TB" > "$D/swclass-$TB/kill-grader.c"
    wanted stop-grader && gen stop-grader "$TC" > "$D/swclass-$TC/stop-grader.c"
    wanted forge-ancestors && gen forge-ancestors "$TG" > "$D/swclass-$TG/forge-ancestors.c"
    if wanted inc-fifo; then
        fill "$TD" < "$H/inc-fifo.c" > "$D/swclass-$TD/inc-fifo.c"
        mkfifo "$D/swclass-$TD/pipe.h"
    fi
    for X in $classes; do
        ls -A "$D/swclass-$(token_of $X)" > "$BOOK/entries-$X"
        mkdir "$D/tmp-$X" # grade's TMPDIR: what it leaves there is reported
    done
    w=0
    while [ $w -lt $CHECK_WORKERS ]; do
        mkdir -p "$D/swcheck-$(check_token $w)" "$D/tmp-k$w"
        w=$((w + 1))
    done
    CHECK_LIST=""
    for p in $CHECK_PLUGINS; do wanted "$p" && CHECK_LIST="$CHECK_LIST $p"; done
    # What grade and check print goes to files of the grading user, as a
    # teacher's terminal or redirection would be (reachable through
    # /proc/PID/fd/1, whatever directory they are in).
    for f in $classes; do : > "$BOOK/out-$f"; : > "$BOOK/err-$f"; done
    w=0
    while [ $w -lt $CHECK_WORKERS ]; do
        : > "$BOOK/ck-out-$w"
        : > "$BOOK/ck-err-$w"
        [ "$M" = user ] && chown swhostile "$BOOK/ck-out-$w" "$BOOK/ck-err-$w"
        w=$((w + 1))
    done
    if [ "$M" = user ]; then
        chown -R -h swhostile:"$(id -g swhostile)" "$D" || fail "cannot give $D to swhostile"
        for f in $classes; do chown swhostile "$BOOK/out-$f" "$BOOK/err-$f"; done
    fi
    hashes > "$BOOK/before"
    note "classes made"

    # ---- grade the classes at once, and run check, try and record beside them ----
    grades=""
    GRADES_START=$(now_ms)
    for X in $classes; do
        rm -f "$BOOK/rc-$X"
        # shellcheck disable=SC2046
        ( RUN_TMPDIR=$D/tmp-$X
          cd "$D" && runas "$M" timeout -k 5 "$GRADE_LIMIT" "$SWB" grade --assignment assignment.txt \
              $(limits_of $X) --csv "grades-$X.csv" --results "results-$X.json" "swclass-$(token_of $X)" \
              >"$BOOK/out-$X" 2>"$BOOK/err-$X"
          echo $? > "$BOOK/rc-$X.tmp" && mv "$BOOK/rc-$X.tmp" "$BOOK/rc-$X" ) &
        grades="$grades $!"
    done
    checks=""
    w=0
    while [ $w -lt $CHECK_WORKERS ]; do
        check_part $w $CHECK_WORKERS &
        checks="$checks $!"
        w=$((w + 1))
    done
    # Watch: note when each grade ends (and copy its gradebook then); a
    # grader stopped at two looks in a row (SIGSTOP) is reported and continued.
    start=$(now_ms)
    left=$classes
    seen=""
    reported=""
    while [ -n "$left" ] && [ $(($(now_ms) - start)) -lt $(((GRADE_LIMIT + 15) * 1000)) ]; do
        still=""
        for X in $left; do
            if [ -f "$BOOK/rc-$X" ]; then
                eval "END_$X=\$(now_ms)"
                gb_hash "$X" > "$BOOK/gb-$X"
                cp "$D/grades-$X.csv" "$BOOK/grades-$X.csv" 2>/dev/null
                cp "$D/results-$X.json" "$BOOK/results-$X.json" 2>/dev/null
                note "class $X graded (exit $(cat "$BOOK/rc-$X"))"
            else
                still="$still $X"
            fi
        done
        left=$still
        stops=$(stopped $TA $TB $TC $TD $TE $TF $TG)
        now=""
        for p in $(echo "$stops" | cut -d' ' -f1); do
            case " $seen " in
                *" $p "*)
                    t=$(echo "$stops" | grep "^$p " | cut -d' ' -f2 | head -1)
                    case " $reported " in
                        *" $t "*) ;;
                        *)
                            who="class with token $t"
                            [ "$t" = "$TC" ] && who=stop-grader
                            [ "$t" = "$TG" ] && who=forge-ancestors
                            bad "$who: a grading process (pid $p) was stopped (SIGSTOP): the class hangs until someone sends SIGCONT"
                            reported="$reported $t"
                            ;;
                    esac
                    kill -CONT "$p" 2>/dev/null
                    ;;
                *) now="$now $p" ;;
            esac
        done
        seen=$now
        sleep 0.4
    done
    for j in $grades; do wait "$j"; done
    [ -z "$left" ] || bad "grade of class(es)$left did not end within $((GRADE_LIMIT + 15)) s"

    # (c) the gradebook, unchanged for 5 s after each grade ended
    changed=""
    while :; do
        all_done=1
        for X in $classes; do
            eval "end=\${END_$X:-0}"
            [ $(($(now_ms) - end)) -lt 5000 ] && all_done=0
            case " $changed " in *" $X "*) continue ;; esac
            if [ "$(gb_hash "$X")" != "$(cat "$BOOK/gb-$X" 2>/dev/null)" ]; then
                bad "class $X: the gradebook changed $(($(now_ms) - end)) ms after grade exited (a daemon?): it now holds $(evil_texts "$D/grades-$X.csv")$(grep -c ',pass,' "$D/grades-$X.csv") passes"
                changed="$changed $X"
            fi
        done
        [ $all_done = 1 ] && break
        sleep 0.25
    done
    # (d) nothing outlives grade
    report_survivors "grade" $TA $TB $TC $TD $TE $TF $TG
    note "gradebooks watched for 5 s"
    for j in $checks; do wait "$j"; done
    note "check, try and record done"
    # temporary directories: none left behind, whatever happened to grade or check
    for t in "$D"/tmp-*; do
        n=$(ls -A "$t" | wc -l | tr -d ' ')
        [ "$n" -eq 0 ] && continue
        left="$n, e.g. $(ls -A "$t" | head -1)"
        case ${t##*/tmp-} in
            k*) who="check, try or record" ;;
            B) who="kill-grader: grade" ;;
            C) who="stop-grader: grade" ;;
            D) who="inc-fifo: grade" ;;
            G) who="forge-ancestors: grade" ;;
            *) who="class ${t##*/tmp-}: grade" ;;
        esac
        bad "$who left temporary files behind in its TMPDIR ($left)"
    done
    report_survivors "check, try and record" $(check_token 0) $(check_token 1) $(check_token 2)
    # (e) markers outside a sandbox, connections to the listener
    report_markers "$RUN?$U"
    # (b) honest and protected files, byte for byte
    hashes > "$BOOK/after"
    paste -d' ' "$BOOK/before" "$BOOK/after" | awk '$1 != $3 { print $3, $4 }' > "$BOOK/changed"
    while read -r h f; do
        bad "${f#"$D"/}: changed by the hostile submissions (sha256 now $(echo "$h" | cut -c1-16)...)"
    done < "$BOOK/changed"
    # (a), (c), (f) per class
    for X in $classes; do judge_class "$X"; done
    AS=""
}

# The passes run at once (each its own tokens, files and processes): most
# of a pass is waiting on watchdogs and the 5 s window.
passes=""
for m in $MODES; do
    case $m in root) l=r ;; user) l=u ;; container) l=c ;; *) l=s ;; esac
    ( suite "$m" $l ) &
    passes="$passes $!"
done
for p in $passes; do
    wait "$p" || bad "a pass of the suite stopped early (see the message above)"
done
n=$(cat "$WORK/failures" 2>/dev/null | wc -l | tr -d ' ')
[ "$n" -eq 0 ] || { echo "$n hostile-suite failure(s)"; exit 1; }
echo "ok"
