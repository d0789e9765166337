#!/usr/bin/env python3
"""The kit on Debian 13 (trixie), ctest `platforms.debian13`: the system students use, with
Embree 4.3, Catch2 3.7, OpenImageIO 2.5 and GCC 14, where the kit is otherwise built and tested
on Debian 12 (Embree 3.13, Catch2 2, OpenImageIO 2.4, GCC 12).

Usage: debian13_test.py --source KIT --work FOLDER [--keep]

What it proves, each phase timed:
1. debootstrap makes a minimal trixie root, afresh each run, in FOLDER/trixie-root: nothing is
   reused from an earlier run, as on the fresh machine CI runs on.
2. The kit's files (those git tracks) copied there, the kit's own scripts/install-deps.sh
   installs everything PathLab needs on a bare Debian 13, and run again finds nothing missing.
3. `make build` builds the whole kit there without a compiler warning.
4. ctest passes there with nothing skipped, neither a ctest entry nor a Catch2 test case: the
   tests a student's machine runs (sampling, scene, render, the estimators and lab tests, the
   handouts, the window under Xvfb), the benchmark and its agreement with Embree's own
   pathtracer. LEFT_OUT lists the tests not run there, and why.
5. The grader's batch grading of a class, hostile submissions included, in its bubblewrap
   sandbox: grader.batch's test with --class-only, after ctest (its timed renders beside no
   other test of the root's).

The root is entered through enter_root.sh: every mount is made in namespaces of the test's own
and vanishes with them, so none is ever left below the build folder, even when the test fails,
times out or is interrupted. When the test passes, the root (2.4 GB) is deleted; when it
fails, it is kept for a look (--keep keeps it either way), and the next run replaces it.

Skipped (exit 77, one line saying why) where it cannot run: not root, no debootstrap or
namespaces, Debian's archive out of reach, too little disk space.
"""
import argparse
import ctypes
import os
import re
import resource
import shutil
import signal
import subprocess
import sys
import time
import urllib.request

SKIPPED = 77  # the test's SKIP_RETURN_CODE (tests/CMakeLists.txt)
MIRROR = os.environ.get("PATHLAB_DEBIAN_MIRROR", "http://deb.debian.org/debian")
SUITE = "trixie"
# Readable by every user, as a CI checkout is: the grader, run as root, runs its sandbox as an
# unused user id, which must read the kit (from /root, mode 700, grader batch cannot grade).
KIT_IN_ROOT = "/opt/pathlab"
FREE_BYTES_NEEDED = 6 << 30  # the root with PathLab's packages and build is 2.4 GB
# The kit's tests not run in the root, and why (times measured on the 2-core CI machine, which
# runs this test in about 10 minutes without them).
LEFT_OUT = {
    "release": "packs and builds the student release afresh, 10 minutes; the release's build "
               "and tests are those run here, minus the solutions",
    "gradescope": "builds the Gradescope autograder afresh, 4 minutes; its sandbox is the one "
                  "grader.batch uses here",
    "grader.checks": "the gradings judged by their speed, which run alone on the host: here "
                     "they would share the cores with this test's own builds and renders (the "
                     "speed check is in CPU time, and the solutions graded 40 times under load "
                     "never failed it, but a timed verdict is the host's question, not this "
                     "system's); the grader's checks run here in grader.batch, on correct, "
                     "buggy and hostile submissions",
    "grader.mutants": "the grader's verdicts on the stubs and each mutant, 3 minutes; the grader "
                      "is the same code on every system, and the class graded here in "
                      "grader.batch has correct, buggy and hostile submissions",
    "estimators.mutants": "the lab tests against 16 mutant labs, 5 minutes or more here: the lab tests "
                          "themselves run here on the solutions, and whether they catch a mutant "
                          "is the tests' code, the same on every system (the host's make test "
                          "runs it)",
    "grader.batch": "run after ctest on its own, with --class-only: the class graded once in the "
                    "sandbox, each verdict and each hostile submission checked; it leaves out the "
                    "batch run again, killed and restarted, and sharded, which are the grader's "
                    "own bookkeeping, the same on every system (2 of its 4 minutes)",
    "grader.instructor": "an instructor's term of batches, 2 minutes; its sandbox, canary and "
                         "gradebook are those grader.batch runs here",
    "release.rubric": "a release packed with an instructor's rubric, 2 minutes here: Python's "
                      "packaging and the grader's rubric checks, the same on every system (the "
                      "release's build and tests are those run here)",
    "grader.pages": "the grader's HTML in headless Chromium: the page's layout, not this "
                    "system's code, which the host's make test checks",
    "grader.slow": "label slow: 200 gradings, not part of `make test` anywhere",
    "platforms.debian13": "this test",
    "docs.fifth_lab": "the kit copied with a seventh lab in its list and built again, 8 minutes "
                      "here: the lab list's CMake and switches are the same on every system, and "
                      "the kit built here has six labs through the same list",
    "grader.load": "a slow lab graded while busy processes load the machine, 3 minutes: its "
                   "limits are in CPU time, which the host's make test checks; on top of this "
                   "test's own load it measures the host, not this system",
    "format": "the code's layout, checked with Debian 12's clang-format 14 (Debian 13's 19 lays "
              "code out otherwise, and the test skips with it)",
    "platforms.clang_libcxx": "the kit built again with clang and libc++, which the host's "
                              "make test runs; 5 minutes more here",
    "platforms.tsan": "the renderer and the viewer built again with ThreadSanitizer, which the "
                      "host's make test runs: races are in PathLab's code, not in the system's",
}
# Tests that must have run and passed, whatever else the kit registers.
REQUIRED = ("sampling", "scene", "render", "estimators", "estimators.lab1", "estimators.lab2",
            "estimators.lab3", "estimators.lab4", "estimators.lab5", "estimators.lab6", "grader",
            "handouts",
            "viewer.window", "bench.smoke", "bench.embree_agreement")
