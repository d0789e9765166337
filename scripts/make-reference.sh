#!/usr/bin/env bash
# `make reference [REFERENCE_SPP=N] [REFERENCE_SIZE=W]`: the converged image of the VI2 Cornell
# box that the window's convergence plot measures against, at the window's default size (512 x
# 512), cached as BUILD/references/cornell_box_VI2_Specular.512x512.exr, where the window finds it
# (apps/viewer/convergence_reference.h). Unbiased: lab 4 at continueProb 0.8, 4096 spp, about
# 8 minutes on 2 cores. The instructor's kit renders the reference solution; the student release,
# which has none, renders the student's own labs/roulette.cpp, which must pass its tests first
# (make test-labs) for the plot to mean anything.
set -uo pipefail
build=${1:-build}
spp=${2:-4096}
size=${3:-512}
kit=$(cd "$(dirname "$0")/.." && pwd)
scene=cornell_box_VI2_Specular
case "$spp$size" in
    *[!0-9]*|'') echo "make reference: REFERENCE_SPP=$spp and REFERENCE_SIZE=$size must be whole numbers" >&2
                 exit 2 ;;
esac

if [ -d "$kit/solutions" ]; then
    whose=(--solution)
    what="the reference solution of lab 4"
else
    whose=()
    what="your labs/roulette.cpp (right only if it passes make test-labs)"
fi
cd "$build" || exit 2
mkdir -p references
out=references/$scene.${size}x${size}.exr
echo "make reference: rendering $what, continueProb 0.8, ${size}x${size} pixels, $spp spp" \
     "(4096 spp at 512x512: about 8 minutes on 2 cores)"
start=$(date +%s)
./viewer -c "$kit/models/$scene.ecs" --lab roulette "${whose[@]}" --continue-prob 0.8 \
         --seed 900002 --size "$size" "$size" --spp "$spp" -o "$out" || exit $?
echo "make reference: $(pwd)/$out in $(( $(date +%s) - start )) s; the window at ${size}x${size}" \
     "plots its error against it"
