#include "tradeoff.h"

#include <stdexcept>

namespace whitted {

Scene withSettings(const Scene&, const TradeoffSettings&) {
    throw std::logic_error("not implemented yet");
}
ReferenceRender renderReference(const Scene&, int, const StopPredicate&) {
    throw std::logic_error("not implemented yet");
}
std::vector<TradeoffPoint> runTradeoff(const Scene&, const Image&, const TradeoffGrid&,
                                       const TradeoffCallback&, const StopPredicate&) {
    throw std::logic_error("not implemented yet");
}
void markParetoFront(std::vector<TradeoffPoint>&) {
    throw std::logic_error("not implemented yet");
}
std::vector<ProgressiveSample> progressiveCurve(const Scene&, const Image&, const StopPredicate&) {
    throw std::logic_error("not implemented yet");
}

}  // namespace whitted
