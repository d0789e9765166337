// PathLab reads OBJ and MTL files itself, in one pass, and builds the mesh and the materials as
// tinyobjloader 2.0.0rc10 built them when it read the kit's scenes: the expectations here were
// taken from that library, so a change to the reading that moves a vertex, cuts a face another
// way or reads a number to another last bit fails them.
#include "catch.h"
#include "test_support.h"

#include "pathlab/scene_io/obj_face_cut.h"
#include "pathlab/scene_io/obj_fields.h"
#include "pathlab/scene_io/obj_loader.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

using namespace pathlab;

namespace {

uint32_t bits(float f) {
    uint32_t u;
    std::memcpy(&u, &f, sizeof u);
    return u;
}

/// FNV-1a (64 bits) of the scene written out: each position, normal, triangle with its material
/// and material, one line each, floats as their bits in hex.
uint64_t sceneHash(const Scene& s) {
    std::string text;
    char line[256];
    for (const Vec3& p : s.positions) {
        std::snprintf(line, sizeof line, "p %08x %08x %08x\n", bits(p.x), bits(p.y), bits(p.z));
        text += line;
    }
    for (const Vec3& n : s.vertexNormals) {
        std::snprintf(line, sizeof line, "n %08x %08x %08x\n", bits(n.x), bits(n.y), bits(n.z));
        text += line;
    }
    for (size_t i = 0; i < s.triangles.size(); ++i) {
        std::snprintf(line, sizeof line, "t %u %u %u m %u\n", s.triangles[i][0], s.triangles[i][1],
                      s.triangles[i][2], s.triangleMaterials[i]);
        text += line;
    }
    for (size_t i = 0; i < s.materials.size(); ++i) {
        const Material& m = s.materials[i];
        text += "mat [" + s.materialNames[i] + "]";
        for (const auto& [key, c] : {std::pair{"Kd", m.Kd}, {"Ks", m.Ks}, {"Kt", m.Kt}}) {
            std::snprintf(line, sizeof line, " %s %08x %08x %08x", key, bits(c.r), bits(c.g),
                          bits(c.b));
            text += line;
        }
        std::snprintf(line, sizeof line, " Ni %08x Ke %08x %08x %08x\n", bits(m.Ni), bits(m.Ke.r),
                      bits(m.Ke.g), bits(m.Ke.b));
        text += line;
    }
    uint64_t hash = 0xcbf29ce484222325ull;
    for (const char c : text) hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ull;
    return hash;
}

struct Expected {
    const char* file;
    size_t triangles, vertices, materials;
    uint64_t hash;
};

} // namespace

TEST_CASE("the kit's OBJ scenes load bit for bit as tinyobjloader 2.0.0rc10 made them", "[scene]") {
    // Taken from the scenes as loaded through tinyobjloader, before PathLab read them itself.
    const Expected expected[] = {
        {"cornell_box_VI2_Specular.obj", 2230, 1150, 7, 0x6bd6d971503ec3c9ull},
        {"cornell_box_diffuse.obj", 30, 60, 3, 0xaf8788f5d7b5faf5ull},
        {"furnace.obj", 3968, 1986, 1, 0x53a3a9697005ed55ull},
        {"furnace_a08.obj", 3968, 1986, 1, 0xf5c3320f1fb17999ull},
        {"furnace_glass.obj", 4928, 2468, 2, 0x103e44e1291779aeull},
        {"furnace_mirror.obj", 4928, 2468, 2, 0xf856beca4d812b12ull},
        {"mirror_furnace.obj", 3968, 1986, 1, 0x7cbfd7bf4265cbedull},
        {"mixed_surfaces.obj", 460, 252, 5, 0x9c969b502b73faf6ull},
        {"refraction_check.obj", 2212, 1114, 3, 0x211697376f2c2232ull},
    };
    for (const Expected& e : expected) {
        INFO(e.file);
        Scene scene;
        loadObj(test::modelPath(e.file), scene);
        CHECK(scene.triangles.size() == e.triangles);
        CHECK(scene.positions.size() == e.vertices);
        CHECK(scene.materials.size() == e.materials);
        CHECK(sceneHash(scene) == e.hash);
    }
}

