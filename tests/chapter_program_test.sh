#!/usr/bin/env bash
# A chapter's program end to end, as a student runs it: --help, a refused unknown option, a small --quick run
# that writes the files the README promises (PNG images of the asked size, SVG plots, CSV tables with 0 rays
# differing from brute force where the program checks), no overwriting without --force, a clear error for a
# folder that cannot be made, and the exercise track's program either working or naming the unfinished
# exercise (exit 3), never crashing; chapters 05 and 06 also redraw their plots from their tables (--replot).
# Usage: chapter_program_test.sh NN PROGRAM EXERCISE_PROGRAM SCRATCH_FOLDER
set -euo pipefail

if [[ $# -ne 4 ]]; then
    echo "usage: $0 NN PROGRAM EXERCISE_PROGRAM SCRATCH_FOLDER" >&2
    exit 2
fi
nn=$1 program=$2 exercise=$3 dir=$4
rm -rf "$dir"
mkdir -p "$dir"
source "$(dirname "$0")/script_support.sh"

# png_size FILE: "WIDTH HEIGHT" from the IHDR chunk, or nothing when FILE is not a PNG.
png_size() {
    [[ $(head -c 8 "$1" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]] || return 0
    local w h
    w=$(od -An -tu1 -j16 -N4 "$1" | awk '{print $1 * 16777216 + $2 * 65536 + $3 * 256 + $4}')
    h=$(od -An -tu1 -j20 -N4 "$1" | awk '{print $1 * 16777216 + $2 * 65536 + $3 * 256 + $4}')
    echo "$w $h"
}

# The run each chapter gets, the files it must write, and the size of the images named in `sized`.
out=$dir/out_folder
case $nn in
01) args=(--quick --width 40 --out "$out/") files=(cornell.png cornell_rays.png teapot.png teapot_rays.png
        renders.csv glossy.csv)
    sized=(teapot.png:"40 30" cornell.png:"40 40") ;;
02) args=(--quick --width 64 --out "$out") files=(teapot.png teapot_tests.png stadium.png stadium_tests.png stadium_grid.png
        scenes.csv insertion.csv lambda_sweep.csv lambda_sweep.svg histogram.svg histogram.csv)
    sized=(teapot.png:"64 48") ;;
03) args=(--quick --width 64 --out "$out") files=(teapot.png teapot_planes.png teapot_stadium.png
        teapot_stadium_planes.png runs.csv)
    sized=(teapot.png:"64 48") ;;
04) args=(--quick --width 64 --out "$out") files=(teapot.png teapot_box_tests.png teapot_stadium.png
        teapot_stadium_box_tests.png runs.csv)
    sized=(teapot.png:"64 48") ;;
05) args=(--quick --width 48 --repeats 1 --out "$out") files=(bins.csv build_vs_trace.svg bins_vs_sah.svg
        stadium_box_tests.png)
    sized=() ;;
06) args=(--quick --width 48 --repeats 1 --out "$out") files=(refinement.csv sah_vs_time_stadium.svg)
    sized=() ;;
07) args=(--quick --width 32 --out "$out") files=(build_phases.csv quality.csv sort.csv scaling.csv phases.svg
                                                     build_vs_trace.svg sort.svg)
    sized=() ;;
08) args=(--quick --width 32 --out "$out") files=(builders.csv)
    sized=() ;;
09) args=(--quick --width 32 --out "$out") files=(compare.csv alpha.csv alpha.svg)
    sized=() ;;
10) args=(--quick --width 32 --out "$out") files=(animation.csv breakeven.csv summary.csv big.csv update_vs_trace.svg sah_drift.svg
        frames/frame_000.png frames/frame_002.png animation.gif)
    sized=(frames/frame_000.png:"32 24") ;;
11) args=(--quick --width 32 --out "$out") files=(steps.csv render.csv staircase.svg render.png)
    sized=(render.png:"32 32") ;;
12) args=(--quick --width 32 --repeats 1 --out "$out") files=(packets.csv lanes.csv vs_ch13.svg stadium_lanes.png)
    sized=() ;;
13) args=(--quick --width 32 --repeats 1 --out "$out") files=(wide.csv speedup.svg)
    sized=() ;;
14) args=(--quick --width 32 --repeats 1 --flight-frames 2 --flight-width 64 --flight-height 36 --out "$out")
    files=(sweep.csv threshold.svg stadium_left.png flight.csv flight_first.png flight_last.png)
    sized=(flight_first.png:"64 36" flight_last.png:"64 36") ;;
