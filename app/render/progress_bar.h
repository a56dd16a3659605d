// whitted-render's progress on stderr.
#pragma once

#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>

#include "base/elapsed.h"

namespace whitted {

// A one-line bar on stderr, shown only once a render has run for a second, so
// quick renders print nothing but their summary.
class ProgressBar {
  public:
    explicit ProgressBar(bool enabled) : enabled_(enabled) {}

    void update(double fraction) {
        if (!enabled_) return;
        std::unique_lock lock(mutex_, std::try_to_lock);
        if (!lock) return;  // another worker is drawing; skipping a frame is fine
        const double elapsed = seconds();
        if (elapsed < 1.0 || elapsed - lastDraw_ < 0.1) return;
        lastDraw_ = elapsed;
        draw(fraction, elapsed);
    }

    void finish() {
        std::lock_guard lock(mutex_);
        if (lastDraw_ < 0) return;
        draw(1.0, seconds());
        std::fputc('\n', stderr);
    }

  private:
    double seconds() const { return secondsSince(start_); }

    void draw(double fraction, double elapsed) {
        constexpr int kWidth = 40;
        const int filled = static_cast<int>(fraction * kWidth);
        std::string bar(filled, '#');
        bar.resize(kWidth, '.');
        std::fprintf(stderr, "\r[%s] %3d%%  %.1f s", bar.c_str(), static_cast<int>(fraction * 100),
                     elapsed);
        std::fflush(stderr);
    }

    bool enabled_;
    std::mutex mutex_;
    double lastDraw_ = -1.0;
    const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace whitted
