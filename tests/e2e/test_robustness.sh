#!/bin/sh
# Runs every row of docs/robustness.md: exit 2, exactly one line on stderr
# with the documented text, nothing on stdout, no core dump, no output file.
. "$(dirname "$0")/lib.sh"
needs_jail
doc="$ROOT/docs/robustness.md"
ulimit -c unlimited 2>/dev/null
mkdir dir
: > empty.trace; : > empty.lesson
# 3000 pseudo-random bytes from a fixed seed: the same file every run, so a
# row's line number is never luck (urandom opened with a clean line 1 in one
# run of 128 or so, and the lesson linter then rightly named line 2).
printf '#include <stdio.h>\nint main(void) { unsigned x = 20261203u; for (int i = 0; i < 3000; i++) { x = x * 1103515245u + 12345u; putchar((int)(x >> 16 & 255)); } return 0; }\n' > rnd.c
cc -o rnd rnd.c && ./rnd > binary.trace || { echo "cannot build the binary.trace fixture"; exit 1; }
cp binary.trace binary.lesson
truncate -s 2G huge.trace; truncate -s 2G huge.lesson
ln -s /proc/self/mem unreadable.trace
echo "not a shared object" > text.so
printf 'int sw_not_the_symbol(void);\nint sw_not_the_symbol(void) { return 0; }\n' > nosym.c
cc -shared -fPIC -o nosym.so nosym.c || { echo "cannot build the nosym.so fixture"; exit 1; }
mkfifo fifo.lesson fifo.trace
: > afile

# --- fixtures for the grading and plugin rows (docs/robustness.md, second table) ---
"$STEPWISE" record spring --steps 5 -o a.trace 2>/dev/null || { echo "cannot record a.trace"; exit 1; }
printf '# stepwise trace 1\n# scene: vortex\n# param n: 200000\n# integrator: euler\n# dt: 1e-9\n# steps: 10000000\nstep,t\n' > big.trace
printf '# stepwise trace 1\n# scene: spring\n# integrator: rk45\n# dt: 0.01\n# steps: 100\n# rtol: 1e-86\nstep,t\n' > rtol.trace
plugin() { # NAME 'C initialiser of the sw_plugin' [body of sw_plugin_info]
    printf '#include <stepwise/integrator.h>\nstatic int st(sw_ode *o, double t, double *y, double h, double *w)\n{ (void)o; (void)t; (void)y; (void)h; (void)w; return 0; }\nstatic const sw_plugin info = %s;\nconst sw_plugin *sw_plugin_info(void);\nconst sw_plugin *sw_plugin_info(void) { %s return &info; }\n' \
        "$2" "${3:-}" > "$1.c"
    cc -std=c11 -shared -fPIC -I"$root/include" -o "$1.so" "$1.c" || { echo "cannot build the $1.so fixture"; exit 1; }
}
plugin longname '{ SW_PLUGIN_ABI, "a-name-far-longer-than-forty-characters-xx", "L", 1, 1, 0, st }'
plugin newline '{ SW_PLUGIN_ABI, "two\nlines", "L", 1, 1, 0, st }'
plugin space '{ SW_PLUGIN_ABI, "euler ", "L", 1, 1, 0, st }'
plugin shadow '{ SW_PLUGIN_ABI, "RK4", "L", 1, 1, 0, st }'
plugin escname '{ SW_PLUGIN_ABI, "x\033[2J", "L", 1, 1, 0, st }'
plugin esclabel '{ SW_PLUGIN_ABI, "fine", "PASS\033[2J", 1, 1, 0, st }'
plugin nullinfo '{ SW_PLUGIN_ABI, "n", "L", 1, 1, 0, st }' 'if (info.abi) return 0;'
plugin infoloop '{ SW_PLUGIN_ABI, "l", "L", 1, 1, 0, st }' 'for (volatile int i = 1; i;) { }'
printf 'int x = ;\n' > bad.c

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
[ $rows -ge 85 ] || { echo "only $rows rows found in $doc"; exit 1; }
[ $bad -eq 0 ]
