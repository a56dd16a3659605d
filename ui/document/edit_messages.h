// Turns core's validation problem for an edit ("spheres[0].radius: must be > 0,
// found 0") into the user's words ("Radius of sphere “ball” must be greater
// than 0"): the item by its name, the field by its label (scene_fields.h),
// the problem by its kind, never by the reason's words. Files and the CLI keep
// core's JSON paths; only the editor's refused edits speak this way.
#pragma once

#include <QString>

#include "scene/scene.h"
#include "scene/scene_io.h"

namespace whitted::ui {

// `scene` is the refused scene the problem was found in (it names the items).
// A problem this does not know keeps core's wording.
QString editProblemText(const SceneProblem& problem, const Scene& scene);

}  // namespace whitted::ui
