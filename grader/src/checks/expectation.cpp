#include "checks/expectation.h"

#include "checks/hypothesis_tests.h"
#include "checks/rays_per_sample.h"
#include "checks/run_limits.h"
#include "checks/seed_variance.h"
#include "common/content_hash.h"
#include "common/scene_files.h"

#include "pathlab/images/image_io.h"
#include "pathlab/support/input_error.h"
#include "pathlab/render/render_stats.h"
#include "pathlab/support/whole_file.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace pathlab::grader {

namespace {

Expectation measure(const LabRunner& solution, const std::string& scene, Lab lab,
                    const Rubric& rubric, int seeds, int spp, const std::string& scratch,
                    const std::function<void()>& step) {
    Expectation e;
    e.solution = std::string(labName(lab));
    e.seeds = seeds;
    e.spp = spp;
    std::vector<std::vector<double>> perRegion;
    std::vector<double> imageSum;
    for (int s = 0; s < seeds; ++s) {
        RenderRequest r{&solution,
                        scene,
                        requestedIdentity(solution, lab, {rubric.maxDepth, rubric.continueProb},
                                          static_cast<uint64_t>(1000000 + s), rubric.width,
                                          rubric.height),
                        spp,
                        1,
                        0,
                        scratch};
        const RenderResult result = renderLab(r, renderLimits(rubric, 20));
        if (!result.ok)
            throw std::runtime_error("the reference solution of " + e.solution + " failed on " +
                                     scene + ": " + result.failure);
        const std::vector<float>& image = result.image();
        const std::vector<double> means =
            regionMeans(image, result.width, result.height, rubric.tiles);
        if (perRegion.empty()) perRegion.resize(means.size()), imageSum.assign(image.size(), 0.0);
        for (size_t i = 0; i < means.size(); ++i) perRegion[i].push_back(means[i]);
        for (size_t i = 0; i < image.size(); ++i) imageSum[i] += image[i];
        step();
    }
    for (const auto& values : perRegion) {
        const MeanEstimate m = batchMean(values);
        e.mean.push_back(m.mean);
        e.standardError.push_back(m.standardError);
    }
    for (double v : imageSum) e.image.push_back(static_cast<float>(v / seeds));
    return e;
}

nlohmann::json toJson(const Expectation& e, const std::string& imageFile) {
    return {{"solution", e.solution},
            {"seeds", e.seeds},
            {"spp", e.spp},
            {"mean", e.mean},
            {"standard_error", e.standardError},
            {"image", imageFile}};
}

Expectation fromJson(const nlohmann::json& j, const std::string& folder, int width, int height) {
    Expectation e;
    e.solution = j.at("solution");
    e.seeds = j.at("seeds");
    e.spp = j.at("spp");
    e.mean = j.at("mean").get<std::vector<double>>();
    e.standardError = j.at("standard_error").get<std::vector<double>>();
    const Image image = readImage(folder + "/" + j.at("image").get<std::string>());
    if (image.width != width || image.height != height)
        throw InputError(folder + "/" + j.at("image").get<std::string>() + ": wrong size");
    e.image = image.rgb;
    return e;
}

} // namespace

std::string referenceParametersHash(const Rubric& r) {
    ContentHash hash;
    for (const double value : {double(r.width), double(r.height), double(r.tiles),
                               double(r.maxDepth), double(r.continueProb)})
        hash.add(std::to_string(value));
    return hash.hex();
}

Expectation analyticExpectation(const Rubric& rubric, double value, const std::string& formula) {
    const size_t values = 3 * (1 + static_cast<size_t>(rubric.tiles) * rubric.tiles);
    const size_t pixels = 3 * static_cast<size_t>(rubric.width) * rubric.height;
    Expectation e;
    e.solution = "analytic: " + formula;
    e.mean.assign(values, value);
    e.standardError.assign(values, 0.0);
    e.image.assign(pixels, static_cast<float>(value));
    return e;
}

