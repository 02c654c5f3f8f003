#!/usr/bin/env bash
# The race end to end, small: --help, a refused option, a tiny run writing its tables, plots and scene image
# with 0 rays differing from brute force; a second run reading brute force's answers from the reference
# cache and giving the same answers; a tampered cache file traced again and replaced; --no-cache neither
# reading nor writing the cache; --cpu pinning one thread's timings (and refusing a CPU it may not use);
# --processes 2 combining two fresh processes; a failing process; a scene
# file that is not there, refused before anything starts.
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

# A scene file that is not there: refused before anything is created or loaded, even with processes.
runs "missing scene" 1 "$race" --scenes builtin:teapot,"$dir/none.ply" --out "$dir/missing" --processes 2
contains "$dir/err" "none.ply: no such file" "missing scene"
[[ ! -e $dir/missing ]] || fail "missing scene: the output folder was created"

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
# them hit the teapot). Its checksum no longer holds.
flags=$(ls "$out"/reference_cache/*_primary_any_*.flags)
count=$(($(stat -c %s "$flags") - 16))
{ head -c 16 "$flags"; head -c "$count" /dev/zero; } >"$dir/zeros" && mv "$dir/zeros" "$flags"
runs "tampered cache" 0 "$race" "${tiny[@]}" --out "$out"
contains "$dir/out" "does not match the checksum in its name" "tampered cache"
contains "$dir/out" "1 stale files replaced" "tampered cache"
[[ $(ls "$out/reference_cache" | wc -l) -eq 5 ]] || fail "tampered cache: the cache should hold 5 files again"

# One thread's timings pinned to a CPU, named in the machine line; a CPU the race may not use refused.
runs "--cpu" 0 "$race" "${tiny[@]}" --out "$dir/pinned" --cpu 0
contains "$dir/out" "one thread's timings on CPU 0" "--cpu 0"
runs "--cpu none" 0 "$race" "${tiny[@]}" --out "$dir/pinned" --cpu none
if grep -q "timings on CPU" "$dir/out"; then fail "--cpu none: the machine line names a CPU"; fi
runs "--cpu 99999" 2 "$race" "${tiny[@]}" --out "$dir/pinned" --cpu 99999
contains "$dir/err" "--cpu 99999: not a CPU this process may run on" "--cpu 99999"

runs "--no-cache" 0 "$race" "${tiny[@]}" --out "$dir/fresh" --no-cache
[[ ! -e $dir/fresh/reference_cache ]] || fail "--no-cache wrote a cache"

# Several fresh processes sharing one cache: each process's files under processes/K, the second measuring
# the structures in reverse order, the combined tables and spread.md beside them, in the first's row order.
many=$dir/many
runs "--processes 0" 2 "$race" "${tiny[@]}" --out "$many" --processes 0
contains "$dir/err" "--processes must be in" "--processes 0"
runs "--processes 2" 0 "$race" "${tiny[@]}" --out "$many" --processes 2 --cache "$out/reference_cache"
for f in race.csv race.md spread.md spread.svg speed_vs_build.svg staircase.svg teapot.png processes/1/race.csv \
    processes/2/race.csv processes/1/race.log; do
    [[ -s $many/$f ]] || fail "--processes 2: $many/$f missing or empty"
done
[[ ! -e $many/reference_cache ]] || fail "--processes 2 --cache elsewhere wrote a cache in --out"
contains "$many/processes/2/race.log" "5 answer sets from" "the processes read the shared cache"
contains "$many/spread.md" "2 fresh processes" "spread.md"
first_order=$(cut -d, -f3,6 "$many/processes/1/race.csv" | tail -n +2)
second_order=$(cut -d, -f3,6 "$many/processes/2/race.csv" | tail -n +2)
[[ $first_order == "$(cut -d, -f3,6 "$many/race.csv" | tail -n +2)" ]] || fail "combined rows not in the first process's order"
[[ $first_order != "$second_order" ]] || fail "the second process did not reverse the structures"
[[ $(sort <<<"$first_order") == $(sort <<<"$second_order") ]] || fail "the two processes measured different rows"
# --more: one process more, after the two; the tables combine three. Then --processes 2 without --more
# drops the third folder, so that a later --more cannot pick it up.
runs "--more" 0 "$race" "${tiny[@]}" --out "$many" --more --cache "$out/reference_cache"
[[ -s $many/processes/3/race.csv ]] || fail "--more: no third process"
contains "$dir/out" "2 earlier processes found" "--more"
contains "$many/spread.md" "3 fresh processes" "--more"
[[ $(cut -d, -f3,6 "$many/processes/3/race.csv" | tail -n +2) == "$first_order" ]] || fail "the third process is reversed"
runs "--processes 2 again" 0 "$race" "${tiny[@]}" --out "$many" --processes 2 --cache "$out/reference_cache"
[[ ! -e $many/processes/3 ]] || fail "--processes 2 kept an earlier third process"
rm "$many/spread.svg"
runs "--processes 0 --more" 0 "$race" "${tiny[@]}" --out "$many" --processes 0 --more
[[ -s $many/spread.svg && ! -e $many/processes/3 ]] || fail "--processes 0 --more: should redraw, run nothing"
# The claim rule: pairs of rows compared within each process (two processes: too few for a verdict).
runs "--processes 0 --more --compare" 0 "$race" "${tiny[@]}" --out "$many" --processes 0 --more \
    --compare ch05-binned16-fast:ch04-median
contains "$many/compare.csv" "teapot,primary,closest,ch05-binned16-fast,ch04-median,2," "--compare: compare.csv"
contains "$many/compare.md" "too few processes" "--compare: compare.md"
runs "--compare, no pair" 2 "$race" "${tiny[@]}" --out "$many" --more --compare ch04-median
contains "$dir/err" "pairs of rows A:B" "--compare, no pair"
runs "--compare, not in the race" 2 "$race" "${tiny[@]}" --out "$many" --more --compare ch04-median:ch13-bvh8-block8
contains "$dir/err" "'ch13-bvh8-block8' is not a row of this race" "--compare, not in the race"
runs "--compare, one process" 2 "$race" "${tiny[@]}" --out "$many" --compare ch04-median:ch05-binned16-fast
contains "$dir/err" "--compare needs several processes" "--compare, one process"
# Processes of another race (other rays) do not combine.
runs "--more, other rays" 1 "$race" "${tiny[@]}" --out "$many" --more --width 20 --cache "$out/reference_cache"
contains "$dir/err" "did not run the same race" "--more, other rays"

# A process that fails (its scene image cannot be written: a folder holds its name) is named, and no
# earlier run's table in its folder passes for its own: processes/1/race.csv is removed before it runs.
rm -f "$many/processes/1/teapot.png" && mkdir "$many/processes/1/teapot.png"
runs "--processes 2, failing" 1 "$race" "${tiny[@]}" --out "$many" --processes 2 --cache "$out/reference_cache"
contains "$dir/err" "process 1 of the race failed" "--processes 2, failing"
contains "$many/processes/1/race.log" "teapot.png" "--processes 2, failing: the child's log"
[[ ! -e $many/processes/1/race.csv ]] || fail "--processes 2, failing: an earlier race.csv was left for the process"

finish race
