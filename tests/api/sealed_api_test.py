#!/usr/bin/env python3
"""The student API is sealed, ctest `api.sealed`: a lab file sees what lab.h documents and cannot
reach the renderer's side of it.

Usage: sealed_api_test.py --build BUILD

Each case is a small lab file compiled exactly as the build compiles labs/branching.cpp (its
command from BUILD/compile_commands.json, syntax only): the lab that uses every documented part
of the API must compile, and each one that reaches for a renderer hook must fail, with the
compiler naming what it refused. The headers a lab file sees through lab.h are listed and compared
with the ones lab.h documents (below), so that a header slipping into the student API is noticed;
the list of labs among them must be the one the build generates (BUILD/generated/include).
"""
import argparse
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from checks import check, exit_code  # noqa: E402

SKIPPED = 77  # the test's SKIP_RETURN_CODE (tests/CMakeLists.txt)

# What the documented lab below may use: every part lab.h's comment lists.
DOCUMENTED_LAB = r"""
#include "pathlab/lab.h"
namespace pathlab::branching {
Color pathTrace(const Ray& ray, int depth, PathContext& ctx) {
    PATHLAB_TODO("lab1.1");
    const Hit hit = ctx.trace(ray);
    if (!hit || depth > ctx.maxDepth || ctx.sampler.get1D() > ctx.continueProb) return Color();
    Color radiance = hit.emitted + ctx.directLight(hit);
    const Material& m = hit.material;
    const Vec2 u = ctx.sampler.get2D();
    const Vec3 d = sampleCosineHemisphere(hit.normal, u);
    radiance += m.Kd * pathTrace(diffuseRay(hit, u), depth + 1, ctx) * (d.x > 0 ? 1.0f : InvPi);
    radiance += m.Ks * pathTrace(mirrorRay(ray, hit), depth + 1, ctx);
    radiance += m.Kt * pathTrace(refractionRay(ray, hit), depth + 1, ctx);
    if (m.Ns > 0) {
        const Ray glossy = glossyRay(ray, hit, Vec3{0, 0, 1});
        if (glossy.kind == RayKind::Glossy)
            radiance += phongBrdf(m, 1.0f) * pathTrace(glossy, depth + 1, ctx);
        const LightSample toLight = ctx.sampleLight(hit);
        const Vec3 local = lobeFrameDirection(ray, hit, toLight.direction);
        const float weight = toLight.delta ? 1.0f : ctx.strategyWeight(Strategy::Light, 0.5f);
        if (toLight.pdf > 0 && toLight.distance > 0 && toLight.cosAtLight > 0)
            radiance += toLight.radiance * phongBrdf(m, local.z) * (weight / toLight.pdf);
        const Hit next = ctx.trace(glossy);
        radiance += next.emitted * ctx.strategyWeight(Strategy::Lobe, ctx.lightPdf(hit, next));
    }
    return isBlack(m.Ke) || ray.kind == RayKind::Diffuse ? radiance : radiance / reduceMax(m.Ke);
}
}
"""

# (what a lab tries, the statement inside pathTrace or the line before the namespace, what the
# compiler's error must mention)
FORBIDDEN = [
    ("hand the next trace() a camera packet", "ctx.primeCameraHit(nullptr, 0);", r"primeCameraHit"),
    ("record the rays into a log", "ctx.recordRaysInto(nullptr);", r"recordRaysInto"),
    ("read the ray counters", "(void)ctx.rayCounters();", r"rayCounters"),
    ("restart the random numbers", "ctx.sampler.startSample(1, 2, 3);", r"startSample"),
    ("replace the sampler", "ctx.sampler = ctx.sampler;", r"deleted|operator="),
    ("copy the context", "PathContext copy = ctx; (void)copy;", r"deleted|PathContext"),
    ("make a context of its own", "PathContext other(*(const RenderScene*)nullptr, {});",
     r"private|PathContext|incomplete"),
    ("use a camera packet", "CameraPacket packet; (void)packet;", r"incomplete|CameraPacket"),
    ("include the renderer's side", "#include \"pathlab/render/path_driver.h\"",
     r"path_driver.h is the renderer's side"),
    ("include the lab tables", "#include \"runner/lab_tables.h\"", r"lab_tables.h"),
]

