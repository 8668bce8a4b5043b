#!/bin/sh
# Runs every row of docs/robustness.md: exit 2, exactly one line on stderr
# with the documented text, nothing on stdout, no core dump, no output file.
. "$(dirname "$0")/lib.sh"
doc="$ROOT/docs/robustness.md"
ulimit -c unlimited 2>/dev/null
mkdir dir
: > empty.trace; : > empty.lesson
head -c 3000 /dev/urandom > binary.trace; cp binary.trace binary.lesson
truncate -s 2G huge.trace; truncate -s 2G huge.lesson
ln -s /proc/self/mem unreadable.trace
echo "not a shared object" > text.so
printf 'int sw_not_the_symbol(void);\nint sw_not_the_symbol(void) { return 0; }\n' > nosym.c
cc -shared -fPIC -o nosym.so nosym.c || { echo "cannot build the nosym.so fixture"; exit 1; }
mkfifo fifo.lesson fifo.trace
: > afile

rows=0 bad=0
# rows: | input | `command` | `expected` |; a command may start with
# environment assignments (`XDG_STATE_HOME=afile stepwise lesson 1`).
grep -E '^\| [^|]+ \| `([A-Z_]+=[^ `]* )*stepwise' "$doc" > rows.txt
while IFS= read -r row; do
    cmd=$(printf '%s\n' "$row" | sed -E 's/^\| [^|]+ \| `([^`]*)` \|.*/\1/')
    want=$(printf '%s\n' "$row" | sed -E 's/.*\| `([^`]*)` \|$/\1/')
    rows=$((rows + 1))
    run=$(printf '%s' "$cmd" | sed -E "s#^(([A-Z_]+=[^ ]* )*)stepwise#\1\"\$STEPWISE\"#")
    eval "$run" </dev/null >out.txt 2>err.txt
    rc=$?
    nerr=$(wc -l < err.txt)
    problem=""
    [ $rc -eq 2 ] || problem="exit $rc, expected 2"
    [ -z "$problem" ] && [ "$nerr" -ne 1 ] && problem="$nerr lines on stderr, expected 1"
    [ -z "$problem" ] && ! grep -qF -- "$want" err.txt && problem="stderr lacks '$want'"
    [ -z "$problem" ] && [ -s out.txt ] && problem="wrote to stdout"
    [ -z "$problem" ] && ls core* >/dev/null 2>&1 && problem="core dump"
    for f in x.trace nodir; do [ -z "$problem" ] && [ -e "$f" ] && problem="left $f behind"; done
    if [ -n "$problem" ]; then
        bad=$((bad + 1))
        echo "FAIL: $cmd: $problem"
        sed 's/^/    stderr: /' err.txt | head -3
    fi
    rm -f out.txt err.txt core*
done < rows.txt
echo "robustness: $((rows - bad)) of $rows rows as documented"
[ $rows -ge 60 ] || { echo "only $rows rows found in $doc"; exit 1; }
[ $bad -eq 0 ]
