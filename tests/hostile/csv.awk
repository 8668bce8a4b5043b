# The gradebook read strictly (RFC 4180: quoted fields, doubled quotes,
# line breaks inside quotes; records end in CRLF or LF), for the hostile
# suite. The header must start student,file,verdict,first_failing_step,message
# (later columns: id, remarks, similar, score, max).
#   awk -f csv.awk grades.csv              one line per record:
#       FILE<TAB>VERDICT<TAB>STEP<TAB>MESSAGE<TAB>STUDENT
#       (tabs, CRs and LFs inside a field shown as spaces)
#   awk -v cells=1 -f csv.awk grades.csv   one line per cell that starts
#       with = + - @ TAB or CR (spreadsheet formula injection, OWASP):
#       FILE<TAB>COLUMN<TAB>the cell's first 60 bytes
# Exits 1 (with a message on stderr) when the file is not such a CSV.
function field(    f, c) {
    if (substr(rec, pos, 1) == "\"") {
        pos++; f = ""
        for (;;) {
            if (pos > length(rec)) { bad = 1; return f }
            c = substr(rec, pos, 1)
            if (c == "\"") {
                if (substr(rec, pos + 1, 1) == "\"") { f = f "\""; pos += 2; continue }
                pos++; return f
            }
            f = f c; pos++
        }
    }
    c = index(substr(rec, pos), ",")
    if (c == 0) { f = substr(rec, pos); pos = length(rec) + 1; return f }
    f = substr(rec, pos, c - 1); pos += c - 1; return f
}
function flat(s) { gsub(/[\t\r\n]/, " ", s); return s }
BEGIN { names[1] = "student"; names[2] = "file"; names[3] = "verdict"; names[4] = "first_failing_step"; names[5] = "message"; names[6] = "id"; names[7] = "remarks"; names[8] = "similar"; names[9] = "score"; names[10] = "max" }
{
    line = $0
    sub(/\r$/, "", line)
    if (pending != "") { rec = pending "\n" line } else rec = line
    # a record continues while its quotes are unbalanced
    q = rec; nq = gsub(/"/, "", q)
    if (nq % 2) { pending = rec; next }
    pending = ""
    nrec++
    pos = 1; n = 0; bad = 0
    while (pos <= length(rec) + 1) {
        F[++n] = field()
        if (substr(rec, pos, 1) == ",") { pos++; continue }
        if (pos > length(rec)) break
        bad = 1; break
    }
    if (nrec == 1)
        ncols = n
    if (bad || n != ncols || n < 5) { print "csv.awk: malformed record " nrec ": " rec > "/dev/stderr"; failed = 1; exit 1 }
    if (nrec == 1) {
        if (substr(rec, 1, 47) != "student,file,verdict,first_failing_step,message") {
            print "csv.awk: bad header: " rec > "/dev/stderr"; failed = 1; exit 1
        }
        next
    }
    if (cells) {
        for (i = 1; i <= ncols; i++)
            if (F[i] ~ /^[=+@\t\r-]/) printf "%s\t%s\t%s\n", flat(F[2]), names[i], flat(substr(F[i], 1, 60))
    } else
        printf "%s\t%s\t%s\t%s\t%s\t%s\t%s\n", flat(F[2]), flat(F[3]), flat(F[4]), flat(F[5]), flat(F[1]),
               (ncols >= 10 ? F[9] : ""), (ncols >= 10 ? F[10] : "")
}
END {
    if (failed) exit 1
    if (pending != "") { print "csv.awk: a quoted field never ends" > "/dev/stderr"; exit 1 }
    if (nrec < 1) { print "csv.awk: empty" > "/dev/stderr"; exit 1 }
}
