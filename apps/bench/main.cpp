// bench: how fast PathLab renders next to Embree's raw traversal and Embree's own pathtracer.
// Run `bench --help` for the options; `make bench` runs it on the VI2 Cornell box.
#include "bench_options.h"
#include "bench_report.h"
#include "bench_scene.h"
#include "first_frame.h"
#include "memory_probe.h"
#include "peer_comparison.h"
#include "scaling_measurement.h"
#include "scene_measurement.h"

#include "pathlab/support/input_error.h"
#include "pathlab/support/program_main.h"
#include "pathlab/render/renderer.h"
#include "pathlab/render/render_stats.h"
#include "pathlab/support/this_process.h"
#include "pathlab/support/whole_file.h"

#include <cstdio>
#include <filesystem>

namespace {

using namespace pathlab;
using namespace pathlab::bench;

/// The VI2 box beside this program (the build folder links models/), or as run from the source.
std::string defaultScene() {
    const std::string name = "models/cornell_box_VI2_Specular.ecs";
    const std::filesystem::path beside = thisProgram().parent_path() / name;
    return std::filesystem::exists(beside) ? beside.string() : name;
}

/// The scenes to measure: those named with --scene, or the VI2 box and Embree's Cornell box (as
/// the comparison with Embree's pathtracer renders it) when it is installed.
std::vector<BenchScene> scenesToMeasure(const BenchOptions& options) {
    std::vector<BenchScene> scenes;
    for (const std::string& file : options.scenes) scenes.push_back(sceneFromFile(file));
    if (scenes.empty()) {
        scenes.push_back(sceneFromFile(defaultScene()));
        if (std::filesystem::is_regular_file(options.peerScene))
            scenes.push_back(peerSceneFromFile(options.peerScene, options.peerLightScale));
    }
    return scenes;
}

int runBench(BenchOptions options) {
    const std::vector<BenchScene> scenes = scenesToMeasure(options);
    if (options.memoryProbe) return runMemoryProbe(scenes.front(), options);
    const int threads = options.threads > 0 ? options.threads : Renderer::defaultThreads();
    if (!options.jsonFile.empty()) checkWritable(options.jsonFile);

    BenchReport report;
    if (!options.peerOnly) {
        const SceneSettings settings{options.width,  options.height, options.spp,
                                     options.passes, threads,        options.parameters};
        for (const BenchScene& scene : scenes) {
            std::fprintf(stderr, "bench: measuring %s ...\n", scene.name.c_str());
            report.scenes.push_back(measureScene(scene, settings));
        }
    }
    for (int pathLength : options.peerPathLengths) {
        report.peers.push_back(comparePeer(options, threads, pathLength));
    }
    report.memory.note = "not measured (--peer-only)";
    report.firstFrame.note = "not measured (--peer-only)";
    if (!options.peerOnly) {
        std::fprintf(stderr, "bench: scaling ...\n");
        const SceneSettings settings{options.width,  options.height, 1,
                                     options.passes, threads,        options.parameters};
        report.scaling.push_back(measureScaling(scenes.front(), settings, Lab::Roulette, threads));
        report.firstFrame = measureFirstFrame((thisProgram().parent_path() / "viewer").string(),
                                              scenes.front(), options.firstFrameRuns);
        report.memory = measurePeakMemory(thisProgram(), scenes.front(), options);
    }
    printReport(report, stdout);
    if (!options.jsonFile.empty()) writeFileAtomically(options.jsonFile, reportJson(report));
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    return runMain("bench", [&] {
        const BenchOptions options = parseBenchOptions(argc, argv);
        if (options.help) {
            std::fputs(benchOptionsHelp(), stdout);
            return 0;
        }
        return runBench(options);
    });
}
