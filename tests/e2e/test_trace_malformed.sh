#!/bin/sh
# Malformed traces: each gives exit 2, exactly one line on stderr naming the
# file and the line ("FILE:LINE: ..."), nothing else, and no crash. Files far
# larger than any trace are read in bounded memory (run under a 16 MB
# address-space limit, a third of the files' size).
. "$(dirname "$0")/lib.sh"

"$SW" record spring --steps 50 -o good.csv 2>/dev/null || fail "record failed"
# good.csv: line 1 magic, 2-15 metadata, 16 header, 17-67 rows (steps 0-50)
[ "$(sed -n 16p good.csv)" = "step,t,x0,y0,vx0,vy0,energy" ] || fail "unexpected layout"
"$SW" check good.csv >/dev/null 2>&1 || fail "good.csv does not pass"

# expect NAME LINE TEXT: check m.csv, want exit 2 and "m.csv:LINE: ...TEXT..."
expect() {
    "$SW" check m.csv >out 2>err </dev/null
    rc=$?
    [ "$rc" -eq 2 ] || fail "$1: exit $rc, want 2 ($(cat out err))"
    [ "$(wc -l < err)" -eq 1 ] || fail "$1: stderr is not one line: $(cat err)"
    grep -q "^stepwise: m.csv:$2: " err || fail "$1: does not name m.csv:$2: $(cat err)"
    grep -q -- "$3" err || fail "$1: message lacks '$3': $(cat err)"
    [ ! -s out ] || fail "$1: wrote a report: $(cat out)"
}

sed '1s/.*/step,t,x0/' good.csv > m.csv;                  expect "wrong first line" 1 "not a stepwise trace"
sed '1s/.*/# stepwise trace 2/' good.csv > m.csv;          expect "format version" 1 "format 2"
sed '16s/.*/step,t,x0,y0,vx0,vy0/' good.csv > m.csv;       expect "missing column" 16 "missing column 'energy'"
sed '16s/$/,e1,e2,e3,e4,e5,e6,e7,e8,e9/' good.csv > m.csv;        expect "nine extra columns" 16 "at most 8 extra columns"
sed '16s/vx0/vx1/' good.csv > m.csv;                       expect "misnamed column" 16 "missing column 'vx0'"
sed '30s/,[^,]*$//' good.csv > m.csv;                      expect "missing cell" 30 "6 cells"
sed '30s/$/,1/' good.csv > m.csv;                          expect "extra cell" 30 "more than the header"
sed '30s/,0,/,zero,/' good.csv > m.csv;                    expect "non-numeric" 30 "'zero', which is not a number"
sed '30s/,0,/,,/' good.csv > m.csv;                        expect "empty cell" 30 "empty cell"
sed '30s/^13,/13.5,/' good.csv > m.csv;                    expect "fractional step" 30 "a step is a whole number"
head -c -7 good.csv > m.csv;                               expect "truncated last line" 67 "cut short"
sed 's/^# scene: spring/# scene: trampoline/' good.csv > m.csv; expect "unknown scene" 3 "unknown scene 'trampoline'"
sed 's/^# param k:/# param stiffness:/' good.csv > m.csv;  expect "unknown parameter" 4 "no parameter 'stiffness'"
sed 's/^# param m: 1/# param m: 0/' good.csv > m.csv;      expect "parameter out of range" 5 "outside its range"
sed 's/^# every: 1/# colour: blue/' good.csv > m.csv;      expect "unknown key" 13 "unknown metadata key 'colour'"
sed '/^# dt:/d' good.csv > m.csv;                          expect "missing dt" 15 "lacks '# dt"
sed 's/^# dt: 0.02/# dt: fast/' good.csv > m.csv;          expect "bad dt" 11 "'dt' wants"
sed "s/^# steps: 50/# until: 0.5/" good.csv > m.csv;       expect "rows beyond until" 49 "until:. 0.5"
sed '2s/.*/# dt: 0.01/' good.csv > m.csv;                  expect "duplicate key" 11 "given twice"
sed 's/^# integrator: euler/# integrator: leapfrog-2000/' good.csv > m.csv; expect "unknown integrator" 10 "unknown integrator 'leapfrog-2000'"
sed '40s/.*//' good.csv > m.csv;                           expect "blank line" 40 "empty line"
sed '50s/^/# note: hello\n/' good.csv > m.csv;              expect "comment among rows" 50 "only a '# diverged"
{ cat good.csv; sed -n '60,67p' good.csv; } > m.csv;      expect "more rows than steps" 72 "more rows than the metadata allows"
: > m.csv;                                                 expect "empty file" 1 "empty file"
printf '\n' > m.csv;                                       expect "one empty line" 1 "not a stepwise trace"
head -c 4096 "$SW" > m.csv;                                expect "binary file (ELF)" 1 "binary data"
{ head -30 good.csv; printf '13,0.26,1.4\0000,0,0,0,1\n'; } > m.csv; expect "NUL byte in a row" 31 "binary data"
head -15 good.csv > m.csv;                                 expect "no header row" 16 "no header row"

# Far larger than any trace: one 48 MB line, and 48 MB of extra rows. The
# line cap (64 + 48 bytes per column) and the row bound from the metadata
# stop the reader early; memory stays small. ulimit -v caps the address
# space at 16 MB, so holding either file whole would fail.
# A sanitizer build reserves terabytes of address space and cannot run
# under the cap; it still checks the messages, without the limit.
limit="ulimit -v 16384"
if ! (eval "$limit"; "$SW" check good.csv) >/dev/null 2>&1; then
    limit=":"
    echo "note: $SW cannot run under ulimit -v 16384 (a sanitizer build?); no memory cap"
fi
{ cat good.csv; head -c 50000000 /dev/zero | tr '\0' '7'; echo; } > m.csv
(eval "$limit"; expect "one huge line" 68 "line longer than 784 bytes") || exit 1
{ head -16 good.csv; yes '0,0,1.5,0,0,0,1.25' | head -n 2600000; } > m.csv
[ "$(wc -c < m.csv)" -gt 40000000 ] || fail "the big file is not big"
(eval "$limit"; expect "millions of rows" 72 "more rows than the metadata allows") || exit 1
head -c 50000000 /dev/urandom > m.csv
(eval "$limit"; expect "50 MB of random bytes" 1 "") || exit 1

# A directory and a missing file: one line, exit 2.
"$SW" check "$dir" >/dev/null 2>err; [ $? -eq 2 ] && [ "$(wc -l < err)" -eq 1 ] || fail "directory"
"$SW" check nothere.csv >/dev/null 2>err; [ $? -eq 2 ] && grep -q 'nothere.csv:1: cannot open' err \
    || fail "missing file: $(cat err)"

# The same errors as JSON for an autograder: an object with status "error".
sed '30s/,0,/,zero,/' good.csv > m.csv
"$SW" check --json m.csv >out 2>err
[ $? -eq 2 ] || fail "--json: exit not 2"
grep -q '"status": "error"' out && grep -q '"error": "m.csv:30: ' out || fail "--json error: $(cat out)"
echo "ok"
