#include "pathlab/render/renderer.h"

#include "pathlab/render/lab_crash_line.h"

#include "pathlab/support/cpu_clock.h"

#include "parallel_hand_off.h"

#include "pathlab/render/camera_packet.h"
#include "pathlab/render/path_driver.h"

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

namespace pathlab {

struct Renderer::Arena {
    /// TBB runs at most as many threads as this process may use (its cores, or fewer when its
    /// affinity is limited, as a Slurm job's is), however large an arena is asked for: more
    /// (--threads 8 on 2 cores) must raise that limit for as long as this renderer lives. Only
    /// raised: a limit below TBB's own would hold back every other renderer alive (TBB keeps the
    /// smallest limit asked for).
    std::optional<tbb::global_control> moreThreadsThanCores;
    tbb::task_arena arena;
    explicit Arena(int threads) : arena(threads) {
        if (static_cast<size_t>(threads) >
            tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism))
            moreThreadsThanCores.emplace(tbb::global_control::max_allowed_parallelism,
                                         static_cast<size_t>(threads));
    }
};

namespace {

/// pathTrace recurses once per bounce; Russian roulette with a high continueProb in a bright
/// furnace can go hundreds deep, more than TBB's default worker stack allows.
void ensureDeepStacks() {
    static tbb::global_control stack(tbb::global_control::thread_stack_size, 16u << 20);
}

/// Samples a tile finishes before it adds them to the renderer's progress: a fraction of a
/// millisecond of a correct lab's work, far below what a watchdog or a progress line can tell.
constexpr uint64_t PublishedSamples = 256;

/// A sample whose camera ray waits in a packet: its pixel, and its random numbers just after
/// the pixel jitter, where pathTrace takes them up.
struct PendingSample {
    int pixel;
    uint64_t sampleIndex;
    Sampler sampler;
};

} // namespace

/// The first exception any tile threw, to throw again once the tiles are done.
class Renderer::FirstFailure {
public:
    void keep(std::exception_ptr error) {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (!error_) error_ = std::move(error);
        happened_.store(true, std::memory_order_relaxed);
    }
    bool happened() const { return happened_.load(std::memory_order_relaxed); }
    void rethrow() const {
        if (error_) std::rethrow_exception(error_);
    }

private:
    std::mutex mutex_;
    std::exception_ptr error_;
    std::atomic<bool> happened_{false};
};

/// One pass's tiles: what they share (the image, the camera, the lab and its parameters, the
/// pass's seed and samples) and the rendering of one, on whichever thread takes it.
class Renderer::PassTiles {
public:
    PassTiles(const RenderScene& scene, AccumulationBuffer& buffer, const Camera& camera,
              PathTraceFunction pathTrace, const LabParameters& parameters, uint64_t seed, int spp,
              int tileSize, RenderProgress& progress, bool logRays)
        : scene_(scene), buffer_(buffer), camera_(camera), pathTrace_(pathTrace),
          parameters_(parameters), seed_(seed), spp_(spp), tileSize_(tileSize),
          width_(buffer.width()), height_(buffer.height()),
          tilesX_((width_ + tileSize - 1) / tileSize), tilesY_((height_ + tileSize - 1) / tileSize),
          firstSample_(static_cast<uint64_t>(buffer.samplesPerPixel())), progress_(progress),
          tileLogs_(logRays ? static_cast<size_t>(tilesX_) * tilesY_ : 0) {}

    int count() const { return tilesX_ * tilesY_; }

