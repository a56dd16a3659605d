// The biases a quality plan measures before it samples: the depth, chosen
// where what deeper rays add is within its share of the target (at the
// probe's size, then at the picture's where a pixel may be off by too much),
// and what float arithmetic changes against double there.
#pragma once

#include <optional>

#include "analysis/quality_probes.h"
#include "analysis/quality_target.h"

namespace whitted::planning {

// The deepest depth a plan chooses: kLookAhead short of the deepest SPEC
// allows, which it is judged against (judged against one level deeper, the
// last depth was taken in a room of lossless mirrors, where light comes out
// only every few levels). A render to a quality follows no ray too light to
// matter (kQualityPruneWeight), so a level deeper adds only the rays that
// light trapped among glass balls keeps bright: on the generated fields at
// 640x480, 0 to 29% more rays from depth 16 to 48, where pixels still
// changed by 35 to 160 codes. Capped at 16, as when every ray was followed
// and each level cost more than the last, 4 of the 12 Previews and Finals
// of those fields could not meet their target (docs/design/quality-planning.md,
// "The depth, measured").
constexpr int kDeepestPlanned = kMaxDepth - kLookAhead;

// The samples a pixel the picture's check also looks with, for slivers its
// centres miss: about 32 / the limit's codes, within [1, maxSamples] and 8.
int pictureCheckSamples(double largestCodes, int maxSamples);

// Chooses (or, when given, measures) the depth at the probe's size: the
// plan's depth fields.
void planDepth(ProbeRenders& probes, std::optional<int> given, int maxSamples, QualityPlan& plan);

// For a target with a limit on the largest error, the depth checked at the
// picture's own size, and taken deeper until it fits there.
void checkDepthAtPictureSize(ProbeRenders& probes, int maxSamples, QualityPlan& plan);

// Float against double at the chosen depth: the plan's precision fields.
void planPrecision(ProbeRenders& probes, QualityPlan& plan);

}  // namespace whitted::planning
