// A thread of its own that serves requests one at a time: the editor's render,
// float-versus-double and error workers. One statement of their rules, tested
// once (tests/core/test_request_thread.cpp):
//
//   - request() hands a request over and returns at once with its ticket;
//     the work runs on the thread, never on the caller's.
//   - LatestWins: a new request replaces the one waiting and makes the running
//     one stale; EveryRequest: requests wait in line and each runs once.
//   - cancel() drops what waits and makes the running one stale;
//     dropWaiting() drops what waits and leaves the rest as it is.
//   - stale(ticket) is what a long work asks between steps: a stale work's
//     result is wanted by nobody, so it stops. The destructor makes every
//     ticket stale, and returns once the running work has.
//
// No Qt: the workers hand results to the GUI through their own signals.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <utility>

namespace whitted {

template <typename Request>
class RequestThread {
  public:
    enum class Policy { LatestWins, EveryRequest };
    // Runs on the thread with each request taken and its ticket.
    using Work = std::function<void(Request&& request, std::uint64_t ticket)>;

    // `atStart` runs first on the new thread (to lower its priority, say).
    RequestThread(Policy policy, Work work, std::function<void()> atStart = {})
        : policy_(policy), work_(std::move(work)), thread_([this, start = std::move(atStart)] {
              if (start) start();
              run();
          }) {}

    ~RequestThread() {
        {
            std::lock_guard lock(mutex_);
            quitting_ = true;
        }
        wake_.notify_one();
        thread_.join();
    }

    RequestThread(const RequestThread&) = delete;
    RequestThread& operator=(const RequestThread&) = delete;

    // The request's ticket: 1, 2, 3... in the order of the calls.
    std::uint64_t request(Request request) {
        std::uint64_t ticket;
        {
            std::lock_guard lock(mutex_);
            ticket = ++last_;
            if (policy_ == Policy::LatestWins) {
                waiting_.clear();
                staleBelow_ = ticket;
            }
            waiting_.push_back({std::move(request), ticket});
        }
        wake_.notify_one();
        return ticket;
    }

    // Drops the waiting requests and makes the running one stale. Takes a
    // ticket of its own, so that latestTicket() moves past every result due.
    void cancel() {
        std::lock_guard lock(mutex_);
        waiting_.clear();
        staleBelow_ = ++last_;
    }

    // Drops the waiting requests, at once, and nothing else: for a caller
    // about to ask again, whose waiting request holds what it is about to
    // change (the editor's render request holds the scene an edit is about to
    // write, which it would otherwise copy).
    void dropWaiting() {
        std::deque<Waiting> dropped;
        std::lock_guard lock(mutex_);
        dropped.swap(waiting_);
    }

    std::uint64_t latestTicket() const { return last_.load(); }

    // Whether the request of `ticket` is no longer wanted. Any thread.
    bool stale(std::uint64_t ticket) const {
        return quitting_.load(std::memory_order_relaxed) ||
               ticket < staleBelow_.load(std::memory_order_relaxed);
    }

  private:
    struct Waiting {
        Request request;
        std::uint64_t ticket;
    };

    void run() {
        for (;;) {
            std::optional<Waiting> next;
            {
                std::unique_lock lock(mutex_);
                wake_.wait(lock, [this] { return quitting_ || !waiting_.empty(); });
                if (quitting_) return;
                next.emplace(std::move(waiting_.front()));
                waiting_.pop_front();
            }
            work_(std::move(next->request), next->ticket);
        }
    }

    const Policy policy_;
    const Work work_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<Waiting> waiting_;  // guarded by mutex_
    // Written under mutex_, read by stale() from any thread.
    std::atomic<std::uint64_t> last_{0}, staleBelow_{0};
    std::atomic<bool> quitting_{false};
    std::thread thread_;  // last: starts once everything above exists
};

}  // namespace whitted
