#include "ray_tree_json.h"

namespace whitted {
namespace {

nlohmann::ordered_json triple(const Vec3& v) {
    return {v.x, v.y, v.z};
}

const char* kindName(RayTreeNode::Kind kind) {
    switch (kind) {
        case RayTreeNode::Kind::Camera:
            return "camera";
        case RayTreeNode::Kind::Reflection:
            return "reflection";
        case RayTreeNode::Kind::Refraction:
            return "refraction";
        case RayTreeNode::Kind::Shadow:
            return "shadow";
    }
    return "camera";
}

nlohmann::ordered_json nodeJson(const RayTreeNode& n, const Scene& scene) {
    nlohmann::ordered_json j;
    j["kind"] = kindName(n.kind);
    j["origin"] = triple(n.origin);
    j["direction"] = triple(n.direction);
    j["depth"] = n.depth;
    j["hit"] =
        n.hit >= 0 ? nlohmann::ordered_json(scene.spheres[std::size_t(n.hit)].name) : nullptr;
    j["t"] = n.t;
    j["weight"] = n.weight;
    j["contribution"] = triple(n.contribution);
    if (n.kind == RayTreeNode::Kind::Shadow) {
        j["light"] = scene.lights[std::size_t(n.light)].name;
        j["transmittance"] = n.transmittance;
    } else {
        j["radiance"] = triple(n.radiance);
    }
    if (n.hit >= 0) j["entering"] = n.entering;
    if (n.totalInternalReflection) j["total_internal_reflection"] = true;
    if (n.cutOff) j["past_depth"] = triple(n.pastDepth);
    j["children"] = nlohmann::ordered_json::array();
    for (const RayTreeNode& c : n.children) j["children"].push_back(nodeJson(c, scene));
    return j;
}

}  // namespace

nlohmann::ordered_json rayTreeJson(const PixelRayTree& tree, const Scene& scene) {
    return {{"pixel", {tree.x, tree.y}},
            {"value", triple(tree.value)},
            {"rays", nodeJson(tree.root, scene)}};
}

}  // namespace whitted
