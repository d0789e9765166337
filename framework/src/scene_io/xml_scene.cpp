#include "pathlab/scene_io/xml_scene.h"

#include "pathlab/support/input_error.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

namespace pathlab {

namespace {

bool hasXmlExtension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension == ".xml";
}

bool startsLikeXml(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char bytes[256] = {};
    in.read(bytes, sizeof bytes);
    std::string start(bytes, static_cast<size_t>(in.gcount()));
    if (start.rfind("\xEF\xBB\xBF", 0) == 0) start.erase(0, 3);
    const size_t first = start.find_first_not_of(" \t\r\n");
    if (first == std::string::npos) return false;
    start.erase(0, first);
    return start.rfind("<?xml", 0) == 0 || start.rfind("<scene", 0) == 0;
}

} // namespace

bool isXmlScene(const std::string& path) { return hasXmlExtension(path) || startsLikeXml(path); }

void refuseXmlScene(const std::string& path) {
    if (isXmlScene(path))
        throw InputError(path + ": an Embree XML scene; PathLab reads OBJ (-i FILE.obj) and "
                                "Embree's .ecs scripts that name OBJ files, not Embree's XML "
                                "format");
}

} // namespace pathlab
