#include "pathlab/inspect/inspection_json.h"

#include "pathlab/support/input_error.h"

#include <nlohmann/json.hpp>

namespace pathlab {

namespace {

using nlohmann::json;

json rgb(const Color& c) { return json::array({c.r, c.g, c.b}); }
json xyz(const Vec3& v) { return json::array({v.x, v.y, v.z}); }
template <typename T> json optional(const std::optional<T>& value) {
    return value ? json(*value) : json(nullptr);
}
json optionalColor(const std::optional<Color>& c) { return c ? rgb(*c) : json(nullptr); }

Lab labOf(const std::string& name, const std::string& source) {
    if (const std::optional<Lab> lab = labFromName(name)) return *lab;
    throw InputError(source + ": the lab \"" + name + "\" is none of this kit's (" +
                     labNames(", ") + ")");
}

Implementation implementationOf(const std::string& name, const std::string& source) {
    for (Implementation impl : {Implementation::Student, Implementation::Solution})
        if (implementationName(impl) == name) return impl;
    throw InputError(source + ": \"" + name + "\" is neither \"student\" nor \"solution\"");
}

Color colorOf(const json& j) {
    return {j.at(0).get<float>(), j.at(1).get<float>(), j.at(2).get<float>()};
}
Vec3 vec3Of(const json& j) {
    return {j.at(0).get<float>(), j.at(1).get<float>(), j.at(2).get<float>()};
}
std::optional<Color> optionalColorOf(const json& j) {
    return j.is_null() ? std::nullopt : std::optional<Color>(colorOf(j));
}

json vertexJson(const InspectedVertex& v) {
    json continued = json::array();
    for (const PathContinuation& c : v.continuedBy)
        continued.push_back({{"child", c.child},
                             {"component", c.component},
                             {"probability", optional(c.probability)},
                             {"weighted_by", c.weightedBy.empty() ? json() : json(c.weightedBy)}});
    json roulette = nullptr;
    if (v.roulette)
        roulette = {{"draw", v.roulette->draw},
                    {"continue_prob", v.roulette->continueProb},
                    {"went_on", v.roulette->wentOn}};
    json shadow = nullptr;
    if (v.shadowRay) shadow = {{"from", xyz(v.shadowRay->from)}, {"to", xyz(v.shadowRay->to)}};
    const PathContinuation* first = v.continuedBy.empty() ? nullptr : &v.continuedBy.front();
    return {{"index", v.index},
            {"parent", v.parent},
            {"depth", v.depth},
            {"arrived_by", v.arrivedBy},
            {"origin", xyz(v.ray.origin)},
            {"direction", xyz(v.ray.direction)},
            {"found", v.found},
            {"position", xyz(v.position)},
            {"material",
             {{"Kd", rgb(v.material.Kd)},
              {"Ks", rgb(v.material.Ks)},
              {"Kt", rgb(v.material.Kt)},
              {"Ke", rgb(v.material.Ke)},
              {"Ni", v.material.Ni}}},
            {"emitted", rgb(v.emitted)},
            {"throughput", optionalColor(v.throughput)},
            {"linear", v.linear},
            {"emission_weight", optionalColor(v.emissionWeight)},
            {"emission_added", rgb(v.emissionAdded)},
            {"direct_light_called", v.directLightCalled},
            {"direct_light", rgb(v.directLight)},
            {"direct_light_added", rgb(v.directLightAdded)},
            {"shadow_ray", shadow},
            {"draws", v.draws},
            {"component", first ? json(first->component) : json(nullptr)},
            {"probability", first ? optional(first->probability) : json(nullptr)},
            {"continued_by", continued},
            {"roulette", roulette}};
}

json inspectionObject(const PixelInspection& inspection) {
    json samples = json::array();
    for (const InspectedSample& s : inspection.samples) {
        json vertices = json::array(), calls = json::array();
        for (const InspectedVertex& v : s.vertices) vertices.push_back(vertexJson(v));
        for (const InspectedCall& c : s.calls)
            calls.push_back({{"type", c.type}, {"vertex", c.vertex}, {"draws", c.drawsBefore}});
        samples.push_back({{"index", s.index},
                           {"contribution", rgb(s.contribution)},
                           {"vertices", vertices},
                           {"calls", calls}});
    }
    const RenderIdentity& identity = inspection.identity;
    return {{"lab", labName(identity.lab)},
            {"impl", implementationName(identity.implementation)},
            {"pixel", {inspection.x, inspection.y}},
            {"seed", identity.seed},
            {"max_depth", identity.parameters.maxDepth},
            {"continue_prob", identity.parameters.continueProb},
            {"uses_roulette", inspection.usesRoulette},
            {"samples", samples}};
}

InspectedVertex vertexOf(const json& j) {
    InspectedVertex v;
    v.index = j.at("index").get<int>();
    v.parent = j.at("parent").get<int>();
    v.depth = j.at("depth").get<int>();
    v.arrivedBy = j.at("arrived_by").get<std::string>();
    v.ray = {vec3Of(j.at("origin")), vec3Of(j.at("direction")), RayKind::Camera};
    v.found = j.at("found").get<bool>();
    v.position = vec3Of(j.at("position"));
    const json& m = j.at("material");
    v.material = {colorOf(m.at("Kd")), colorOf(m.at("Ks")), colorOf(m.at("Kt")),
                  m.at("Ni").get<float>(), colorOf(m.at("Ke"))};
    v.emitted = colorOf(j.at("emitted"));
    v.throughput = optionalColorOf(j.at("throughput"));
    v.linear = j.value("linear", true);
    v.emissionWeight = optionalColorOf(j.at("emission_weight"));
    v.emissionAdded = colorOf(j.at("emission_added"));
    v.directLightCalled = j.at("direct_light_called").get<bool>();
    v.directLight = colorOf(j.at("direct_light"));
    v.directLightAdded = colorOf(j.at("direct_light_added"));
    if (!j.at("shadow_ray").is_null())
        v.shadowRay = ShadowSegment{vec3Of(j.at("shadow_ray").at("from")),
                                    vec3Of(j.at("shadow_ray").at("to"))};
    v.draws = j.at("draws").get<std::vector<float>>();
    for (const json& c : j.at("continued_by"))
        v.continuedBy.push_back(
            {c.at("child").get<int>(), c.at("component").get<std::string>(),
             c.at("probability").is_null() ? std::nullopt
                                           : std::optional<float>(c.at("probability").get<float>()),
             c.value("weighted_by", json()).is_string() ? c.at("weighted_by").get<std::string>()
                                                        : std::string()});
    if (!j.at("roulette").is_null())
        v.roulette = RouletteDraw{j.at("roulette").at("draw").get<float>(),
                                  j.at("roulette").at("continue_prob").get<float>(),
                                  j.at("roulette").at("went_on").get<bool>()};
    return v;
}

} // namespace

std::string inspectionJson(const PixelInspection& lab, const PixelInspection* reference,
                           const PathComparison* comparison) {
    json out = inspectionObject(lab);
    if (reference) out["reference"] = inspectionObject(*reference);
    if (comparison) {
        json divergence = nullptr;
        if (const auto& d = comparison->divergence)
            divergence = {{"sample", lab.samples[d->sample].index},
                          {"vertex", d->vertex},
                          {"kind", d->kind},
                          {"step", d->step},
                          {"text", d->text}};
        out["comparison"] = {{"samples_compared", comparison->samplesCompared},
                             {"comparable", comparison->comparable},
                             {"divergence", divergence},
                             {"summary", describeComparison(*comparison, lab)}};
    }
    return out.dump(1) + "\n";
}

namespace {

/// What the inspector writes, and nothing else: the indices within the sample's vertices, the
/// names among those it uses, the samples numbered in order. The grader reads a file a lab's
/// process wrote, and its comparison indexes vertices by these numbers and quotes these names.
void checkWritten(const PixelInspection& inspection, const std::string& source) {
    const auto fail = [&](const std::string& what) {
        throw InputError(source + ": not a path inspector's JSON (" + what + ")");
    };
    const auto oneOf = [](const std::string& name, std::initializer_list<const char*> names) {
        for (const char* n : names)
            if (name == n) return true;
        return false;
    };
    for (size_t s = 0; s < inspection.samples.size(); ++s) {
        const InspectedSample& sample = inspection.samples[s];
        const int count = static_cast<int>(sample.vertices.size());
        if (sample.index != s) fail("sample " + std::to_string(s) + " is numbered otherwise");
        for (int i = 0; i < count; ++i) {
            const InspectedVertex& v = sample.vertices[static_cast<size_t>(i)];
            if (v.index != i || v.parent < -1 || v.parent >= i)
                fail("vertex " + std::to_string(i) + "'s index or parent");
            if (!oneOf(v.arrivedBy, {"camera", "diffuse", "mirror", "refraction", "specular",
                                     "glossy", "unknown"}))
                fail("vertex " + std::to_string(i) + " arrived by no ray the inspector names");
            for (const PathContinuation& c : v.continuedBy)
                if (c.child <= i || c.child >= count ||
                    !oneOf(c.component,
                           {"diffuse", "mirror", "refraction", "specular", "glossy", "unknown"}) ||
                    !oneOf(c.weightedBy, {"", "Kd", "Ks", "Kt"}))
                    fail("vertex " + std::to_string(i) + "'s continuation");
        }
        // A trace names the vertex it found, an end none, a light either.
        for (const InspectedCall& call : sample.calls)
            if (call.vertex < -1 || call.vertex >= count ||
                !oneOf(call.type, {"trace", "light", "end"}) ||
                (call.type == "trace" && call.vertex < 0) ||
                (call.type == "end" && call.vertex != -1))
                fail("a call of sample " + std::to_string(s));
    }
}

} // namespace

PixelInspection readInspectionJson(const std::string& text, const std::string& source) {
    // Far above any replay's (64 samples of a few vertices: tens of kilobytes).
    constexpr size_t MaxBytes = 8 << 20;
    if (text.size() > MaxBytes)
        throw InputError(source + ": not a path inspector's JSON (" + std::to_string(text.size()) +
                         " bytes)");
    try {
        const json j = json::parse(text);
        PixelInspection inspection;
        RenderIdentity& identity = inspection.identity;
        identity.lab = labOf(j.at("lab").get<std::string>(), source);
        identity.implementation = implementationOf(j.at("impl").get<std::string>(), source);
        inspection.x = j.at("pixel").at(0).get<int>();
        inspection.y = j.at("pixel").at(1).get<int>();
        identity.seed = j.at("seed").get<uint64_t>();
        identity.parameters.maxDepth = j.at("max_depth").get<int>();
        identity.parameters.continueProb = j.at("continue_prob").get<float>();
        inspection.usesRoulette = j.at("uses_roulette").get<bool>();
        for (const json& s : j.at("samples")) {
            InspectedSample sample;
            sample.index = s.at("index").get<uint64_t>();
            sample.contribution = colorOf(s.at("contribution"));
            for (const json& v : s.at("vertices")) sample.vertices.push_back(vertexOf(v));
            for (const json& c : s.at("calls"))
                sample.calls.push_back({c.at("type").get<std::string>(), c.at("vertex").get<int>(),
                                        c.at("draws").get<std::vector<float>>()});
            inspection.samples.push_back(std::move(sample));
        }
        checkWritten(inspection, source);
        return inspection;
    } catch (const json::exception& error) {
        throw InputError(source + ": not a path inspector's JSON (" + error.what() + ")");
    }
}

} // namespace pathlab
