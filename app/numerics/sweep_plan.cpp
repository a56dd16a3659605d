#include "sweep_plan.h"

#include <cmath>
#include <string>

#include "scene/scene_transform.h"

namespace whitted::numerics {

std::string_view sweepId(SweepKind kind) {
    switch (kind) {
        case SweepKind::Scale10:
            return "scale10";
        case SweepKind::Scale2:
            return "scale2";
        case SweepKind::Translate:
            return "translate";
    }
    return "?";
}

std::string_view sweepTitle(SweepKind kind) {
    switch (kind) {
        case SweepKind::Scale10:
            return "scale ×10^k";
        case SweepKind::Scale2:
            return "scale ×2^k";
        case SweepKind::Translate:
            return "move by (1,1,1)·10^k";
    }
    return "?";
}

namespace {

// Through the decimal parser rather than pow(): strtod rounds correctly.
double powerOfTen(int k) {
    return std::stod("1e" + std::to_string(k));
}

}  // namespace

std::string transformLabel(const SweepPoint& p) {
    const std::string ten = "1e" + std::to_string(p.k);
    switch (p.kind) {
        case SweepKind::Scale10:
            return ten;
        case SweepKind::Scale2:
            return "2^" + std::to_string(p.k);
        case SweepKind::Translate:
            return "(" + ten + ", " + ten + ", " + ten + ")";
    }
    return "?";
}

Scene sceneAt(const Scene& base, const SweepPoint& p) {
    Scene s;
    switch (p.kind) {
        case SweepKind::Scale10:
            s = scaledScene(base, powerOfTen(p.k));
            break;
        case SweepKind::Scale2:
            s = scaledScene(base, std::ldexp(1.0, p.k));
            break;
        case SweepKind::Translate:
            s = translatedScene(base, Vec3(powerOfTen(p.k)));
            break;
    }
    s.render.precision = p.precision;
    return s;
}

namespace {

void addRange(std::vector<SweepPoint>& out, SweepKind kind, Precision precision, int from, int to,
              int step = 1) {
    for (int k = from; k <= to; k += step) out.push_back({kind, precision, k});
}

// [-inner, inner] in steps of 1, then out to ±outer in steps of `step`.
void addWide(std::vector<SweepPoint>& out, SweepKind kind, Precision precision, int inner,
             int outer, int step) {
    addRange(out, kind, precision, -outer, -inner - step, step);
    addRange(out, kind, precision, -inner, inner);
    addRange(out, kind, precision, inner + step, outer, step);
}

}  // namespace

std::vector<SweepPoint> sweepPlan(bool quick) {
    constexpr Precision F = Precision::Float, D = Precision::Double;
    std::vector<SweepPoint> plan;
    if (quick) {
        addRange(plan, SweepKind::Scale10, F, -2, 2);
        addRange(plan, SweepKind::Scale10, D, -2, 2);
        addRange(plan, SweepKind::Scale2, F, -3, 3);
        addRange(plan, SweepKind::Scale2, D, -3, 3);
        addRange(plan, SweepKind::Translate, F, 0, 2);
        addRange(plan, SweepKind::Translate, D, 0, 2);
        return plan;
    }
    // Float's own range ends near 1e±38, double's near 1e±308: the outer points
    // show what happens once the scene's numbers leave it.
    addWide(plan, SweepKind::Scale10, F, 20, 40, 5);
    addWide(plan, SweepKind::Scale10, D, 40, 200, 10);
    addRange(plan, SweepKind::Scale2, F, -20, 20);
    addRange(plan, SweepKind::Scale2, D, -20, 20);
    addRange(plan, SweepKind::Translate, F, 0, 12);
    addRange(plan, SweepKind::Translate, D, 0, 20);
    return plan;
}

}  // namespace whitted::numerics
