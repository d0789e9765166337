#include "read_file.h"

#include "pathlab/input_error.h"

#include <fstream>
#include <sstream>

namespace pathlab::grader {

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot be read");
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

} // namespace pathlab::grader