    /// Renders tile `tile` (row by row from the top left), spp samples a pixel.
    void render(int tile) {
        PathDriver driver(scene_, parameters_);
        if (!tileLogs_.empty()) driver.recordRaysInto(&tileLogs_[static_cast<size_t>(tile)]);
        const int x0 = (tile % tilesX_) * tileSize_, y0 = (tile / tilesX_) * tileSize_;
        const int x1 = std::min(x0 + tileSize_, width_), y1 = std::min(y0 + tileSize_, height_);
        // Camera rays go to Embree a packet at a time; each sample's pathTrace then finds its
        // camera ray's hit waiting in the context. Samples keep their order within a pixel, so
        // every pixel's sums add up exactly as one by one.
        CameraPacket packet;
        uint64_t unpublished = 0; // samples finished but not yet added to progress_
        std::vector<PendingSample> pending;
        pending.reserve(CameraPacket::Size);
        for (int y = y0; y < y1; ++y) {
            for (int x = x0; x < x1; ++x) {
                const int pixel = y * width_ + x;
                const uint64_t pixelStart =
                    PathDriver::pixelStreamStart(seed_, static_cast<uint64_t>(pixel));
                for (int s = 0; s < spp_; ++s) {
                    const uint64_t sampleIndex = firstSample_ + static_cast<uint64_t>(s);
                    driver.startSampleAt(pixelStart, sampleIndex);
                    const Vec2 jitter = driver.context().sampler.get2D();
                    packet.rays[packet.count] = camera_.generateRay(
                        static_cast<float>(x) + jitter.x, static_cast<float>(y) + jitter.y);
                    pending.push_back({pixel, sampleIndex, driver.savedSampler()});
                    if (++packet.count == CameraPacket::Size)
                        tracePending(driver, packet, pending, unpublished);
                }
            }
        }
        if (packet.count > 0) tracePending(driver, packet, pending, unpublished);
        progress_.add(unpublished);
        // Counted per tile in the context, summed here once: nothing shared per ray.
        intersect_.fetch_add(driver.rayCounters().intersect, std::memory_order_relaxed);
        occluded_.fetch_add(driver.rayCounters().occluded, std::memory_order_relaxed);
    }

    RayCounters counters() const { return {intersect_.load(), occluded_.load()}; }
    const std::optional<NonfiniteSample>& firstNonfinite() const { return nonfinite_.first(); }
    void appendRaysTo(RayLog& log) const {
        for (const RayLog& tileLog : tileLogs_) log.append(tileLog);
    }

private:
    /// Traces the packet's camera rays and runs the lab on each of its samples, in order.
    void tracePending(PathDriver& driver, CameraPacket& packet, std::vector<PendingSample>& pending,
                      uint64_t& unpublished) {
        scene_.intersect(packet);
        for (int i = 0; i < packet.count; ++i) {
            const PendingSample& sample = pending[static_cast<size_t>(i)];
            driver.restoreSampler(sample.sampler);
            driver.primeCameraHit(&packet, i);
            const uint64_t raysBefore = driver.rayCounters().intersect;
            const Color radiance = pathTrace_(packet.rays[i], 0, driver.context());
            if (!buffer_.addSample(sample.pixel, radiance))
                nonfinite_.note({sample.pixel % width_, sample.pixel / width_, sample.sampleIndex,
                                 driver.rayCounters().intersect - raysBefore, radiance});
        }
        // Published a few hundred samples at a time: the counter is shared by every worker, and
        // its cache line passed between cores after every packet would cost a little.
        unpublished += static_cast<uint64_t>(packet.count);
        if (unpublished >= PublishedSamples) progress_.add(std::exchange(unpublished, 0));
        packet.count = 0;
        pending.clear();
    }

    const RenderScene& scene_;
    AccumulationBuffer& buffer_;
    const Camera& camera_;
    PathTraceFunction pathTrace_;
    const LabParameters& parameters_;
    const uint64_t seed_;
    const int spp_, tileSize_, width_, height_, tilesX_, tilesY_;
    const uint64_t firstSample_;
    RenderProgress& progress_;
    std::vector<RayLog> tileLogs_;
    FirstNonfiniteSample nonfinite_;
    std::atomic<uint64_t> intersect_{0}, occluded_{0};
};

Renderer::Renderer(const RenderScene& scene, int threads)
    : scene_(scene), threads_(threads > 0 ? threads : defaultThreads()),
      arena_(std::make_unique<Arena>(threads_)) {
    ensureDeepStacks();
}

