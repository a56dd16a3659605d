#include "depth_truncation.h"

#include <stdexcept>

namespace whitted {

Image depthTruncationMap(const Scene&, const StopPredicate&) {
    throw std::logic_error("depthTruncationMap: not implemented yet");
}

float largestTruncation(const Image&) {
    throw std::logic_error("largestTruncation: not implemented yet");
}

int depthWithinTolerance(const Scene&, double) {
    throw std::logic_error("depthWithinTolerance: not implemented yet");
}

}  // namespace whitted
