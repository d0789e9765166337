#include "pathlab/support/whole_file.h"

#include "pathlab/support/input_error.h"
#include "pathlab/support/this_process.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace pathlab {

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot be read");
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

namespace {

namespace fs = std::filesystem;

/// Where `target` is written before the rename: beside it, so the rename stays in one file
/// system. The process id keeps two processes writing one file from sharing a temporary.
fs::path temporaryFor(const fs::path& target) {
    return target.parent_path() /
           ("." + target.filename().string() + ".tmp" + std::to_string(processId()));
}

} // namespace

void checkWritable(const std::string& path) {
    const fs::path temporary = temporaryFor(path);
    const bool created = std::ofstream(temporary, std::ios::binary).good();
    std::error_code ignored;
    fs::remove(temporary, ignored);
    if (!created) throw InputError(path + ": cannot write the file (is its folder there?)");
}

void writeFileAtomically(const std::string& path, const std::string& text) {
    const fs::path target(path);
    const fs::path temporary = temporaryFor(target);
    {
        std::ofstream out(temporary, std::ios::binary);
        out << text;
        out.close();
        if (!out) {
            std::error_code ignored;
            fs::remove(temporary, ignored);
            throw InputError(path + ": cannot write the file");
        }
    }
    std::error_code error;
    fs::rename(temporary, target, error);
    if (error) {
        fs::remove(temporary, error);
        throw InputError(path + ": cannot move the finished file into place");
    }
}

} // namespace pathlab
