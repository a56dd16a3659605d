// Float against double for one scene, as the editor's float-versus-double view
// shows it: both renders, where they differ in display values (a heat map and
// counts), and how many pixels took a different hit, shadow or total internal
// reflection decision (ray_decisions.h).
#pragma once

#include <cstddef>

#include "image/image.h"
#include "scene/scene.h"
#include "tracer/renderer.h"

namespace whitted {

struct PrecisionComparison {
    int width = 0, height = 0;  // the size both sides were rendered at
    Image heatMap;              // heat_map.h: black where the two renders agree
    std::size_t pixels = 0;     // width * height
    std::size_t over1 = 0;      // pixels whose displayDifference() exceeds 1/255
    std::size_t over2 = 0;      // ... exceeds 2/255
    float largest = 0.0f;       // the largest displayDifference(), in [0, 1] (x255: 8-bit steps)
    // Pixels whose camera ray tree (through the pixel centre) first differs in a hit,
    // in a shadow, in a total internal reflection (firstDifference()); each pixel
    // counts at most once, under the first decision that differs.
    std::size_t hitDiffers = 0;
    std::size_t shadowDiffers = 0;
    std::size_t tirDiffers = 0;
    bool stopped = false;  // `stop` said so before the end: the other fields are incomplete
};

// Renders the scene in float and in double at width x height (its camera, its
// samples per pixel and depth, render() in one pass on all cores) and compares
// the two. `stop` is asked between tile rows and pixel rows.
PrecisionComparison comparePrecisions(const Scene& scene, int width, int height,
                                      const StopPredicate& stop = {});

// The same comparison between two scenes, each rendered in its own precision:
// comparePrecisions() is compareScenes(scene in float, scene in double). Counting
// decisions assumes the scenes list their lights and spheres alike, as a scene
// and a copy with other numbers do.
PrecisionComparison compareScenes(const Scene& a, const Scene& b, int width, int height,
                                  const StopPredicate& stop = {});

}  // namespace whitted
