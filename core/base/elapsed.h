// Wall-clock seconds since a start, on the steady clock (which no clock
// adjustment moves): the time a render, a probe or a measurement took.
#pragma once

#include <chrono>

namespace whitted {

inline double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace whitted
