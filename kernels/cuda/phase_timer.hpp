#pragma once
// Where a MultiBlock sweep's time goes, kernel by kernel
// (SmoothOptions::time_phases). Each chunk of sweeps between two host
// checks is a chain of events: begin() before its first kernel, end_of()
// after each kernel, and the time between two consecutive events is charged
// to the kernel that ended at the second. The host's check between chunks
// (the state copy and its wait) is charged to no kernel; the first kernel
// of a chunk does carry its own launch latency, since the GPU is idle when
// the chain begins. collect() reads a chunk's events once the stream has
// synchronised, so the same events serve every chunk. Disabled, it records
// nothing.
#include <cuda_runtime.h>

#include <cstddef>
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

  // Adds the chunk's times to the totals. Call once the stream has
  // synchronised, before the next begin().
  void collect() {
    for (std::size_t k = 1; k < used_; ++k)
      if (phases_[k]) add(phases_[k], events_[k]->ms_since(*events_[k - 1]));
    used_ = 0;
  }

  // Milliseconds per phase over the chunks collected, phases in the order
  // they first ended.
  const std::vector<std::pair<std::string, double>>& totals() const { return totals_; }

 private:
  void mark(const char* phase) {
    if (!enabled_) return;
    if (used_ == events_.size()) {
      events_.push_back(std::make_unique<Event>());
      phases_.push_back(nullptr);
    }
    phases_[used_] = phase;
    events_[used_++]->record(stream_);
  }

  void add(const char* phase, double ms) {
    for (auto& [name, total] : totals_)
      if (name == phase) {
        total += ms;
        return;
      }
    totals_.emplace_back(phase, ms);
  }

  cudaStream_t stream_;
  bool enabled_;
  std::vector<std::unique_ptr<Event>> events_;  // reused by every chunk
  std::vector<const char*> phases_;             // what events_[k] ends; nullptr where a chain begins
  std::size_t used_ = 0;                        // events recorded in this chunk
  std::vector<std::pair<std::string, double>> totals_;
};

}  // namespace tetsmooth::cuda
