#pragma once
// Where a MultiBlock sweep's time goes, kernel by kernel
// (SmoothOptions::time_phases): an event is recorded after each kernel, and
// the time between two consecutive events is charged to the kernel that
// ended at the second. begin() starts a new chain, so that a gap the GPU
// spends idle (the host reading the stop flag back) is charged to no kernel.
// Disabled, it records nothing.
#include <cuda_runtime.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "kernels/cuda/cuda_event.hpp"

namespace tetsmooth::cuda {

class PhaseTimer {
 public:
  PhaseTimer(cudaStream_t stream, bool enabled) : stream_(stream), enabled_(enabled) {}

  void begin() { mark(nullptr); }
  // `phase` must outlive the timer (the callers pass string literals).
  void end_of(const char* phase) { mark(phase); }

  // Milliseconds per phase summed over the chains, phases in the order they
  // first ended; waits for the last event first.
  std::vector<std::pair<std::string, double>> totals() const {
    std::vector<std::pair<std::string, double>> out;
    if (!events_.empty()) events_.back()->synchronize();
    for (std::size_t k = 1; k < events_.size(); ++k) {
      if (!phases_[k]) continue;
      const double ms = events_[k]->ms_since(*events_[k - 1]);
      auto it = out.begin();
      while (it != out.end() && it->first != phases_[k]) ++it;
      if (it == out.end())
        out.emplace_back(phases_[k], ms);
      else
        it->second += ms;
    }
    return out;
  }

 private:
  void mark(const char* phase) {
    if (!enabled_) return;
    events_.push_back(std::make_unique<Event>());
    events_.back()->record(stream_);
    phases_.push_back(phase);
  }

  cudaStream_t stream_;
  bool enabled_;
  std::vector<std::unique_ptr<Event>> events_;
  std::vector<const char*> phases_;  // nullptr where a chain begins
};

}  // namespace tetsmooth::cuda
