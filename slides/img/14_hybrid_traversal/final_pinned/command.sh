# The final tracer's race (chapter 14 quotes its verdicts).
# Run from the repository root. RACE: the race program (default build/release/bin/race); OUT: where the run goes
# (default this folder); further arguments go to the race (./course figures --measure adds --against this
# folder's compare.csv and a --cache). Five processes, one thread's timings on one CPU.
"${RACE:-build/release/bin/race}" --scenes builtin:teapot_stadium,../shared/scenes/bunny.ply,../shared/scenes/sponza.obj,../shared/scenes/armadillo.obj --processes 5 \
 --accels final,ch14-hybrid16-auto,final-sbvh,ch13-bvh8-block8,ch13-bvh8-block8-octant,embree-medium,embree-high,embree-medium-packet8 \
 --compare final:embree-medium,final:embree-high,final:embree-medium-packet8,final:ch14-hybrid16-auto,final-sbvh:final,final-sbvh:embree-medium,final-sbvh:embree-high,ch13-bvh8-block8-octant:ch13-bvh8-block8 \
 --out "${OUT:-slides/img/14_hybrid_traversal/final_pinned}" "$@"