15) args=(--quick --out "$out") files=(escapes.csv spawn.csv far.csv scale.csv scale.svg table.csv escape_vs_speed.svg
        spawn_totals.csv escapes_by_placement.csv escapes_by_sphere.csv escapes_by_aim.csv)
    sized=() ;;
*) echo "$0: no end-to-end run known for chapter $nn" >&2; exit 2 ;;
esac

# --help, and an unknown option refused.
runs "--help" 0 "$program" --help
contains "$dir/out" "usage: ch$nn" "--help"
contains "$dir/out" "--out" "--help"
runs "unknown option" 2 "$program" --no-such-option
contains "$dir/err" "unknown option --no-such-option" "unknown option"

# Chapters 01 to 06: a bad command line is refused before anything is created; --help states the largest
# image and thread count; an image too large for the machine's memory is refused at once, saying how much it
# needs (STRAHL_MEMORY_LIMIT_MB stands for a small machine); --threads beyond 1024 is refused.
case $nn in
01 | 03 | 04) max_side=16384 ;;
02) max_side=8192 ;;
05 | 06) max_side=4096 ;;
*) max_side= ;;
esac
if [[ -n $max_side ]]; then
    runs "bad command line" 2 "$program" --quick --width 0 --out "$dir/never/"
    [[ ! -e $dir/never ]] || fail "bad command line: --out $dir/never was created before the refusal"
    runs "--help" 0 "$program" --help
    contains "$dir/out" "$max_side" "--help states the largest image"
    has_threads=$(grep -c -- "--threads" "$dir/out" || true)
    [[ $has_threads -eq 0 ]] || contains "$dir/out" "0..1024" "--help states the thread limit"
    export STRAHL_MEMORY_LIMIT_MB=16
    runs "an image too large for memory" 1 "$program" --width "$max_side" --out "$dir/never/"
    contains "$dir/err" "of memory needed, but only 16 MiB available" "an image too large for memory"
    [[ ! -e $dir/never ]] || fail "an image too large for memory: --out $dir/never was created"
    unset STRAHL_MEMORY_LIMIT_MB
    if [[ $has_threads -ne 0 ]]; then
        runs "--threads 2147483647" 2 "$program" --quick --threads 2147483647 --out "$dir/never/"
        contains "$dir/err" "--threads must lie in [0, 1024]" "--threads 2147483647"
        [[ ! -e $dir/never ]] || fail "--threads 2147483647: --out $dir/never was created"
    fi
fi

# Chapter 01 writes one image to a file named with --out: not through a link to nothing, and a read-only
# file is refused before the render (checked as a user other than root, who may write it anyway).
if [[ $nn == 01 ]]; then
    ln -s "$dir/link_target.png" "$dir/dangling.png"
    runs "--out a dangling link" 1 "$program" --quick --scene teapot --width 16 --out "$dir/dangling.png" --force
    contains "$dir/err" "which does not exist; not writing through it" "--out a dangling link"
    [[ ! -e $dir/link_target.png ]] || fail "--out a dangling link: written through it"
    # As root: without the capabilities that let root write a read-only file (not as another user, who may not
    # reach a clone under a folder only root can enter, such as mktemp -d's).
    as_user=()
    [[ $(id -u) -ne 0 ]] || as_user=(setpriv --bounding-set=-dac_override,-dac_read_search)
    if [[ $(id -u) -ne 0 ]] || command -v setpriv >/dev/null; then
        mkdir -p "$dir/read_only" && chmod 777 "$dir/read_only"
        echo x >"$dir/read_only/teapot.png" && chmod 444 "$dir/read_only/teapot.png"
        rc=0
        "${as_user[@]}" "$program" --quick --scene teapot --width 16 --out "$dir/read_only/teapot.png" --force \
            >"$dir/out" 2>"$dir/err" || rc=$?
        [[ $rc -eq 1 ]] || fail "read-only --out with --force: exit $rc, expected 1"
        contains "$dir/err" "cannot replace" "read-only --out with --force"
        ! grep -q "Mrays/s" "$dir/out" || fail "read-only --out with --force: rendered before refusing"
    fi
fi

