#!/usr/bin/env bash
# ./course release end to end: a student release made from this build's compiled solutions holds no
# solution source, refuses to overwrite a folder and to make a release of itself, tells its pristine stubs
# from a student's work, and builds chapter 02 against chapter 01's compiled reference: the reference tests
# pass, the stubs score 0 and the solo check's cell_range file earns exactly 02.1's points.
# Usage: release_test.sh COURSE_ROOT BUILD_FOLDER SCRATCH_FOLDER
set -euo pipefail

if [[ $# -ne 3 ]]; then
    echo "usage: $0 COURSE_ROOT BUILD_FOLDER SCRATCH_FOLDER" >&2
    exit 2
fi
root=$1 build=$2 dir=$3
rm -rf "$dir"
mkdir -p "$dir"
source "$(dirname "$0")/script_support.sh"
rel=$dir/release

mkdir -p "$dir/taken" && touch "$dir/taken/mine.txt"
runs "a non-empty folder" 1 "$root/course" release "$dir/taken"
contains "$dir/err" "exists and is not an empty folder" "a non-empty folder"
[[ -f $dir/taken/mine.txt ]] || fail "a non-empty folder: its file is gone"

runs "release" 0 "$root/course" release "$rel" --from "$build"
[[ ! -e $rel/solutions ]] || fail "the release holds solutions/"
[[ $(cat "$rel/reference/ARCH") == native || $(cat "$rel/reference/ARCH") == x86-64 ]] || fail "reference/ARCH"
[[ -f $rel/reference/02_uniform_grid/cell_range.cpp.o ]] || fail "reference/02_uniform_grid/cell_range.cpp.o missing"
# No solution's source anywhere in the release, under any name.
(cd "$root" && git ls-files 'solutions/*.cpp' | xargs sha256sum | cut -d' ' -f1 | sort -u) >"$dir/solution_sums"
find "$rel" -type f -name '*.*pp' -print0 | xargs -0 sha256sum | cut -d' ' -f1 | sort -u >"$dir/release_sums"
[[ -z $(comm -12 "$dir/solution_sums" "$dir/release_sums") ]] || fail "a solution's source is in the release"
[[ -n $(find "$rel/reference" -name '*.cpp') ]] && fail "reference/ holds .cpp files"

runs "a release of a release" 1 "$rel/course" release "$dir/again"
contains "$dir/err" "a release cannot make a release" "a release of a release"
runs "stubs, pristine" 0 "$rel/course" stubs
contains "$dir/out" "holds the pristine stubs" "stubs, pristine"
echo "// my work" >>"$rel/exercises/02_uniform_grid/cell_range.cpp"
runs "stubs, changed" 0 "$rel/course" stubs
contains "$dir/out" "holds your work (1 file(s) changed" "stubs, changed"
(cd "$root" && git show HEAD:exercises/02_uniform_grid/cell_range.cpp) >"$rel/exercises/02_uniform_grid/cell_range.cpp"

# Chapter 02 built in the release: its exercise track on the stubs, its solutions track and chapter 01's
# from the compiled reference.
runs "configure" 0 cmake -S "$rel" -B "$rel/build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O3 -DNDEBUG"
contains "$dir/out" "a student release" "configure"
runs "build" 0 cmake --build "$rel/build" -j 2 --target test_ch02_solutions test_ch02_exercises test_ch02_solo_cell_range
bin=$rel/build/bin
runs "the reference's tests" 0 "$bin/test_ch02_solutions"
contains "$dir/out" "All tests passed" "the reference's tests"
# points FILE: "earned possible" of a grade file (tests/test_main.cpp's lines).
points() { awk -F'\t' '{ p += $3; if ($4 == 1) e += $3 } END { printf "%d %d\n", e, p }' "$1"; }
STRAHL_GRADE_FILE=$dir/stubs.tsv "$bin/test_ch02_exercises" --reporter compact >"$dir/stubs.log" 2>&1 || true
read -r earned possible < <(points "$dir/stubs.tsv")
[[ $possible -gt 0 && $earned -eq 0 ]] || fail "the stubs score $earned of $possible (expected 0 of more than 0)"
STRAHL_GRADE_FILE=$dir/solo.tsv "$bin/test_ch02_solo_cell_range" --reporter compact >"$dir/solo.log" 2>&1 || true
read -r earned_solo possible_solo < <(awk -F'\t' 'index($2, "02.1 ") == 1' "$dir/solo.tsv" | points /dev/stdin)
read -r earned_all _ < <(points "$dir/solo.tsv")
[[ $possible_solo -gt 0 && $earned_solo -eq $possible_solo && $earned_all -eq $earned_solo ]] \
    || fail "stubs + the compiled cell_range.cpp earn $earned_all points, 02.1's $earned_solo of $possible_solo (expected all of 02.1's, nothing else)"
echo "release: stubs $earned of $possible, compiled cell_range.cpp alone $earned_solo"
finish "release"
