#pragma once
/// Options of Embree's tutorials (its pathtracer and the .ecs scripts written for it) that
/// PathLab has no meaning for: their values are skipped, so that the options after them still
/// read, and they are named in one warning per script rather than stopping it.

#include "pathlab/scene_io/option_reader.h"
#include "pathlab/scene_io/scene_script.h"

#include <optional>
#include <string>
#include <vector>

namespace pathlab {

/// If `name` (without dashes) is one of Embree's options PathLab ignores, reads its values and
/// returns how the warning names it: as written, values included, with a word on why where
/// PathLab has something close ("--max-path-length 8 (PathLab's depth is --max-depth)").
std::optional<std::string> skipEmbreeOnlyOption(OptionReader& in, const Token& option,
                                                const std::string& name);

/// The ignored options, grouped by the script that gave them (the command line is one group).
class IgnoredOptions {
public:
    void add(const Token& option, std::string asWritten);

    /// One line per script, in the order they were read: "warning: FILE:LINE: ignored Embree
    /// options PathLab has no meaning for: --shader uv, --compare-threshold 700", LINE the first
    /// one's; on the command line without FILE:LINE.
    std::vector<std::string> warnings() const;

private:
    struct Group {
        std::string file;
        int firstLine = 0;
        std::vector<std::string> options;
    };
    std::vector<Group> groups_;
};

} // namespace pathlab
