#!/usr/bin/env python3
"""PathLab's threads under ThreadSanitizer (clang's -fsanitize=thread).

What it proves, in a build folder of its own beside the kit's (CMakePresets.json's `tsan`):
  - the renderer's tiles, rendered in parallel by TBB's workers, share nothing they should not:
    the render tests that render with several threads and passes ([rng]: 1 against 2 threads,
    a second pass on the same buffer) and run the viewer headless ([stats]) run under TSan. Not
    the noise-figure tests, which render millions of samples through the same code: under TSan
    (several times slower) they would take CI minutes to prove nothing more;
  - the viewer's render thread and the window hand frames over, restart and stop without a race:
    the window test (tests/viewer/window_test.py) runs the viewer under Xvfb, keys and all, and a
    window whose lab never returns, ended by the renderer's watchdog from a thread of its own.
It builds only what those need (the framework, the labs, the viewer, the viewer around the
endless-loop mutant, the render tests). A race
report makes the program exit 66, which fails the test.

libtbb is not instrumented, so TSan does not see TBB hand a task to a worker and back: the
renderer tells it of its own data's hand-off (framework/src/render/renderer.cpp), and
tests/platforms/tsan.supp suppresses the reports on TBB's own task objects, and on Embree's and
Mesa's memory (also uninstrumented), each entry saying why.

Exits 77 (skipped, with the reason on a line starting "skipped:") when clang++, ThreadSanitizer's
runtime, Xvfb, xdotool or oiiotool is missing.
"""
import os
import platform
import shutil
import subprocess
import sys

from platform_support import SKIP, TimedSteps, build_arguments, clang_or_skip

HERE = os.path.dirname(os.path.abspath(__file__))
# Two threads and a mutex: TSan's runtime starts, and reports no race.
PROBE = """#include <mutex>
#include <thread>
int main() { std::mutex m; int n = 0;
  std::thread t([&] { std::lock_guard<std::mutex> l(m); ++n; });
  { std::lock_guard<std::mutex> l(m); ++n; } t.join(); return n == 2 ? 0 : 1; }
"""


def tsan_launcher(compiler, folder):
    """How to start a TSan program here: [] directly, the setarch prefix, or None if it cannot.

    TSan's runtime in clang 14 (Debian 12) expects the memory layout of a kernel with at most 28
    bits of mmap randomisation; on a kernel with more (vm.mmap_rnd_bits = 32, as recent Ubuntu
    kernels have) it dies at start with "unexpected memory mapping". `setarch -R` turns address
    randomisation off for the program and its children, which TSan's runtime does not need.
    """
    source, program = os.path.join(folder, "probe.cpp"), os.path.join(folder, "probe")
    with open(source, "w") as f:
        f.write(PROBE)
    built = subprocess.run([compiler, "-fsanitize=thread", "-std=c++17", source, "-o", program],
                           capture_output=True, text=True)
    if built.returncode != 0:
        return None, "clang++ cannot link ThreadSanitizer's runtime:\n" + built.stderr.strip()
    for prefix in ([], ["setarch", platform.machine(), "-R"]):
        if prefix and not shutil.which("setarch"):
            break
        probe = subprocess.run(prefix + [program], capture_output=True, text=True)
        if probe.returncode == 0:
            return prefix, ""
        reason = probe.stderr.strip().splitlines()[-1:] or [f"exit {probe.returncode}"]
    return None, "a ThreadSanitizer program does not run here: " + reason[0]


def main():
    args = build_arguments(__doc__.splitlines()[0])
    compiler = clang_or_skip()
    for tool, package in (("Xvfb", "xvfb"), ("xdotool", "xdotool"),
                          ("oiiotool", "openimageio-tools")):
        if not shutil.which(tool):
            print(f"skipped: {tool}, which the window test needs, is not installed "
                  f"(apt install {package})")
            return SKIP
    shutil.rmtree(args.build, ignore_errors=True)
    os.makedirs(args.build)
    launcher, why = tsan_launcher(compiler, args.build)
    if launcher is None:
        print("skipped: " + why)
        return SKIP
    if launcher:
        print("TSan: programs run under " + " ".join(launcher) +
              " (this kernel's address randomisation is more than clang 14's TSan allows)")

    steps = TimedSteps("TSan")
    steps.run(["cmake", "--preset", "tsan", "-B", args.build, f"-DCMAKE_CXX_COMPILER={compiler}"],
              args.source, "configure")
    steps.run(["cmake", "--build", args.build, "-j", str(args.jobs), "--target", "viewer",
               "viewer_mutant_uniform_endless_loop", "test_render"], args.source, "build")

    # Every report, with both stacks, then exit 66 (TSan's exit code after a report).
    env = dict(os.environ, TSAN_OPTIONS=" ".join([
        "suppressions=" + os.path.join(HERE, "tsan.supp"), "second_deadlock_stack=1"]))
    steps.run(launcher + [os.path.join(args.build, "tests", "test_render"), "[rng],[stats]"],
              args.build, "render tests", env)
    steps.run(launcher + [sys.executable, os.path.join(args.source, "tests", "viewer", "window_test.py"),
                          os.path.join(args.build, "viewer"), os.path.join(args.source, "models"),
                          os.path.join(args.build, "mutants", "uniform_endless_loop")],
              args.build, "window test", env)
    steps.report()
    return 0


if __name__ == "__main__":
    sys.exit(main())
