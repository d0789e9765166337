#include "pathlab/scene_io/scene_script.h"

#include "pathlab/support/text_file.h"

#include <sstream>

namespace pathlab {

std::vector<Token> readSceneScript(const std::string& path) {
    // UTF-16 and a byte-order mark are what a Windows editor's "Unicode" writes.
    const std::string text = readTextFile(path, "the scene script");
    std::vector<Token> tokens;
    int lineNumber = 0;
    for (const std::string_view textLine : textLines(text)) {
        ++lineNumber;
        std::string line(textLine.substr(0, textLine.find('#')));
        std::istringstream words(line);
        for (std::string word; words >> word;) tokens.push_back({word, path, lineNumber});
    }
    return tokens;
}

std::vector<Token> commandLineTokens(int argc, const char* const* argv) {
    std::vector<Token> tokens;
    for (int i = 1; i < argc; ++i) tokens.push_back({argv[i], "", 0});
    return tokens;
}

} // namespace pathlab
