#!/usr/bin/env bash
# The numbers in the course's texts against the CSVs the programs wrote (bash and awk only: the course runs
# on bare Debian 12, whose awk is mawk).
#
# Usage: check_numbers.sh [--list] COURSE_ROOT
#
# Texts: README.md, chapters/*/README.md, chapters/*/NOTES.md, chapters/*/NOTES_earlier.md and slides/*.md.
#
# Convention. An HTML comment on the line(s) before a Markdown table declares where its numbers come from:
#
#     <!-- numbers: slides/img/05_sah/bins.csv [more.csv ...] [labels: N] [derived: percent(A,B)]
#          [join: A+B] [columns: rows|any] -->
#     | scene | tree | build ms | ...
#     |---|---|---|
#
# Paths are relative to the repository root. Blank lines may separate the comment from the table, and a
# table may have several such comments (their sources add up); a numbers comment that no table follows is
# an error. A source is a CSV (every field that is a number counts) or a Markdown table a program wrote
# (the race's *_spread.md: every number in its table body rows counts).
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
# The token check is by value: a number found anywhere in the sources passes it. It catches a typo, a
# stale figure or a wrong rounding. A median of an odd number of processes is one of their values, so it
# passes against the per-process CSV.
#
# The column rule catches a right value in the wrong cell. A table column's numbers are split by their
# place in the cell: its sub-column k holds the k-th number of each of its cells (in "82.72 (81.52 to
# 87.69)" 82.72 is number 1, 81.52 number 2, 87.69 number 3; a cell with one number has only number 1).
# Each sub-column of each checked column (outside the label columns) must be held, every one of its
# numbers (those the token check found), at the precision written, by ONE source column:
#   - a column of one CSV source (its header names it),
#   - a derivation named in derived: over one CSV source (ratio(A,B) of its rows; percent(A,B), for
#     numbers written with '%'),
#   - in a Markdown source, number k of the cells of one column of one of its tables (the spread's
#     "18.866 (17.673 to 19.741)" gives three source columns: medians, smallest, largest),
#   - a join declared in the comment (below).
# Which source column may differ from one table column, or sub-column, to the next. Three words in the
# numbers comment adjust the rule for one table, and only where its layout needs it:
#   join: A+B[+C...][, D+E...]  the named columns of a CSV source count as one source column (a table
#       column whose shadow-ray rows are any-hit figures: join: closest_mrays_s+any_mrays_s; a memory
#       column in KiB and MiB: join: memory_kib+memory_mib). Each name must be a column of a source.
#   columns: rows  a transposed table (one quantity per row, a parameter per column): the rule holds
#       for each body row instead of each column.
#   columns: any   opts the table out of the column rule (the token check stays): for a table that mixes
#       quantities within its columns and rows (a last row of Mrays/s below ratio rows). Use sparingly.
# The keywords labels:, derived:, join: and columns: follow the sources.
#
# One machine per table. A source that records where it was measured (a CSV's cpu column, as the race's
# race.csv has; a race spread's "Machine: NAME," line) names its processor; the sources of one table must
# name one between them, and the text from the table's heading (the nearest line starting with #) down to
# the table must name it as texts write it: "Intel(R) Xeon(R) Processor" is Intel Xeon, "AMD EPYC 7B13
# 64-Core Processor" AMD EPYC 7B13. Sources that record no machine (older CSVs) are not checked for it.
#
# Output: FILE:LINE: token 'X' not found in CSV(s) ... for each number that matches nothing (with the
# nearest value of the sources); FILE:LINE: column 'HEADER' [(number k of its cells)]: no single source
# column holds all its numbers (best: the source column that holds most of them, how many; misses: the
# tokens it lacks, with their lines), LINE being the table's header (under columns: rows, "row 'LABEL'"
# and the row's line); and a summary: N tables checked, M numbers, C sub-columns each held by one source
# column, tables opted out, K unannotated tables with numbers (in a column that is not the first), which
# --list names, and the tables whose sources name their machine; FILE:LINE: ... measured on NAME; the text
# above it ... does not say so, and FILE:LINE: one table, two machines. Exit 1 on any mismatch, a column the
# rule rejects, a machine unnamed or two, a missing source or a numbers comment that annotates no table; 0
# otherwise.
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
for f in README.md chapters/*/README.md chapters/*/NOTES.md chapters/*/NOTES_earlier.md slides/*.md; do
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

# cpu_name(s): a processor's name as texts write it: "Intel(R) Xeon(R) Processor" is Intel Xeon, "AMD EPYC
# 7B13 64-Core Processor" AMD EPYC 7B13 (trademarks, "Processor", "CPU" and what follows, core counts cut).
function cpu_name(s) {
    gsub(/[(](R|TM|r|tm)[)]/, "", s)
    sub(/ CPU.*$/, "", s); sub(/ @.*$/, "", s)
    gsub(/ [0-9]+-Core/, "", s); gsub(/ Processor/, "", s)
    gsub(/[ \t]+/, " ", s); sub(/^ /, "", s); sub(/ $/, "", s)
    return s
}
# add_cpu(path, name): a machine a source was measured on (a CSV's cpu column, a race spread's "Machine:").
function add_cpu(path, name) {
    name = cpu_name(name)
    if (name == "" || (path, name) in HASCPU) return
    HASCPU[path, name] = 1
    CPULIST[path] = (CPULIST[path] == "" ? "" : CPULIST[path] "|") name
}

# load(path): read a source once: its numbers into VAL[path, 1..NVAL[path]], a CSV's rows into
# CELL[path, row, column] with COLS[path, name] the column of each header name, and its source columns
# (for the column rule) into SCV[id, 1..SCN[id]]: one per CSV column, one per number position of each
# column of each table of a Markdown source; PCOLS[path] lists their ids.
function load(path,   line, nf, f, i, row, ismd, hdr, n, tbl, ncell, cell, c, p, id, hcell, h, m) {
    if (path in LOADED) return LOADED[path]
    if ((getline line < path) < 0) { LOADED[path] = 0; return 0 }
    close(path)
    LOADED[path] = 1
    ismd = (path ~ /[.]md$/)
    NVAL[path] = 0
    PCOLS[path] = ""
    row = 0
    tbl = 0
    while ((getline line < path) > 0) {
        sub(/\r$/, "", line)
        if (ismd) {
            if (line ~ /^Machine: /) { m = line; sub(/^Machine: /, "", m); sub(/,.*/, "", m); add_cpu(path, m) }
            if (line !~ /^[ \t]*[|]/) { hdr = 0; continue }
            if (line ~ /^[ \t]*[|][-:| \t]*$/) continue   # the |---| line, between a header and its rows
            if (!hdr) {   # a table's header row
                hdr = 1
                tbl++
                header_cells(line, hcell)
                for (c in hcell) MDHDR[path, tbl, c] = trim(hcell[c])
                continue
            }
            n = tokenize(line)
            for (i = 1; i <= n; i++) VAL[path, ++NVAL[path]] = TV[i]
            ncell = split_cells(line, cell)
            for (c = 1; c <= ncell; c++) {
                n = tokenize(cell[c])
                for (p = 1; p <= n; p++) {
                    if (!((path, tbl, c, p) in MDCOL)) {
                        id = new_column(path, "", 0)
                        h = MDHDR[path, tbl, c]
                        SCNAME[id] = path " table " tbl " column '" h "'" (p > 1 ? " number " p : "")
                        MDCOL[path, tbl, c, p] = id
                    }
                    id = MDCOL[path, tbl, c, p]
                    SCV[id, ++SCN[id]] = TV[p]
                }
            }
            continue
        }
        nf = split(line, f, ",")
        if (row == 0) {
            for (i = 1; i <= nf; i++) {
                COLS[path, f[i]] = i
                if (f[i] == "cpu") CPUCOL[path] = i
                CSVCOL[path, i] = new_column(path, "", 0)
                SCNAME[CSVCOL[path, i]] = path " column '" f[i] "'"
            }
            NCOL[path] = nf
            row = 1
            continue
        }
        row++
        if (path in CPUCOL) add_cpu(path, f[CPUCOL[path]])
        for (i = 1; i <= nf; i++) {
            if (!is_number(f[i])) continue
            VAL[path, ++NVAL[path]] = f[i] + 0
            CELL[path, row, i] = f[i] + 0
            if ((path, i) in CSVCOL) { id = CSVCOL[path, i]; SCV[id, ++SCN[id]] = f[i] + 0 }
        }
    }
    NROW[path] = row
    close(path)
    return 1
}

