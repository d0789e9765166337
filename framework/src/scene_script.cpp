#include "pathlab/scene_script.h"

#include "pathlab/input_error.h"

#include <fstream>
#include <sstream>

namespace pathlab {

std::vector<Token> readSceneScript(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw InputError(path + ": cannot open the scene script");
    std::vector<Token> tokens;
    std::string line;
    for (int lineNumber = 1; std::getline(in, line); ++lineNumber) {
        if (const size_t hash = line.find('#'); hash != std::string::npos) line.erase(hash);
        std::istringstream words(line);
        for (std::string word; words >> word;) tokens.push_back({word, path, lineNumber});
    }
    if (in.bad()) throw InputError(path + ": read error");
    return tokens;
}

std::vector<Token> commandLineTokens(int argc, const char* const* argv) {
    std::vector<Token> tokens;
    for (int i = 1; i < argc; ++i) tokens.push_back({argv[i], "", 0});
    return tokens;
}

} // namespace pathlab
