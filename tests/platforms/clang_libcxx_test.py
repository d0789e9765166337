#!/usr/bin/env python3
"""The kit built with clang and libc++, the nearest this machine has to a Mac's Apple clang, with
AddressSanitizer and UndefinedBehaviorSanitizer.

What it proves, in a build folder of its own beside the kit's:
  - the framework, the labs (the stubs and the solutions) and the viewer compile with clang and
    libc++ with warnings as errors, and the grader, the benchmark and the tests below compile
    and link (not the grader's mutant labs: copies of the solutions, half the build);
  - the build without the Linux-only parts (PATHLAB_SANDBOX=OFF: no bubblewrap sandbox, seccomp
    filter or batch grading), which is what macOS builds, and `grader batch` there says in one
    line that it needs Linux;
  - its test suite passes: sampling, scene, render (but the noise figure at 1024 spp), the lab
    tests on the solutions, the grader's own unit tests, the window under Xvfb, and a local
    grade of one lab;
  - and does so under ASan and UBSan, with the kit's debug checks on (PATHLAB_DEBUG_CHECKS): no
    out-of-bounds access, use after free, leak or undefined behaviour in any of it. A report
    stops the program with a non-zero exit, which fails the test that ran it.
The sanitizers ride on this build rather than a third one of the whole kit: CI's time is short,
and a build with them is also a clang + libc++ build.
Debian's OpenImageIO is built against libstdc++, so the image plug-in alone is built with it
(its interface is C only, and it is sanitized like the rest). The configuration is CMakePresets.json's `clang-libcxx-asan`, which
is `clang-libcxx` (kept for maintainers, without the sanitizers) plus PATHLAB_SANITIZE.

Exits 77 (skipped, with the reason on a line starting "skipped:") when clang++ or libc++ is
not installed.
"""
import os
import re
import shutil
import subprocess
import sys
import time

from platform_support import SKIP, TimedSteps, build_arguments, clang_or_skip

TARGETS = ["viewer", "viewer_solutions_as_student", "grader", "bench", "test_sampling",
           "test_scene", "test_render", "test_estimators", "test_grader", "test_process",
           # the window test's stuck window: the viewer around the endless-loop mutant
           "viewer_mutant_uniform_endless_loop"]


def libcxx_missing(compiler):
    probe = subprocess.run([compiler, "-x", "c++", "-std=c++17", "-stdlib=libc++", "-E", "-"],
                           input="#include <vector>\n", capture_output=True, text=True)
    return probe.returncode != 0


def lsan_crashed(output):
    """Whether a failed ctest run's `output` shows LeakSanitizer itself crashing, and no leak."""
    return ("LeakSanitizer has encountered a fatal error" in output
            and "detected memory leaks" not in output)


