#!/usr/bin/env bash
# The race end to end, small: --help, a refused option, a tiny run writing its tables, plots and scene image
# with 0 rays differing from brute force; a second run reading brute force's answers from the reference
# cache and giving the same answers; a tampered cache file traced again and replaced; --no-cache neither
# reading nor writing the cache.
# Usage: race_test.sh PATH/TO/race SCRATCH_FOLDER
set -euo pipefail

if [[ $# -ne 2 ]]; then
    echo "usage: $0 RACE SCRATCH_FOLDER" >&2
    exit 2
fi
race=$1 dir=$2
rm -rf "$dir"
mkdir -p "$dir"
source "$(dirname "$0")/../script_support.sh"

runs "--help" 0 "$race" --help
contains "$dir/out" "--no-cache" "--help"
runs "unknown option" 2 "$race" --no-such-option
contains "$dir/err" "unknown option --no-such-option" "unknown option"

out=$dir/race
tiny=(--scenes builtin:teapot --accels ch04-median,ch05-binned16-fast --width 16 --height 12 --repeats 1)
runs "first run" 0 "$race" "${tiny[@]}" --out "$out"
for f in race.csv race.md speed_vs_build.svg staircase.svg teapot.png; do
    [[ -s $out/$f ]] || fail "first run: $out/$f missing or empty"
done
contains "$dir/out" "0 answer sets from" "first run traces the reference"
[[ $(ls "$out/reference_cache" | wc -l) -eq 5 ]] || fail "the cache should hold 5 files (2 closest, 3 any)"
cp "$out/race.csv" "$dir/first.csv"

runs "second run" 0 "$race" "${tiny[@]}" --out "$out"
contains "$dir/out" "5 answer sets from" "second run reads the cache"
contains "$dir/out" "0 traced by brute force" "second run reads the cache"
# The same answers: every diff column of both runs 0 (the race exits 1 otherwise), and the same rows.
[[ $(cut -d, -f1-4 "$dir/first.csv") == $(cut -d, -f1-4 "$out/race.csv") ]] || fail "the two runs' rows differ"

# A cache file whose answers are wrong but well-formed: every any-hit flag of the primary rays 0 (most of
# them hit the teapot).
flags=$(ls "$out"/reference_cache/*_primary_any_*.flags)
count=$(($(stat -c %s "$flags") - 16))
{ head -c 16 "$flags"; head -c "$count" /dev/zero; } >"$dir/zeros" && mv "$dir/zeros" "$flags"
runs "tampered cache" 0 "$race" "${tiny[@]}" --out "$out"
contains "$dir/out" "is stale" "tampered cache"
contains "$dir/out" "1 stale files replaced" "tampered cache"

runs "--no-cache" 0 "$race" "${tiny[@]}" --out "$dir/fresh" --no-cache
[[ ! -e $dir/fresh/reference_cache ]] || fail "--no-cache wrote a cache"

finish race