# The quick run writes every promised file.
runs "quick run" 0 "$program" "${args[@]}"
# Chapter 01 reports the rays per pixel where the Cornell box's rough mirror is seen first.
[[ $nn != 01 ]] || contains "$dir/out" "see a rough mirror first:" "quick run: the rough mirror's pixels"
for f in "${files[@]}"; do
    [[ -s $out/$f ]] || { fail "quick run: $out/$f missing or empty"; continue; }
    case $f in
    *.png) [[ -n $(png_size "$out/$f") ]] || fail "$f is not a PNG file" ;;
    *.svg) grep -q "<svg" "$out/$f" || fail "$f holds no <svg> element" ;;
    *.csv) [[ $(wc -l <"$out/$f") -ge 2 ]] || fail "$f has no rows under its header" ;;
    esac
done
for entry in "${sized[@]}"; do
    f=${entry%%:*} want=${entry#*:}
    [[ -f $out/$f ]] || continue
    got=$(png_size "$out/$f")
    [[ $got == "$want" ]] || fail "$f is $got pixels, expected $want"
done
# Every checked row agrees with brute force: a 'differing' column of zeros.
for f in "${files[@]}"; do
    [[ $f == *.csv && -f $out/$f ]] || continue
    col=$(head -n 1 "$out/$f" | tr ',' '\n' | grep -nx differing | cut -d: -f1 || true)
    [[ -n $col ]] || continue
    bad=$(awk -F, -v c="$col" 'NR > 1 && $c != 0' "$out/$f")
    [[ -z $bad ]] || fail "$f: rays differing from brute force in: $bad"
done

# The measured tables end each row with the machine (strahl/machine.hpp: cpu,threads,kernels,date); the tables
# of counts, the same on any machine, do not.
case $nn in
01) stamped=(renders.csv) ;; 02) stamped=(scenes.csv insertion.csv lambda_sweep.csv) ;;
03 | 04) stamped=(runs.csv) ;; 05) stamped=(bins.csv) ;; 06) stamped=(refinement.csv) ;;
07) stamped=(build_phases.csv quality.csv sort.csv scaling.csv) ;; 08) stamped=(builders.csv) ;;
09) stamped=(compare.csv alpha.csv) ;; 10) stamped=(animation.csv breakeven.csv big.csv) ;;
11) stamped=(steps.csv render.csv) ;; 12) stamped=(packets.csv) ;; 13) stamped=(wide.csv) ;;
14) stamped=(sweep.csv flight.csv) ;;
15) stamped=(escapes.csv scale.csv table.csv escapes_by_placement.csv escapes_by_sphere.csv escapes_by_aim.csv) ;;
*) stamped=() ;;
esac
for f in "${files[@]}"; do
    [[ $f == *.csv && -f $out/$f ]] || continue
    want=no
    for g in "${stamped[@]}"; do [[ $g != "$f" ]] || want=yes; done
    if [[ $want == yes ]]; then
        head -n 1 "$out/$f" | grep -q ',cpu,threads,kernels,date$' || fail "$f: no machine columns in its header"
        bad=$(awk -F, 'NR > 1 && NF > 4 && ($(NF-3) == "" || $(NF-2) < 1 || $NF !~ /^[0-9][0-9][0-9][0-9]-[0-9][0-9]-[0-9][0-9]$/)' "$out/$f")
        [[ -z $bad ]] || fail "$f: rows without a machine: $bad"
    else
        ! head -n 1 "$out/$f" | grep -q ',cpu,threads,kernels,date$' || fail "$f: machine columns on a table of counts"
    fi
done

# Chapter 01's --sweep: a row per mesh size, tests per ray equal to the primitive count, a plot.
if [[ $nn == 01 ]]; then
    runs "--sweep" 0 "$program" --sweep --quick --out "$dir/sweep/"
    [[ $(tail -n +2 "$dir/sweep/sweep.csv" | wc -l) -eq 4 ]] || fail "--sweep: sweep.csv has not 4 rows"
    bad=$(awk -F, 'NR > 1 && ($2 != $5 || !($4 > 0))' "$dir/sweep/sweep.csv")
    [[ -z $bad ]] || fail "--sweep: rows whose tests per ray differ from the primitives or with no speed: $bad"
    contains "$dir/sweep/sweep.svg" "slope -1" "--sweep's plot"
fi

# Chapter 01's tables: the course's teapot (4,096 triangles) by default, and the glossy samples 1, 4, 16, 32.
if [[ $nn == 01 ]]; then
    [[ $(awk -F, '$1 == "teapot" { print $2 }' "$out/renders.csv") == 4096 ]] ||
        fail "renders.csv: the teapot has not the course's 4,096 triangles"
    [[ $(awk -F, 'NR > 1 { printf "%s ", $1 }' "$out/glossy.csv") == "1 4 16 32 " ]] ||
        fail "glossy.csv: not a row each for 1, 4, 16 and 32 glossy samples"
