# The race behind the verdicts that chapter 10 quotes (the two-level BVH against the flattened scene).
# Run from the repository root. RACE: the race program (default build/release/bin/race); OUT: where the run goes
# (default this folder); further arguments go to the race (./course figures --measure adds --against this
# folder's compare.csv and a --cache). Five processes, one thread's timings on one CPU.
"${RACE:-build/release/bin/race}" --scenes builtin:teapot_field,chapters/10_two_level/scenes/sponza_teapots.scene --processes 5 \
 --accels ch05-binned16-fast,ch10-two-level,embree-medium,embree-medium-instanced \
 --compare ch10-two-level:ch05-binned16-fast,embree-medium-instanced:embree-medium,ch10-two-level:embree-medium-instanced,ch05-binned16-fast:embree-medium \
 --out "${OUT:-slides/img/16_race/claims_10}" "$@"
