#include "pathlab/whole_file.h"

#include "pathlab/input_error.h"
#include "pathlab/this_process.h"

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

void writeFileAtomically(const std::string& path, const std::string& text) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    // The process id keeps two processes writing one file from sharing a temporary.
    const fs::path temporary = target.parent_path() / ("." + target.filename().string() + ".tmp" +
                                                       std::to_string(processId()));
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
