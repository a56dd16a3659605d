#include "analysis/plan_memo.h"

#include <algorithm>
#include <chrono>

namespace whitted {

namespace {

// The view's target and the one an export or a preset's tooltip asks about:
// a few scenes' plans, each holding a copy of its scene.
constexpr std::size_t kPlansKept = 4;

// How often a waiting asker looks whether it should stop.
constexpr std::chrono::milliseconds kStopPoll{20};

}  // namespace

PlanMemo::Entry* PlanMemo::find(const Scene& scene, const QualityTarget& target, int maxSamples) {
    for (const std::unique_ptr<Entry>& e : entries_)
        if (e->maxSamples == maxSamples && e->target == target && plannedAlike(e->scene, scene))
            return e.get();
    return nullptr;
}

void PlanMemo::forget(const Entry* entry) {
    std::erase_if(entries_, [&](const std::unique_ptr<Entry>& e) { return e.get() == entry; });
}

std::shared_ptr<const QualityPlan> PlanMemo::plan(const Scene& scene, const QualityTarget& target,
                                                  int maxSamples, const StopPredicate& stop) {
    std::unique_lock lock(mutex_);
    for (;;) {
        const Entry* found = find(scene, target, maxSamples);
        if (!found) break;
        if (found->plan) return found->plan;
        // Being made by another asker: wait for it, or for its stopping.
        planned_.wait_for(lock, kStopPoll);
        if (stop && stop()) {
            auto stopped = std::make_shared<QualityPlan>();
            stopped->target = target;
            stopped->stopped = true;
            return stopped;
        }
    }
    entries_.push_back(std::make_unique<Entry>(Entry{scene, target, maxSamples, nullptr}));
    Entry* making = entries_.back().get();
    ++plansMade_;
    lock.unlock();
    auto made = std::make_shared<const QualityPlan>(
        planQuality(scene, target, maxSamples, std::nullopt, stop));
    lock.lock();
    if (made->stopped) {
        forget(making);
    } else {
        making->plan = made;
        // The oldest finished plans go first; plans being made stay.
        while (entries_.size() > kPlansKept) {
            const auto oldest = std::find_if(entries_.begin(), entries_.end(),
                                             [](const auto& e) { return e->plan != nullptr; });
            if (oldest == entries_.end()) break;
            entries_.erase(oldest);
        }
    }
    planned_.notify_all();
    return made;
}

int PlanMemo::plansMade() const {
    std::lock_guard lock(mutex_);
    return plansMade_;
}

}  // namespace whitted
