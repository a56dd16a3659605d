// The rules of core/base/request_thread.h, which the editor's render,
// float-versus-double and error workers rely on: what runs, in what order, on
// which thread, and when a running request learns it is stale.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "base/request_thread.h"

namespace whitted {
namespace {

using Policy = RequestThread<std::string>::Policy;

// What the thread did, and a gate that holds a work until the test opens it.
struct Log {
    std::mutex mutex;
    std::condition_variable changed;
    std::vector<std::string> ran;     // requests, in the order they started
    std::vector<std::string> staled;  // requests that saw themselves stale while held
    std::thread::id thread;
    bool gateOpen = false;

    void started(const std::string& request) {
        std::lock_guard lock(mutex);
        ran.push_back(request);
        thread = std::this_thread::get_id();
        changed.notify_all();
    }
    // Waits until `n` requests have started (at most 10 s).
    bool waitForRuns(std::size_t n) {
        std::unique_lock lock(mutex);
        return changed.wait_for(lock, std::chrono::seconds(10), [&] { return ran.size() >= n; });
    }
    void openGate() {
        std::lock_guard lock(mutex);
        gateOpen = true;
        changed.notify_all();
    }
};

// A work that, for requests starting with "hold", waits until it is stale or
// the gate opens, as a long render polls between tiles.
RequestThread<std::string>::Work holdingWork(Log& log, RequestThread<std::string>*& self) {
    return [&log, &self](std::string&& request, std::uint64_t ticket) {
        log.started(request);
        if (request.rfind("hold", 0) != 0) return;
        std::unique_lock lock(log.mutex);
        while (!log.gateOpen) {
            if (self->stale(ticket)) {
                log.staled.push_back(request);
                log.changed.notify_all();
                return;
            }
            log.changed.wait_for(lock, std::chrono::milliseconds(1));
        }
    };
}

TEST(RequestThread, LatestWins_ANewRequestStalesTheRunningOne_AndOnlyTheNewestWaitingRuns) {
    Log log;
    RequestThread<std::string>* self = nullptr;
    RequestThread<std::string> worker(Policy::LatestWins, holdingWork(log, self));
    self = &worker;
    EXPECT_EQ(worker.request("hold 1"), 1u);
    ASSERT_TRUE(log.waitForRuns(1));
    EXPECT_FALSE(worker.stale(1));
    worker.request("2");
    worker.request("3");
    EXPECT_EQ(worker.request("4"), 4u);
    EXPECT_TRUE(worker.stale(1));
    EXPECT_FALSE(worker.stale(4));
    ASSERT_TRUE(log.waitForRuns(2));
    std::lock_guard lock(log.mutex);
    EXPECT_EQ(log.ran, (std::vector<std::string>{"hold 1", "4"}));
    EXPECT_EQ(log.staled, std::vector<std::string>{"hold 1"});
    EXPECT_NE(log.thread, std::this_thread::get_id());
    EXPECT_EQ(worker.latestTicket(), 4u);
}

// A worker running "hold 1", which waits at the gate, with "2" waiting behind it.
struct HeldWithOneWaiting {
    explicit HeldWithOneWaiting(Policy policy) : worker(policy, holdingWork(log, self)) {
        self = &worker;
        worker.request("hold 1");
        holding = log.waitForRuns(1);
        worker.request("2");
    }
    Log log;
    RequestThread<std::string>* self = nullptr;
    RequestThread<std::string> worker;
    bool holding = false;
};

TEST(RequestThread, Cancel_StalesTheRunningOne_DropsTheWaiting_ThenServesAgain) {
    for (const Policy policy : {Policy::LatestWins, Policy::EveryRequest}) {
        HeldWithOneWaiting held(policy);
        ASSERT_TRUE(held.holding);
        auto& [log, self, worker, holding] = held;
        worker.cancel();
        EXPECT_TRUE(worker.stale(1));
        EXPECT_TRUE(worker.stale(2));
        EXPECT_EQ(worker.latestTicket(), 3u) << "cancel takes a ticket of its own";
        EXPECT_EQ(worker.request("4"), 4u);
        EXPECT_FALSE(worker.stale(4));
        ASSERT_TRUE(log.waitForRuns(2));
        std::lock_guard lock(log.mutex);
        EXPECT_EQ(log.ran, (std::vector<std::string>{"hold 1", "4"}));
        EXPECT_EQ(log.staled, std::vector<std::string>{"hold 1"});
    }
}

TEST(RequestThread, DropWaiting_TheWaitingNeverRuns_TheRunningGoesOn_TicketsAsTheyWere) {
    for (const Policy policy : {Policy::LatestWins, Policy::EveryRequest}) {
        HeldWithOneWaiting held(policy);
        ASSERT_TRUE(held.holding);
        auto& [log, self, worker, holding] = held;
        const bool runningStale = worker.stale(1);
        worker.dropWaiting();
        EXPECT_EQ(worker.stale(1), runningStale);
        EXPECT_EQ(worker.latestTicket(), 2u);
        log.openGate();
        EXPECT_EQ(worker.request("3"), 3u);
        ASSERT_TRUE(log.waitForRuns(2));
        std::lock_guard lock(log.mutex);
        EXPECT_EQ(log.ran, (std::vector<std::string>{"hold 1", "3"}));
    }
    // What a dropped request held is let go of at once.
    std::mutex gate;
    std::unique_lock held(gate);
    std::atomic<int> started{0};
    RequestThread<std::shared_ptr<int>> worker(
        RequestThread<std::shared_ptr<int>>::Policy::LatestWins,
        [&](std::shared_ptr<int>&&, std::uint64_t) {
            ++started;
            std::lock_guard wait(gate);
        });
    worker.request(std::make_shared<int>(1));
    for (int i = 0; i < 10000 && started == 0; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    ASSERT_EQ(started, 1) << "the first runs, and waits for the gate";
    const auto payload = std::make_shared<int>(2);
    worker.request(payload);
    EXPECT_EQ(payload.use_count(), 2) << "waiting";
    worker.dropWaiting();
    EXPECT_EQ(payload.use_count(), 1) << "dropped";
    held.unlock();
}

TEST(RequestThread, EveryRequest_RunsEachOnceInOrder_NoneStale) {
    Log log;
    RequestThread<std::string>* self = nullptr;
    RequestThread<std::string> worker(Policy::EveryRequest, holdingWork(log, self));
    self = &worker;
    worker.request("hold 1");
    ASSERT_TRUE(log.waitForRuns(1));
    worker.request("2");
    worker.request("3");
    EXPECT_FALSE(worker.stale(1));
    log.openGate();
    ASSERT_TRUE(log.waitForRuns(3));
    std::lock_guard lock(log.mutex);
    EXPECT_EQ(log.ran, (std::vector<std::string>{"hold 1", "2", "3"}));
    EXPECT_TRUE(log.staled.empty());
}

TEST(RequestThread, Destruction_StalesTheRunningWork_AndNothingWaitingRuns) {
    Log log;
    {
        RequestThread<std::string>* self = nullptr;
        RequestThread<std::string> worker(Policy::EveryRequest, holdingWork(log, self));
        self = &worker;
        worker.request("hold 1");
        ASSERT_TRUE(log.waitForRuns(1));
        worker.request("2");
    }  // returns only once "hold 1" has stopped, the gate never opened
    EXPECT_EQ(log.ran, std::vector<std::string>{"hold 1"});
    EXPECT_EQ(log.staled, std::vector<std::string>{"hold 1"});
}

TEST(RequestThread, AtStart_RunsOnTheWorkersThreadBeforeAnyWork) {
    Log log;
    std::thread::id startedOn;
    std::size_t runsAtStart = 99;
    RequestThread<std::string>* self = nullptr;
    RequestThread<std::string> worker(Policy::LatestWins, holdingWork(log, self), [&] {
        startedOn = std::this_thread::get_id();
        runsAtStart = log.ran.size();
    });
    self = &worker;
    worker.request("1");
    ASSERT_TRUE(log.waitForRuns(1));
    std::lock_guard lock(log.mutex);
    EXPECT_EQ(startedOn, log.thread);
    EXPECT_EQ(runsAtStart, 0u);
}

}  // namespace
}  // namespace whitted
