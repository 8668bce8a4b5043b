#!/bin/sh
# --similarity on a trace homework with values drawn per student: two
# correct traces of students who were drawn the same value are identical
# by design and never paired (a range of 11 values in a class of 22 gave
# 13 such pairs of honest students, QA 2026-12-07); a copy made for the
# other student's value fails its check and is still paired; so is a copy
# whose header was edited to the copier's own value (the same rows under
# another header, QA). Two files at the scene's defaults (a run without
# --set) are paired with a note saying so: a forgotten --set, not a copy.
. "$(dirname "$0")/lib.sh"
cat > hw.txt <<'A'
# stepwise assignment 1
# kind: trace
# secret: a teacher's own words for this test 4417
# scene: spring
# integrator: verlet
# param k: one of 80, 120
# dt: 0.01
# steps: 100
A
{ echo "Name,ID,Email"; for i in 1 2 3 4 5 6 7 8 9 10 11 12; do echo "Student $i,10$i,s$i@uni.edu"; done; } > roster.csv
"$SW" handout --assignment hw.txt --roster roster.csv -o sheets > /dev/null 2>&1 || fail "handout"
k_of() { # N: student N's drawn k, from their sheet
    f=$(awk -F, -v n="Student $1" 'NR > 1 && $1 == n { print $3 }' sheets/handout.csv | tr -d '\r')
    sed -n 's/^# param k: //p' "sheets/$f"
}
for i in 1 2 3 4 5; do
    d="class/Student ${i}_10${i}_assignsubmission_file_"
    mkdir -p "$d"
    "$SW" record spring --set k="$(k_of $i)" -i verlet --dt 0.01 --steps 100 -o "$d/swing.trace" >/dev/null 2>&1 ||
        fail "record for student $i"
done
# five students, two values: at least two of them share one
[ "$(for i in 1 2 3 4 5; do k_of $i; done | sort | uniq -d | wc -l)" -ge 1 ] || fail "no two students share a value"
# student 6 copies the file of a student drawn the other value
for i in 1 2 3 4 5; do [ "$(k_of $i)" != "$(k_of 6)" ] && src=$i && break; done
[ -n "${src:-}" ] || fail "every student drew student 6's value"
mkdir -p "class/Student 6_106_assignsubmission_file_"
cp "class/Student ${src}_10${src}_assignsubmission_file_/swing.trace" "class/Student 6_106_assignsubmission_file_/"
# student 7 copies it too, and writes their own k into its header
for i in 1 2 3 4 5; do [ "$(k_of $i)" != "$(k_of 7)" ] && src7=$i && break; done
[ -n "${src7:-}" ] || fail "every student drew student 7's value"
mkdir -p "class/Student 7_107_assignsubmission_file_"
sed "s/^# param k: .*/# param k: $(k_of 7)/" "class/Student ${src7}_10${src7}_assignsubmission_file_/swing.trace" \
    > "class/Student 7_107_assignsubmission_file_/swing.trace"
# students 8 to 12 forget --set: the scene's default k, in each
for i in 8 9 10 11 12; do
    d="class/Student ${i}_10${i}_assignsubmission_file_"
    mkdir -p "$d"
    "$SW" record spring -i verlet --dt 0.01 --steps 100 -o "$d/swing.trace" >/dev/null 2>&1 || fail "record $i"
done
"$SW" grade --assignment hw.txt --roster roster.csv --similarity class > g.out 2>&1
[ $? -le 1 ] || fail "grade: $(cat g.out)"
[ "$(grep -c ' +pass ' g.out)" -eq 0 ] && [ "$(grep -Ec '^  Student [1-5] .* pass ' g.out)" -eq 5 ] ||
    fail "the five honest students do not all pass: $(cat g.out)"
grep -Eq "^  Student 6 .* fail .*made for other parameters" g.out || fail "the copy passed: $(cat g.out)"
# pairs with student 6 only (their file is also byte-identical to any other
# student drawn the source's value), none between the honest five
grep -E '^  [0-9.]+  .*~' g.out | grep -Ev "Student ([6-9]|1[012]) " && fail "honest students paired: $(cat g.out)"
grep -Eq "^  1\.00  (Student $src \(swing.trace\)  ~  Student 6|Student 6 \(swing.trace\)  ~  Student $src)" g.out ||
    fail "the copy is not paired with its source: $(cat g.out)"
grep -Eq "^  1\.00  (Student $src7 \(swing.trace\)  ~  Student 7|Student 7 \(swing.trace\)  ~  Student $src7) .*the same rows, byte for byte .* under headers that differ" g.out ||
    fail "the copy with an edited header is not paired with its source: $(cat g.out)"
# a pair of them drawn different values: paired, saying why it may be no copy
drawn_apart=0
for i in 8 9 10 11 12; do for j in 8 9 10 11 12; do
    [ "$i" -lt "$j" ] && [ "$(k_of $i)" != "$(k_of $j)" ] || continue
    drawn_apart=$((drawn_apart + 1))
    grep -Eq "(Student $i \(swing.trace\)  ~  Student $j|Student $j \(swing.trace\)  ~  Student $i) \(swing.trace\): byte-identical .*; both at the scene's default parameters" g.out ||
        fail "two runs without --set ($i, $j): no pair saying so: $(cat g.out)"
done; done
[ "$drawn_apart" -ge 1 ] || fail "students 8 to 12 all drew one value: the note was not tested"
exit 0