# new_column(path, name, pct): a new source column of path (pct: it holds percentages, matched by a
# token written with '%' only); its id.
function new_column(path, name, pct,   id) {
    id = ++NSC
    SCN[id] = 0
    SCNAME[id] = name
    SCPCT[id] = pct
    PCOLS[path] = PCOLS[path] " " id
    return id
}

# derived_column(t, path): the source column of derivation t (DKIND, DA, DB) over path's rows, built once;
# 0 where path lacks one of its columns.
function derived_column(t, path,   dk, id, a, b, r, x, y) {
    dk = DKIND[t] SUBSEP DA[t] SUBSEP DB[t] SUBSEP path
    if (dk in DERCOL) return DERCOL[dk]
    DERCOL[dk] = 0
    if (path ~ /[.]md$/ || !((path, DA[t]) in COLS) || !(is_number(DB[t]) || (path, DB[t]) in COLS)) return 0
    id = ++NSC
    SCN[id] = 0
    SCNAME[id] = DKIND[t] "(" DA[t] "," DB[t] ") of " path
    SCPCT[id] = (DKIND[t] == "percent")
    a = COLS[path, DA[t]]; b = is_number(DB[t]) ? 0 : COLS[path, DB[t]]
    for (r = 2; r <= NROW[path]; r++) {
        if (!((path, r, a) in CELL) || !(b == 0 || (path, r, b) in CELL)) continue
        x = CELL[path, r, a]; y = (b == 0) ? DB[t] + 0 : CELL[path, r, b]
        if (DKIND[t] == "percent") {
            if (x == 0) continue
            SCV[id, ++SCN[id]] = 100 * (y / x - 1)
        } else {
            if (y == 0) continue
            SCV[id, ++SCN[id]] = x / y
        }
    }
    DERCOL[dk] = id
    return id
}

