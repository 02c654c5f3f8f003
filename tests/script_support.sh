# Shared by the end-to-end test scripts (sourced, not run): a failure counter, fail, contains and runs.
# Each script ends with finish NAME.
failures=0

# fail WHAT: count a failed check and say which.
fail() {
    echo "FAILED: $*" >&2
    failures=$((failures + 1))
}

# contains FILE TEXT WHAT: FILE holds TEXT (a fixed string); else a failure that shows FILE.
contains() {
    grep -qF -- "$2" "$1" || { fail "$3: expected '$2' in:"; sed 's/^/    /' "$1" | head -n 40 >&2; }
}

# runs WHAT CODE PROGRAM ARGS...: PROGRAM ARGS exits with CODE; stdout in $dir/out, stderr in $dir/err
# ($dir: the calling script's scratch folder); else a failure that shows the end of both.
runs() {
    local what=$1 code=$2 prog=$3
    shift 3
    local rc=0
    "$prog" "$@" >"$dir/out" 2>"$dir/err" || rc=$?
    if [[ $rc -ne $code ]]; then
        fail "$what: exit $rc, expected $code"
        sed 's/^/    /' "$dir/out" "$dir/err" | tail -n 40 >&2
    fi
}

# finish NAME: exit 1 if any check failed, 0 otherwise, saying which.
finish() {
    if [[ $failures -ne 0 ]]; then
        echo "$1 end to end: $failures check(s) failed" >&2
        exit 1
    fi
    echo "$1 end to end: all checks passed"
}
