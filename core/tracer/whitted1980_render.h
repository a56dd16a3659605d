// The render behind RenderOptions::whitted1980 (whitted1980_sampling.h says
// what it samples): render() hands the prepared scene here.
#pragma once

#include "tracer/renderer.h"

namespace whitted {

template <typename T>
RenderResult renderWhitted1980(const PreparedScene<T>& s, const RenderSettings& settings,
                               const RenderOptions& options, const TileCallback& onTile,
                               const StopPredicate& shouldStop);

}  // namespace whitted
