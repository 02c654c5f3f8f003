#!/usr/bin/env bash
# The numbers in the course's texts against the CSVs the programs wrote (bash and awk only: the course runs
# on bare Debian 12, whose awk is mawk).
#
# Usage: check_numbers.sh [--list] COURSE_ROOT
#
# Texts: README.md, chapters/*/README.md, chapters/*/NOTES.md and slides/*.md.
#
# Convention. An HTML comment on the line(s) before a Markdown table declares where its numbers come from:
#
#     <!-- numbers: slides/img/05_sah/bins.csv [more.csv ...] [labels: N] [derived: percent(A,B)] -->
#     | scene | tree | build ms | ...
#     |---|---|---|
#
# Paths are relative to the repository root. Blank lines may separate the comment from the table, and a
# table may have several such comments (their sources add up); a numbers comment that no table follows is
# an error. A source is a CSV (every field that is a number counts) or a Markdown table a program wrote
# (the race's *_spread.md: every number in its table rows counts).
#
# What is checked: every number in the body rows of an annotated table (below the header and the |---|
# line) must equal some number of its sources at the precision it is written with: the source's value,
# rounded to the token's decimals, gives the token (2.80 matches 2.7963; 1,234 matches 1234.4; 3.1e-5
# matches 3.14e-5). A number is a run of digits, with thousands commas (1,234), a fraction (.80) and an
# exponent (e-5) allowed, a sign where the character before it is not a letter, digit or ')' (-10.6%, but
# 0.12-0.16 is 0.12 and 0.16), and a unit "%" or "x" after it or an "x" before it (0.51x, x1.05): the
# number is compared as written, so a percentage or a ratio must be a column of the source. Not numbers:
# digits glued to a letter, digit, '_' or '.' on either side (bvh16, ch05-binned16, v2, BVH8_CPU), and
# anything inside `code spans`.
# Label columns: the first column of a table names its rows (teapot (4096), 16 bins, 1e-6 at 0) and is
# never checked; "labels: N" makes it the first N columns (labels: 0 checks every column).
# derived: percent(A,B) also accepts a percentage that is the change from column A to column B of one row
# of a CSV source, 100 (B / A - 1) rounded to the token's decimals (-10.6% for sah_before 25.22,
# sah_after 22.54); ratio(A,B) likewise accepts A / B of one row, as a ratio (0.51x) or a bare number;
# B may be a constant, for a unit: ratio(memory_bytes,1024) is KiB. Several: derived: percent(A,B), ratio(C,D).
# Nothing else is derived: a ratio of two rows, a difference or a sum is not checked,
# and a table holding one stays unannotated.
# The check is by value, not by place: a number found anywhere in the sources passes. It catches a typo, a
# stale figure or a wrong rounding, not a right value copied into the wrong cell. A median of an odd
# number of processes is one of their values, so it passes against the per-process CSV.
#
# Output: FILE:LINE: token 'X' not found in CSV(s) ... for each number that matches nothing (with the
# nearest value of the sources), and a summary: N tables checked, M numbers, K unannotated tables with
# numbers (in a column that is not the first), which --list names. Exit 1 on any mismatch, a missing
# source or a numbers comment that annotates no table; 0 otherwise.
set -euo pipefail

list=0
root=
for arg in "$@"; do
    case $arg in
    --list) list=1 ;;
    -h | --help)
        sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'
        exit 0
        ;;
    -*)
        echo "check_numbers.sh: unknown option $arg" >&2
        exit 2
        ;;
    *) root=$arg ;;
    esac
done
if [[ -z $root || ! -d $root ]]; then
    echo "usage: $0 [--list] COURSE_ROOT" >&2
    exit 2
