#include "mesh/io/temp_file_cleanup.hpp"

#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstring>
#include <mutex>

namespace tetsmooth {
namespace {

// A signal handler may only touch lock-free atomics and fixed storage, so
// the registry is a small table of path buffers with a state each.
constexpr int kSlots = 16;
constexpr std::size_t kMaxPath = 4096;
enum SlotState : int { kFree = 0, kFilling = 1, kArmed = 2 };

struct Slot {
  std::atomic<int> state{kFree};
  char path[kMaxPath];
};
Slot g_slots[kSlots];
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs lock-free atomics");

// The signals whose default action does not end the process (or that
// cannot be caught); every other one, from 1 to NSIG - 1 (the real-time
// ones included), ends it, and a temporary left by any of them would be as
// stray as one left by Ctrl-C. SIGKILL alone can leave one.
bool ends_the_process(int sig) {
  switch (sig) {
    case SIGKILL: case SIGSTOP:                                   // not caught
    case SIGCHLD: case SIGCONT: case SIGURG: case SIGWINCH:       // ignored by default
    case SIGTSTP: case SIGTTIN: case SIGTTOU:                     // stop, not end
      return false;
    default:
      return true;
  }
}

extern "C" void remove_temps_and_die(int sig) {
  for (Slot& s : g_slots)
    if (s.state.load(std::memory_order_acquire) == kArmed) ::unlink(s.path);
  // The default action now, so the parent sees the process end by `sig`.
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  ::sigaction(sig, &dfl, nullptr);
  ::raise(sig);
}

void install_handlers_once() {
  static std::once_flag once;
  std::call_once(once, [] {
    struct sigaction act {};
    act.sa_handler = remove_temps_and_die;
    sigemptyset(&act.sa_mask);
    for (int sig = 1; sig < NSIG; ++sig)
      if (ends_the_process(sig)) sigaddset(&act.sa_mask, sig);  // one clean-up at a time
    for (int sig = 1; sig < NSIG; ++sig) {
      struct sigaction old {};
      if (!ends_the_process(sig) || ::sigaction(sig, nullptr, &old) != 0 || old.sa_handler != SIG_DFL) continue;
      ::sigaction(sig, &act, nullptr);
    }
  });
}

}  // namespace

int remember_temp_file(const std::string& path) {
  if (path.size() >= kMaxPath) return -1;
  install_handlers_once();
  for (int k = 0; k < kSlots; ++k) {
    int expected = kFree;
    if (!g_slots[k].state.compare_exchange_strong(expected, kFilling, std::memory_order_acq_rel)) continue;
    std::memcpy(g_slots[k].path, path.c_str(), path.size() + 1);
    g_slots[k].state.store(kArmed, std::memory_order_release);
    return k;
  }
  return -1;
}

void forget_temp_file(int slot) {
  if (slot >= 0 && slot < kSlots) g_slots[slot].state.store(kFree, std::memory_order_release);
}

}  // namespace tetsmooth
