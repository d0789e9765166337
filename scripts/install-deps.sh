#!/usr/bin/env bash
# Installs the Debian/Ubuntu packages PathLab needs that are not installed yet. Uses apt-get
# directly as root, through sudo otherwise; does nothing when everything is present.
set -euo pipefail

packages=(
    make cmake g++ ninja-build pkg-config python3 # make: a minimal Debian has none
    libembree-dev embree-tools          # ray tracing; Embree's own viewer/pathtracer to compare with
    libopenimageio-dev openimageio-tools # image files
    libtbb-dev                          # threads
    libtinyobjloader-dev                # OBJ/MTL
    nlohmann-json3-dev                  # stats and grader JSON
    libglfw3-dev libgl-dev libimgui-dev # the window
    catch2                              # tests
    xvfb xdotool                        # tests of the window without a screen
    bubblewrap                          # sandboxed grading
    pandoc gnuplot-nox                  # handouts and their figures
)
# The instructor's kit (it has solutions/; the student release does not) also needs these.
kit=$(dirname "$0")/..
if [ -d "$kit/solutions" ]; then
    packages+=(
        git                             # the grader reads submissions that are git repositories
        debootstrap                     # ctest -L platforms: the kit on Debian 13, in its own root
    )
fi

if ! command -v dpkg-query >/dev/null 2>&1; then
    echo "install-deps: not a Debian/Ubuntu system; install the equivalents of: ${packages[*]}" >&2
    exit 0
fi

missing=()
for package in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$package")
    fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "install-deps: installing ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then
    apt_get=(apt-get)
elif command -v sudo >/dev/null 2>&1; then
    apt_get=(sudo apt-get)
else
    echo "install-deps: missing packages and no root or sudo to install them; as root run:" >&2
    echo "  apt-get install ${missing[*]}" >&2
    exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${apt_get[@]}" update -qq
"${apt_get[@]}" install -y -qq --no-install-recommends "${missing[@]}"
