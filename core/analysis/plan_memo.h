// Plans kept for the next asker of the same plan. In the editor the
// view's render to a target, the Render tab's prediction of it and an export
// at the scene's size each plan the same render, and planning is
// deterministic: the same scene, target and sample limit give the same plan
// (whatever the scene's own samples per pixel and depth, which it chooses).
// On a field of 150 glass balls at Final it takes up to 27 s, so the second
// asker takes the first one's plan, and one that comes while it is being made
// waits for it instead of making it again beside it.
#pragma once

#include <condition_variable>
#include <memory>
#include <mutex>
#include <vector>

#include "analysis/quality_target.h"
#include "scene/scene.h"
#include "tracer/renderer.h"

namespace whitted {

class PlanMemo {
  public:
    // planQuality(scene, target, maxSamples) with the depth chosen, or the
    // same plan made before. A plan `stop` cut short is returned (stopped)
    // but not kept; an asker waiting for it then plans for itself.
    std::shared_ptr<const QualityPlan> plan(const Scene& scene, const QualityTarget& target,
                                            int maxSamples, const StopPredicate& stop = {});

    // Plans made here rather than taken from before: what a test counts.
    int plansMade() const;

  private:
    struct Entry {
        Scene scene;
        QualityTarget target;
        int maxSamples = 0;
        std::shared_ptr<const QualityPlan> plan;  // null while it is being made
    };
    Entry* find(const Scene& scene, const QualityTarget& target, int maxSamples);
    void forget(const Entry* entry);

    mutable std::mutex mutex_;
    std::condition_variable planned_;
    std::vector<std::unique_ptr<Entry>> entries_;  // the newest last
    int plansMade_ = 0;
};

}  // namespace whitted