# (phase, wall seconds, CPU seconds) of each phase run. The CPU time says how busy the machine
# was with other work: that lengthens the wall time, not the CPU time.
PHASES = []
HERE = os.path.dirname(os.path.abspath(__file__))
ENTER_ROOT = os.path.join(HERE, "enter_root.sh")


class Terminated(Exception):
    """SIGTERM, turned into an exception so that the running phase's processes are killed."""


def on_sigterm(signum, frame):
    raise Terminated()


def skip(reason):
    print(f"skipped: {reason}", flush=True)
    sys.exit(SKIPPED)


def fail(message):
    print(f"FAILED: {message}", flush=True)
    sys.exit(1)


def tail(path, lines=40):
    with open(path, errors="replace") as f:
        return "".join(f.readlines()[-lines:])


def in_namespaces(command):
    """command in mount and process namespaces of its own: what it mounts, and every process it
    starts, goes when it goes or is killed."""
    return ["unshare", "--mount", "--propagation", "private", "--pid", "--fork", "--kill-child",
            "--", *command]


def in_root(root, script):
    return [ENTER_ROOT, root, "/bin/bash", "-euo", "pipefail", "-c", script]


def run_phase(name, command, log, timeout):
    """Runs command, output to log; returns (exit status, seconds), the status None if it took
    longer than timeout. Kills it, and so everything in its namespaces, on any way out."""
    shown = command[-1] if command[0] == ENTER_ROOT else " ".join(command)
    print(f"{name}: {shown}", flush=True)
    start, cpu = time.monotonic(), cpu_seconds()
    with open(log, "w") as out:
        process = subprocess.Popen(command, stdout=out, stderr=subprocess.STDOUT,
                                   stdin=subprocess.DEVNULL, preexec_fn=die_with_this_process)
        try:
            status = process.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            status = None
        finally:
            if process.poll() is None:
                process.kill()
                process.wait()
    seconds, cpu = time.monotonic() - start, cpu_seconds() - cpu
    PHASES.append((name, seconds, cpu))
    print(f"{name}: {seconds:.0f} s (CPU {cpu:.0f} s)" +
          ("" if status == 0 else f", {'timed out' if status is None else 'failed'}"), flush=True)
    return status, seconds


def die_with_this_process():
    """In the child: the kernel kills it if this test dies, even by SIGKILL (a ctest timeout);
    unshare --kill-child then takes the rest of the phase's processes with it."""
    PR_SET_PDEATHSIG = 1
    ctypes.CDLL(None, use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGKILL)


def cpu_seconds():
    """CPU time of the processes this one started and waited for, and those they waited for."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def phase(name, command, log, timeout):
    """run_phase that fails the test, with the log's tail, unless command succeeds."""
    status, seconds = run_phase(name, command, log, timeout)
    if status is None:
        fail(f"{name} took longer than {timeout} s; the end of {log}:\n{tail(log)}")
    if status != 0:
        fail(f"{name} failed (exit status {status}); the end of {log}:\n{tail(log)}")
    return seconds


