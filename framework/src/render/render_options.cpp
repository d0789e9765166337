#include "pathlab/render/render_options.h"

#include "pathlab/scene_io/embree_only_options.h"
#include "pathlab/support/input_error.h"
#include "pathlab/scene_io/option_reader.h"
#include "pathlab/support/parse_number.h"
#include "pathlab/scene_io/scene_script.h"
#include "pathlab/scene_io/xml_scene.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <filesystem>
#include <functional>
#include <map>

namespace pathlab {

namespace {

namespace fs = std::filesystem;

/// "--max-depth", "-max-depth" -> "max-depth": Embree's scene scripts use one dash, GNU style two.
std::string optionName(const std::string& text) {
    if (text.size() >= 2 && text[0] == '-' && text[1] == '-') return text.substr(2);
    if (text.size() >= 2 && text[0] == '-') return text.substr(1);
    return {};
}

using Handler = std::function<void(const Token&)>;
using Handlers = std::map<std::string, Handler>;

/// The scene's options: its files, camera, lights and image size. -c reads a script in place.
Handlers sceneOptions(RenderOptions& o, OptionReader& in, int& scriptDepth) {
    // Embree's --directionallight, and its alias -dirlight, which Embree's scripts use.
    const Handler directionalLight = [&](const Token& t) {
        DirectionalLight light;
        light.direction = in.vec3(t);
        if (dot(light.direction, light.direction) == 0)
            OptionReader::fail(t, "option " + t.text + " expects a direction, not 0 0 0");
        const Vec3 e = in.vec3(t);
        if (e.x < 0 || e.y < 0 || e.z < 0)
            OptionReader::fail(t, "option " + t.text + ": an irradiance cannot be negative");
        light.irradiance = {e.x, e.y, e.z};
        o.directionalLights.push_back(light);
    };
    return {
        {"c",
         [&](const Token& t) {
             const std::string path = in.path(t);
             if (o.sceneName.empty()) o.sceneName = fs::path(path).stem().string();
             o.sceneScripts.push_back(path);
             in.includeScript(path, ++scriptDepth);
         }},
        {"i",
         [&](const Token& t) {
             const std::string path = in.path(t);
             refuseXmlScene(path);
             if (o.sceneName.empty()) o.sceneName = fs::path(path).stem().string();
             o.objFiles.push_back(path);
         }},
        {"vp",
         [&](const Token& t) {
             o.camera.position = in.vec3(t);
             o.cameraSet = o.cameraPositionSet = true;
         }},
        {"vi",
         [&](const Token& t) {
             o.camera.lookAt = in.vec3(t);
             o.cameraSet = o.cameraLookAtSet = true;
             o.viewDirection.reset();
         }},
        {"vd",
         [&](const Token& t) {
             const Vec3 direction = in.vec3(t);
             if (dot(direction, direction) == 0)
                 OptionReader::fail(t, "option " + t.text + " expects a direction, not 0 0 0");
             o.viewDirection = direction;
             o.cameraSet = true;
         }},
        {"vu", [&](const Token& t) { o.camera.up = in.vec3(t), o.cameraSet = true; }},
        {"lefthanded", [&](const Token&) { o.camera.leftHanded = true; }},
        {"righthanded", [&](const Token&) { o.camera.leftHanded = false; }},
        {"fov",
         [&](const Token& t) {
             const float fov = in.number(t, "an angle in degrees");
             if (!(fov > 0 && fov < 180))
                 OptionReader::fail(t,
                                    "option " + t.text + " expects an angle in (0, 180) degrees");
             o.camera.fovDegrees = fov, o.cameraSet = o.fovSet = true;
         }},
        {"pointlight",
         [&](const Token& t) {
             PointLight light;
             light.position = in.vec3(t);
             const Vec3 i = in.vec3(t);
             if (i.x < 0 || i.y < 0 || i.z < 0)
                 OptionReader::fail(t,
                                    "option " + t.text + ": a light intensity cannot be negative");
             light.intensity = {i.x, i.y, i.z};
             o.pointLights.push_back(light);
         }},
        {"directionallight", directionalLight},
        {"dirlight", directionalLight},
        {"glossy-exponent",
         [&](const Token& t) {
             const float n = in.number(t, "a Phong exponent");
             if (!(n > 0 && n <= 1e6f))
                 OptionReader::fail(t, "option " + t.text +
                                           " expects a Phong exponent above 0 and at most 1e6");
             o.glossyExponent = n;
         }},
        {"size",
         [&](const Token& t) {
             o.width = in.positive(t, "a width in pixels", 16384);
             o.height = in.positive(t, "a height in pixels", 16384);
         }},
    };
}

/// The estimator's options: which lab, whose code, its parameters, seed and threads.
Handlers estimatorOptions(RenderOptions& o, OptionReader& in) {
    return {
        {"lab",
         [&](const Token& t) {
             const Token& name = in.value(t, "a lab name");
             const std::optional<Lab> lab = labFromName(name.text);
             if (!lab)
                 OptionReader::fail(t, "option --lab expects one of " + labNames(", ") + ", got '" +
                                           name.text + "'");
             o.lab = *lab;
         }},
        {"solution", [&](const Token&) { o.implementation = Implementation::Solution; }},
        {"student", [&](const Token&) { o.implementation = Implementation::Student; }},
        {"max-depth",
         [&](const Token& t) {
             const long long d = in.integer(t, "a depth (0 or more)");
             if (d < 0 || d > 1000)
                 OptionReader::fail(t, "option " + t.text +
                                           " expects a depth from 0 to 1000, got " +
                                           std::to_string(d));
             o.parameters.maxDepth = static_cast<int>(d);
         }},
        {"continue-prob",
         [&](const Token& t) {
             const float p = in.number(t, "a probability");
             if (!(p > 0 && p < 1))
                 OptionReader::fail(t, "option " + t.text +
                                           " expects a probability strictly between 0 and 1 "
                                           "(0 never continues, 1 never ends), got " +
                                           std::to_string(p));
             o.parameters.continueProb = p;
         }},
        {"strategy",
         [&](const Token& t) {
             const Token& name = in.value(t, "a strategy");
             if (name.text == "both")
                 o.parameters.strategies = StrategyChoice::Both;
             else if (name.text == "light")
                 o.parameters.strategies = StrategyChoice::LightOnly;
             else if (name.text == "lobe")
                 o.parameters.strategies = StrategyChoice::LobeOnly;
             else
                 OptionReader::fail(t, "option --strategy expects both, light or lobe, got '" +
                                           name.text + "'");
         }},
        {"seed",
         [&](const Token& t) {
             const long long s = in.integer(t, "a seed (0 or more)");
             if (s < 0) OptionReader::fail(t, "option " + t.text + " expects a seed of 0 or more");
             o.seed = static_cast<uint64_t>(s);
         }},
        {"threads", [&](const Token& t) { o.threads = in.positive(t, "a thread count", 1024); }},
        {"reverse-tiles", [&](const Token&) { o.reverseTiles = true; }},
        {"watchdog",
         [&](const Token& t) {
             const float seconds = in.number(t, "a number of seconds");
             if (!(seconds >= 0 && seconds <= 86400))
                 OptionReader::fail(t, "option " + t.text +
                                           " expects seconds from 0 (never) to 86400, got " +
                                           in.current().text);
             o.watchdogSeconds = seconds;
         }},
    };
}

/// The headless outputs' options (-o, --stats, --seeds, the inspector's) and --help.
Handlers outputOptions(RenderOptions& o, OptionReader& in) {
    return {
        {"o", [&](const Token& t) { o.outputImage = in.value(t, "an image file name").text; }},
        {"spp", [&](const Token& t) { o.spp = in.positive(t, "samples per pixel", 1 << 24); }},
        {"stats", [&](const Token& t) { o.statsFile = in.value(t, "a .json file name").text; }},
        {"seeds",
         [&](const Token& t) { o.seedCount = in.positive(t, "a number of seeds", 100000); }},
        {"inspect",
         [&](const Token& t) {
             o.inspect = true;
             o.inspectX = static_cast<int>(in.integer(t, "a pixel's X and Y"));
             o.inspectY = static_cast<int>(in.integer(t, "a pixel's X and Y"));
         }},
        {"inspect-samples",
         [&](const Token& t) { o.inspectSamples = in.positive(t, "a number of samples", 4096); }},
        {"inspect-out",
         [&](const Token& t) { o.inspectOut = in.value(t, "a .json file name").text; }},
        {"pick-test", [&](const Token&) { o.pickTest = true; }},
        {"warp-test", [&](const Token&) { o.warpTest = true; }},
        {"warp-image",
         [&](const Token& t) {
             o.warpTest = true;
             o.warpImage = in.value(t, "a .png file name").text;
         }},
        {"lobe-dump", [&](const Token& t) { o.lobeDump = in.value(t, "a file name").text; }},
        {"strategy-figure",
         [&](const Token& t) { o.strategyFigure = in.value(t, "a .png file name").text; }},
        {"warp-samples",
         [&](const Token& t) {
             o.warpSamples =
                 static_cast<uint64_t>(in.positive(t, "a number of samples", 100000000));
         }},
        {"help", [&](const Token&) { o.help = true; }},
        {"h", [&](const Token&) { o.help = true; }},
    };
}

} // namespace

RenderOptions parseRenderOptions(int argc, const char* const* argv, const ExtraOptions& extra) {
    RenderOptions o;
    OptionReader in(commandLineTokens(argc, argv));
    int scriptDepth = 0;
    IgnoredOptions ignored;
    Handlers handlers = sceneOptions(o, in, scriptDepth);
    handlers.merge(estimatorOptions(o, in));
    handlers.merge(outputOptions(o, in));

    while (!in.done()) {
        const Token& token = in.take();
        const std::string name = optionName(token.text);
        const auto handler = handlers.find(name);
        const auto extraHandler = extra.find(name);
        if (handler == handlers.end() && extraHandler != extra.end()) {
            const Token option = token;
            extraHandler->second(in, option);
            continue;
        }
        if (handler == handlers.end()) {
            const Token option = token;
            if (std::optional<std::string> skipped = skipEmbreeOnlyOption(in, option, name)) {
                ignored.add(option, std::move(*skipped));
                continue;
            }
            const std::string what =
                optionName(option.text).empty() ? "unexpected argument '" : "unknown option '";
            OptionReader::fail(option, what + option.text + "' (viewer --help lists the options)");
        }
        const Token option = token; // `token` may move when a -c script is inserted
        handler->second(option);
    }
    // As Embree reads --vd: the look-at point is the position plus the direction.
    if (o.viewDirection && o.cameraPositionSet) {
        o.camera.lookAt = o.camera.position + *o.viewDirection;
        o.cameraLookAtSet = true;
        o.viewDirection.reset();
    }
    for (const std::string& warning : ignored.warnings())
        std::fprintf(stderr, "%s\n", warning.c_str());
    return o;
}

std::string renderOptionsHelp() {
    char defaultWatchdog[16];
    std::snprintf(defaultWatchdog, sizeof defaultWatchdog, "%g", RenderWatchdog::DefaultSeconds);
    return std::string(R"(scene
  -c FILE.ecs            read options from an Embree scene script (paths relative to it)
  -i FILE.obj            add an OBJ mesh (and the .mtl files it names)
  --vp X Y Z --vi X Y Z --vu X Y Z --fov DEG
                         camera position, look-at point, up vector, vertical field of view
                         (without --vp and --vi: the whole model, from the front)
  --vd X Y Z             view direction: look at --vp + (X,Y,Z); without --vp, at the model
  --lefthanded, --righthanded
                         Embree's camera handedness: right-handed (the default) sees +x on the
                         left looking down +z with +y up; left-handed mirrors that
  --pointlight X Y Z R G B
                         a point light at (X,Y,Z) with intensity (R,G,B) in W/sr
                         (without any light: one at the camera)
  --dirlight DX DY DZ R G B
                         a directional light travelling along (DX,DY,DZ), irradiance (R,G,B)
                         in W/m² on a surface facing it (also --directionallight)
  --glossy-exponent N    every glossy material (MTL illum 2 with Ns) takes the Phong exponent N
                         instead of its own (lab 5; make sweep's exponent sweep)
  --size W H             image size in pixels (default 512 512)
estimator
)") + "  --lab NAME             " +
           labNames(" | ") + " (default " + std::string(labName(AllLabs[0])) + ")\n" +
           R"(  --solution             run the reference solution instead of your labs/ code
  --max-depth N          labs 1-3: bounces after the primary hit (default 3)
  --continue-prob P      labs 4-6: Russian-roulette continuation probability, 0<P<1 (default 0.1)
  --strategy S           lab 6: both (multiple importance sampling, the default), or light or
                         lobe alone: ctx.strategyWeight gives the other strategy weight 0
  --seed S               random seed (default 0); the image depends only on it
  --threads N            worker threads (default: all cores)
  --reverse-tiles        render the tiles last to first: the same image when the lab takes
                         every random number from ctx.sampler (how the grader checks that)
  --watchdog SECONDS     a render whose lab finishes no sample for SECONDS (an endless loop?)
                         ends with a line naming the lab and exit status 1; 0 = never
                         (default )" +
           defaultWatchdog + R"( s)
headless
  -o FILE                render --spp samples per pixel and write FILE (.exr .pfm .hdr: linear
                         radiance; .png: sRGB, clamped), no window
  --spp N                samples per pixel for -o (default 16)
  --stats FILE.json      write what was measured: time, samples/s, frame rate, rays, mean
                         radiance, noise, efficiency, the first NaN or infinite sample (with
                         the window: after --frames or at quit, the panel's figures)
  --seeds K              render K independent images, for seeds S to S+K-1: -o a.pfm writes
                         a-S.pfm ..., and --stats s.json writes s-S.json ... (one process,
                         one scene load: how the grader renders its seeds)
path inspector
  --inspect X Y          replay pixel (X,Y)'s first samples path by path: each vertex's
                         material, ray, emission and direct light added, the lab's throughput,
                         the component it picked and the probability it divided by; beside the
                         reference solution's on the same random numbers, where the build has
                         it, with the first vertex where they differ (after -o's render, or
                         alone without -o)
  --inspect-samples N    how many of the pixel's samples (default 8)
  --inspect-out FILE.json
                         write them as JSON instead of printing the table
  --pick-test            labs 2-4: replay 16 samples of each of 32x32 pixels and test, material
                         by material, how often the lab went on by each component against the
                         probability it divided by (chi-square); exit status 1 when they differ
warp test (labs 5 and 6; no scene needed)
  --warp-test            draw --warp-samples directions from the lab's sampleLobe at exponents
                         1, 12 and 60, count them over the sphere against lobePdf integrated
                         over the same cells (chi-square; a right pair fails 1 time in 1000),
                         and say what disagrees; exit status 1 when they do
  --warp-image FILE.png  also draw it: observed counts, expected counts, their difference
  --warp-samples N       directions per exponent (default 1000000)
  --lobe-dump FILE       the grader's: write what sampleLobe and lobePdf give for inputs drawn
                         from --seed, for the grader to judge against the Phong lobe
strategies (lab 6)
  --strategy-figure FILE.png
                         render the scene (-c) three times at --spp, with the light strategy
                         alone, the lobe strategy alone and both (--strategy), write the
                         three side by side, and print each one's noise figure
)";
}

} // namespace pathlab
