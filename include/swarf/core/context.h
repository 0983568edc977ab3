// An explicit context for long operations (STYLE.md 4): progress reports, cancellation
// and the thread count travel in it. Library code never prints.
#pragma once

#include <atomic>
#include <functional>
#include <string_view>

namespace swarf {

struct Context {
  /// Called with a stage name and a fraction in [0, 1]. May be empty.
  std::function<void(std::string_view stage, double fraction)> progress;
  /// Set to true (from any thread) to ask the running operation to stop with kCancelled.
  const std::atomic<bool>* cancel = nullptr;
  /// Worker threads for parallel stages; 0 = all hardware threads. Results never depend on it.
  int threads = 0;

  void report(std::string_view stage, double fraction) const {
    if (progress) progress(stage, fraction);
  }
  bool cancelled() const { return cancel != nullptr && cancel->load(std::memory_order_relaxed); }
};

/// A context that reports nothing, cannot be cancelled and uses every core.
inline const Context& default_context() {
  static const Context ctx;
  return ctx;
}

}  // namespace swarf