fi

# Chapter 02's histogram: the shares of the references add up to 100% in each scene.
if [[ $nn == 02 ]]; then
    bad=$(awk -F, 'NR > 1 { t += $3; s += $4 } END { if (t < 99.9 || t > 100.1 || s < 99.9 || s > 100.1) print t, s }' \
          "$out/histogram.csv")
    [[ -z $bad ]] || fail "histogram.csv: the shares of the references add up to $bad, not 100 and 100"
    # The course's scenes by default: the same teapot (4,096 triangles) alone and in the stadium (7,232).
    got=$(awk -F, 'NR > 1 && $2 == "triangles" { printf "%s %s ", $1, $3 }' "$out/scenes.csv")
    [[ $got == "teapot 4096 stadium 7232 " ]] || fail "scenes.csv: scenes '$got', not teapot 4096 and stadium 7232"
    [[ $(tail -n +2 "$out/insertion.csv" | cut -d, -f1 | tr '\n' ' ') == "box exact " ]] ||
        fail "insertion.csv: not a box and an exact row"
fi

# Chapter 04's --sweep: per mesh size a brute-force row (tests per ray = N) and three structures, each with
# far fewer triangle tests per ray than N on the largest mesh, a speed, and the three-panel plot.
if [[ $nn == 04 ]]; then
    runs "--sweep" 0 "$program" --sweep --quick --out "$dir/sweep"
    [[ $(tail -n +2 "$dir/sweep/sweep.csv" | wc -l) -eq 12 ]] || fail "--sweep: sweep.csv has not 12 rows"
    bad=$(awk -F, 'NR > 1 && $2 == "brute force" && $5 != $1' "$dir/sweep/sweep.csv")
    [[ -z $bad ]] || fail "--sweep: brute-force rows whose tests per ray are not N: $bad"
    bad=$(awk -F, 'NR > 1 && $2 != "brute force" && !($6 > 0 && $4 > 0 && $5 * 50 < $1 + 0 || $1 < 1000)' "$dir/sweep/sweep.csv")
    [[ -z $bad ]] || fail "--sweep: structures without a speed or testing over N/50 triangles per ray at N >= 1000: $bad"
    contains "$dir/sweep/sweep.svg" "nodes (cells) visited per ray" "--sweep's plot"
fi

# Chapters 05, 06 and 10 redraw their plots from the table they wrote: the same points, and bad tables are refused.
if [[ $nn == 05 || $nn == 06 || $nn == 10 ]]; then
    if [[ $nn == 05 ]]; then table=bins.csv plots=(build_vs_trace.svg bins_vs_sah.svg)
    elif [[ $nn == 10 ]]; then table=animation.csv plots=(update_vs_trace.svg sah_drift.svg)
    else table=refinement.csv plots=(sah_vs_time_stadium.svg); fi
    runs "--replot" 0 "$program" --replot "$out/$table" --out "$dir/replot"
    for f in "${plots[@]}"; do
        [[ $(grep -c "<circle" "$dir/replot/$f" || true) -eq $(grep -c "<circle" "$out/$f" || true) ]] ||
            fail "--replot: $f has not the same points as the first run's"
    done
    runs "--replot again without --force" 1 "$program" --replot "$out/$table" --out "$dir/replot"
    contains "$dir/err" "not overwriting" "--replot again without --force"
    echo "scene,tree" >"$dir/bad.csv"
    runs "--replot of a foreign file" 1 "$program" --replot "$dir/bad.csv" --out "$dir/replot2"
    article=a
    [[ $table != animation.csv ]] || article=an
    contains "$dir/err" "is not $article $table written by ch$nn" "--replot of a foreign file"
    # The table without its machine columns (an older file's form, which --replot reads too), so that its
    # last field is a number.
    awk -F, -v OFS=, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "cpu") c = i } { if (c) NF = c - 1; print }' \
        "$out/$table" >"$dir/plain.csv"
    runs "--replot of a table without machine columns" 0 "$program" --replot "$dir/plain.csv" --out "$dir/replot7"
    { head -n 1 "$dir/plain.csv"; head -n 2 "$dir/plain.csv" | tail -n 1 | sed 's/,[^,]*$/,nan/'; } >"$dir/nan.csv"
    runs "--replot of a NaN" 1 "$program" --replot "$dir/nan.csv" --out "$dir/replot3"
    contains "$dir/err" "line 2: 'nan' is not a number" "--replot of a NaN"
    # A subnormal is a number; one beyond double's range is out of range, not "not a number".
    { head -n 1 "$dir/plain.csv"; head -n 2 "$dir/plain.csv" | tail -n 1 | sed 's/,[^,]*$/,4e-320/'; } >"$dir/tiny.csv"
    runs "--replot of a subnormal" 0 "$program" --replot "$dir/tiny.csv" --out "$dir/replot5"
    { head -n 1 "$dir/plain.csv"; head -n 2 "$dir/plain.csv" | tail -n 1 | sed 's/,[^,]*$/,1e999/'; } >"$dir/huge.csv"
    runs "--replot of 1e999" 1 "$program" --replot "$dir/huge.csv" --out "$dir/replot6"
    contains "$dir/err" "line 2: '1e999' is out of range" "--replot of 1e999"
    if [[ $nn == 06 ]]; then
        { head -n 1 "$dir/plain.csv"; head -n 2 "$dir/plain.csv" | tail -n 1 | sed 's/^[^,]*,/..\/escape,/'; } >"$dir/path.csv"
        runs "--replot of a scene named like a path" 1 "$program" --replot "$dir/path.csv" --out "$dir/replot4"
        contains "$dir/err" "is no plain name" "--replot of a scene named like a path"
        [[ ! -e $dir/escape.svg && ! -e $dir/sah_vs_time_escape.svg ]] || fail "--replot wrote outside its folder"
    fi
