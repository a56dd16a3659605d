#include "analysis/pixel_ray_tree.h"

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "tracer/scalar_ray_tree.h"

namespace whitted {
namespace {

RayTreeNode::Kind kindOf(TreeRay ray) {
    switch (ray) {
        case TreeRay::Camera:
            return RayTreeNode::Kind::Camera;
        case TreeRay::Reflection:
            return RayTreeNode::Kind::Reflection;
        case TreeRay::Refraction:
            return RayTreeNode::Kind::Refraction;
    }
    return RayTreeNode::Kind::Camera;
}

// Builds the tree as ScalarRayTree walks it, and on leaving each ray has the
// kernel trace it: once at its own depth (its radiance) and once at the
// maximum depth, where it spawns nothing (its own shading).
template <typename T>
struct TreeBuilder {
    static constexpr bool kWantsShadows = true;
    const Scene& scene;
    const PreparedScene<T>& s;
    std::unique_ptr<PreparedScene<T>> deeper;  // prepared when a ray is cut off
    RayTreeNode root;
    struct Open {
        RayTreeNode* node;
        Ray<T> ray;
        T weight;
    };
    std::vector<Open> path;  // the ray being walked and those above it

    void hit(int) {}
    void shadow(int) {}
    void tir(bool total) { path.back().node->totalInternalReflection = total; }
    void cutOff(T) { path.back().node->cutOff = true; }
    bool descend(T, int) { return true; }

    void enter(TreeRay kind, const Ray<T>& ray, const std::optional<Hit<T>>& hit, int depth,
               T weight) {
        RayTreeNode* node = path.empty() ? &root : &path.back().node->children.emplace_back();
        node->kind = kindOf(kind);
        node->origin = s.frameOrigin + Vec3(ray.origin);
        node->direction = Vec3(ray.dir);
        node->depth = depth;
        node->weight = double(weight);
        if (hit) {
            node->hit = hit->sphere;
            node->t = double(hit->t);
            // As ScalarRayTree and the kernel decide it, expression for expression.
            const Vec<T> p = ray.origin + hit->t * ray.dir;
            const Vec<T> outward = glm::normalize(p - s.spheres.centre[hit->sphere]);
            node->entering = !(glm::dot(ray.dir, outward) > T(0));
        }
        path.push_back({node, ray, weight});
    }

    void shadowRay(int light, const Vec<T>& p, const Vec<T>& l, T distance, T sj) {
        const Open& at = path.back();
        RayTreeNode& n = at.node->children.emplace_back();
        n.kind = RayTreeNode::Kind::Shadow;
        n.origin = s.frameOrigin + Vec3(p);
        n.direction = Vec3(l);
        n.depth = at.node->depth;
        n.weight = at.node->weight;
        n.t = double(distance);
        n.light = light;
        n.transmittance = double(sj);
    }

    void leave() {
        const Open open = path.back();
        path.pop_back();
        RayTreeNode& node = *open.node;
        RayCounts counts;
        const Vec<T> radiance = traceRay(s, open.ray, node.depth, counts);
        const Vec<T> own = node.hit < 0 ? s.background : traceRay(s, open.ray, s.maxDepth, counts);
        node.radiance = Vec3(radiance);
        node.contribution = Vec3(open.weight * own);
        if (node.cutOff) {
            if (!deeper) {
                Scene deep = scene;
                deep.render.maxDepth = scene.render.maxDepth + kPastDepthLevels;
                deeper = std::make_unique<PreparedScene<T>>(prepareScene<T>(deep));
            }
            const Vec<T> beyond = traceRay(*deeper, open.ray, node.depth, counts);
            node.pastDepth = Vec3(open.weight * (beyond - own));
        }
    }
};

template <typename T>
PixelRayTree treeIn(const Scene& scene, int x, int y) {
    const PreparedScene<T> s = prepareScene<T>(scene);
    TreeBuilder<T> builder{scene, s, nullptr, {}, {}};
    ScalarRayTree<T, TreeBuilder<T>>(s, builder).tracePixel(x, y);
    PixelRayTree tree;
    tree.x = x;
    tree.y = y;
    tree.root = std::move(builder.root);
    // The image holds float whatever the precision traced.
    tree.value = Vec3(glm::vec3(tree.root.radiance));
    return tree;
}

}  // namespace

PixelRayTree pixelRayTree(const Scene& scene, int x, int y) {
    return pixelRayTree(scene, x, y, scene.render.precision);
}

PixelRayTree pixelRayTree(const Scene& scene, int x, int y, Precision precision) {
    if (x < 0 || y < 0 || x >= scene.render.width || y >= scene.render.height)
        throw std::out_of_range("pixel " + std::to_string(x) + "," + std::to_string(y) +
                                " is outside the " + std::to_string(scene.render.width) + "x" +
                                std::to_string(scene.render.height) + " picture");
    return precision == Precision::Float ? treeIn<float>(scene, x, y) : treeIn<double>(scene, x, y);
}

Vec3 sumOfContributions(const RayTreeNode& node) {
    Vec3 sum = node.contribution;
    for (const RayTreeNode& child : node.children) sum += sumOfContributions(child);
    return sum;
}

}  // namespace whitted
