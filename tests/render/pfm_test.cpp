// PFM, read and written without the image-file plug-in: against bytes laid out by hand from the
// format's definition (header "PF\nW H\nscale\n", 32-bit floats, rows bottom-up, the scale's sign
// giving the byte order), and broken files refused with the file named.
#include "catch.h"
#include "messages.h"
#include "test_support.h"

#include "pathlab/images/image_io.h"
#include "pathlab/support/input_error.h"
#include "pathlab/support/whole_file.h"

#include <cstdint>
#include <cstring>
#include <fstream>

using namespace pathlab;

namespace {

void writeBytes(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

/// A float's four bytes, little- or big-endian, whatever this machine's order.
std::string floatBytes(float v, bool bigEndian) {
    uint32_t bits;
    std::memcpy(&bits, &v, 4);
    std::string out(4, '\0');
    for (int i = 0; i < 4; ++i)
        out[bigEndian ? 3 - i : i] = static_cast<char>((bits >> (8 * i)) & 0xff);
    return out;
}

std::string errorReading(const std::string& path) {
    return messageOf<InputError>([&] { readImage(path); });
}

} // namespace

TEST_CASE("a PFM is written as the format defines it: bottom row first, little-endian",
          "[render][images]") {
    const std::string dir = test::temporaryFolder("pfm-write");
    // 2x2: top row (1, 2), bottom row (3, 4), grey.
    writeImage(dir + "/w.pfm", 2, 2, {1, 1, 1, 2, 2, 2, 3, 3, 3, 4, 4, 4});
    std::string expected = "PF\n2 2\n-1.0\n";
    for (float v : {3.f, 4.f, 1.f, 2.f})
        for (int c = 0; c < 3; ++c) expected += floatBytes(v, false);
    CHECK(readFile(dir + "/w.pfm") == expected);
}

TEST_CASE("a PFM is read in either byte order, in colour or grey", "[render][images]") {
    const std::string dir = test::temporaryFolder("pfm-read");
    std::string big = "PF\n1 2\n1.0\n"; // positive scale: big-endian; bottom row first
    for (float v : {0.25f, 0.5f, 0.75f, 1.5f, 2.5f, 3.5f}) big += floatBytes(v, true);
    writeBytes(dir + "/big.pfm", big);
    const Image colour = readImage(dir + "/big.pfm");
    REQUIRE(colour.width == 1);
    REQUIRE(colour.height == 2);
    CHECK(colour.rgb == std::vector<float>{1.5f, 2.5f, 3.5f, 0.25f, 0.5f, 0.75f});
    std::string grey = "Pf\n2 1\n-1\n" + floatBytes(7, false) + floatBytes(8, false);
    writeBytes(dir + "/grey.pfm", grey);
    CHECK(readImage(dir + "/grey.pfm").rgb == std::vector<float>{7, 7, 7, 8, 8, 8});
}

TEST_CASE("a broken PFM is refused, naming the file and the fault", "[render][images][bad-input]") {
    const std::string dir = test::temporaryFolder("pfm-bad");
    writeBytes(dir + "/short.pfm", "PF\n2 2\n-1.0\n" + floatBytes(1, false));
    CHECK(errorReading(dir + "/short.pfm") ==
          dir + "/short.pfm: cannot read the image: the file ends before its pixels do");
    writeBytes(dir + "/header.pfm", "P6\n2 2\n255\n");
    CHECK(errorReading(dir + "/header.pfm")
              .find(dir + "/header.pfm: cannot read the image: not a PFM header") == 0);
    writeBytes(dir + "/huge.pfm", "PF\n100000 100000\n-1.0\n");
    CHECK(errorReading(dir + "/huge.pfm").find("not a PFM header") != std::string::npos);
    CHECK(errorReading(dir + "/missing.pfm").find(dir + "/missing.pfm: cannot read the image") ==
          0);
}