# column_has(id, tok, v, u, d): source column id holds a value that, at the token's precision, is it.
function column_has(id, tok, v, u, d,   i, k) {
    if (SCPCT[id] && tok !~ /%$/) return 0
    if (d >= 0) {
        if (!((id, d) in CBUILT)) {
            CBUILT[id, d] = 1
            for (i = 1; i <= SCN[id]; i++) CKEYS[id, d, key(SCV[id, i], d)] = 1
        }
        if ((id, d, key(v, d)) in CKEYS) return 1
    }
    for (i = 1; i <= SCN[id]; i++)
        if (close_enough(SCV[id, i], v, u)) return 1
    return 0
}

function trim(s) { gsub(/^[ \t]+|[ \t]+$/, "", s); return s }

# header_cells(line, cells): a header row's cell texts (backticks dropped), their number.
function header_cells(line, cells,   s, n, c) {
    s = line
    gsub(/\\[|]/, "/", s)
    gsub(/`/, "", s)
    sub(/^[ \t]*[|]/, "", s)
    sub(/[|][ \t]*$/, "", s)
    n = split(s, cells, "|")
    for (c = 1; c <= n; c++) cells[c] = trim(cells[c])
    return n
}

# split_cells(line, cells): a table row's cells (code spans and escaped pipes blanked), their number.
function split_cells(line, cells,   s) {
    s = line
    gsub(/`[^`]*`/, " ", s)      # code spans are names, not numbers
    gsub(/\\[|]/, " ", s)
    sub(/^[ \t]*[|]/, "", s)
    sub(/[|][ \t]*$/, "", s)
    return split(s, cells, "|")
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
        if (w[i] == "columns:") { mode = "columns"; continue }
        if (w[i] == "join:") { mode = "join"; continue }
        if (mode == "columns") {
            if (w[i] != "any" && w[i] != "rows") problem(F ":" FNR ": columns: expects any or rows, got '" w[i] "'")
            P_COLMODE = w[i]; mode = "src"; continue
        }
        if (mode == "join") {
            m = split(w[i], spec, ",")
            for (j = 1; j <= m; j++) {
                if (spec[j] !~ /^[^+]+([+][^+]+)+$/) {
                    problem(F ":" FNR ": join: expects A+B[+C...], got '" spec[j] "'")
                    continue
                }
                P_JOIN[++P_NJOIN] = spec[j]
            }
            continue
        }
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
    PENDING = 0; P_NSRC = 0; P_NDER = 0; P_LABELS = 1; P_COLMODE = ""; P_NJOIN = 0
}

# start_table(): the table whose header is the previous line; its annotation is the pending one.
function start_table(   s, i) {
    INTABLE = 1
    TABLE_LINE = FNR - 1
    HEADER = PREV
    NSRC = 0; NDER = 0; LABELS = 1; TABLE_NUMBERS = 0
    COLMODE = ""; NJOIN = 0; NG = 0; ROWS = 0; ANN_LINE = P_LINE
    delete CTN; delete CTT; delete CTV; delete CTU; delete CTD; delete CTL; delete PMAX
    delete GLINE; delete GN; delete GNAME
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
        check_machine()
        for (i = 1; i <= P_NDER; i++) { DKIND[i] = P_DKIND[i]; DA[i] = P_DA[i]; DB[i] = P_DB[i] }
        NDER = P_NDER
        LABELS = P_LABELS
        COLMODE = P_COLMODE
        for (i = 1; i <= P_NJOIN; i++) JOIN[i] = P_JOIN[i]
        NJOIN = P_NJOIN
    }
    PENDING = 0; P_NSRC = 0; P_NDER = 0; P_LABELS = 1; P_COLMODE = ""; P_NJOIN = 0
}

