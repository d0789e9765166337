#pragma once
/// A frame rate a student can write down: the median of the recent frames, not the last one.

#include <algorithm>
#include <deque>
#include <vector>

namespace pathlab {

class FrameRate {
public:
    static constexpr size_t Window = 31; ///< frames the median is taken over
    void add(double seconds) {
        recent_.push_back(seconds);
        if (recent_.size() > Window) recent_.pop_front();
    }
    void clear() { recent_.clear(); }
    /// Median seconds per frame of the last frames (0 before the first).
    double medianSeconds() const {
        if (recent_.empty()) return 0;
        std::vector<double> sorted(recent_.begin(), recent_.end());
        std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
        return sorted[sorted.size() / 2];
    }
    double framesPerSecond() const {
        const double s = medianSeconds();
        return s > 0 ? 1.0 / s : 0.0;
    }

private:
    std::deque<double> recent_;
};

} // namespace pathlab