def check_preconditions(work):
    if os.geteuid() != 0:
        skip("needs root (debootstrap, and the mounts of the Debian 13 root); run ctest as root")
    for program in ("debootstrap", "unshare", "pivot_root"):
        if not shutil.which(program):
            skip(f"{program} is not installed (scripts/install-deps.sh installs debootstrap)")
    if not os.path.exists(f"/usr/share/debootstrap/scripts/{SUITE}"):
        skip(f"this debootstrap does not know Debian 13 ({SUITE}); a newer one does")
    probe = subprocess.run(in_namespaces(["true"]), capture_output=True, text=True)
    if probe.returncode != 0:
        skip(f"cannot make mount and process namespaces here (a container without "
             f"CAP_SYS_ADMIN?): {probe.stderr.strip()}")
    release = f"{MIRROR}/dists/{SUITE}/Release"
    try:
        urllib.request.urlopen(urllib.request.Request(release, method="HEAD"), timeout=30)
    except OSError as error:
        skip(f"cannot reach Debian's archive ({release}: {error})")
    os.makedirs(work, exist_ok=True)
    free = shutil.disk_usage(work).free
    if free < FREE_BYTES_NEEDED:
        skip(f"needs {FREE_BYTES_NEEDED >> 30} GB free in {work}, has {free / (1 << 30):.1f} GB")


def mounts_below(folder):
    """Mount points at or below folder in this process's mount namespace."""
    found = []
    with open("/proc/self/mountinfo") as f:
        for line in f:
            point = line.split()[4].encode().decode("unicode_escape")
            if point == folder or point.startswith(folder + "/"):
                found.append(point)
    return found


def remove_root(root):
    """Deletes a root of an earlier run, never through a mount point."""
    if not os.path.lexists(root):
        return
    mounted = mounts_below(root)
    if mounted:
        fail(f"not deleting {root}: something is mounted below it ({', '.join(mounted)})")
    subprocess.run(["rm", "-rf", "--one-file-system", root], check=True)


def make_root(root, logs):
    remove_root(root)
    log = os.path.join(logs, "debootstrap.log")
    # In namespaces of its own too: debootstrap mounts /proc and /sys in the root while it works.
    command = in_namespaces(["debootstrap", "--variant=minbase", SUITE, root, MIRROR])
    status, seconds = run_phase("debootstrap", command, log, timeout=1200)
    if status != 0:
        with open(log, errors="replace") as f:
            unreachable = [line.strip() for line in f if re.search(
                r"Failed getting release file|Couldn't download|Temporary failure resolving|"
                r"Could not resolve|Connection timed out|No route to host", line)]
        if unreachable:
            skip(f"debootstrap could not download from Debian's archive: {unreachable[0]}")
        fail(f"debootstrap {'took too long' if status is None else 'failed'}; the end of {log}:"
             f"\n{tail(log)}")
    return seconds


def copy_kit(source, root):
    """The kit's files as the student release takes them: those git tracks, as they are."""
    sys.path.insert(0, os.path.join(source, "scripts"))
    import package_kit

    target = root + KIT_IN_ROOT
    files = package_kit.kit_files(source)
    for name in files:
        os.makedirs(os.path.dirname(os.path.join(target, name)), exist_ok=True)
        shutil.copy2(os.path.join(source, name), os.path.join(target, name))
    # A throwaway root: dpkg need not wait for each file to reach the disk.
    with open(os.path.join(root, "etc/dpkg/dpkg.cfg.d/pathlab-unsafe-io"), "w") as f:
        f.write("force-unsafe-io\n")
    return len(files)


def versions(root):
    script = ("dpkg-query -W -f '${Package} ${Version}\\n' libembree-dev catch2 "
              "libopenimageio-dev g++ cmake bubblewrap")
    result = subprocess.run(in_root(root, script), capture_output=True, text=True)
    return " ".join(f"{name} {version}," for name, version in
                    (line.split() for line in result.stdout.splitlines())).rstrip(",")


def ctest_results(output):
    """[(name, result, seconds)] from ctest's progress lines."""
    return [(m.group(1), m.group(2).strip("* "), float(m.group(3))) for m in re.finditer(
        r"Test\s+#\d+: (\S+) \.*\s*(.*?)\s+([\d.]+) sec", output)]


