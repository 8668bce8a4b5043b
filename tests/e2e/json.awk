# A strict JSON parser in awk (RFC 8259 grammar, one value, nothing after
# it), for the tests: a fresh Debian has awk but not python or jq. Prints
# each scalar as "path=value" (strings unquoted), e.g. "tests[2].score=0";
# exits 1 on the first syntax error. Used as: awk -f json.awk FILE.
function err(what) { printf "json error at byte %d: %s\n", pos, what > "/dev/stderr"; bad = 1; exit 1 }
function ch() { return substr(s, pos, 1) }
function ws() { while (pos <= n && index(" \t\n\r", ch()) > 0) pos++ }
function value(path,    c) {
    ws(); c = ch()
    if (c == "{") return object(path)
    if (c == "[") return array(path)
    if (c == "\"") { print path "=" string(); return }
    if (substr(s, pos, 4) == "true") { pos += 4; print path "=true"; return }
    if (substr(s, pos, 5) == "false") { pos += 5; print path "=false"; return }
    if (substr(s, pos, 4) == "null") { pos += 4; print path "=null"; return }
    if (match(substr(s, pos), /^-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][-+]?[0-9]+)?/)) {
        print path "=" substr(s, pos, RLENGTH); pos += RLENGTH; return
    }
    err("no value")
}
function object(path,    key, first) {
    pos++; ws()
    if (ch() == "}") { pos++; return }
    for (;;) {
        ws(); if (ch() != "\"") err("key expected")
        key = string(); ws()
        if (ch() != ":") err("':' expected")
        pos++
        value(path == "" ? key : path "." key); ws()
        if (ch() == ",") { pos++; continue }
        if (ch() == "}") { pos++; return }
        err("',' or '}' expected")
    }
}
function array(path,    i) {
    pos++; ws()
    if (ch() == "]") { pos++; return }
    for (i = 0; ; i++) {
        value(path "[" i "]"); ws()
        if (ch() == ",") { pos++; continue }
        if (ch() == "]") { pos++; return }
        err("',' or ']' expected")
    }
}
function string(    out, c, start) {
    pos++; out = ""
    for (;;) {
        if (pos > n) err("unterminated string")
        c = ch()
        if (c == "\"") { pos++; return out }
        if (c == "\\") {
            c = substr(s, pos + 1, 1)
            if (c == "u") {
                if (!match(substr(s, pos + 2, 4), /^[0-9a-fA-F][0-9a-fA-F][0-9a-fA-F][0-9a-fA-F]$/)) err("bad \\u")
                out = out "?"; pos += 6; continue
            }
            if (index("\"\\/bfnrt", c) == 0) err("bad escape")
            out = out c; pos += 2; continue
        }
        if (c < " ") err("control character in a string")
        out = out c; pos++
    }
}
{ s = s $0 "\n" }
END {
    if (bad) exit 1
    n = length(s); pos = 1
    value(""); ws()
    if (pos <= n) err("text after the value")
}
