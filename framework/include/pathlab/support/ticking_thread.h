#pragma once
/// A thread that wakes every so often until its owner stops it: the render watchdog's and the
/// progress line's. Stopping wakes it at once, not at its next tick.

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace pathlab {

/// Neither copied nor moved (its mutex is neither).
class TickingThread {
public:
    /// Stops the thread, if one was started, and joins it. Declared after what the thread's
    /// body reads, a TickingThread member is destroyed before it.
    ~TickingThread();

    /// Runs `body` on a thread of its own; it calls sleep() between its ticks.
    void start(std::function<void()> body);
    /// Waits `duration`, or less if the thread is stopped meanwhile: false once it is stopped.
    bool sleep(std::chrono::duration<double> duration);

private:
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stopping_ = false;
    std::thread thread_;
};

} // namespace pathlab