SceneReference referenceHeader(const std::string& scene, const Rubric& rubric, int maxDepth,
                               float continueProb) {
    SceneReference ref;
    ref.scene = scene;
    ref.kitVersion = PATHLAB_VERSION;
    ref.width = rubric.width;
    ref.height = rubric.height;
    ref.tiles = rubric.tiles;
    ref.maxDepth = maxDepth;
    ref.continueProb = continueProb;
    ref.parametersHash = referenceParametersHash(rubric);
    return ref;
}

SceneReference measureReference(const LabRunner& solution, const std::string& scenePath,
                                const Rubric& rubric, int seeds, int sppFactor,
                                const std::string& scratch, const Progress& progress) {
    SceneReference ref = referenceHeader(std::filesystem::path(scenePath).stem().string(), rubric,
                                         rubric.maxDepth, rubric.continueProb);
    ref.sceneFilesHash = sceneFilesHash(scenePath);
    // The noise figure of a correct lab, as the grader measures a student's: the rubric's seeds
    // at the rubric's spp, in several independent groups whose figures are averaged.
    const int noiseGroups = 6;
    const int total = 2 * seeds + static_cast<int>(LabCount) * noiseGroups;
    int done = 0;
    auto step = [&] {
        if (progress) progress(++done, total);
    };
    const int spp = rubric.forLab(Lab::Importance).correctnessSpp * sppFactor;
    // Importance and roulette: the fastest to converge of the depth-limited and unbiased labs.
    ref.depthLimited =
        measure(solution, scenePath, Lab::Importance, rubric, seeds, spp, scratch, step);
    ref.unbiased = measure(solution, scenePath, Lab::Roulette, rubric, seeds, spp, scratch, step);
    for (Lab lab : AllLabs) {
        const int labSpp = rubric.forLab(lab).correctnessSpp;
        double sum = 0;
        RayCounters rays;
        for (int g = 0; g < noiseGroups; ++g) {
            const RenderRequest r{&solution,
                                  scenePath,
                                  requestedIdentity(solution, lab,
                                                    {rubric.maxDepth, rubric.continueProb},
                                                    static_cast<uint64_t>(2000000 + 1000 * g),
                                                    rubric.width, rubric.height),
                                  labSpp,
                                  rubric.seeds,
                                  0,
                                  scratch};
            const RenderResult result = renderLab(r, renderLimits(rubric, 20));
            if (!result.ok)
                throw std::runtime_error("the reference solution failed: " + result.failure);
            std::vector<std::vector<float>> images;
            for (const RenderedImage& rendered : result.images) {
                images.push_back(rendered.rgb);
                rays += rendered.rays;
            }
            sum += trimmedSampleVariance(images, labSpp) / noiseGroups;
            step();
        }
        ref.noise[lab] = sum;
        ref.noiseSpp[lab] = labSpp;
        ref.bounceRays[lab] = raysPerSample(rays, double(rubric.width) * rubric.height * labSpp *
                                                      rubric.seeds * noiseGroups)
                                  .bounce;
        ref.bounceRaysKnown = true;
    }
    ref.noiseSeeds = rubric.seeds;
    return ref;
}

