#!/usr/bin/env bash
# ./course slides end to end. Part "figures": every figure the decks show exists, and a deck naming a
# missing figure is refused with its name. Part "html": chapter 04's deck renders to one self-contained HTML
# file (its figures embedded, nothing fetched) holding its slides; skipped (exit 77) where pandoc, which
# ./course slides installs and the base set-up does not, is absent.
# Usage: slides_test.sh COURSE_ROOT SCRATCH_FOLDER figures|html
set -euo pipefail

if [[ $# -ne 3 ]]; then
    echo "usage: $0 COURSE_ROOT SCRATCH_FOLDER figures|html" >&2
    exit 2
fi
root=$1 dir=$2 part=$3
rm -rf "$dir"
mkdir -p "$dir"
source "$(dirname "$0")/script_support.sh"

case $part in
figures)
    runs "every deck's figures" 0 "$root/course" slides --check
    contains "$dir/out" "every figure present" "every deck's figures"
    # A copy of the course with one deck naming a figure that is not there.
    mkdir -p "$dir/copy/slides/img"
    cp "$root/course" "$dir/copy/"
    printf '# Chapter 99: a deck\n\n![a figure](img/99/missing.png)\n' >"$dir/copy/slides/99_test.md"
    runs "a missing figure" 1 "$dir/copy/course" slides --check
    contains "$dir/err" "slides/99_test.md: slides/img/99/missing.png" "a missing figure"
    ;;
html)
    if ! command -v pandoc >/dev/null; then
        echo "pandoc is not installed (./course slides installs it): rendering not tested"
        exit 77
    fi
    runs "render chapter 04" 0 "$root/course" slides 04 --out "$dir/html"
    html=$dir/html/04_bvh.html
    [[ -s $html ]] || fail "$html missing or empty"
    contains "$html" "Chapter 04: the bounding volume hierarchy" "the deck's title"
    contains "$html" "data:image/png;base64," "the figures embedded"
    grep -q 'src="img/' "$html" && fail "a figure is linked, not embedded"
    slides=$(grep -c '<section' "$html" || true)
    [[ $slides -ge 5 ]] || fail "only $slides slides rendered"
    echo "rendered $slides slides, $(wc -c <"$html") bytes"
    ;;
*) echo "unknown part $part" >&2; exit 2 ;;
esac
finish "slides $part"
