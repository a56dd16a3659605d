// What this machine gives a second thread, for work that shares nothing but
// the cores and the memory: the ceiling for any program's two-thread speed-up
// here. Each probe times the same work on one thread and then on each of two
// at once; 2.00 means the second thread lost nothing. On a virtual machine the
// two vCPUs may share a physical core's units, its clock or its memory with
// each other and with other guests, which no counter inside shows.
#pragma once

#include <string>
#include <vector>

namespace whitted::bench {

struct ProbeResult {
    std::string name;
    double oneThreadMs = 0;   // the work on one thread, fastest run
    double twoThreadsMs = 0;  // the same work on each of two threads at once, fastest run
    double speedUp() const { return 2.0 * oneThreadMs / twoThreadsMs; }
};

// Dependent integer multiplies (one core's latency, no unit saturated),
// independent vector multiply-adds (the floating-point units), reads of a
// buffer far larger than the caches (the memory's bandwidth) and first
// writes to new pages (the kernel's page faults); each the fastest of `runs`.
std::vector<ProbeResult> probeMachine(int runs);

}  // namespace whitted::bench
