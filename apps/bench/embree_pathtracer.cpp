#include "embree_pathtracer.h"

#include "process/child_process.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace pathlab::bench {

namespace {

std::vector<std::string> commandLine(const PathtracerJob& job, int spp) {
    std::vector<std::string> argv = {job.program};
    argv.insert(argv.end(), job.scene.arguments.begin(), job.scene.arguments.end());
    for (const std::string& a :
         {std::string("--size"), std::to_string(job.width), std::to_string(job.height),
          std::string("--spp"), std::to_string(spp), std::string("--max-path-length"),
          std::to_string(job.maxPathLength), std::string("--threads"), std::to_string(job.threads)})
        argv.push_back(a);
    return argv;
}

ChildRun runOrThrow(const std::vector<std::string>& argv) {
    ChildRun result = runChild(argv);
    if (result.exitCode != 0)
        throw std::runtime_error(argv[0] + " failed (status " + std::to_string(result.exitCode) +
                                 "): " + result.output.substr(0, 400));
    return result;
}

/// A binary PPM (P6, maxval 255) as values k/255.
std::vector<float> readPpm(const std::string& path, int width, int height) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    size_t at = 0;
    std::vector<std::string> fields;
    while (fields.size() < 4 && at < bytes.size()) {
        while (at < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[at]))) ++at;
        const size_t start = at;
        while (at < bytes.size() && !std::isspace(static_cast<unsigned char>(bytes[at]))) ++at;
        fields.push_back(bytes.substr(start, at - start));
    }
    ++at; // exactly one white-space byte ends the header; pixel bytes may look like white space
    const size_t values = 3 * static_cast<size_t>(width) * height;
    if (fields.size() < 4 || fields[0] != "P6" || fields[1] != std::to_string(width) ||
        fields[2] != std::to_string(height) || fields[3] != "255" || bytes.size() < at + values)
        throw std::runtime_error(path + ": not the " + std::to_string(width) + "x" +
                                 std::to_string(height) + " 8-bit PPM image expected");
    std::vector<float> rgb(values);
    for (size_t i = 0; i < values; ++i)
        rgb[i] = static_cast<float>(static_cast<unsigned char>(bytes[at + i])) / 255.0f;
    return rgb;
}

} // namespace

PathtracerSpeed pathtracerSpeed(const PathtracerJob& job, int spp, int frames) {
    // Its --benchmark mode prints the frames' rates only, and a run's CPU time holds its
    // start-up and warm-up frame too. Two runs that differ only by their timed frames differ in
    // CPU time by those frames' alone. On this 2-core machine under load (each process had a
    // quarter to a third of its cores), Embree's CPU time per frame differenced this way agreed
    // within 2-5% over three rounds at 512x512, and the run of no timed frames took one frame's
    // CPU time and 0-10 ms more: the start-up is small, the differencing steady. At tiny sizes
    // it is not: the start-up's 5 ms of CPU time varied by 0.5 ms from run to run, more than a
    // 24x16 frame takes.
    const auto run = [&](int timedFrames) {
        std::vector<std::string> argv = commandLine(job, spp);
        for (const std::string& a : {std::string("--benchmark"), std::string("1"),
                                     std::to_string(timedFrames), std::string("--legacy")})
            argv.push_back(a);
        return runOrThrow(argv);
    };
    const ChildRun start = run(0);
    const ChildRun timed = run(frames);

    // "BENCHMARK_RENDER_MAX 3.7026": frames per second of the fastest frame; _AVG of their mean.
    PathtracerSpeed speed;
    std::istringstream lines(timed.output);
    for (std::string line; std::getline(lines, line);) {
        std::istringstream words(line);
        std::string key;
        double fps = 0;
        if (!(words >> key >> fps)) continue;
        if (key == "BENCHMARK_RENDER_MAX")
            speed.samplesPerSecond = fps * job.width * job.height * spp;
        if (key == "BENCHMARK_RENDER_AVG") speed.framesPerSecond = fps;
    }
    if (!(speed.samplesPerSecond > 0))
        throw std::runtime_error(job.program + " printed no BENCHMARK_RENDER_MAX line");
    speed.startCpuSeconds = start.cpuSeconds;
    speed.cpuSecondsPerFrame = (timed.cpuSeconds - start.cpuSeconds) / frames;
    // The start-up's variation (a tenth of it, as above) over the timed frames' CPU time is the
    // figure's error: frames of at least four times the start-up keep it to a few percent.
    constexpr double LeastFramesPerStartUp = 4;
    const double framesCpuSeconds = speed.cpuSecondsPerFrame * frames;
    if (framesCpuSeconds > 0 &&
        framesCpuSeconds >= LeastFramesPerStartUp * speed.startUpCpuSeconds())
        speed.samplesPerCpuSecond =
            static_cast<double>(job.width) * job.height * spp / speed.cpuSecondsPerFrame;
    return speed;
}

std::vector<float> pathtracerImage(const PathtracerJob& job, int spp, const std::string& folder) {
    const std::string file = (std::filesystem::path(folder) / "embree-pathtracer.ppm").string();
    std::vector<std::string> argv = commandLine(job, spp);
    argv.push_back("-o");
    argv.push_back(file);
    runOrThrow(argv);
    std::vector<float> rgb = readPpm(file, job.width, job.height);
    std::filesystem::remove(file);
    return rgb;
}

float embreeStoredValue(float radiance) {
    // Embree's tutorials: (unsigned int)(255.01f * clamp(value, 0.0f, 1.0f)).
    return std::floor(255.01f * std::clamp(radiance, 0.0f, 1.0f)) / 255.0f;
}

} // namespace pathlab::bench