fi

# Chapter 11 draws its staircase from a race's medians (the committed race_ch11.csv), and refuses other files.
if [[ $nn == 11 ]]; then
    race_csv="$(dirname "$0")/../slides/img/16_race/race_ch11.csv"
    runs "--from-race" 0 "$program" --from-race "$race_csv" --out "$dir/from_race"
    contains "$dir/from_race/staircase.svg" "ch13-bvh16" "--from-race's plot"
    contains "$dir/from_race/staircase.svg" "type-sorted" "--from-race's plot"
    # staircase.csv: the plot's figures, step 1 at x1 on every ray set, each row its speed over step 1's.
    contains "$dir/from_race/staircase.csv" "scene,structure,rays,mrays_s,x_step1" "--from-race's table"
    bad=$(awk -F, 'NR > 1 { k = $1 "," $3; if (!(k in first)) first[k] = $4;
                   if ($2 == "virtual" && $5 != 1) print; d = $4 / first[k] - $5; if (d > 1e-4 || d < -1e-4) print }' \
          "$dir/from_race/staircase.csv")
    [[ -z $bad ]] || fail "staircase.csv: x_step1 is not each speed over step 1's: $bad"
    [[ $(grep -c ',virtual,' "$dir/from_race/staircase.csv") -ge 3 ]] || fail "staircase.csv: no step 1 rows"
    runs "--from-race of a foreign file" 1 "$program" --from-race "$out/steps.csv" --out "$dir/from_race2"
    contains "$dir/err" "is not a race.csv written by the race" "--from-race of a foreign file"
fi