TEST_CASE("numbers are read by tinyobjloader's decimal parser, not rounded correctly", "[scene]") {
    // Its sum of digit x 10^-k in double lands above the float midpoint this number lies just
    // below: tinyobjloader 2.0.0rc10 read this 'v' coordinate as 0x3f0c3dcc, where strtod (or
    // strtof) and a cast give the float below.
    const char* word = "0.547817915678024192";
    const char* token = word;
    CHECK(bits(objfields::real(&token)) == 0x3f0c3dccu);
    CHECK(*token == '\0');
    CHECK(bits(static_cast<float>(std::strtod(word, nullptr))) == 0x3f0c3dcbu);
    CHECK(bits(std::strtof(word, nullptr)) == 0x3f0c3dcbu);
    const char* none = " x1";
    CHECK(objfields::real(&none, 7.0) == 7.0f); // not a number: the fallback
}

TEST_CASE("a convex face of more than 4 corners is cut by tinyobjloader's ear clipping",
          "[scene]") {
    // A regular hexagon around (10, 5): tinyobjloader 2.0.0rc10 cut it into these triangles,
    // not the fan from its first corner (its ear test depends on where the origin is).
    const std::vector<float> positions = {10.0707f, 5.9975f, 0, 9.1715f,  5.5600f, 0,
                                          9.1008f,  4.5625f, 0, 9.9293f,  4.0025f, 0,
                                          10.8285f, 4.4400f, 0, 10.8992f, 5.4375f, 0};
    std::vector<ObjCorner> face;
    for (int i = 0; i < 6; ++i) face.push_back({i, -1});
    std::vector<ObjCornerTriangle> triangles;
    cutObjFace(face, positions, triangles);
    const int expected[4][3] = {{0, 1, 2}, {3, 4, 5}, {3, 5, 0}, {0, 2, 3}};
    REQUIRE(triangles.size() == 4);
    for (size_t t = 0; t < 4; ++t)
        for (size_t k = 0; k < 3; ++k) CHECK(triangles[t][k].position == expected[t][k]);
}

TEST_CASE("a quad is cut along its shorter diagonal, v0-v2 only where strictly shorter",
          "[scene]") {
    // tinyobjloader 2.0.0rc10: the rectangle's diagonals are equal, so it is cut along v1-v3.
    const std::vector<float> positions = {0, 0, 0, 2, 0, 0, 2, 1, 0, 0, 1, 0};
    std::vector<ObjCornerTriangle> triangles;
    cutObjFace({{0, -1}, {1, -1}, {2, -1}, {3, -1}}, positions, triangles);
    REQUIRE(triangles.size() == 2);
    CHECK(triangles[0][0].position == 0);
    CHECK(triangles[0][1].position == 1);
    CHECK(triangles[0][2].position == 3);
    CHECK(triangles[1][0].position == 1);
    CHECK(triangles[1][1].position == 2);
    CHECK(triangles[1][2].position == 3);
}

TEST_CASE("MTL values as tinyobjloader read them: map_Kd's 0.6 per file, a name's first "
          "definition",
          "[scene]") {
    // tinyobjloader 2.0.0rc10 gives a material with map_Kd a Kd of 0.6 only where no Kd line
    // came before in the same file (its flag is never reset at 'newmtl'), and a 'usemtl' of a
    // name defined twice selects the first definition.
    const std::string dir = test::temporaryFolder("obj-bit-identity");
    std::ofstream(dir + "/m.mtl") << "newmtl a\nKd 0.2 0.2 0.2\nnewmtl b\nmap_Kd t.png\n";
    std::ofstream(dir + "/n.mtl") << "newmtl c\nmap_Kd t.png\nnewmtl a\nKd 0.9 0.9 0.9\n";
    std::ofstream(dir + "/a.obj") << "mtllib m.mtl n.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                     "usemtl b\nf 1 2 3\nusemtl c\nf 1 2 3\nusemtl a\nf 1 2 3\n";
    Scene scene;
    loadObj(dir + "/a.obj", scene);
    REQUIRE(scene.materials.size() == 4);
    CHECK(scene.materialNames == std::vector<std::string>{"a", "b", "c", "a"});
    CHECK(scene.materials[1].Kd.r == 0.0f);              // b: m.mtl had a Kd before
    CHECK(bits(scene.materials[2].Kd.r) == 0x3f19999au); // c: 0.6f, none before in n.mtl
    CHECK(scene.triangleMaterials == std::vector<uint32_t>{1, 2, 0});
}
