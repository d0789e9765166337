#include "pathlab/support/ticking_thread.h"

namespace pathlab {

TickingThread::~TickingThread() {
    if (!thread_.joinable()) return;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

void TickingThread::start(std::function<void()> body) { thread_ = std::thread(std::move(body)); }

bool TickingThread::sleep(std::chrono::duration<double> duration) {
    std::unique_lock<std::mutex> lock(mutex_);
    return !wake_.wait_for(lock, duration, [this] { return stopping_; });
}

} // namespace pathlab
