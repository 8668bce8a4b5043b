#!/bin/sh
# What grade prints about a class, letter by letter (issue 36's feedback
# wording): the table's columns line up in terminal cells whatever the
# letters (é is two bytes and one cell, 日 three and two) and a long cell
# is cut by width; a class folder given with a trailing slash has its
# paths joined once; --feedback files are named with the roster's fold
# (Poincaré: Poincare), distinct when two names fold alike; a long message
# is cut after a whole word, and the probe's reason is whole.
. "$(dirname "$0")/lib.sh"

"$SW" record spring --steps 20 -o ref.trace 2>/dev/null || fail "cannot record the assignment"
mkdir class
student() { # NAME FILE: a passing trace that says it is NAME's
    { echo '# stepwise trace 1'; echo "# student: $1"; sed -n '2,$p' ref.trace; } > "class/$2"
}
student "Ada Lovelace" ada.trace
student "Henri Poincaré" poincare.trace
student "henri poincare" hp.trace
student "Émilie du Châtelet" emilie.trace
student "日本 太郎" nihon.trace
student "Srinivasa Ramanujan Iyengar" ramanujan.trace
cp ref.trace "class/café_éèà_crème_brûlée_au_four.trace"

# --- the table: every row's verdict starts at the header's cell ----------------
"$SW" grade --assignment ref.trace class/ --feedback fb > out 2>err || fail "grade: $(cat out err)"
cells() { LC_ALL=C.UTF-8 wc -L; } # display cells (wcwidth) of one line
head_at=$(grep '^  student ' out | sed 's/ verdict .*//' | cells)
[ "$head_at" -eq 47 ] || fail "the header's verdict at cell $head_at, want 47: $(cat out)"
[ "$(grep -c ' pass ' out)" -eq 7 ] || fail "want 7 passing rows: $(cat out)"
grep ' pass ' out | while IFS= read -r row; do
    at=$(printf '%s\n' "$row" | sed 's/ pass .*//' | cells)
    [ "$at" -eq "$head_at" ] || fail "a row's verdict at cell $at, the header's at $head_at: '$row'"
done || exit 1
# Cut by width, "..." within the 24 cells: 21 letters, most of them two bytes.
grep -q ' café_éèà_crème_brûlée\.\.\. pass ' out || fail "the long file name is not cut to 24 cells: $(cat out)"
grep -q ' Srinivasa Ramanuj\.\.\. ' out || fail "the long name is not cut to 20 cells: $(cat out)"

# --- paths joined once, however many slashes the folder is given with -------------
for arg in class/ class//; do
    "$SW" grade --assignment ref.trace "$arg" --csv - --results r.json > csv 2>err || fail "grade $arg: $(cat err)"
    grep -q '//' csv r.json && fail "grade $arg: a path with '//': $(grep -h '//' csv r.json | head -3)"
    grep -q '^Ada Lovelace,class/ada.trace,pass' csv || fail "grade $arg: $(cat csv)"
done

# --- feedback files: the roster's fold, case kept; a clash made distinct ------------
ls fb > names
grep -qx 'Emilie_du_Chatelet.txt' names || fail "no Emilie_du_Chatelet.txt: $(cat names)"
grep -q 'Poincar_\|Poincar\.txt\|Ch_telet' names && fail "a letter dropped, not folded: $(cat names)"
[ "$(grep -ci '^henri_poincare\(-2\)\{0,1\}\.txt$' names)" -eq 2 ] ||
    fail "Henri Poincaré and henri poincare do not get two files: $(cat names)"
[ "$(sort -f names | uniq -i | wc -l)" -eq 7 ] || fail "two files differ only in case: $(cat names)"
grep -l 'Feedback for Henri Poincaré' fb/*.txt | grep -qi 'henri_poincare' ||
    fail "Henri Poincaré's feedback is not in a Henri_Poincare file"

# --- a long message cut after a whole word -----------------------------------------
# A plugin whose compiler error is longer than the table's last column:
# every word ends in z, so a word cut in two shows.
if "$SW" autograder --probe >/dev/null 2>&1 && command -v cc >/dev/null 2>&1; then
    mkdir plugins
    { printf '#error '; i=1; while [ $i -le 80 ]; do printf 'word%dz ' $i; i=$((i + 1)); done; echo; } > plugins/bad.c
    "$SW" grade --assignment ref.trace plugins > out 2>err
    row=$(grep ' bad\.c ' out)
    printf '%s\n' "$row" | grep -Eq ' word[0-9]+z\.\.\.$' || fail "the message is not cut after a word: '$row'"
fi

# --- the probe's reason whole: as root, in a container without user namespaces -----
if [ "$(id -u)" -eq 0 ] && cc -std=c11 -O2 -o nouserns "$ROOT/tests/e2e/nouserns.c" 2>/dev/null &&
   ./nouserns true; then
    STEPWISE_JAIL=ns ./nouserns "$SW" autograder --probe > out 2>err && fail "the probe passes without user namespaces"
    [ "$(wc -l < err)" -eq 1 ] || fail "the probe's reason is not one line: $(cat err)"
    grep -q '(docs/sandbox\.md)$' err || fail "the probe's reason is cut: $(cat err)"
    grep -q 'unshare(' err || fail "the probe does not say what failed: $(cat err)"
fi
echo ok
