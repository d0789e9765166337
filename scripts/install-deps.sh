#!/usr/bin/env bash
# Installs what PathLab needs and is not installed yet: Debian and Ubuntu packages with apt-get
# (as root, through sudo otherwise), macOS ones with Homebrew. Elsewhere it stops and prints the
# exact command for the system's package manager. Does nothing when everything is present.
# With --list, prints the packages this system needs, each marked installed or missing, and
# installs nothing.
set -euo pipefail
kit=$(cd "$(dirname "$0")/.." && pwd)
list_only=
case "${1:-}" in
    "") ;;
    --list) list_only=1 ;;
    *) echo "install-deps: unknown option '$1' (--list prints the packages and installs nothing)" >&2
       exit 2 ;;
esac
# Installed by other means (another distribution, vcpkg, by hand): nothing to do.
[ -n "${PATHLAB_DEPS_INSTALLED:-}" ] && [ -z "$list_only" ] && exit 0

# ---- Debian, Ubuntu (and WSL2 with Ubuntu) ----------------------------------------------------
apt_packages=(
    make cmake g++ ninja-build pkg-config python3 # make: a minimal Debian has none
    libembree-dev embree-tools          # ray tracing; Embree's own viewer/pathtracer to compare with
    libopenimageio-dev openimageio-tools # image files
    libtbb-dev                          # threads
    nlohmann-json3-dev                  # stats and grader JSON
    libboost-math-dev                   # the grader's and the tests' distributions (Boost.Math)
    libglfw3-dev libgl-dev libimgui-dev # the window
    catch2                              # tests
    xvfb xdotool                        # tests of the window without a screen
    bubblewrap                          # sandboxed grading
    pandoc gnuplot-nox                  # handouts and their figures
)
# The instructor's kit (it has solutions/; the student release does not) also needs these.
if [ -d "$kit/solutions" ]; then
    apt_packages+=(
        git                             # the grader reads submissions that are git repositories
        clang libc++-dev libc++abi-dev  # ctest -L platforms: the kit with clang and libc++
        clang-format                    # ctest format: the code's layout
        debootstrap                     # ctest -L platforms: the kit on Debian 13, in its own root
    )
    # ctest grader.pages: the grader's pages in a headless browser. Ubuntu has Chromium only as a
    # snap, not an apt package; there the test skips. make profile: perf, which Ubuntu ships per
    # kernel (linux-tools-generic).
    if grep -qx 'ID=debian' /etc/os-release 2>/dev/null; then
        apt_packages+=(chromium linux-perf)
    fi
fi

# ---- macOS (Homebrew) -------------------------------------------------------------------------
# Homebrew has no Dear ImGui: a release of it goes in third_party/, where CMake finds it
# (cmake/dependencies.cmake).
brew_packages=(cmake ninja pkg-config python embree openimageio tbb nlohmann-json glfw catch2 boost)
imgui_release=v1.90.9

install_with_brew() {
    local missing=()
    for package in "${brew_packages[@]}"; do
        brew list --formula "$package" >/dev/null 2>&1 || missing+=("$package")
    done
    if [ -n "$list_only" ]; then
        for package in "${brew_packages[@]}"; do
            case " ${missing[*]} " in *" $package "*) echo "$package missing" ;; *) echo "$package installed" ;; esac
        done
        return 0
    fi
    if [ ${#missing[@]} -gt 0 ]; then
        echo "install-deps: brew install ${missing[*]}"
        brew install "${missing[@]}"
    fi
    if [ ! -f "$kit/third_party/imgui/imgui.cpp" ]; then
        echo "install-deps: Dear ImGui $imgui_release into third_party/imgui"
        git clone --quiet --depth 1 --branch "$imgui_release" \
            https://github.com/ocornut/imgui.git "$kit/third_party/imgui"
    fi
}

install_with_apt() {
    local missing=()
    for package in "${apt_packages[@]}"; do
        if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
            missing+=("$package")
            [ -n "$list_only" ] && echo "$package missing"
        else
            [ -n "$list_only" ] && echo "$package installed"
        fi
    done
    [ -n "$list_only" ] && return 0
    [ ${#missing[@]} -eq 0 ] && return 0

    echo "install-deps: installing ${missing[*]}"
    local apt_get
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
}

case "$(uname -s)" in
    Darwin)
        if ! command -v brew >/dev/null 2>&1; then
            echo "install-deps: macOS without Homebrew: install it (https://brew.sh), then run" >&2
            echo "  brew install ${brew_packages[*]}" >&2
            echo "and make again (which puts Dear ImGui in third_party/)" >&2
            exit 1
        fi
        install_with_brew
        ;;
    *)
        if command -v dpkg-query >/dev/null 2>&1 && command -v apt-get >/dev/null 2>&1; then
            install_with_apt
        else
            echo "install-deps: not Debian, Ubuntu or macOS: install these with your system's" >&2
            echo "package manager (their Debian names): ${apt_packages[*]}" >&2
            echo "or, with vcpkg (vcpkg.json): cmake --preset windows-vcpkg on Windows;" >&2
            echo "  elsewhere: cmake -B build -DCMAKE_TOOLCHAIN_FILE=\$VCPKG_ROOT/scripts/buildsystems/vcpkg.cmake" >&2
            echo "Once they are installed: PATHLAB_DEPS_INSTALLED=1 make run" >&2
            exit 1
        fi
        ;;
esac
