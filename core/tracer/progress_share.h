#pragma once

#include <algorithm>

namespace whitted {

// The share of a render done, from its work done against the total it
// expects. An adaptive render expects anew after each pass, and its guesses
// grow as often as they shrink: a new total spreads the work it expects to be
// left over what is left of the bar, so the share a user watches never goes
// back (whitted-render's bar went from 21% back to 14% on a glass field).
class ProgressShare {
  public:
    void expect(double workDone, double totalWork) {
        startShare_ = at(workDone);
        startWork_ = workDone;
        total_ = totalWork;
    }

    double at(double workDone) const {
        if (total_ <= startWork_) return startShare_;
        const double ofRest = (workDone - startWork_) / (total_ - startWork_);
        return std::clamp(startShare_ + (1.0 - startShare_) * ofRest, startShare_, 1.0);
    }

  private:
    double startShare_ = 0.0, startWork_ = 0.0, total_ = 0.0;
};

}  // namespace whitted
