// PlanMemo: the editor's view, its prediction and an export plan a render to
// a target once between them.
#include <atomic>
#include <chrono>
#include <memory>
#include <thread>

#include <gtest/gtest.h>

#include "analysis/plan_memo.h"
#include "support/core_support.h"

namespace whitted {
namespace {

using namespace std::chrono_literals;

Scene pictured() {
    return test::seedScene(160, 120);
}

TEST(PlanMemo, SameSceneAndTarget_TheSecondAskerTakesTheFirstsPlan) {
    PlanMemo memo;
    const Scene scene = pictured();
    const auto first = memo.plan(scene, previewQuality(), kDefaultMaxSamples);
    const auto second = memo.plan(scene, previewQuality(), kDefaultMaxSamples);
    EXPECT_EQ(first.get(), second.get());
    EXPECT_EQ(memo.plansMade(), 1);
    // The plan planQuality() makes, reasons and all.
    const QualityPlan direct = planQuality(scene, previewQuality());
    EXPECT_EQ(first->maxDepth, direct.maxDepth);
    EXPECT_EQ(first->why, direct.why);
    EXPECT_GT(first->cpuSeconds, 0.0);
}

TEST(PlanMemo, AnotherCameraTargetOrLimit_PlannedAgain) {
    PlanMemo memo;
    Scene scene = pictured();
    const auto preview = memo.plan(scene, previewQuality(), kDefaultMaxSamples);
    EXPECT_NE(memo.plan(scene, finalQuality(), kDefaultMaxSamples).get(), preview.get());
    EXPECT_NE(memo.plan(scene, previewQuality(), 64).get(), preview.get());
    scene.camera.position.x += 0.1;
    EXPECT_NE(memo.plan(scene, previewQuality(), kDefaultMaxSamples).get(), preview.get());
    EXPECT_EQ(memo.plansMade(), 4);
}

// Choosing a preset sets the samples per pixel and the depth, which a plan
// chooses itself: the plan made before stays. The precision and the
// picture's size are planned again.
TEST(PlanMemo, OtherSamplesOrDepth_TheSamePlan_OtherPrecisionOrSize_PlannedAgain) {
    PlanMemo memo;
    const Scene scene = pictured();
    const auto final = memo.plan(scene, finalQuality(), kDefaultMaxSamples);
    Scene preset = scene;
    preset.render.samplesPerPixel = 128;
    preset.render.maxDepth = 8;
    EXPECT_EQ(memo.plan(preset, finalQuality(), kDefaultMaxSamples).get(), final.get());
    EXPECT_EQ(planQuality(preset, finalQuality()).why, final->why);  // what it would have made
    Scene doubled = scene;
    doubled.render.precision = Precision::Double;
    EXPECT_NE(memo.plan(doubled, finalQuality(), kDefaultMaxSamples).get(), final.get());
    Scene wider = scene;
    wider.render.width = 200;
    EXPECT_NE(memo.plan(wider, finalQuality(), kDefaultMaxSamples).get(), final.get());
    EXPECT_EQ(memo.plansMade(), 3);
}

TEST(PlanMemo, StoppedPlan_IsNotKept_TheNextAskerPlans) {
    PlanMemo memo;
    const Scene scene = pictured();
    const auto stopped =
        memo.plan(scene, previewQuality(), kDefaultMaxSamples, [] { return true; });
    EXPECT_TRUE(stopped->stopped);
    const auto planned = memo.plan(scene, previewQuality(), kDefaultMaxSamples);
    EXPECT_FALSE(planned->stopped);
    EXPECT_EQ(memo.plansMade(), 2);
}

// The first asker's stop predicate holds its planning back until the test
// releases it, so that others come while the plan is being made.
struct HeldPlanning {
    PlanMemo memo;
    Scene scene = pictured();
    std::atomic<bool> started{false}, released{false}, firstDone{false};

    std::shared_ptr<const QualityPlan> first(bool stopAfterHold) {
        bool held = false;
        auto plan = memo.plan(scene, previewQuality(), kDefaultMaxSamples, [&] {
            if (!held) {
                held = true;
                started = true;
                const auto giveUp = std::chrono::steady_clock::now() + 10s;  // a failed test
                while (!released && std::chrono::steady_clock::now() < giveUp)
                    std::this_thread::sleep_for(1ms);
            }
            return stopAfterHold;
        });
        firstDone = true;
        return plan;
    }
    void waitUntilStarted() const {
        while (!started) std::this_thread::sleep_for(1ms);
    }
};

// Two askers of the same plan, the second coming while the first makes it.
void askTwice(HeldPlanning& h, bool firstStops, std::shared_ptr<const QualityPlan>& a,
              std::shared_ptr<const QualityPlan>& b) {
    std::thread first([&] { a = h.first(firstStops); });
    std::thread second([&] {
        h.waitUntilStarted();
        b = h.memo.plan(h.scene, previewQuality(), kDefaultMaxSamples);
    });
    h.waitUntilStarted();
    std::this_thread::sleep_for(100ms);  // the second is waiting by now
    h.released = true;
    first.join();
    second.join();
}

TEST(PlanMemo, SecondAskerWhileItIsMade_WaitsForTheSamePlan) {
    HeldPlanning h;
    std::shared_ptr<const QualityPlan> a, b;
    askTwice(h, false, a, b);
    EXPECT_EQ(a.get(), b.get());
    EXPECT_FALSE(b->stopped);
    EXPECT_EQ(h.memo.plansMade(), 1);
}

TEST(PlanMemo, FirstAskerStopped_TheWaitingOnePlansForItself) {
    HeldPlanning h;
    std::shared_ptr<const QualityPlan> a, b;
    askTwice(h, true, a, b);
    EXPECT_TRUE(a->stopped);
    EXPECT_FALSE(b->stopped);
    EXPECT_EQ(h.memo.plansMade(), 2);
}

// A waiting asker whose own request went stale does not wait for the plan.
TEST(PlanMemo, WaitingAskerStopped_ReturnsAStoppedPlanWhileTheOtherPlans) {
    HeldPlanning h;
    std::shared_ptr<const QualityPlan> a;
    std::thread first([&] { a = h.first(false); });
    h.waitUntilStarted();
    const auto b = h.memo.plan(h.scene, previewQuality(), kDefaultMaxSamples, [] { return true; });
    EXPECT_FALSE(h.firstDone);
    h.released = true;
    first.join();
    EXPECT_TRUE(b->stopped);
    EXPECT_FALSE(a->stopped);
    EXPECT_EQ(h.memo.plansMade(), 1);
}

}  // namespace
}  // namespace whitted
