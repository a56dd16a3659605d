#include "analysis/ray_decisions.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "tracer/scalar_ray_tree.h"

namespace whitted {

namespace {

// Records the walk's decisions in the tracer's order.
struct DecisionRecorder {
    static constexpr bool kWantsShadows = true;
    std::vector<Decision>& out;
    void hit(int sphere) { out.push_back({DecisionKind::Hit, sphere}); }
    void shadow(int shadowed) { out.push_back({DecisionKind::Shadow, shadowed}); }
    void tir(bool total) { out.push_back({DecisionKind::Tir, total ? 1 : 0}); }
    template <typename T>
    void cutOff(T) {}
    template <typename T>
    bool descend(T, int) {
        return true;
    }
};

// One step of a 64-bit hash over a sequence: the running value is re-mixed at every
// element (splitmix64's finaliser), so order and length both matter.
std::uint64_t mix(std::uint64_t h, int value) {
    std::uint64_t x = h ^ (std::uint64_t(std::int64_t(value)) + 0x9e3779b97f4a7c15ull);
    x ^= x >> 30;
    x *= 0xbf58476d1ce4e5b9ull;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebull;
    x ^= x >> 31;
    return x;
}

}  // namespace

template <typename T>
void pixelDecisions(const PreparedScene<T>& s, int i, int j, std::vector<Decision>& out) {
    out.clear();
    DecisionRecorder recorder{out};
    ScalarRayTree<T, DecisionRecorder>(s, recorder).tracePixel(i, j);
}

DecisionSignature signatureOf(const std::vector<Decision>& decisions) {
    DecisionSignature sig;
    for (const Decision& d : decisions) {
        std::uint64_t& h = d.kind == DecisionKind::Hit      ? sig.hits
                           : d.kind == DecisionKind::Shadow ? sig.shadows
                                                            : sig.tir;
        h = mix(h, d.value);
    }
    return sig;
}

DecisionDifference firstDifference(const std::vector<Decision>& a, const std::vector<Decision>& b) {
    const std::size_t n = std::min(a.size(), b.size());
    for (std::size_t i = 0; i < n; ++i) {
        if (a[i] == b[i]) continue;
        if (a[i].kind != b[i].kind) return DecisionDifference::Hit;
        switch (a[i].kind) {
            case DecisionKind::Hit:
                return DecisionDifference::Hit;
            case DecisionKind::Shadow:
                return DecisionDifference::Shadow;
            case DecisionKind::Tir:
                return DecisionDifference::Tir;
        }
    }
    return a.size() == b.size() ? DecisionDifference::None : DecisionDifference::Hit;
}

template void pixelDecisions<float>(const PreparedScene<float>&, int, int, std::vector<Decision>&);
template void pixelDecisions<double>(const PreparedScene<double>&, int, int,
                                     std::vector<Decision>&);

}  // namespace whitted