def check_tests(root, log):
    with open(log, errors="replace") as f:
        output = f.read()
    results = ctest_results(output)
    for name, result, seconds in results:
        print(f"  {name:28} {result:10} {seconds:7.1f} s")
    problems = [f"{name}: {result}" for name, result, _ in results if result != "Passed"]
    ran = {name for name, result, _ in results if result == "Passed"}
    problems += [f"{name}: did not run" for name in REQUIRED if name not in ran]
    # Inside the root everything the tests need is installed, so nothing may skip; Catch2 3's
    # summary counts the test cases that skipped ("test cases: 5 | 4 passed | 1 skipped").
    last_test_log = os.path.join(root + KIT_IN_ROOT, "build/Testing/Temporary/LastTest.log")
    if not os.path.exists(last_test_log):
        return problems + [f"ctest wrote no {last_test_log}"], len(ran)
    with open(last_test_log, errors="replace") as f:
        detail = f.read()
    problems += [f"a Catch2 test case skipped: {line.strip()}" for line in detail.splitlines()
                 if re.match(r"test cases:.*\| *\d+ skipped", line)]
    problems += [f"skipped: {line.strip()}" for line in detail.splitlines()
                 if line.startswith("skipped:")]
    return problems, len(ran)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--source", required=True, help="the kit")
    parser.add_argument("--work", required=True, help="a folder in the build folder")
    parser.add_argument("--keep", action="store_true", help="keep the root when the test passes")
    args = parser.parse_args()
    source, work = os.path.abspath(args.source), os.path.abspath(args.work)
    root, logs = os.path.join(work, "trixie-root"), os.path.join(work, "logs")
    signal.signal(signal.SIGTERM, on_sigterm)

    check_preconditions(work)
    shutil.rmtree(logs, ignore_errors=True)
    os.makedirs(logs)
    print(f"Debian 13 in {root}; logs in {logs}", flush=True)
    for name, why in LEFT_OUT.items():
        print(f"left out: {name} ({why})")

    start = time.monotonic()
    make_root(root, logs)
    print(f"copied the kit's {copy_kit(source, root)} files to {KIT_IN_ROOT}", flush=True)
    phase(
        "install-deps", in_root(root, f"cd {KIT_IN_ROOT} && scripts/install-deps.sh"),
        os.path.join(logs, "install-deps.log"), timeout=1500)
    again = subprocess.run(in_root(root, f"cd {KIT_IN_ROOT} && scripts/install-deps.sh"),
                           capture_output=True, text=True)
    if again.returncode != 0 or again.stdout.strip() or again.stderr.strip():
        fail(f"install-deps.sh run again should find nothing missing; it said:\n"
             f"{again.stdout}{again.stderr}")
    print(f"installed: {versions(root)}", flush=True)

    build_log = os.path.join(logs, "build.log")
    phase("make build", in_root(root, f"cd {KIT_IN_ROOT} && make build"), build_log,
          timeout=1800)
    with open(build_log, errors="replace") as f:
        warnings = [line.rstrip() for line in f if re.search(r"warning:|CMake Warning", line)]
    if warnings:
        fail(f"{len(warnings)} warnings in the build ({build_log}):\n" + "\n".join(warnings[:20]))

    left_out = "|".join(re.escape(name) for name in LEFT_OUT)
    tests_log = os.path.join(logs, "ctest.log")
    ctest = (f"cd {KIT_IN_ROOT}/build && ctest --output-on-failure -j \"$(nproc)\" -LE slow "
             f"-E '^({left_out})$'")
    status, _ = run_phase("ctest", in_root(root, ctest), tests_log, timeout=1800)
    problems, passed = check_tests(root, tests_log)
    if status is None:
        problems.append("ctest took longer than 1800 s")
    elif status != 0 and not problems:
        problems.append(f"ctest exited with status {status}")
    if problems:
        fail("in Debian 13:\n  " + "\n  ".join(problems) + f"\nthe end of {tests_log}:\n" +
             tail(tests_log, 80))

    phase("grader batch",
          in_root(root, f"cd {KIT_IN_ROOT} && python3 tests/grader/batch_test.py --build build "
                        f"--source . --class-only"),
          os.path.join(logs, "grader-batch.log"), timeout=1500)

    print("\nDebian 13 (trixie), phase by phase:")
    for name, seconds, cpu in PHASES:
        print(f"  {name:14} {seconds:6.0f} s   CPU {cpu:6.0f} s")
    print(f"  {'total':14} {time.monotonic() - start:6.0f} s")
    print(f"the kit builds without warnings, its {passed} tests pass on Debian 13, and so does "
          f"a batch grading of a class in the sandbox")
    if not args.keep:
        remove_root(root)


if __name__ == "__main__":
    try:
        main()
    except (KeyboardInterrupt, Terminated):
        fail("interrupted; the root's processes and mounts went with their namespaces")
