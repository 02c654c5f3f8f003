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
[[ -n $(find "$rel/reference" -name '*.cpp' -not -path "$rel/reference/stubs/*") ]] && fail "reference/ holds .cpp files other than the stubs' copy"

runs "a release of a release" 1 "$rel/course" release "$dir/again"
contains "$dir/err" "a release cannot make a release" "a release of a release"
runs "stubs, pristine" 0 "$rel/course" stubs
contains "$dir/out" "holds the pristine stubs" "stubs, pristine"
echo "// my work" >>"$rel/exercises/02_uniform_grid/cell_range.cpp"
runs "stubs, changed" 0 "$rel/course" stubs
contains "$dir/out" "holds your work (1 file(s) changed" "stubs, changed"

# The grading and solo checks on the pristine stubs while exercises/ holds a student's work, here work that
# does not even compile: the check builds the release's own copy of the stubs (reference/stubs/) apart,
# against the compiled reference of chapters 01 and 02, and leaves the student's file as it is.
printf '#error my unfinished work\n' >>"$rel/exercises/02_uniform_grid/dda_step.cpp"
cp "$rel/exercises/02_uniform_grid/dda_step.cpp" "$dir/work.cpp"
runs "stubs --check 02" 0 "$rel/course" stubs --check 02
contains "$dir/out" "the pristine stubs are built apart" "stubs --check 02"
contains "$dir/out" "stubs score 0 of" "stubs --check 02"
contains "$dir/out" "solo check: 4 exercise files" "stubs --check 02"
cmp -s "$dir/work.cpp" "$rel/exercises/02_uniform_grid/dda_step.cpp" || fail "stubs --check touched the student's file"
[[ -x $rel/build/release-stubs/bin/test_ch02_solo_cell_range ]] || fail "no solo binary in build/release-stubs"
contains "$rel/build/release-stubs/configure.log" "a student release" "configure"

# The reference's own tests, built in the same folder from the compiled solutions.
runs "build" 0 cmake --build "$rel/build/release-stubs" -j 2 --target test_ch02_solutions
runs "the reference's tests" 0 "$rel/build/release-stubs/bin/test_ch02_solutions"
contains "$dir/out" "All tests passed" "the reference's tests"
finish "release"