void saveReference(const std::string& folder, const SceneReference& ref) {
    const std::string depthImage = ref.scene + ".depth_limited.exr";
    const std::string unbiasedImage = ref.scene + ".unbiased.exr";
    writeImage(folder + "/" + depthImage, ref.width, ref.height, ref.depthLimited.image);
    writeImage(folder + "/" + unbiasedImage, ref.width, ref.height, ref.unbiased.image);
    nlohmann::json noise, bounceRays = nullptr;
    for (Lab lab : AllLabs) {
        noise[std::string(labName(lab))] = ref.noise[lab];
        if (ref.bounceRaysKnown) bounceRays[std::string(labName(lab))] = ref.bounceRays[lab];
    }
    const nlohmann::json j = {
        {"scene", ref.scene},
        {"made_by", "grader make-references"},
        {"kit_version", ref.kitVersion},
        {"scene_files_hash", ref.sceneFilesHash},
        {"grading_parameters_hash", ref.parametersHash},
        {"width", ref.width},
        {"height", ref.height},
        {"tiles", ref.tiles},
        {"max_depth", ref.maxDepth},
        {"continue_prob", ref.continueProb},
        {"depth_limited", toJson(ref.depthLimited, depthImage)},
        {"unbiased", toJson(ref.unbiased, unbiasedImage)},
        {"noise", noise},
        {"noise_seeds", ref.noiseSeeds},
        {"noise_spp", ref.noiseSpp.values},
        {"noise_is", "per-sample variance of the reference solutions, from the spread of the "
                     "rubric's seeds at the rubric's spp, the noisiest 1% of pixels left out "
                     "(grader/src/seed_variance.h)"},
        {"bounce_rays_per_sample", bounceRays},
    };
    writeFileAtomically(folder + "/" + ref.scene + ".json", j.dump(1) + "\n");
}

SceneReference loadReference(const std::string& folder, const std::string& scenePath,
                             const Rubric& rubric) {
    const std::string scene = std::filesystem::path(scenePath).stem().string();
    const std::string path = folder + "/" + scene + ".json";
    std::ifstream in(path);
    if (!in) throw InputError(path + ": no stored reference");
    SceneReference ref;
    try {
        const nlohmann::json j = nlohmann::json::parse(in);
        ref.scene = j.at("scene");
        ref.kitVersion = j.at("kit_version");
        ref.sceneFilesHash = j.value("scene_files_hash", "");
        ref.parametersHash = j.value("grading_parameters_hash", "");
        ref.width = j.at("width");
        ref.height = j.at("height");
        ref.tiles = j.at("tiles");
        ref.maxDepth = j.at("max_depth");
        ref.continueProb = j.at("continue_prob");
        // Stale before anything else is read: its images may have another size.
        std::vector<std::string> changed;
        if (ref.sceneFilesHash != sceneFilesHash(scenePath))
            changed.push_back("the scene's files (" + scenePath +
                              " and the .obj/.mtl it names) changed");
        if (ref.parametersHash != referenceParametersHash(rubric))
            changed.push_back("the rubric's image size, tiles, max_depth or continue_prob changed");
        if (ref.kitVersion != PATHLAB_VERSION)
            changed.push_back("it was made by PathLab " + ref.kitVersion + ", this is " +
                              PATHLAB_VERSION);
        if (!changed.empty()) {
            std::string why;
            for (const std::string& c : changed) why += (why.empty() ? "" : "; ") + c;
            throw StaleReference(path + " no longer fits: " + why + " since it was measured");
        }
        ref.depthLimited = fromJson(j.at("depth_limited"), folder, ref.width, ref.height);
        ref.unbiased = fromJson(j.at("unbiased"), folder, ref.width, ref.height);
        for (Lab lab : AllLabs) {
            if (!j.at("noise").contains(std::string(labName(lab))))
                throw InputError(path + ": no figures for the lab \"" + std::string(labName(lab)) +
                                 "\" (measured before the lab was in the lab list)");
            ref.noise[lab] = j.at("noise").at(std::string(labName(lab)));
        }
        ref.noiseSeeds = j.at("noise_seeds");
        ref.bounceRaysKnown =
            j.contains("bounce_rays_per_sample") && j.at("bounce_rays_per_sample").is_object();
        if (ref.bounceRaysKnown)
            for (Lab lab : AllLabs)
                ref.bounceRays[lab] =
                    j.at("bounce_rays_per_sample").at(std::string(labName(lab))).get<double>();
        ref.noiseSpp.values = j.at("noise_spp").get<decltype(ref.noiseSpp.values)>();
    } catch (const nlohmann::json::exception& e) {
        throw InputError(path + ": " + e.what());
    }
    return ref;
}

} // namespace pathlab::grader
