#!/usr/bin/env bash
# `make run`: the VI2 Cornell box in the window when there is a display, otherwise rendered
# headless to an image whose path is printed.
set -euo pipefail
build=${1:-build}
cd "$build"
scene=models/cornell_box_VI2_Specular.ecs
if [ -n "${DISPLAY:-}" ]; then
    exec ./viewer -c "$scene"
fi
image=cornell_box_VI2_Specular.png
echo "make run: no display (DISPLAY is not set), rendering headless with the reference solution"
./viewer -c "$scene" --lab importance --solution --spp 256 -o "$image"
echo "make run: the image is $(pwd)/$image"
echo "make run: your own labs/ code: cd $build && ./viewer -c $scene --lab branching -o mine.png"
