// File helpers. Outputs are written to a temporary file beside the target and renamed,
// so a failure never leaves a partial output behind.
#pragma once

#include <string>
#include <string_view>

#include "swarf/core/status.h"

namespace swarf {

/// Reads a whole file. kIo with the path in the message when it cannot be read.
Result<std::string> read_file(const std::string& path);

/// Writes content to path atomically (temporary file in the same folder, then rename).
/// Creates missing parent folders. A symbolic link is followed (the file it names is
/// replaced, the link kept); a device or pipe (/dev/null, a FIFO) is written in place.
Status write_file_atomic(const std::string& path, std::string_view content);

}  // namespace swarf
