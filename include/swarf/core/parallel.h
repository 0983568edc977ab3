// Deterministic parallel loops: each index is handled exactly once and writes only its own
// result slot, so the output never depends on the number of threads (STYLE.md 12).
#pragma once

#include <cstddef>
#include <functional>

namespace swarf {

/// Number of worker threads to use for `requested` (0 = hardware concurrency), at least 1.
int resolve_threads(int requested);

/// Calls body(i) for every i in [0, n), spread over `threads` threads (0 = all cores),
/// in dynamically scheduled chunks. body must only write state owned by index i.
/// Exceptions thrown by body are rethrown on the calling thread (the first one wins).
void parallel_for(std::size_t n, int threads, const std::function<void(std::size_t)>& body);

}  // namespace swarf
