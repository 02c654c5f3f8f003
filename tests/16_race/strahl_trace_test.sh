#!/usr/bin/env bash
# strahl-trace end to end: help and list, a real query writing rays and hits, the same rays through another
# exact structure giving a byte-identical hits file, any-hit queries, and clear refusals of bad input.
# Usage: strahl_trace_test.sh PATH/TO/strahl-trace SCRATCH_FOLDER
set -euo pipefail

if [[ $# -ne 2 ]]; then
    echo "usage: $0 STRAHL_TRACE SCRATCH_FOLDER" >&2
    exit 2
fi
trace=$1
dir=$2
rm -rf "$dir"
mkdir -p "$dir"
source "$(dirname "$0")/../script_support.sh"

# succeeds WHAT ARGS...: strahl-trace ARGS exits 0; its stdout and stderr go to $dir/out.
succeeds() {
    local what=$1
    shift
    local rc=0
    "$trace" "$@" >"$dir/out" 2>&1 || rc=$?
    [[ $rc -eq 0 ]] || { fail "$what: exit $rc, expected 0"; sed 's/^/    /' "$dir/out" >&2; }
}

# refuses WHAT CODE TEXT ARGS...: strahl-trace ARGS exits with CODE and says TEXT on stderr.
refuses() {
    local what=$1 code=$2 text=$3
    shift 3
    local rc=0
    "$trace" "$@" >"$dir/out" 2>"$dir/err" || rc=$?
    [[ $rc -eq $code ]] || fail "$what: exit $rc, expected $code"
    contains "$dir/err" "$text" "$what"
}

# --help and --list.
succeeds "--help" --help
contains "$dir/out" "usage: strahl-trace" "--help"
contains "$dir/out" "--accel" "--help"
succeeds "--list" --list
grep -q '^brute ' "$dir/out" || fail "--list: no line starting with 'brute'"
grep -q '^ch01-virtual ' "$dir/out" || fail "--list: no line starting with 'ch01-virtual'"
[[ $(head -n 1 "$dir/out") == brute* ]] || fail "--list: brute force is not listed first"

# A real query: generate primary rays, trace them with brute force, keep rays and hits.
succeeds "brute force query" --scene builtin:teapot --accel brute --gen primary --width 32 --height 24 \
    --rays-out "$dir/R" --out "$dir/H"
contains "$dir/out" "Mrays/s" "brute force query"
contains "$dir/out" "rays        768 (closest hit)" "brute force query"
grep -Eq '^hits +[1-9][0-9]* ' "$dir/out" || fail "brute force query: no hits reported"
[[ $(stat -c %s "$dir/R") -eq $((16 + 32 * 768)) ]] || fail "rays file: $(stat -c %s "$dir/R") bytes, expected $((16 + 32 * 768))"
[[ $(stat -c %s "$dir/H") -eq $((16 + 16 * 768)) ]] || fail "hits file: $(stat -c %s "$dir/H") bytes, expected $((16 + 16 * 768))"
[[ $(head -c 8 "$dir/R") == STRAHLR1 ]] || fail "rays file: wrong magic"
[[ $(head -c 8 "$dir/H") == STRAHLH1 ]] || fail "hits file: wrong magic"

# The same rays through chapter 01's tracer: the hits file is identical, byte for byte.
succeeds "ch01-virtual on the saved rays" --scene builtin:teapot --rays "$dir/R" --accel ch01-virtual --out "$dir/H2"
contains "$dir/out" "structure   ch01-virtual" "ch01-virtual on the saved rays"
cmp "$dir/H" "$dir/H2" || fail "brute force and ch01-virtual wrote different hits files"
# ...and on two threads.
succeeds "brute force on 2 threads" --scene builtin:teapot --rays "$dir/R" --threads 2 --out "$dir/H3"
cmp "$dir/H" "$dir/H3" || fail "brute force on 2 threads wrote a different hits file"

# Any hit: explicitly, and implied by shadow rays; both structures agree on it too.
succeeds "--any-hit" --scene builtin:teapot --rays "$dir/R" --accel brute --any-hit --out "$dir/A"
contains "$dir/out" "(any hit)" "--any-hit"
grep -Eq '^occluded +[1-9][0-9]* ' "$dir/out" || fail "--any-hit: nothing occluded"
succeeds "--any-hit, ch01-virtual" --scene builtin:teapot --rays "$dir/R" --accel ch01-virtual --any-hit --out "$dir/A2"
cmp "$dir/A" "$dir/A2" || fail "any-hit files differ between brute and ch01-virtual"
succeeds "shadow rays" --scene builtin:teapot --gen shadow --width 32 --height 24
contains "$dir/out" "(any hit)" "shadow rays"

# Errors: a clear message and a non-zero exit.
refuses "unknown structure" 1 "no structure named 'no-such-tree' (have: brute, ch01-virtual" \
    --scene builtin:teapot --accel no-such-tree --gen primary --width 8 --height 8
refuses "missing scene file" 1 "$dir/missing.obj" --scene "$dir/missing.obj" --gen primary --width 8 --height 8
printf 'NOTRAYS!\0\0\0\0\0\0\0\0' >"$dir/bad_magic"
refuses "rays file with a wrong magic" 1 "does not start with STRAHLR1" --scene builtin:teapot --rays "$dir/bad_magic"
refuses "a hits file as rays" 1 "does not start with STRAHLR1" --scene builtin:teapot --rays "$dir/H"
cp "$dir/H2" "$dir/H2.before" || fail "no hits file H2 from the run above"
refuses "--out onto an existing file" 1 "pass --force" --scene builtin:teapot --rays "$dir/R" --out "$dir/H2"
cmp "$dir/H2" "$dir/H2.before" || fail "--out without --force changed the existing file"
succeeds "--out onto an existing file with --force" --scene builtin:teapot --rays "$dir/R" --out "$dir/H2" --force
refuses "a bad number for --width" 2 "--width expects an integer, got '3x'" \
    --scene builtin:teapot --gen primary --width 3x
refuses "an unknown ray set" 1 "unknown ray set 'sideways'" --scene builtin:teapot --gen sideways --width 8 --height 8
refuses "neither --rays nor --gen" 2 "exactly one of --rays FILE and --gen KIND" --scene builtin:teapot
# One file for two outputs, or an output onto the rays it reads: refused even with --force, nothing written.
cp "$dir/R" "$dir/R.before"
refuses "--rays-out and --out alike" 2 "name the same file" --scene builtin:teapot --gen primary --width 8 \
    --height 8 --rays-out "$dir/same" --out "$dir/same" --force
[[ ! -e $dir/same ]] || fail "--rays-out and --out alike: a file was written"
refuses "--out onto the rays read" 2 "names the rays file it would read" --scene builtin:teapot --rays "$dir/R" \
    --out "$dir/./R" --force
cmp "$dir/R" "$dir/R.before" || fail "--out onto the rays read: the rays file changed"

# Hostile command lines: refused at once with the limit named, nothing created.
refuses "--threads 2147483647" 2 "--threads must lie in [1, 1024], not 2147483647" --scene builtin:teapot \
    --gen primary --width 8 --height 8 --threads 2147483647 --out "$dir/threads/H"
[[ ! -e $dir/threads ]] || fail "--threads 2147483647: the --out folder was created"
# --list with a width of 0 dropped Embree's packet row without a word: the size is checked for --list too.
refuses "--list --width 0" 2 "--width and --height must lie in 1..16384" --list --width 0
succeeds "--help" --help
contains "$dir/out" "1..16384" "--help states the image size limit"
contains "$dir/out" "1..1024" "--help states the thread limit"
# An image too large for the memory there is: refused before anything is allocated or created, saying
# how much it needs (STRAHL_MEMORY_LIMIT_MB stands for a small machine).
export STRAHL_MEMORY_LIMIT_MB=64
refuses "too large for memory" 1 "16384 x 16384 primary rays: about 25" --scene builtin:teapot --gen primary \
    --width 16384 --height 16384 --out "$dir/big/H" --rays-out "$dir/big/R"
contains "$dir/err" "GiB of memory needed, but only 64 MiB available" "too large for memory"
[[ ! -e $dir/big ]] || fail "too large for memory: the --out folder was created"
export STRAHL_MEMORY_LIMIT_MB=0
refuses "rays file too large for memory" 1 "tracing the 768 rays of '$dir/R': about" --scene builtin:teapot \
    --rays "$dir/R" --out "$dir/big/H"
[[ ! -e $dir/big ]] || fail "rays file too large for memory: the --out folder was created"
export STRAHL_MEMORY_LIMIT_MB=1024
succeeds "small enough for memory" --scene builtin:teapot --gen primary --width 64 --height 48
unset STRAHL_MEMORY_LIMIT_MB
# A symbolic link to nothing as --out: not written through (its target would appear where it points).
ln -s "$dir/link_target" "$dir/dangling"
refuses "--out a dangling link" 1 "is a symbolic link to '$dir/link_target', which does not exist" \
    --scene builtin:teapot --rays "$dir/R" --out "$dir/dangling" --force
[[ ! -e $dir/link_target ]] || fail "--out a dangling link: written through it"
# A read-only --out with --force: found before tracing. As root, the program runs without the capabilities
# that let root write a read-only file (not as another user: that user may not reach a clone under a folder
# only root can enter, such as mktemp -d's).
as_user=()
[[ $(id -u) -ne 0 ]] || as_user=(setpriv --bounding-set=-dac_override,-dac_read_search)
if [[ $(id -u) -ne 0 ]] || command -v setpriv >/dev/null; then
    mkdir -p "$dir/read_only" && chmod 777 "$dir/read_only"
    cp "$dir/R" "$dir/read_only/R" && chmod 444 "$dir/read_only/R"
    cp "$dir/H" "$dir/read_only/H" && chmod 444 "$dir/read_only/H"
    rc=0
    "${as_user[@]}" "$trace" --scene builtin:teapot --rays "$dir/read_only/R" --out "$dir/read_only/H" --force \
        >"$dir/out" 2>"$dir/err" || rc=$?
    [[ $rc -eq 1 ]] || fail "read-only --out with --force: exit $rc, expected 1"
    contains "$dir/err" "cannot replace '$dir/read_only/H'" "read-only --out with --force"
    ! grep -q "Mrays/s" "$dir/out" || fail "read-only --out with --force: traced before refusing"
else
    echo "note: read-only --out not checked (running as root without setpriv)"
fi
# A scene of extent 2e19 (or 7e12: the triangle tests overflow and every hit is lost): refused by the loader,
# naming the vertex and the cause.
printf 'v 0 0 0\nv 2e19 0 2e19\nv 0 2e19 2e19\nf 1 2 3\n' >"$dir/huge.obj"
refuses "a scene too large for float" 1 "huge.obj" --scene "$dir/huge.obj" --gen primary --width 8 --height 8
contains "$dir/err" "beyond +-1e12, the largest coordinate the course accepts" "a scene too large for float"
# A scene 1e-30 across (below min_extent, 1e-8, the triangle tests' products underflow and every hit is lost,
# with exit 0 and "hits 0" before the rule): refused, naming its extent and the range; so is a scene file's
# instance scaled that small.
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1e-30 0 0\n0 1e-30 0\n3 0 1 2\n' >"$dir/tiny.ply"
refuses "a scene too small for float" 1 "tiny.ply: is 1e-30 across" --scene "$dir/tiny.ply" --gen primary --width 8 --height 8
contains "$dir/err" "below 1e-8, the smallest extent the course accepts" "a scene too small for float"
contains "$dir/err" "extents from 1e-8 to coordinates of +-1e12" "a scene too small for float"

# An instanced scene file (chapter 10): the two-level BVH and brute force over the flattened copy find the
# same triangles (the same ids) for the same rays; a malformed line is refused with its number.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$dir/tri.obj"
printf 'mesh tri tri.obj\nfield tri 3 3 1.5 1.5\ninstance tri translate 0 2 0 rotate x 30\n' >"$dir/field.scene"
succeeds "an instanced scene, ch10-two-level" --scene "$dir/field.scene" --accel ch10-two-level --gen primary \
    --width 32 --height 24 --rays-out "$dir/RI" --out "$dir/HI"
contains "$dir/out" "10 instances of 1 mesh" "an instanced scene"
succeeds "an instanced scene, ch10-brute-instanced" --scene "$dir/field.scene" --rays "$dir/RI" \
    --accel ch10-brute-instanced --out "$dir/HI2"
cmp -s "$dir/HI" "$dir/HI2" || fail "an instanced scene: ch10-two-level's hits differ from the instanced brute force's"
printf 'mesh tri tri.obj\ninstance tri scale 0\n' >"$dir/singular.scene"
refuses "a singular instance" 1 "singular.scene:2: the transform is singular" --scene "$dir/singular.scene" \
    --gen primary --width 8 --height 8
printf 'mesh tri tri.obj\ninstance tri scale 1e-30\n' >"$dir/tiny.scene"
refuses "an instance too small for float" 1 "tiny.scene:2: mesh 'tri' as this line places it is 1e-30 across" \
    --scene "$dir/tiny.scene" --accel ch10-two-level --gen primary --width 8 --height 8

finish strahl-trace
