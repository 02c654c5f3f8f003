# The race behind the verdicts that chapters 13 and 15 quote (wide trees against the binary tree and Embree; the watertight test's cost).
# Run from the repository root. RACE: the race program (default build/release/bin/race); OUT: where the run goes
# (default this folder); further arguments go to the race (./course figures --measure adds --against this
# folder's compare.csv and a --cache). Five processes, one thread's timings on one CPU.
"${RACE:-build/release/bin/race}" --scenes ../shared/scenes/bunny.ply,../shared/scenes/sponza.obj --processes 5 \
 --accels ch05-binned16-fast,ch13-bvh8,ch13-bvh8-optimal,ch13-bvh16,ch15-mt-fast,ch15-watertight-fast,ch15-watertight-bvh16,embree-medium \
 --compare ch13-bvh16:ch05-binned16-fast,ch13-bvh8-optimal:ch05-binned16-fast,ch13-bvh16:embree-medium,ch13-bvh8:embree-medium,ch13-bvh8-optimal:embree-medium,ch05-binned16-fast:embree-medium,ch15-watertight-fast:ch15-mt-fast,ch15-watertight-bvh16:ch13-bvh16,ch15-watertight-bvh16:embree-medium \
 --out "${OUT:-slides/img/16_race/claims_13_15}" "$@"
