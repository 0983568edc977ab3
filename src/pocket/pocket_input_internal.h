// Shared by the pocket readers.
#pragma once

#include <string_view>
#include <vector>

#include "swarf/pocket/pocket_input.h"

namespace swarf::pocket {

/// The loop with the largest area becomes the outer boundary, the others islands.
Result<Pocket> pocket_from_loops(std::vector<Ring> loops, std::string_view source);

}  // namespace swarf::pocket
