#!/usr/bin/env bash
# tests/check_numbers.sh on small made-up courses: a right table passes; a wrong number, a table whose
# sources were measured on a machine the text does not name, and a table from two machines fail.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
failures=0

# course NAME TEXT: a course root holding README.md = TEXT and two race CSVs (AMD EPYC, Intel Xeon).
course() {
    local root=$scratch/$1
    mkdir -p "$root/slides/img"
    printf '%s\n' "$2" > "$root/README.md"
    printf 'scene,structure,closest_mrays_s,cpu,threads\nbunny,final,7.25,AMD EPYC 7B13 64-Core Processor,1\n' > "$root/slides/img/amd.csv"
    printf 'scene,structure,closest_mrays_s,cpu,threads\nbunny,final,6.50,Intel(R) Xeon(R) Processor,1\n' > "$root/slides/img/intel.csv"
    echo "$root"
}
# expect WANT NAME TEXT [PATTERN]: check_numbers.sh on that course exits WANT (0 or 1), its output matching PATTERN.
expect() {
    local want=$1 name=$2 text=$3 pattern=${4:-} root out rc=0
    root=$(course "$name" "$text")
    out=$(bash "$here/check_numbers.sh" "$root" 2>&1) || rc=$?
    if [[ $rc -ne $want ]] || { [[ -n $pattern ]] && ! grep -q -- "$pattern" <<<"$out"; }; then
        echo "FAIL $name: exit $rc (expected $want${pattern:+, output matching '$pattern'}):"
        echo "$out"
        failures=$((failures + 1))
    else
        echo "ok   $name"
    fi
}
table='<!-- numbers: slides/img/amd.csv -->
| scene | Mrays/s |
|---|---|
| bunny | 7.25 |'

expect 0 named "# Race
One thread on the AMD EPYC 7B13:

$table" "1 tables whose sources name their machine"
expect 1 wrong_number "# Race
One thread on the AMD EPYC 7B13:

${table/7.25 |/7.52 |}" "token '7.52' not found"
expect 1 unnamed "# Race
One thread:

$table" "measured on AMD EPYC 7B13; the text above it"
# The name must stand in the table's own section, not an earlier one.
expect 1 named_elsewhere "# Machines
AMD EPYC 7B13 throughout.
# Race
One thread:

$table" "does not say so"
expect 1 two_machines "# Race
On the AMD EPYC 7B13 and the Intel Xeon:

<!-- numbers: slides/img/amd.csv slides/img/intel.csv -->
| scene | AMD | Intel |
|---|---|---|
| bunny | 7.25 | 6.50 |" "two machines"
expect 0 intel_named "# Race
Intel Xeon, one thread:

<!-- numbers: slides/img/intel.csv -->
| scene | Mrays/s |
|---|---|
| bunny | 6.50 |"

[[ $failures -eq 0 ]] || { echo "$failures case(s) failed"; exit 1; }
echo "all cases as expected"