# The headers of pathlab/ a lab file sees through lab.h: the types and functions lab.h's comment
# documents, and what they are made of. lab_list.h among them is the build's: CMake writes it
# from framework/lab_list.txt into BUILD/generated/include.
DOCUMENTED_HEADERS = {
    "lab.h", "lab_declarations.h", "lab_list.h", "call_site.h", "color.h", "constants.h", "cosine_hemisphere.h", "hit.h",
    "light_sample.h",
    "glossy_lobe.h", "material.h", "orthonormal_basis.h", "path_context.h", "random_stream.h", "ray.h",
    "sampler.h",
    "scattering.h", "small_angle_sin_cos.h", "todo.h", "vec3.h",
}


def lab_compile_command(build):
    commands = os.path.join(build, "compile_commands.json")
    if not os.path.exists(commands):
        print("skipped: no compile_commands.json (Visual Studio's generator writes none)")
        sys.exit(SKIPPED)
    with open(commands) as f:
        entries = json.load(f)
    for entry in entries:
        if entry["file"].endswith(os.path.join("labs", "branching.cpp")) and \
                "pathlab_student" in entry.get("output", entry.get("command", "")):
            words = entry["arguments"] if "arguments" in entry else shlex.split(entry["command"])
            # Drop the output and the source: each case gives its own, syntax only.
            kept, skip = [], False
            for word in words:
                if skip:
                    skip = False
                    continue
                if word in ("-o", "-c"):
                    skip = True
                    continue
                kept.append(word)
            return kept, entry["directory"]
    sys.exit("sealed_api_test: labs/branching.cpp (pathlab_student) is not in compile_commands.json")


def compile_lab(command, directory, source, extra=()):
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "branching.cpp")
        with open(path, "w") as f:
            f.write(source)
        result = subprocess.run(command + list(extra) + ["-fsyntax-only", path], cwd=directory,
                                capture_output=True, text=True)
        return result.returncode, result.stdout + result.stderr


def with_statement(statement):
    if statement.startswith("#include"):
        return statement + "\n" + DOCUMENTED_LAB
    return DOCUMENTED_LAB.replace("PATHLAB_TODO(\"lab1.1\");", statement, 1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", required=True)
    args = parser.parse_args()
    command, directory = lab_compile_command(args.build)

    status, output = compile_lab(command, directory, DOCUMENTED_LAB)
    check(status == 0, "a lab using every documented part compiles" +
          ("" if status == 0 else "; the compiler said:\n" + output))

    for what, statement, mentions in FORBIDDEN:
        status, output = compile_lab(command, directory, with_statement(statement))
        refused = status != 0 and re.search(mentions, output) is not None
        check(refused, f"a lab cannot {what}" +
              ("" if refused else f" ({statement!r} compiled; the compiler said:\n"
                                  f"{output[-800:]})"))

    status, output = compile_lab(command, directory, DOCUMENTED_LAB, extra=["-H"])
    included = [os.path.join(directory, line.lstrip(". ").strip()) for line in output.splitlines()
                if line.startswith(".") and "/pathlab/" in line]
    # The student API is pathlab/ itself: a header of a folder in it (pathlab/render/, ...) is
    # the framework's side, which lab.h must not bring in.
    outside = sorted({path for path in included
                      if os.path.basename(os.path.dirname(os.path.normpath(path))) != "pathlab"})
    check(not outside, "every header a lab file sees is one of pathlab/*.h, none of its folders'"
          + ("" if not outside else f": {outside}"))
    seen = {os.path.basename(path) for path in included}
    extra_headers, missing = sorted(seen - DOCUMENTED_HEADERS), sorted(DOCUMENTED_HEADERS - seen)
    ok = status == 0 and not extra_headers and not missing
    check(ok, f"lab.h brings in exactly the documented headers ({len(seen)} of pathlab/)" +
          ("" if ok else f": not documented {extra_headers}, documented but gone {missing}"))
    generated = os.path.realpath(os.path.join(args.build, "generated", "include", "pathlab",
                                              "lab_list.h"))
    lists = sorted({os.path.realpath(path) for path in included
                    if os.path.basename(path) == "lab_list.h"})
    check(lists == [generated], f"the lab_list.h a lab file sees is the one the build generates "
                                f"from framework/lab_list.txt ({generated}): {lists}")
    return exit_code()


if __name__ == "__main__":
    sys.exit(main())
