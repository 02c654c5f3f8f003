#!/usr/bin/env bash
# ./course figures end to end: the drawn figures of chapters 05 to 15 (plots redrawn from the
# committed CSVs, diagrams drawn by the chapters' code) come out byte for byte as committed under slides/img/,
# so that every committed figure is what its program draws; the raced jobs of --measure run end to end (small);
# an unknown chapter is refused.
# Usage: figures_test.sh COURSE_ROOT BIN_FOLDER SCRATCH_FOLDER
set -euo pipefail

if [[ $# -ne 3 ]]; then
    echo "usage: $0 COURSE_ROOT BIN_FOLDER SCRATCH_FOLDER" >&2
    exit 2
fi
root=$1 bin=$2 dir=$3
rm -rf "$dir"
mkdir -p "$dir"
source "$(dirname "$0")/script_support.sh"

runs "figures 05 06 07 08 09 10 11 12 13 14 15" 0 "$root/course" figures 05 06 07 08 09 10 11 12 13 14 15 --bin "$bin" --into "$dir/tree"
contains "$dir/out" "files written under" "figures 05 06 07 08 09 10 11 12 13 14 15"
n=0
while IFS= read -r f; do
    n=$((n + 1))
    cmp -s "$dir/tree/$f" "$root/$f" || fail "$f: not as committed (redrawn: $dir/tree/$f)"
done < <(cd "$dir/tree" && find slides -type f | sort)
[[ $n -ge 20 ]] || fail "only $n figures drawn"
echo "figures: $n files, each as committed"

# The raced jobs (--measure): each folder's command.sh runs as ./course figures --measure runs it, held against
# its committed verdicts, shrunk by RACE_ARGS (appended last, so they win) to a few rays of one small scene;
# what it writes lands in the scratch tree: the race's tables, each process's, and the verdicts held.
export RACE_ARGS="--scenes builtin:teapot --width 8 --height 2 --repeats 1 --budget 0.01"
runs "figures 16 --measure" 0 "$root/course" figures 16 --measure --bin "$bin" --into "$dir/raced"
unset RACE_ARGS
raced=0
for script in "$root"/slides/img/16_race/*/command.sh; do
    folder=$(basename "$(dirname "$script")")
    raced=$((raced + 1))
    for f in race.csv spread.md compare.csv compare.md verdicts.md processes/5/race.csv; do
        [[ -s $dir/raced/slides/img/16_race/$folder/$f ]] || fail "figures 16 --measure: no $folder/$f"
    done
    contains "$dir/raced/slides/img/16_race/$folder/verdicts.md" "slides/img/16_race/$folder/compare.csv" "$folder's verdicts held against the committed ones"
    contains "$dir/out" "slides/img/16_race/$folder: The same comparisons" "figures 16 --measure says how many verdicts held"
done
[[ $raced -ge 5 ]] || fail "only $raced raced folders under slides/img/16_race/"

runs "figures 99" 1 "$root/course" figures 99 --bin "$bin" --into "$dir/tree2"
contains "$dir/err" "no chapter 99" "figures 99"
finish "figures"