# check_machine(): one machine per table, named in the text. The sources that record their machine (a CPU
# column, a spread's "Machine:" line) must name one processor between them, and the text from the table's
# heading down to its header must name it as texts write it (Intel Xeon, AMD EPYC).
function check_machine(   s, n, c, i, names, list, k) {
    list = ""; k = 0
    for (s = 1; s <= NSRC; s++) {
        if (!(SRC[s] in CPULIST)) continue
        n = split(CPULIST[SRC[s]], c, "|")
        for (i = 1; i <= n; i++)
            if (!(c[i] in names)) { names[c[i]] = 1; list = (k++ ? list " and " : "") c[i] }
    }
    if (k == 0) return
    MACHINE_TABLES++
    if (k > 1) { problem(F ":" P_LINE ": one table, two machines: its sources were measured on " list); return }
    if (index(CONTEXT, list) == 0)
        problem(F ":" TABLE_LINE ": the table's sources were measured on " list "; the text above it (from its heading) does not say so")
}

function end_table() {
    if (INTABLE && ANNOTATED && NSRC > 0 && COLMODE != "any") check_columns()
    if (INTABLE && ANNOTATED && COLMODE == "any") OPTOUTS++
    if (INTABLE && !ANNOTATED && TABLE_NUMBERS > 0) {
        UNANNOTATED++
        UNLIST[UNANNOTATED] = F ":" TABLE_LINE ": " TABLE_NUMBERS " numbers: " HEADER
    }
    INTABLE = 0
}

function body_row(line,   n, cells, c, k, ntok, m, g, lab) {
    n = split_cells(line, cells)
    ROWS++
    for (c = LABELS + 1; c <= n; c++) {
        ntok = tokenize(cells[c])
        for (k = 1; k <= ntok; k++) {
            TABLE_NUMBERS++
            if (!ANNOTATED || NSRC == 0) continue
            NUMBERS++
            if (!found(k)) {
                problem(F ":" FNR ": token '" TOK[k] "' not found in CSV(s) " SRCLIST " (nearest: " NEAREST ")")
                continue
            }
            # kept for the column rule: the k-th number of the cells of group g (a column, or a row)
            g = (COLMODE == "rows") ? ROWS : c
            if (!(g in GLINE)) {
                GLINE[g] = (COLMODE == "rows") ? FNR : TABLE_LINE
                GN[++NG] = g
            }
            m = ++CTN[g, k]
            CTT[g, k, m] = TOK[k]; CTV[g, k, m] = TV[k]; CTU[g, k, m] = TU[k]; CTD[g, k, m] = TD[k]
            CTL[g, k, m] = FNR
            if (k > PMAX[g]) PMAX[g] = k
        }
    }
    if (COLMODE == "rows" && (ROWS in GLINE)) {
        lab = ""
        for (c = 1; c <= LABELS && c <= n; c++) lab = lab (lab == "" ? "" : " ") trim(cells[c])
        GNAME[ROWS] = (lab == "") ? "row " ROWS : lab
    }
}