def main():
    args = build_arguments(__doc__.splitlines()[0])
    compiler = clang_or_skip()
    if libcxx_missing(compiler):
        print("skipped: libc++ is not installed (apt install libc++-dev libc++abi-dev)")
        return SKIP

    shutil.rmtree(args.build, ignore_errors=True)
    steps = TimedSteps("clang + libc++")
    # The preset in CMakePresets.json, which a maintainer uses by hand too, in our own folder.
    steps.run(["cmake", "--preset", "clang-libcxx-asan", "-B", args.build,
               f"-DCMAKE_CXX_COMPILER={compiler}"], args.source, "configure")
    # UBSan's reports with their stack, in every program below and those they start. ASan's
    # defaults stand: a report ends the program, and a leak is checked for at every exit.
    os.environ["UBSAN_OPTIONS"] = "print_stacktrace=1"
    # ASan not following __tls_get_addr: clang 14's runtime, so doing, misreads glibc 2.36's table
    # of dynamically loaded TLS blocks (the image plug-in's libstdc++ among them), and
    # LeakSanitizer's tracer dies scanning a range such as 0x1d97-0x800002e99 ("DTLS 17 at ..."
    # with LSAN_OPTIONS=verbosity=1) at the exit of a viewer that wrote a PNG, every time for some
    # scenes. Leaks are still found without it: the static TLS, stacks and heap are all scanned.
    # (LSAN_OPTIONS=use_tls=0 would also stop the crash, but calls libc++abi's per-thread
    # exception globals a leak at every exit after a throw.)
    os.environ["ASAN_OPTIONS"] = "intercept_tls_get_addr=0"
    # What the steps below run, and the benchmark, so that all of PathLab's own code is compiled
    # with clang; not the grader's mutant labs and their viewers (copies of the solutions, each
    # built four labs at a time: half the build, and no code of their own).
    steps.run(["cmake", "--build", args.build, "-j", str(args.jobs), "--target", *TARGETS],
              args.source, "build")

    # Built with libc++: the standard library a program uses shows in what it links.
    linked = subprocess.run(["ldd", os.path.join(args.build, "viewer")], capture_output=True,
                            text=True).stdout
    if "libc++.so" not in linked:
        print("clang + libc++: the viewer is not linked with libc++:\n" + linked)
        return 1

    tests = ["ctest", "--output-on-failure", "-j", str(args.jobs),
             "-R", r"^(sampling|scene|estimators(\.lab[1-4])?|grader)$"]
    print("$ " + " ".join(tests), flush=True)
    start = time.monotonic()
    result = subprocess.run(tests, cwd=args.build, capture_output=True, text=True)
    steps.timings.append(("tests", time.monotonic() - start))
    output = result.stdout + result.stderr
    print(output, flush=True)
    if result.returncode != 0:
        if not lsan_crashed(output):
            print(f"clang + libc++: tests failed (exit {result.returncode})", flush=True)
            steps.report()
            return 1
        # LeakSanitizer's own tracer has also died, now and then, at a program's exit on this
        # shared machine ("Tracer caught signal 11 ... LeakSanitizer has encountered a fatal
        # error") for no cause found in the program:
        # no finding about PathLab, so the tests that met it run once more. A leak it finds
        # ("detected memory leaks"), or any other failure, is not run again.
        steps.run(tests + ["--rerun-failed"], args.build,
                  "tests again, after LeakSanitizer crashed")
    # The window without LeakSanitizer: Mesa's software OpenGL, unloaded before the check at
    # exit, leaves two blocks of its own that LSan can only call "<unknown module>", which no
    # suppression can name. Every other program here, the viewer headless included, is checked.
    steps.run(["ctest", "--output-on-failure", "-R", r"^viewer\.window$"], args.build,
              "window test",
              dict(os.environ, ASAN_OPTIONS=os.environ["ASAN_OPTIONS"] + ":detect_leaks=0"))
    # The render tests but the one that renders 4 labs to 1024 spp to see the noise figure halve:
    # its code is the other render tests', and sanitized it is most of this test's time. The
    # kit's own build runs it (ctest `render`).
    steps.run([os.path.join(args.build, "tests", "test_render"), "~*-> 1024 spp"], args.build,
              "render tests")

    # A local grade of one lab, through the portable process runner, and batch grading's refusal.
    grader = os.path.join(args.build, "grader")
    graded = subprocess.run([grader, "--viewer", os.path.join(args.build, "viewer_solutions_as_student"),
                             "--lab", "importance"], cwd=args.build, capture_output=True, text=True)
    print(graded.stdout + graded.stderr)
    if not re.search(r"^importance\s+pass \d+/\d+", graded.stdout, re.MULTILINE):
        print("clang + libc++: the local grade of the solution did not pass its correctness check")
        return 1
    batch = subprocess.run([grader, "batch", args.build, "--out", os.path.join(args.build, "batch")],
                           cwd=args.build, capture_output=True, text=True)
    print(batch.stderr.strip())
    if batch.returncode != 2 or "needs Linux and bubblewrap" not in batch.stderr:
        print("clang + libc++: `grader batch` without the sandbox should say it needs Linux")
        return 1
    steps.report()
    return 0


if __name__ == "__main__":
    sys.exit(main())
