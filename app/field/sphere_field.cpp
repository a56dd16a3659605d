#include "sphere_field.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace whitted {

namespace {

void addMaterials(Scene& s) {
    s.materials = {
        {"blue", {0, 0, 1}, 1, 50, 0.5, 0, 1.5, {}},
        {"purple", {0.5, 0, 0.5}, 1, 50, 0.5, 0, 1.5, {}},
        {"white", {1, 0.99, 0.99}, 1, 50, 0.5, 0, 1.5, {}},
        {"mirror", {0.1, 0.1, 0.1}, 1, 60, 0.8, 0, 1.5, {}},
        {"glass", {0, 0, 0}, 1, 200, 0.1, 0.9, 1.5, {}},
        {"floor", {0.75, 0.75, 0.75}, 1, 50, 0.25, 0, 1.5, Checker{{0, 0, 0}, 0.5}},
    };
}

const char* materialOf(int i, FieldMix mix) {
    static const char* const even[] = {"blue", "purple", "white", "mirror", "glass"};
    static const char* const notGlass[] = {"blue", "purple", "white", "mirror"};
    static const char* const notMirror[] = {"blue", "purple", "white", "glass"};
    switch (mix) {
        case FieldMix::mostlyGlass:
            return i % 5 == 0 ? notGlass[(i / 5) % 4] : "glass";
        case FieldMix::mostlyMirrors:
            return i % 5 == 0 ? notMirror[(i / 5) % 4] : "mirror";
        case FieldMix::even:
            break;
    }
    return even[i % 5];
}

Camera cameraOf(const FieldOptions& o) {
    const double middle = o.nearZ + o.depth / 2;
    switch (o.view) {
        case FieldView::inside:
            return {{0, 1.5, middle}, {0, 1.4, middle + 10}, {0, 1, 0}, 73.74};
        case FieldView::above: {
            // tan(73.74° / 2) = 0.75: the box's larger half-side fills the height.
            const double height = std::max(o.halfWidth, o.depth / 2) / 0.75 + o.floatHeight + 1;
            return {{0, height, middle}, {0, -0.5, middle}, {0, 0, 1}, 73.74};
        }
        case FieldView::front:
            break;
    }
    return {{0, 0.35, -1}, {0, 0.25, 0}, {0, 1, 0}, 73.74};
}

// The seed's light in front; high above the middle for the other views, whose
// pictures would otherwise be lit at a grazing angle.
Light lightOf(const FieldOptions& o) {
    if (o.view == FieldView::front) return {"key", {5, 5, -10}, {1, 1, 1}, 1};
    return {"key", {5, 100, o.nearZ + o.depth / 2 - 10}, {1, 1, 1}, 1};
}

// Draws each ball's radius and centre. The draws of the default field (radius,
// x, z) come first and in that order, so that its files stay as they were.
class BallDrawer {
  public:
    explicit BallDrawer(const FieldOptions& o)
        : o_(o),
          rng_(o.seed),
          x_(-o.halfWidth, o.halfWidth),
          z_(o.nearZ, o.nearZ + o.depth),
          radius_(o.logRadii ? std::log(o.minRadius) : o.minRadius,
                  o.logRadii ? std::log(o.maxRadius) : o.maxRadius) {
        if (o.placement != FieldPlacement::clustered) return;
        for (int c = 0; c < std::max(1, o.clusters); ++c) {
            const double cx = x_(rng_);
            const double cz = z_(rng_);
            clusters_.push_back({cx, 0, cz});
        }
    }

    Sphere next(int i) {
        // Separate statements: the draws must come in this order on every compiler.
        const double drawn = radius_(rng_);
        const double radius = o_.logRadii ? std::exp(drawn) : drawn;
        Vec3 centre;
        if (o_.placement == FieldPlacement::clustered) {
            const Vec3& clump = clusters_[std::size_t(pick_(rng_) * double(clusters_.size()))];
            const double dx = spread_(rng_);
            const double dz = spread_(rng_);
            centre = {clump.x + dx * o_.clusterSpread, 0, clump.z + dz * o_.clusterSpread};
        } else {
            const double cx = x_(rng_);
            const double cz = z_(rng_);
            centre = {cx, 0, cz};
        }
        const double lift = o_.floatHeight > 0 ? pick_(rng_) * o_.floatHeight : 0;
        centre.y = -0.5 + radius + lift;
        return {"ball " + std::to_string(i), centre, radius, materialOf(i, o_.mix)};
    }

  private:
    const FieldOptions& o_;
    std::mt19937 rng_;
    std::uniform_real_distribution<double> x_, z_, radius_;
    std::uniform_real_distribution<double> pick_{0.0, 1.0};
    std::normal_distribution<double> spread_{0.0, 1.0};
    std::vector<Vec3> clusters_;
};

}  // namespace

Scene sphereField(const FieldOptions& o) {
    Scene s;
    s.camera = cameraOf(o);
    s.render.maxDepth = 5;
    s.background = {0.002, 0.002, 0.004};
    addMaterials(s);
    s.lights = {lightOf(o)};
    BallDrawer balls(o);
    s.spheres.reserve(std::size_t(o.count) + 1);
    for (int i = 0; i < o.count; ++i) s.spheres.push_back(balls.next(i));
    s.spheres.push_back({"floor", {0, -99999.5, 0}, 99999, "floor"});
    return s;
}

Scene sphereField(const FieldOptions& options, int width, int height) {
    Scene s = sphereField(options);
    s.render.width = width;
    s.render.height = height;
    return s;
}

FieldOptions untunedField(int n) {
    FieldOptions o;
    o.count = 40 + 37 * (n % 9);
    o.seed = 500 + std::uint32_t(n);
    o.halfWidth = 2.0 + n % 4;
    o.depth = 5.0 + 1.5 * (n % 5);
    return o;
}

}  // namespace whitted
