#!/usr/bin/env bash
# `make run [LAB=NAME]`: the VI2 Cornell box (for a lab that writes a glossy lobe, Veach's plates
# at continueProb 0.8) in the window where there is a display, otherwise rendered headless to an
# image whose path is printed. The student release, which has no solutions, renders the student's
# own labs/ (lab 1 unless LAB names another) and says which steps of that lab are still to write;
# the instructor's kit renders the reference solution of lab 3 (or of LAB). The labs are those of
# framework/lab_list.txt.
set -uo pipefail
build=${1:-build}
lab=${2:-}
kit=$(cd "$(dirname "$0")/.." && pwd)
scene=models/cornell_box_VI2_Specular.ecs
# The list's labs, and the fourth field of each (lobe, or nothing).
declare -A routines=()
while read -r name _ _ fourth _; do
    routines[$name]=${fourth:-none}
done < <(grep -v '^[[:space:]]*#' "$kit/framework/lab_list.txt" | grep -v '^[[:space:]]*$')
labs=$(grep -v '^[[:space:]]*#' "$kit/framework/lab_list.txt" | awk 'NF {print $1}' | tr '\n' ' ')

if [ -d "$kit/solutions" ]; then
    lab=${lab:-importance}
    whose=(--solution)
    what="the reference solution of $lab"
    spp=256
else
    lab=${lab:-branching}
    whose=()
    what="your labs/$lab.cpp"
    spp=64
fi
if [ -z "${routines[$lab]:-}" ]; then
    echo "make run: LAB=$lab is not a lab: ${labs% }" >&2
    exit 2
fi
# The lab's handout, as its file names it ("Handout: handouts/NN-NAME.md").
handout=$(grep -o 'handouts/[0-9][0-9]-[A-Za-z-]*\.md' "$kit/labs/$lab.cpp" 2>/dev/null | head -1)
handout=${handout:-handouts/}
extra=()
if [ "${routines[$lab]}" = lobe ]; then
    scene=models/veach_plates.ecs
    extra=(--continue-prob 0.8)
    what="$what on veach_plates at continueProb 0.8"
fi

# The steps of the student's lab still marked PATHLAB_TODO, in one line (a marker may go on to
# name the variables its step uses: PATHLAB_TODO("lab1.2", depth)).
if [ ${#whose[@]} -eq 0 ]; then
    todo=$(grep -o 'PATHLAB_TODO("lab[0-9.]*"' "$kit/labs/$lab.cpp" | grep -o 'lab[0-9.]*' | tr '\n' ' ')
    if [ -n "$todo" ]; then
        echo "make run: labs/$lab.cpp has steps still to write: ${todo% } ($handout);" \
             "each adds nothing to the image until you write it (the stub renders direct light only)"
    else
        echo "make run: labs/$lab.cpp has no PATHLAB_TODO left"
    fi
fi

cd "$build" || exit 2
# A screen to open the window on: on Linux a DISPLAY (X11) or WAYLAND_DISPLAY; macOS always has
# one when logged in (the viewer says so when it cannot use it, over ssh say).
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] || [ "$(uname -s)" = Darwin ]; then
    echo "make run: opening the window on $what (h: help, q: quit)"
    problems=$(mktemp)
    # Its error output goes to the terminal as it comes, and to $problems for the test below.
    { ./viewer -c "$scene" --lab "$lab" "${whose[@]}" "${extra[@]}" 2>&1 1>&3 3>&- | tee "$problems" >&2
      status=${PIPESTATUS[0]}; } 3>&1
    # A display variable that leads nowhere (a stale ssh -X, say): render headless instead.
    if [ $status -ne 2 ] || ! grep -q "^viewer: no display" "$problems"; then
        rm -f "$problems"
        exit $status
    fi
    rm -f "$problems"
fi

image=$lab.png
echo "make run: no display, so rendering $what headless, $spp samples per pixel"
problems=$(mktemp)
report=$(mktemp)
./viewer -c "$scene" --lab "$lab" "${whose[@]}" "${extra[@]}" --spp "$spp" -o "$image" > "$report" 2> "$problems"
status=$?
# The TODO warnings are summed up above; anything else the viewer says is shown as it is, and
# before its report of the render, as the viewer orders them: a NaN warning comes first.
grep -v "TODO(lab[0-9.]*) is not done yet" "$problems" >&2
cat "$report"
rm -f "$problems" "$report"
[ $status -eq 0 ] || exit $status
echo "make run: the image is $(pwd)/$image"
other=uniform
[ "$lab" = uniform ] && other=importance
echo "make run: another lab: make run LAB=$other; the viewer's options: cd $build && ./viewer --help"