# Chapter 15: no ray escapes the watertight test (float or double) in brute force or in a tree walked with a
# conservative or the fast box test; the table has a row per test and box; spawn.csv a row per offset and
# placement (13 placements x 4 offsets); scale.csv's rows and the course's range; --scenes refuses a scene
# that is not there; --from-race's ratios; --totals.
if [[ $nn == 15 ]]; then
    bad=$(awk -F, 'NR > 1 && ($6 == "watertight" || $6 == "watertight-double") && $7 != "plain" && $10 != 0' \
        "$out/escapes.csv")
    [[ -z $bad ]] || fail "escapes.csv: the watertight test lets rays escape in: $bad"
    [[ $(awk -F, 'NR > 1 && $6 == "watertight" && $7 == "fast"' "$out/escapes.csv" | wc -l) -gt 0 ]] ||
        fail "escapes.csv: no rows for the watertight test in the fast walk"
    [[ $(tail -n +2 "$out/table.csv" | wc -l) -eq 15 ]] || fail "table.csv has not 15 rows (5 tests x 3 box tests)"
    [[ $(tail -n +2 "$out/spawn.csv" | wc -l) -eq 52 ]] || fail "spawn.csv has not 52 rows (13 placements x 4 offsets)"
    contains "$dir/out" "escapes per million" "the quick run's output"
    # From far away, with origins moved to the scene (ray_frame), every tree equals its brute force and
    # Moeller-Trumbore finds the watertight test's hits; with origins kept, Moeller-Trumbore's does not.
    [[ $(tail -n +2 "$out/far.csv" | wc -l) -eq 20 ]] || fail "far.csv has not 20 rows (5 distances x 2 tests x 2)"
    bad=$(awk -F, 'NR > 1 && ($3 == "moved" || $2 == "watertight") && $6 != 0' "$out/far.csv")
    [[ -z $bad ]] || fail "far.csv: a tree differs from its brute force with moved origins or the watertight test: $bad"
    bad=$(awk -F, 'NR > 1 && $3 == "moved" { h[$1 "," $2] = $5 } END { for (k in h) { split(k, p, ",");
        if (p[2] == "mt" && h[k] != h[p[1] ",watertight"]) print k } }' "$out/far.csv")
    [[ -z $bad ]] || fail "far.csv: moved, Moeller-Trumbore's hits differ from the watertight test's at: $bad"
    [[ $(awk -F, 'NR > 1 && $2 == "mt" && $3 == "kept" && $6 > 0' "$out/far.csv" | wc -l) -gt 0 ]] ||
        fail "far.csv: with origins kept, Moeller-Trumbore's tree never differs (the effect the frame removes)"
    # The teapot scaled from 1e-30 to 1e16 (47 decades, a row per test): within the course's range (extent at
    # least min_extent, 1e-8; coordinates within max_coordinate, 1e12) every test but the paper's epsilon
    # and Embree find every hit they find at scale 1; below it Moeller-Trumbore's loses them. --replot draws
    # the run's plot again from its CSV, byte for byte, and refuses another CSV.
    rows=$(tail -n +2 "$out/scale.csv" | wc -l)
    [[ $rows -ge 235 && $((rows % 47)) -eq 0 ]] || fail "scale.csv has $rows rows, not 47 scales x 5 or more tests"
    [[ $(head -n 1 "$out/scale.csv") == "scale,extent,coordinate,test,rays,hits,expected,cpu,threads,kernels,date" ]] || fail "scale.csv's header"
    bad=$(awk -F, 'NR > 1 && $2 >= 1e-8 && $3 <= 1e12 && $4 != "mt-epsilon" && $6 != $7' "$out/scale.csv")
    [[ -z $bad ]] || fail "scale.csv: a test loses hits within the course's range: $bad"
    [[ $(awk -F, 'NR > 1 && $2 < 1e-8 && $4 == "mt" && $6 < $7' "$out/scale.csv" | wc -l) -gt 0 ]] ||
        fail "scale.csv: Moeller-Trumbore loses no hit below min_extent (the loss the loader's rule prevents)"
    runs "--replot scale.csv" 0 "$program" --replot "$out/scale.csv" --out "$dir/replot"
    cmp -s "$dir/replot/scale.svg" "$out/scale.svg" || fail "--replot: scale.svg not as the run drew it"
    runs "--replot of a foreign file" 1 "$program" --replot "$out/far.csv" --out "$dir/replot2"
    contains "$dir/err" "is not a scale.csv written by ch15" "--replot of a foreign file"
    runs "--scenes of a missing file" 2 "$program" --quick --scenes "$dir/no_such.ply" --out "$dir/never"
    contains "$dir/err" "--scenes: no file" "--scenes of a missing file"
    [[ ! -e $dir/never ]] || fail "--scenes of a missing file: --out $dir/never was created"
    # --from-race: two processes of a race with ch15-mt-fast and ch15-watertight-fast: per-process ratios
    # 0.5 and 1.0 (primary, closest hit), 2.0 (shadow, any hit), median and range.
    header="scene,triangles,structure,chapter,exact,rays,ray_count,build_ms,memory_bytes,sah_cost,closest_mrays_s"
    header+=",closest_runs,closest_vs_embree,closest_box_per_ray,closest_prim_per_ray,closest_nodes_per_ray"
    header+=",closest_differing,any_mrays_s,any_runs,any_vs_embree,any_box_per_ray,any_prim_per_ray,any_differing"
    row() { echo "s.ply,1,$1,15,1,$2,8,1,1,1,$3,1,1,1,1,1,0,$4,1,1,1,1,0"; }
    mkdir -p "$dir/race/processes/1" "$dir/race/processes/2"
    { echo "$header"; row ch15-mt-fast primary 4 1; row ch15-watertight-fast primary 2 1
      row ch15-mt-fast shadow 9 3; row ch15-watertight-fast shadow 9 6; } >"$dir/race/processes/1/race.csv"
    { echo "$header"; row ch15-mt-fast primary 4 1; row ch15-watertight-fast primary 4 1; } \
        >"$dir/race/processes/2/race.csv"
    runs "--from-race" 0 "$program" --from-race "$dir/race" --out "$dir/ratios"
    contains "$dir/ratios/race_ratios.csv" "s.ply,primary,ch15-watertight-fast,ch15-mt-fast,2,0.75,0.5,1" "--from-race"
    contains "$dir/ratios/race_ratios.csv" "s.ply,shadow,ch15-watertight-fast,ch15-mt-fast,1,2,2,2" "--from-race"
    runs "--from-race of a folder without processes" 1 "$program" --from-race "$dir/ratios" --out "$dir/ratios2"
    contains "$dir/err" "no race.csv" "--from-race of a folder without processes"
    # --totals: the run's four totals again from its escapes.csv and spawn.csv, byte for byte; every offset
    # over the 13 placements (its rays the sum of spawn.csv's); a folder without them refused.
    runs "--totals" 0 "$program" --totals "$out" --out "$dir/totals"
    for f in spawn_totals.csv escapes_by_placement.csv escapes_by_sphere.csv escapes_by_aim.csv; do
        cmp -s "$dir/totals/$f" "$out/$f" || fail "--totals: $f not as the run wrote it"
    done
    [[ $(tail -n +2 "$out/spawn_totals.csv" | wc -l) -eq 4 ]] || fail "spawn_totals.csv has not 4 rows (offsets)"
    want=$(awk -F, 'NR > 1 && $3 == "none" { r += $4 } END { print r }' "$out/spawn.csv")
    grep -q "^none,$want," "$out/spawn_totals.csv" || fail "spawn_totals.csv: the no-offset row's rays are not $want"
    runs "--totals of a folder without them" 1 "$program" --totals "$dir/ratios" --out "$dir/totals2"
