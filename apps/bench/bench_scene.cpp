#include "bench_scene.h"

#include "pathlab/support/input_error.h"
#include "pathlab/support/parse_number.h"
#include "pathlab/scene_io/scene_script.h"

#include <cstdio>
#include <filesystem>

namespace pathlab::bench {

namespace {

namespace fs = std::filesystem;

std::string scaled(const Token& value, float scale) {
    const std::optional<float> v = parseFloat(value.text);
    if (!v)
        throw inputErrorAt(value.file, value.line,
                           "expected a light intensity, got '" + value.text + "'");
    char text[32];
    std::snprintf(text, sizeof text, "%g", *v * scale);
    return text;
}

} // namespace

BenchScene sceneFromFile(const std::string& ecsFile) {
    return {fs::path(ecsFile).stem().string(), ecsFile, {"-c", ecsFile}};
}

BenchScene peerSceneFromFile(const std::string& ecsFile, float lightScale) {
    const std::vector<Token> tokens = readSceneScript(ecsFile);
    BenchScene scene{fs::path(ecsFile).stem().string(), ecsFile, {}};
    for (size_t i = 0; i < tokens.size(); ++i) {
        const std::string& t = tokens[i].text;
        scene.arguments.push_back(t);
        if ((t == "-i" || t == "--i") && i + 1 < tokens.size()) {
            const fs::path file(tokens[++i].text);
            scene.arguments.push_back(file.is_absolute()
                                          ? file.string()
                                          : fs::absolute(fs::path(ecsFile).parent_path() / file)
                                                .lexically_normal()
                                                .string());
        } else if (t == "-pointlight" || t == "--pointlight") {
            if (i + 6 >= tokens.size())
                throw inputErrorAt(tokens[i].file, tokens[i].line, t + " needs x y z r g b");
            for (int k = 0; k < 3; ++k) scene.arguments.push_back(tokens[++i].text);
            for (int k = 0; k < 3; ++k) scene.arguments.push_back(scaled(tokens[++i], lightScale));
        }
    }
    return scene;
}

RenderOptions renderOptionsFor(const BenchScene& scene, int width, int height) {
    std::vector<const char*> argv = {"bench"};
    for (const std::string& a : scene.arguments) argv.push_back(a.c_str());
    RenderOptions options = parseRenderOptions(static_cast<int>(argv.size()), argv.data());
    options.width = width;
    options.height = height;
    return options;
}

} // namespace pathlab::bench
