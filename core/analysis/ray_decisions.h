// The discrete decisions behind one pixel: which sphere each ray of the pixel's
// Whitted ray tree hits, whether each light is shadowed, whether total internal
// reflection happens. Float and double renders that agree on all of them differ
// only by rounding in the shading; a pixel where one flips differs visibly.
//
// The tree is walked with the tracer's own rules (core/tracer/scalar_ray_tree.h). Only the
// camera ray through the pixel centre is followed, whatever samples_per_pixel says.
#pragma once

#include <cstdint>
#include <vector>

#include "tracer/tracer.h"

namespace whitted {

enum class DecisionKind : std::uint8_t {
    Hit,     // value: the sphere a ray hits, -1 for a miss
    Shadow,  // value: 1 when S_j < 1 (something lies between the point and light j)
    Tir,     // value: 1 for total internal reflection at a transparent hit
};

struct Decision {
    DecisionKind kind;
    int value;
    bool operator==(const Decision&) const = default;
};

// The decisions of pixel (i, j)'s ray tree in the order the tracer makes them,
// depth first: a ray's hit; for a hit, one Shadow decision per light with
// non-zero colour (0 where the light is not tested because N·L <= 0 or the
// material is unlit, so the count never depends on a rounding); for a
// transparent hit below max_depth, its Tir decision; then the refracted ray's
// tree, then the reflected ray's. Replaces the contents of `out`.
template <typename T>
void pixelDecisions(const PreparedScene<T>& s, int i, int j, std::vector<Decision>& out);

// The decision list condensed into one 64-bit hash per kind of decision, each
// over that kind's values in order: cheap to store per pixel and compare
// across renders of scenes with the same spheres and lights.
struct DecisionSignature {
    std::uint64_t hits = 0;
    std::uint64_t shadows = 0;
    std::uint64_t tir = 0;
    bool operator==(const DecisionSignature&) const = default;
};
DecisionSignature signatureOf(const std::vector<Decision>& decisions);

// The kind of the first decision in which two lists differ. A list that ends
// early, or a kind that does not match, counts as a different hit: the trees
// have taken different shapes.
enum class DecisionDifference { None, Hit, Shadow, Tir };
DecisionDifference firstDifference(const std::vector<Decision>& a, const std::vector<Decision>& b);

}  // namespace whitted