# candidates(): the table's source columns into CAND[1..NCAND]: every column of every source, the
# declared derivations over each CSV source, and each join: group over each CSV source.
function candidates(   s, path, ids, nid, j, id, jn, names, nn, i, jk, any, r, found_in) {
    NCAND = 0
    for (s = 1; s <= NSRC; s++) {
        path = SRC[s]
        nid = split(PCOLS[path], ids, " ")
        for (j = 1; j <= nid; j++) CAND[++NCAND] = ids[j]
        for (j = 1; j <= NDER; j++) {
            id = derived_column(j, path)
            if (id) CAND[++NCAND] = id
        }
    }
    for (jn = 1; jn <= NJOIN; jn++) {
        nn = split(JOIN[jn], names, "+")
        for (i = 1; i <= nn; i++) found_in[i] = 0
        for (s = 1; s <= NSRC; s++) {
            path = SRC[s]
            jk = JOIN[jn] SUBSEP path
            if (!(jk in JOINCOL)) {
                JOINCOL[jk] = 0
                any = 0
                for (i = 1; i <= nn; i++) if ((path, names[i]) in COLS) any = 1
                if (any) {
                    id = ++NSC
                    SCN[id] = 0; SCPCT[id] = 0
                    SCNAME[id] = path " columns " JOIN[jn] " (joined)"
                    for (i = 1; i <= nn; i++) {
                        if (!((path, names[i]) in COLS)) continue
                        j = CSVCOL[path, COLS[path, names[i]]]
                        for (r = 1; r <= SCN[j]; r++) SCV[id, ++SCN[id]] = SCV[j, r]
                    }
                    JOINCOL[jk] = id
                }
            }
            if (JOINCOL[jk]) CAND[++NCAND] = JOINCOL[jk]
            for (i = 1; i <= nn; i++) if ((path, names[i]) in COLS) found_in[i] = 1
        }
        for (i = 1; i <= nn; i++)
            if (!found_in[i]) problem(F ":" ANN_LINE ": join: column '" names[i] "' is in none of the sources")
    }
}

# check_columns(): the column rule over the table just ended: every sub-column (the k-th number of the
# cells of one column; of one row under "columns: rows") must be held, all of it, by one source column.
function check_columns(   hdr, nh, gi, g, k, m, j, id, cnt, best, bestcnt, miss, nmiss, name, n) {
    nh = header_cells(HEADER, hdr)
    candidates()
    for (gi = 1; gi <= NG; gi++) {
        g = GN[gi]
        for (k = 1; k <= PMAX[g]; k++) {
            n = CTN[g, k] + 0
            if (n == 0) continue
            SUBCOLUMNS++
            best = 0; bestcnt = -1
            for (j = 1; j <= NCAND; j++) {
                id = CAND[j]
                cnt = 0
                for (m = 1; m <= n; m++)
                    if (column_has(id, CTT[g, k, m], CTV[g, k, m], CTU[g, k, m], CTD[g, k, m])) cnt++
                    else if (cnt + n - m <= bestcnt) break   # cannot beat the best any more
                if (cnt > bestcnt) { best = id; bestcnt = cnt }
                if (cnt == n) break
            }
            if (bestcnt == n) continue
            if (COLMODE == "rows") name = "row '" GNAME[g] "'"
            else name = "column '" ((g <= nh && hdr[g] != "") ? hdr[g] : "#" g) "'"
            miss = ""; nmiss = 0
            if (best)
                for (m = 1; m <= n; m++) {
                    if (column_has(best, CTT[g, k, m], CTV[g, k, m], CTU[g, k, m], CTD[g, k, m])) continue
                    if (++nmiss <= 6) miss = miss (nmiss > 1 ? ", " : "") "'" CTT[g, k, m] "' (line " CTL[g, k, m] ")"
                }
            if (nmiss > 6) miss = miss " and " (nmiss - 6) " more"
            problem(F ":" GLINE[g] ": " name (PMAX[g] > 1 ? " (number " k " of its cells)" : "") \
                ": no single source column holds all its numbers" \
                (best ? " (best: " SCNAME[best] ", " bestcnt " of " n "; misses " miss ")" : ""))
        }
    }
}

FNR == 1 {
    if (NR > 1) { end_table(); drop_pending() }
    F = FILENAME
    INFENCE = 0; INTABLE = 0; PREVPIPE = 0; PREV = ""; CONTEXT = ""
    PENDING = 0; P_NSRC = 0; P_NDER = 0; P_LABELS = 1; P_COLMODE = ""; P_NJOIN = 0
}
{ sub(/\r$/, "") }
/^[ \t]*(```|~~~)/ {
    end_table(); PREVPIPE = 0
    if (!INFENCE) drop_pending()
    INFENCE = !INFENCE
    next
}
INFENCE { next }
/^#/ { CONTEXT = "" }
{ CONTEXT = CONTEXT "\n" $0 }
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
    printf "%d tables checked, %d numbers, %d sub-columns each held by one source column, %d table(s) opted out (columns: any), %d unannotated tables with numbers (listed with --list), %d tables whose sources name their machine, named in the text\n",
        TABLES, NUMBERS, SUBCOLUMNS, OPTOUTS, UNANNOTATED, MACHINE_TABLES
    if (PROBLEMS) {
        printf "%d problem(s)\n", PROBLEMS
        exit 1
    }
}
AWK
)

awk -v LIST="$list" "$prog" "${texts[@]}"