fi
cd "$root"
texts=()
for f in README.md chapters/*/README.md chapters/*/NOTES.md slides/*.md; do
    [[ -f $f ]] && texts+=("$f")
done

prog=$(
    cat <<'AWK'
function is_word(c) { return c ~ /[A-Za-z0-9_]/ }
function is_digit(c) { return c ~ /[0-9]/ }

# tokenize(s): the numbers of s into TOK[1..n] (as written), TV (value), TU (the unit of its last digit).
function tokenize(s,   n, i, j, c, p, pp, start, sign, d, e, tok, num, ntok, k) {
    ntok = 0
    n = length(s)
    i = 1
    while (i <= n) {
        c = substr(s, i, 1)
        if (!is_digit(c)) { i++; continue }
        p = (i > 1) ? substr(s, i - 1, 1) : ""
        pp = (i > 2) ? substr(s, i - 2, 1) : ""
        # glued to a word on the left (an 'x' standing alone before it is a ratio: x1.05)
        if ((is_word(p) || p == ".") && !(p == "x" && !is_word(pp))) {
            while (i <= n && (is_word(substr(s, i, 1)) || substr(s, i, 1) == ".")) i++
            continue
        }
        start = i
        sign = ""
        if ((p == "-" || p == "+") && !(is_word(pp) || pp == ")" || pp == ".")) sign = p
        j = i
        while (j <= n && is_digit(substr(s, j, 1))) j++
        # thousands: ",ddd" not followed by a digit, after a first group of 1 to 3 digits
        if (j - i <= 3)
            while (substr(s, j, 1) == "," && substr(s, j + 1, 3) ~ /^[0-9][0-9][0-9]$/ && !is_digit(substr(s, j + 4, 1)))
                j += 4
        d = 0
        if (substr(s, j, 1) == "." && is_digit(substr(s, j + 1, 1))) {
            j++
            while (j <= n && is_digit(substr(s, j, 1))) { j++; d++ }
        }
        e = 0
        if (substr(s, j, 1) ~ /[eE]/) {
            k = j + 1
            if (substr(s, k, 1) ~ /[-+]/) k++
            if (is_digit(substr(s, k, 1))) {
                while (k <= n && is_digit(substr(s, k, 1))) k++
                e = substr(s, j + 1, k - j - 1) + 0
                j = k
            }
        }
        tok = substr(s, start, j - start)
        c = substr(s, j, 1)
        if (c == "%" || (c == "x" && !is_word(substr(s, j + 1, 1)))) j++
        else if (is_word(c) || (c == "." && is_digit(substr(s, j + 1, 1)))) {
            # glued to a word on the right (16th, 2D, 1.2.3)
            while (j <= n && (is_word(substr(s, j, 1)) || substr(s, j, 1) == ".")) j++
            i = j
            continue
        }
        num = tok
        gsub(/,/, "", num)
        ntok++
        TOK[ntok] = ((p == "x" && !is_word(pp)) ? "x" : sign) substr(s, start, j - start)
        TV[ntok] = (sign == "-" ? -1 : 1) * (num + 0)
        TU[ntok] = exp((e - d) * log(10))
        TD[ntok] = (e == 0 && tok !~ /[eE]/) ? d : -1
        i = j
    }
    return ntok
}

function is_number(f) { return f ~ /^[-+]?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][-+]?[0-9]+)?$/ }

# load(path): read a source once: its numbers into VAL[path, 1..NVAL[path]], a CSV's rows into
# CELL[path, row, column] with COLS[path, name] the column of each header name.
function load(path,   line, nf, f, i, row, ismd, hdr, n) {
    if (path in LOADED) return LOADED[path]
    if ((getline line < path) < 0) { LOADED[path] = 0; return 0 }
    close(path)
    LOADED[path] = 1
    ismd = (path ~ /[.]md$/)
    NVAL[path] = 0
    row = 0
    while ((getline line < path) > 0) {
        sub(/\r$/, "", line)
        if (ismd) {
            if (line !~ /^[ \t]*[|]/ || line ~ /^[ \t]*[|][-:| \t]*$/) { hdr = 0; continue }
            if (!hdr) { hdr = 1; continue }   # a table's header row
            n = tokenize(line)
            for (i = 1; i <= n; i++) VAL[path, ++NVAL[path]] = TV[i]
            continue
        }
        nf = split(line, f, ",")
        if (row == 0) {
            for (i = 1; i <= nf; i++) COLS[path, f[i]] = i
            row = 1
            continue
        }
        row++
        for (i = 1; i <= nf; i++) {
            if (!is_number(f[i])) continue
            VAL[path, ++NVAL[path]] = f[i] + 0
            CELL[path, row, i] = f[i] + 0
        }
    }
    NROW[path] = row
    close(path)
    return 1
}

function key(v, d,   k) {
    k = sprintf("%." d "f", v)
    if (k ~ /^-0[.]?0*$/) k = substr(k, 2)
    return k
}

# indexed(path, d): the set of path's numbers rounded to d decimals, KEYS[path, d, key], built once.
function indexed(path, d,   i) {
    if ((path, d) in BUILT) return
    BUILT[path, d] = 1
    for (i = 1; i <= NVAL[path]; i++) KEYS[path, d, key(VAL[path, i], d)] = 1
}

function close_enough(c, v, u) {
    return (c - v <= u / 2 * (1 + 1e-9) + 1e-12 * (v < 0 ? -v : v)) && (v - c <= u / 2 * (1 + 1e-9) + 1e-12 * (v < 0 ? -v : v))
}

# found(k): token k of TOK matches a number of the table's sources (or a declared derivation);
# NEAREST is the closest source number when it does not.
function found(k,   s, path, i, c, best, bd, dd, r, t, a, b, v, u, q, x, y) {
    v = TV[k]; u = TU[k]
    if (TD[k] >= 0)
        for (s = 1; s <= NSRC; s++) {
            path = SRC[s]
            indexed(path, TD[k])
            if ((path, TD[k], key(v, TD[k])) in KEYS) return 1
        }
    bd = -1
    for (s = 1; s <= NSRC; s++) {
        path = SRC[s]
        for (i = 1; i <= NVAL[path]; i++) {
            c = VAL[path, i]
            if (close_enough(c, v, u)) return 1
            dd = c - v; if (dd < 0) dd = -dd
            if (bd < 0 || dd < bd) { bd = dd; best = c }
        }
    }
    for (t = 1; t <= NDER; t++) {
        if (DKIND[t] == "percent" && TOK[k] !~ /%$/) continue
        for (s = 1; s <= NSRC; s++) {
            path = SRC[s]
            if (!((path, DA[t]) in COLS) || !(is_number(DB[t]) || (path, DB[t]) in COLS)) continue
            a = COLS[path, DA[t]]; b = is_number(DB[t]) ? 0 : COLS[path, DB[t]]
            for (r = 2; r <= NROW[path]; r++) {
                if (!((path, r, a) in CELL) || !(b == 0 || (path, r, b) in CELL)) continue
                x = CELL[path, r, a]; y = (b == 0) ? DB[t] + 0 : CELL[path, r, b]
                if (DKIND[t] == "percent") {
                    if (x == 0) continue
                    q = 100 * (y / x - 1)
                } else {
                    if (y == 0) continue
                    q = x / y
                }
                if (close_enough(q, v, u)) return 1
            }
        }
    }
    NEAREST = (bd < 0) ? "none" : best
    return 0
}

function problem(msg) { print msg; PROBLEMS++ }

# parse_annotation(line): add a numbers comment's sources, labels and derivations to the pending ones.
function parse_annotation(line,   body, n, w, i, j, mode, m, spec) {
    body = line
    sub(/^[ \t]*<!--[ \t]*numbers:/, "", body)
    if (body !~ /-->[ \t]*$/) {
        problem(F ":" FNR ": a numbers comment must close on its own line (-->)")
        return
    }
    sub(/-->[ \t]*$/, "", body)
    gsub(/,[ \t]+/, ",", body)
    n = split(body, w, /[ \t]+/)
    mode = "src"
    for (i = 1; i <= n; i++) {
        if (w[i] == "") continue
        if (w[i] == "labels:") { mode = "labels"; continue }
        if (w[i] == "derived:") { mode = "derived"; continue }
        if (mode == "labels") { P_LABELS = w[i] + 0; mode = "src"; continue }
        if (mode == "derived") {
            m = split(w[i], spec, ",")
            for (j = 1; j <= m; j += 2) {
                if (spec[j] !~ /^(percent|ratio)[(][^()]+$/ || spec[j + 1] !~ /^[^()]+[)]$/) {
                    problem(F ":" FNR ": derived: expects percent(A,B) or ratio(A,B), got '" w[i] "'")
                    break
                }
                P_NDER++
                P_DKIND[P_NDER] = substr(spec[j], 1, index(spec[j], "(") - 1)
                P_DA[P_NDER] = substr(spec[j], index(spec[j], "(") + 1)
                P_DB[P_NDER] = spec[j + 1]; sub(/[)]$/, "", P_DB[P_NDER])
            }
            continue
        }
        P_NSRC++
        P_SRC[P_NSRC] = w[i]
    }
    if (P_NSRC == 0) problem(F ":" FNR ": a numbers comment without a source")
    P_LINE = FNR
    PENDING = 1
}

function drop_pending() {
    if (PENDING) problem(F ":" P_LINE ": a numbers comment that annotates no table")
    PENDING = 0; P_NSRC = 0; P_NDER = 0; P_LABELS = 1
}

# start_table(): the table whose header is the previous line; its annotation is the pending one.
function start_table(   s, i) {
    INTABLE = 1
    TABLE_LINE = FNR - 1
    HEADER = PREV
    NSRC = 0; NDER = 0; LABELS = 1; TABLE_NUMBERS = 0
    ANNOTATED = PENDING
    if (PENDING) {
        TABLES++
        for (s = 1; s <= P_NSRC; s++) {
            if (!load(P_SRC[s])) {
                problem(F ":" P_LINE ": source '" P_SRC[s] "' not found")
                continue
            }
            SRC[++NSRC] = P_SRC[s]
            SRCLIST = (s == 1 ? "" : SRCLIST " ") P_SRC[s]
        }
        for (i = 1; i <= P_NDER; i++) { DKIND[i] = P_DKIND[i]; DA[i] = P_DA[i]; DB[i] = P_DB[i] }
        NDER = P_NDER
        LABELS = P_LABELS
    }
    PENDING = 0; P_NSRC = 0; P_NDER = 0; P_LABELS = 1
}

function end_table() {
    if (INTABLE && !ANNOTATED && TABLE_NUMBERS > 0) {
        UNANNOTATED++
        UNLIST[UNANNOTATED] = F ":" TABLE_LINE ": " TABLE_NUMBERS " numbers: " HEADER
    }
    INTABLE = 0
}

function body_row(line,   s, n, cells, c, k, ntok) {
    s = line
    gsub(/`[^`]*`/, " ", s)      # code spans are names, not numbers
    gsub(/\\[|]/, " ", s)
    sub(/^[ \t]*[|]/, "", s)
    sub(/[|][ \t]*$/, "", s)
    n = split(s, cells, "|")
    for (c = LABELS + 1; c <= n; c++) {
        ntok = tokenize(cells[c])
        for (k = 1; k <= ntok; k++) {
            TABLE_NUMBERS++
            if (!ANNOTATED || NSRC == 0) continue
            NUMBERS++
            if (!found(k))
                problem(F ":" FNR ": token '" TOK[k] "' not found in CSV(s) " SRCLIST " (nearest: " NEAREST ")")
        }
    }
}

FNR == 1 {
    if (NR > 1) { end_table(); drop_pending() }
    F = FILENAME
    INFENCE = 0; INTABLE = 0; PREVPIPE = 0; PREV = ""
    PENDING = 0; P_NSRC = 0; P_NDER = 0; P_LABELS = 1
}
{ sub(/\r$/, "") }
/^[ \t]*(```|~~~)/ {
    end_table(); PREVPIPE = 0
    if (!INFENCE) drop_pending()
    INFENCE = !INFENCE
    next
}
INFENCE { next }
INTABLE && /^[ \t]*[|]/ { body_row($0); next }
INTABLE { end_table() }
PREVPIPE && /^[ \t]*[|][ \t]*:?-+:?[ \t]*([|][ \t]*:?-+:?[ \t]*)*[|]?[ \t]*$/ { PREVPIPE = 0; start_table(); next }
PREVPIPE { drop_pending(); PREVPIPE = 0 }
/^[ \t]*[|]/ { PREVPIPE = 1; PREV = $0; next }
/^[ \t]*<!--[ \t]*numbers:/ { parse_annotation($0); next }
/^[ \t]*$/ { next }
{ drop_pending() }

END {
    end_table(); drop_pending()
    if (LIST)
        for (i = 1; i <= UNANNOTATED; i++) print "unannotated: " UNLIST[i]
    printf "%d tables checked, %d numbers, %d unannotated tables with numbers (listed with --list)\n",
        TABLES, NUMBERS, UNANNOTATED
    if (PROBLEMS) {
        printf "%d problem(s)\n", PROBLEMS
        exit 1
    }
}
AWK
)

awk -v LIST="$list" "$prog" "${texts[@]}"
