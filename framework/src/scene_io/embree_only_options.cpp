#include "pathlab/scene_io/embree_only_options.h"

#include <map>

namespace pathlab {

namespace {

/// Why PathLab ignores an option, where there is more to say than that it has no meaning here.
enum class Reason { None, Geometry, Depth };

struct EmbreeOnlyOption {
    int values;
    Reason reason = Reason::None;
};

/// The values each takes, as Embree's tutorial.cpp reads them (`pathtracer --help` names most;
/// where its help omits a value, as for --debug0 and --grid-res, the code is followed).
const std::map<std::string, EmbreeOnlyOption>& embreeOnlyOptions() {
    static const std::map<std::string, EmbreeOnlyOption> options = {
        // The device, the window, the shaders and the image comparison.
        {"rtcore", {1}},
        {"isa", {1}},
        {"verbose", {1}},
        {"affinity", {0}},
        {"set_affinity", {1}},
        {"start_threads", {1}},
        {"delta", {0}},
        {"compare", {1}},
        {"compare-threshold", {1}},
        {"fullscreen", {0}},
        {"print-frame-rate", {0}},
        {"print-camera", {0}},
        {"debug0", {1}},
        {"debug1", {1}},
        {"debug2", {1}},
        {"debug3", {1}},
        {"time", {1}},
        {"shader", {1}}, // and `cycles` takes a scale after it
        {"mode", {1}},
        {"coherent", {0}},
        {"incoherent", {0}},
        // The scene graph's conversions, instancing, animation and named cameras.
        {"merge-triangles-to-grids", {0}},
        {"merge-quads-to-grids", {0}},
        {"grid-res", {2}},
        {"remove-mblur", {0}},
        {"remove-non-mblur", {0}},
        {"instancing", {1}},
        {"animation", {0}},
        {"print-cameras", {0}},
        {"camera", {1}},
        // Lights PathLab has no counterpart for: an ambient light would light the rays that
        // leave the scene, which the labs return black; a distant light's R G B is radiance in
        // a cone, not irradiance, and has none in a cone of angle 0.
        {"ambientlight", {3}},
        {"ambient", {3}},
        {"distantlight", {7}},
        // The pathtracer's own.
        {"accumulate", {1}},
        {"max-path-length", {1, Reason::Depth}},
        // Geometry made from numbers rather than read from a file.
        {"animlist", {1, Reason::Geometry}},
        {"triangle-plane", {11, Reason::Geometry}},
        {"quad-plane", {11, Reason::Geometry}},
        {"grid-plane", {11, Reason::Geometry}},
        {"subdiv-plane", {12, Reason::Geometry}},
        {"hair-plane", {12, Reason::Geometry}},
        {"curve-plane", {12, Reason::Geometry}},
        {"sphere", {4, Reason::Geometry}},
        {"triangle-sphere", {5, Reason::Geometry}},
        {"quad-sphere", {5, Reason::Geometry}},
        {"grid-sphere", {5, Reason::Geometry}},
        {"triangle-sphere-mblur", {8, Reason::Geometry}},
        {"quad-sphere-mblur", {8, Reason::Geometry}},
        {"subdiv-sphere", {6, Reason::Geometry}},
        {"point-sphere", {6, Reason::Geometry}},
        {"point-sphere-mblur", {9, Reason::Geometry}},
        {"disc-sphere", {6, Reason::Geometry}},
        {"oriented-disc-sphere", {6, Reason::Geometry}},
    };
    return options;
}

const char* explanation(Reason reason) {
    switch (reason) {
    case Reason::None: return "";
    case Reason::Geometry: return " (PathLab does not generate geometry)";
    case Reason::Depth: return " (PathLab's depth is --max-depth)";
    }
    return "";
}

} // namespace

std::optional<std::string> skipEmbreeOnlyOption(OptionReader& in, const Token& option,
                                                const std::string& name) {
    EmbreeOnlyOption known{0};
    if (name.rfind("convert-", 0) == 0) {
        known = {0}; // the scene graph's conversions (--convert-triangles-to-quads, ...)
    } else {
        const auto found = embreeOnlyOptions().find(name);
        if (found == embreeOnlyOptions().end()) return std::nullopt;
        known = found->second;
    }
    std::string asWritten = option.text;
    for (int i = 0; i < known.values; ++i) {
        const std::string value = in.value(option, "a value").text;
        asWritten += " " + value;
        if (name == "shader" && value == "cycles")
            asWritten += " " + in.value(option, "a value").text;
    }
    return asWritten + explanation(known.reason);
}

void IgnoredOptions::add(const Token& option, std::string asWritten) {
    auto group = groups_.begin();
    while (group != groups_.end() && group->file != option.file) ++group;
    if (group == groups_.end())
        group = groups_.insert(groups_.end(), Group{option.file, option.line, {}});
    group->options.push_back(std::move(asWritten));
}

std::vector<std::string> IgnoredOptions::warnings() const {
    std::vector<std::string> lines;
    for (const Group& group : groups_) {
        std::string line = "warning: ";
        if (!group.file.empty()) line += group.file + ":" + std::to_string(group.firstLine) + ": ";
        line += "ignored Embree options PathLab has no meaning for: ";
        for (size_t i = 0; i < group.options.size(); ++i)
            line += (i ? ", " : "") + group.options[i];
        lines.push_back(line);
    }
    return lines;
}

} // namespace pathlab