fi

# Chapter 07 redraws its three plots from a folder of its CSV files (--replot DIR), the same SVG bytes as
# the run wrote; a folder without them is refused before anything is created.
if [[ $nn == 07 ]]; then
    runs "--replot" 0 "$program" --replot "$out" --out "$dir/replot"
    for f in phases.svg build_vs_trace.svg sort.svg; do
        cmp -s "$out/$f" "$dir/replot/$f" || fail "--replot: $f differs from the run's"
    done
    mkdir -p "$dir/empty"
    runs "--replot of a folder without the CSVs" 2 "$program" --replot "$dir/empty" --out "$dir/replot7"
    contains "$dir/err" "--replot: no" "--replot of a folder without the CSVs"
    [[ ! -e $dir/replot7 ]] || fail "--replot of a folder without the CSVs made its output folder"
fi

# Chapter 08 draws the Pareto plot from a race's table (--from-race CSV): pareto.csv and pareto.svg, the
# frontier marked; a file that is no race.csv is refused before any folder is made.
if [[ $nn == 08 ]]; then
    race_csv=$(dirname "$0")/../slides/img/16_race/race_meshes.csv
    runs "--from-race" 0 "$program" --from-race "$race_csv" --out "$dir/pareto"
    [[ -s $dir/pareto/pareto.svg ]] || fail "--from-race: no pareto.svg"
    [[ $(awk -F, '$7 == 1' "$dir/pareto/pareto.csv" | wc -l) -ge 4 ]] || fail "--from-race: fewer than 4 frontier points"
    printf 'scene,structure\nx,y\n' >"$dir/notrace.csv"
    runs "--from-race of a foreign file" 1 "$program" --from-race "$dir/notrace.csv" --out "$dir/pareto2"
    contains "$dir/err" "is not a race.csv" "--from-race of a foreign file"
    [[ ! -e $dir/pareto2 ]] || fail "--from-race of a foreign file made its output folder"
fi

