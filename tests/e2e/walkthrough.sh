# What the walk-through tests share (tests/e2e/test_walkthrough_*.sh): each
# does one of docs/architecture.md's walk-throughs ("Adding a ...") in a
# scratch copy of the tree, in the files the docs name, and builds it.
# Sourced after lib.sh; gives walkthrough_full NAME (skips below the full
# tier), walkthrough_copy (the tree into $copy), insert_before,
# insert_in_table and walkthrough_build.

# walkthrough_full NAME: a walk-through builds a copy of the tree (a minute
# or two): full tier only (make test-full).
walkthrough_full() {
    if [ -n "${SW_TEST_QUICK:-}" ]; then
        echo "skip: the $1 walk-through is built in a scratch copy at the full tier (make test-full)"
        exit 77
    fi
}

# walkthrough_copy: the tree as it is into $copy (built objects too, so
# only what the walk-through touches is compiled again), without the
# program and its git data.
walkthrough_copy() {
    copy=$WORK/copy
    mkdir -p "$copy"
    (cd "$ROOT" && tar --exclude=./.git --exclude=./stepwise -cf - .) | (cd "$copy" && tar -xf -) ||
        fail "cannot copy the tree"
}

# insert_before FILE ERE TEXTFILE: TEXTFILE's lines before the last line of
# FILE matching ERE (fails when none does).
insert_before() {
    awk -v re="$2" -v add="$3" '
        { line[NR] = $0; if ($0 ~ re) last = NR }
        END {
            if (!last) exit 1
            for (i = 1; i <= NR; i++) {
                if (i == last) while ((getline l < add) > 0) print l
                print line[i]
            }
        }' "$1" >"$1.new" && mv "$1.new" "$1"
}

# insert_in_table FILE ERE TEXTFILE: TEXTFILE's lines before the first line
# "};" after the line of FILE matching ERE (the table it opens); fails when
# there is no such table.
insert_in_table() {
    awk -v re="$2" -v add="$3" '
        $0 ~ re { inside = 1 }
        inside && /^\};/ { while ((getline l < add) > 0) print l; inside = 0; done = 1 }
        { print }
        END { if (!done) exit 1 }' "$1" >"$1.new" && mv "$1.new" "$1"
}

# walkthrough_build TARGET...: make the targets in the copy with warnings
# as errors; fails with the log's end when it does not build.
walkthrough_build() {
    (cd "$copy" && make -j2 WERROR=1 "$@") >"$WORK/build.log" 2>&1 ||
        { tail -30 "$WORK/build.log"; fail "the walk-through's tree does not build ($*)"; }
}
