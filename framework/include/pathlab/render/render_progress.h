#pragma once
/// How far a Renderer's passes have got, read from another thread: by a watchdog that notices a
/// lab which stopped finishing samples, and by a headless render's progress line.

#include <atomic>
#include <cstdint>

namespace pathlab {

/// Counts kept by Renderer::renderPass as it goes. Each tile adds its finished samples a few
/// hundred at a time (whole camera packets, never per ray) with relaxed atomics, so a render
/// that nobody watches pays next to nothing; a reader sees the counts late by that much per
/// worker, a fraction of a millisecond of a correct lab's work, which is all a watchdog or a
/// progress line needs.
class RenderProgress {
public:
    /// Samples finished by all passes so far, over the renderer's life.
    uint64_t samplesFinished() const { return finished_.load(std::memory_order_relaxed); }
    /// Whether a pass is under way: only then does a standstill of samplesFinished mean anything
    /// (between passes, a window that rendered its --frames idles).
    bool passRunning() const { return running_.load(std::memory_order_relaxed); }
    /// The samples of the pass under way (or of the last one) ...
    uint64_t passSamples() const { return passSamples_.load(std::memory_order_relaxed); }
    /// ... and how many of them are finished.
    uint64_t passSamplesFinished() const {
        return samplesFinished() - passFirst_.load(std::memory_order_relaxed);
    }

    /// Renderer::renderPass's side: a pass of `samples` samples begins, ...
    void passStarts(uint64_t samples) {
        passFirst_.store(samplesFinished(), std::memory_order_relaxed);
        passSamples_.store(samples, std::memory_order_relaxed);
        running_.store(true, std::memory_order_relaxed);
    }
    /// ... `samples` more of it are done, ...
    void add(uint64_t samples) { finished_.fetch_add(samples, std::memory_order_relaxed); }
    /// ... and it is over, finished, cancelled or failed.
    void passEnds() { running_.store(false, std::memory_order_relaxed); }

private:
    std::atomic<uint64_t> finished_{0};
    std::atomic<uint64_t> passFirst_{0};   ///< samplesFinished when the pass began
    std::atomic<uint64_t> passSamples_{0}; ///< samples in the pass
    std::atomic<bool> running_{false};
};

} // namespace pathlab