# Chapter 11's step report (exercise 11.4): a race folder of two processes (the committed medians copied)
# gives step_report.csv with the paired ratios and the counter that moved; a folder without processes/ is
# refused, naming it, before any file is written.
if [[ $nn == 11 ]]; then
    race_csv=$(dirname "$0")/../slides/img/16_race/race_ch11.csv
    mkdir -p "$dir/steprace/processes/1" "$dir/steprace/processes/2"
    cp "$race_csv" "$dir/steprace/processes/1/race.csv"
    cp "$race_csv" "$dir/steprace/processes/2/race.csv"
    runs "--step-report" 0 "$program" --step-report "$dir/steprace" --out "$dir/step"
    contains "$dir/out" "your prediction" "--step-report"
    [[ $(grep -c ',2,' "$dir/step/step_report.csv") -ge 6 ]] || fail "--step-report: fewer than 6 rows over 2 processes"
    contains "$dir/step/step_report.csv" "memory bytes" "--step-report: the counter that moved"
    runs "--step-report of a folder without processes" 1 "$program" --step-report "$dir/empty11" --out "$dir/step2"
    contains "$dir/err" "processes" "--step-report of a folder without processes"
    [[ ! -e $dir/step2/step_report.csv ]] || fail "--step-report of a folder without processes wrote a report"
fi

# Chapters 03 to 06 draw their figures (--diagrams DIR): whole SVG files in a folder made for them, not
# replaced without --force; the exercise track's program draws them too or names the unfinished exercise.
case $nn in
03) diagrams=(near_far.svg) ;;
04) diagrams=(subdivision.svg flattened.svg slab_test.svg) ;;
05) diagrams=(sweep_and_bins.svg) ;;
06) diagrams=(rotation.svg) ;;
*) diagrams=() ;;
esac
if [[ ${#diagrams[@]} -gt 0 ]]; then
    runs "--help" 0 "$program" --help
    contains "$dir/out" "--diagrams DIR" "--help lists --diagrams"
    runs "--diagrams" 0 "$program" --diagrams "$dir/diagrams/figures"
    for f in "${diagrams[@]}"; do
        [[ -s $dir/diagrams/figures/$f ]] || { fail "--diagrams: $f missing or empty"; continue; }
        head -c 5 "$dir/diagrams/figures/$f" | grep -q "<svg" && grep -q "</svg>" "$dir/diagrams/figures/$f" ||
            fail "--diagrams: $f is not a whole SVG file"
    done
    runs "--diagrams again without --force" 1 "$program" --diagrams "$dir/diagrams/figures"
    contains "$dir/err" "not overwriting" "--diagrams again without --force"
    runs "--diagrams again with --force" 0 "$program" --diagrams "$dir/diagrams/figures" --force
    if [[ $exercise != none ]]; then
        rc=0
        "$exercise" --diagrams "$dir/diagrams/exercise" >"$dir/out" 2>"$dir/err" || rc=$?
        [[ $rc -eq 0 || $rc -eq 3 ]] || fail "exercise program --diagrams: exit $rc, expected 0 or 3"
    fi
fi

# Nothing is overwritten unless asked: the same run again is refused and leaves the files as they were.
cp -r "$out" "$dir/before" 2>/dev/null || mkdir -p "$dir/before"
runs "second run without --force" 1 "$program" "${args[@]}"
contains "$dir/err" "not overwriting" "second run without --force"
diff -r "$dir/before" "$out" >/dev/null || fail "a refused run changed files in $out"
runs "second run with --force" 0 "$program" "${args[@]}" --force

# A folder that cannot be made (it would lie inside a regular file): a clear error, exit 1.
touch "$dir/plain_file"
if [[ $nn == 01 ]]; then blocked=$dir/plain_file/sub/; else blocked=$dir/plain_file/sub; fi
runs "unwritable --out" 1 "$program" "${args[@]:0:${#args[@]}-1}" "$blocked"
contains "$dir/err" "cannot create folder" "unwritable --out"

# The exercise track's program: either the student's finished work runs (exit 0), or it names the first
# exercise not yet done, with its file (exit 3). (None in a build without the exercise track.)
rc=0
if [[ $exercise == none ]]; then
    echo "note: no exercise track in this build (the sanitizer preset): its program is not checked here"
else
    "$exercise" "${args[@]:0:${#args[@]}-1}" "$dir/exercise_out/" >"$dir/out" 2>"$dir/err" || rc=$?
fi
if [[ $rc -eq 3 ]]; then
    grep -Eq "exercise $nn\.[0-9]+ .* is not done yet: exercises/" "$dir/err" ||
        { fail "exercise program: exit 3 without naming the exercise"; sed 's/^/    /' "$dir/err" >&2; }
elif [[ $rc -ne 0 ]]; then
    fail "exercise program: exit $rc, expected 0 or 3"
    sed 's/^/    /' "$dir/out" "$dir/err" | tail -n 40 >&2
fi

finish "ch$nn program"