Renderer::~Renderer() = default;

int Renderer::defaultThreads() { return std::max(1, tbb::info::default_concurrency()); }

bool Renderer::renderPass(AccumulationBuffer& buffer, const Camera& camera,
                          PathTraceFunction pathTrace, const LabParameters& parameters,
                          uint64_t seed, int spp, const std::atomic<bool>* cancel, RayLog* log) {
    PassTiles tiles(scene_, buffer, camera, pathTrace, parameters, seed, spp, tileSize_, progress_,
                    log != nullptr);
    // Ended whichever way the pass ends, a lab's exception included.
    const struct PassUnderWay {
        RenderProgress& progress;
        ~PassUnderWay() { progress.passEnds(); }
    } underWay{progress_};
    progress_.passStarts(static_cast<uint64_t>(buffer.width()) *
                         static_cast<uint64_t>(buffer.height()) * static_cast<uint64_t>(spp));
    FirstFailure failure;
    const PassCpuTime cpu = renderTilesInParallel(tiles, cancel, failure);
    processCpuSeconds_ += cpu.process;
    cpuSeconds_ += cpu.threads;
    failure.rethrow();
    counters_ += tiles.counters();
    const std::optional<NonfiniteSample>& nonfinite = tiles.firstNonfinite();
    if (nonfinite && (!firstNonfinite_ || nonfinite->before(*firstNonfinite_)))
        firstNonfinite_ = nonfinite;
    if (log) tiles.appendRaysTo(*log);
    if (cancel && cancel->load()) return false;
    buffer.finishPass(spp);
    return true;
}

Renderer::PassCpuTime Renderer::renderTilesInParallel(PassTiles& tiles,
                                                      const std::atomic<bool>* cancel,
                                                      FirstFailure& failure) {
    // Their addresses name the hand-offs to TSan; static, so that a task names them without
    // reading the loop's closure (parallel_hand_off.h).
    static const char passStarts = 0, tilesFinished = 0;
    // CPU time per stretch of tiles a thread renders: two readings of its clock per stretch, a
    // microsecond against the tiles' milliseconds.
    const bool perThread = cpuClock() == CpuClock::PerThread;
    std::atomic<uint64_t> cpuNanoseconds{0};
    // The free function, not this class's accessor of the same name.
    const double processBefore = pathlab::processCpuSeconds();
    const int count = tiles.count();
    releaseTo(&passStarts);
    arena_->arena.execute([&] {
        tbb::parallel_for(
            tbb::blocked_range<int>(0, count, 1), [&](const tbb::blocked_range<int>& range) {
                acquireFrom(&passStarts);
                LabCrashLine::prepareCrashStack(); // once per thread: a lab's crash is named
                const double cpuBefore = perThread ? threadCpuSeconds() : 0;
                for (int tile = range.begin(); tile != range.end(); ++tile) {
                    if (cancel && cancel->load(std::memory_order_relaxed)) break;
                    if (failure.happened()) break;
                    // A lab's exception (a broken check) is kept and thrown again after the
                    // loop, in this thread's own C++ runtime: carried through TBB's, which may
                    // be another (the clang + libc++ build), it would arrive as an unknown
                    // object.
                    try {
                        tiles.render(reverseTiles_ ? count - 1 - tile : tile);
                    } catch (...) {
                        failure.keep(std::current_exception());
                    }
                }
                if (perThread)
                    cpuNanoseconds.fetch_add(
                        static_cast<uint64_t>(std::llround(1e9 * (threadCpuSeconds() - cpuBefore))),
                        std::memory_order_relaxed);
                releaseTo(&tilesFinished);
            });
    });
    acquireFrom(&tilesFinished);
    const double processSpent = pathlab::processCpuSeconds() - processBefore;
    return {processSpent,
            perThread ? 1e-9 * static_cast<double>(cpuNanoseconds.load()) : processSpent};
}

} // namespace pathlab
