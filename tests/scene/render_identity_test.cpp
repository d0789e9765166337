// One render's identity (lab, implementation, parameters, seed, size) crosses into a child viewer
// as arguments written once (renderIdentityArguments) and read once (parseRenderOptions): every
// part of it arrives as it was sent, continueProb to the float's last bit.
#include "catch.h"

#include "pathlab/render/render_identity.h"
#include "pathlab/render/render_options.h"

#include <cmath>
#include <string>
#include <vector>

using namespace pathlab;

namespace {

RenderIdentity readBack(const RenderIdentity& sent) {
    const std::vector<std::string> arguments = renderIdentityArguments(sent);
    std::vector<const char*> argv = {"viewer"};
    for (const std::string& a : arguments) argv.push_back(a.c_str());
    return parseRenderOptions(static_cast<int>(argv.size()), argv.data());
}

} // namespace

TEST_CASE("a render's identity read back from its arguments is the one sent", "[scene]") {
    RenderIdentity sent;
    sent.lab = AllLabs.back();
    sent.implementation = Implementation::Solution;
    sent.parameters = {7, 0.1234567f};
    sent.seed = 1234567890123ull;
    sent.width = 97;
    sent.height = 31;
    const RenderIdentity received = readBack(sent);
    CHECK(received == sent);
    // Six decimals (std::to_string) would have sent 0.123457.
    CHECK(received.parameters.continueProb == 0.1234567f);
    sent.implementation = Implementation::Student;
    CHECK(readBack(sent) == sent);
}

TEST_CASE("every continueProb a float holds in (0, 1) survives the arguments", "[scene]") {
    // The floats next to 0.8 and to the smallest probabilities, where rounding would show first.
    for (float p : {0.8f, std::nextafter(0.8f, 1.0f), std::nextafter(0.8f, 0.0f), 1e-7f,
                    std::nextafter(1.0f, 0.0f), 0.1f}) {
        RenderIdentity sent;
        sent.parameters.continueProb = p;
        CHECK(readBack(sent).parameters.continueProb == p);
    }
}
