#include "bench_options.h"

#include "pathlab/support/input_error.h"
#include "pathlab/support/parse_number.h"

#include <charconv>
#include <cmath>
#include <functional>
#include <map>
#include <string_view>

namespace pathlab::bench {

namespace {

class Arguments {
public:
    Arguments(int argc, const char* const* argv) : argc_(argc), argv_(argv) {}
    bool done() const { return next_ >= argc_; }
    std::string_view take() { return argv_[next_++]; }

    std::string text(std::string_view option) {
        if (done()) throw InputError("option " + std::string(option) + " needs a value");
        return std::string(take());
    }
    int integer(std::string_view option, int min, int max) {
        const std::string t = text(option);
        int v = 0;
        auto [end, error] = std::from_chars(t.data(), t.data() + t.size(), v);
        if (error != std::errc() || end != t.data() + t.size() || v < min || v > max)
            throw InputError("option " + std::string(option) + " expects an integer from " +
                             std::to_string(min) + " to " + std::to_string(max) + ", got '" + t +
                             "'");
        return v;
    }
    /// A comma-separated list of integers from min to max, like 2,4,8.
    std::vector<int> integers(std::string_view option, int min, int max) {
        const std::string t = text(option);
        std::vector<int> values;
        for (std::string_view piece : splitAt(t, ',')) {
            int v = 0;
            auto [end, error] = std::from_chars(piece.data(), piece.data() + piece.size(), v);
            if (error != std::errc() || end != piece.data() + piece.size() || v < min || v > max)
                throw InputError("option " + std::string(option) + " expects integers from " +
                                 std::to_string(min) + " to " + std::to_string(max) +
                                 " separated by commas, like 2,4,8, got '" + t + "'");
            values.push_back(v);
        }
        return values;
    }
    float number(std::string_view option, float min, float max) {
        const std::string t = text(option);
        const float v = parseFloat(t).value_or(std::nanf(""));
        if (!(v > min && v < max))
            throw InputError("option " + std::string(option) + " expects a number in (" +
                             std::to_string(min) + ", " + std::to_string(max) + "), got '" + t +
                             "'");
        return v;
    }

private:
    int argc_;
    const char* const* argv_;
    int next_ = 1;
};

} // namespace

BenchOptions parseBenchOptions(int argc, const char* const* argv) {
    BenchOptions o;
    Arguments in(argc, argv);
    // Each option reads its values (if any) from `in`; `name` is how it was spelled.
    using Reader = std::function<void(std::string_view name)>;
    const std::map<std::string_view, Reader> readers = {
        {"--scene", [&](auto name) { o.scenes.push_back(in.text(name)); }},
        {"--size",
         [&](auto name) {
             o.width = in.integer(name, 1, 16384);
             o.height = in.integer(name, 1, 16384);
         }},
        {"--spp", [&](auto name) { o.spp = in.integer(name, 1, 1 << 20); }},
        {"--passes", [&](auto name) { o.passes = in.integer(name, 1, 1000); }},
        {"--threads", [&](auto name) { o.threads = in.integer(name, 1, 1024); }},
        {"--max-depth", [&](auto name) { o.parameters.maxDepth = in.integer(name, 0, 1000); }},
        {"--continue-prob", [&](auto name) { o.parameters.continueProb = in.number(name, 0, 1); }},
        {"--json", [&](auto name) { o.jsonFile = in.text(name); }},
        {"--pathtracer", [&](auto name) { o.pathtracer = in.text(name); }},
        {"--no-pathtracer", [&](auto) { o.pathtracer.clear(); }},
        {"--peer-scene", [&](auto name) { o.peerScene = in.text(name); }},
        {"--peer-light-scale", [&](auto name) { o.peerLightScale = in.number(name, 0, 1e6f); }},
        {"--peer-spp", [&](auto name) { o.peerSpp = in.integer(name, 1, 1 << 20); }},
        {"--peer-image-spp", [&](auto name) { o.peerImageSpp = in.integer(name, 1, 1 << 20); }},
        {"--peer-path-lengths", [&](auto name) { o.peerPathLengths = in.integers(name, 1, 64); }},
        {"--peer-only", [&](auto) { o.peerOnly = true; }},
        {"--first-frame-runs", [&](auto name) { o.firstFrameRuns = in.integer(name, 0, 100); }},
        {"--memory-size",
         [&](auto name) {
             o.memoryWidth = in.integer(name, 1, 16384);
             o.memoryHeight = in.integer(name, 1, 16384);
         }},
        {"--memory-frames", [&](auto name) { o.memoryFrames = in.integer(name, 0, 1 << 20); }},
        {"--memory-probe", [&](auto) { o.memoryProbe = true; }},
        {"--help", [&](auto) { o.help = true; }},
        {"-h", [&](auto) { o.help = true; }},
    };
    while (!in.done()) {
        const std::string_view option = in.take();
        const auto reader = readers.find(option);
        if (reader == readers.end())
            throw InputError("unknown option '" + std::string(option) +
                             "' (bench --help lists them)");
        reader->second(option);
    }
    return o;
}

const char* benchOptionsHelp() {
    return R"(usage: bench [options]

Measures how fast PathLab renders next to Embree's own ray traversal, and next to Embree's
pathtracer, and prints one table per scene. Speed is compared by CPU time, which other programs
on the machine change little; wall-clock figures stand beside it, and scaling is wall-clock.

  --scene FILE.ecs       scene to measure (repeatable; default models/cornell_box_VI2_Specular.ecs)
  --size W H             image size of the timed renders (default 512 512)
  --spp N                samples per pixel of one timed pass (default 2)
  --passes N             timed passes after one warm-up pass; the one of least CPU time
                         counts (the fastest by wall-clock time in the scaling; default 3)
  --threads N            threads of the multi-threaded figures (default: all cores)
  --max-depth N          labs 1-3 (default 3)
  --continue-prob P      lab 4 (default 0.1)
  --json FILE            also write the results as JSON
Embree's pathtracer (package embree-tools)
  --pathtracer PROGRAM   its executable (default: )" PATHLAB_EMBREE_PATHTRACER R"( in PATH)
  --no-pathtracer        skip the comparison
  --peer-scene FILE.ecs  its scene (default )" PATHLAB_EMBREE_MODELS_DIR R"(/cornell_box.ecs)
  --peer-light-scale S   scales the scene's point lights so the 8-bit output does not clip
                         (default 0.1)
  --peer-spp N           samples per pixel of one timed frame (default 4); the frames'
                         CPU time is a run's of --passes frames less a run's of none
  --peer-image-spp N     samples per pixel of the images whose means are compared (default 16)
  --peer-path-lengths L,...
                         Embree's path lengths to compare at, PathLab's importance solution
                         at max-depth L-1 (default 2,4,8)
  --peer-only            measure only the comparison with Embree's pathtracer
The viewer's first frame
  --first-frame-runs N   starts of the viewer's window under xvfb-run, timed from the
                         program's start to its first frame and its first image on screen;
                         the median counts (default 3; 0 skips them)
Memory
  --memory-size W H      size of the progressive render whose peak memory is measured
                         (default 1920 1080)
  --memory-frames N      frames it renders (default 8; 0 skips the measurement)
)";
}

} // namespace pathlab::bench
