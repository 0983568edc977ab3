#include "swarf/core/io.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>

namespace swarf {
namespace {

namespace fs = std::filesystem;

Status io_error(const std::string& path, const std::string& what) {
  return {Error::kIo, path + ": " + what};
}

// A name beside the target that no concurrent writer in this or another process picks.
std::string temp_name(const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  // Built by appending: GCC 12 reports a false -Wrestrict on chained operator+ here.
  std::string name = ".";
  name += target.filename().string();
  name += ".tmp.";
  name += std::to_string(::getpid());
  name += '.';
  name += std::to_string(counter.fetch_add(1));
  return (target.parent_path() / name).string();
}

}  // namespace

Result<std::string> read_file(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) return io_error(path, "is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) return io_error(path, std::string("cannot open: ") + std::strerror(errno));
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) return io_error(path, "read failed");
  return ss.str();
}

Status write_file_atomic(const std::string& path, std::string_view content) {
  if (path.empty()) return io_error("(empty path)", "no output file named");
  std::error_code ec;
  // A link is followed, so that the file it names is replaced and the link stays.
  fs::path target(path);
  if (fs::is_symlink(target, ec)) {
    const fs::path real = fs::weakly_canonical(target, ec);
    if (!ec) target = real;
  }
  // A device or a pipe (-o /dev/null, a named pipe) is written in place: there is no file
  // to leave half-written, and renaming a temporary file over /dev/null would replace the
  // device itself where the user may write to /dev.
  const fs::file_status st = fs::status(target, ec);
  if (fs::exists(st) && !fs::is_regular_file(st) && !fs::is_directory(st)) {
    std::ofstream out(target, std::ios::binary);
    if (!out) return io_error(path, std::string("cannot write: ") + std::strerror(errno));
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) return io_error(path, "write failed");
    return {};
  }
  if (target.has_parent_path()) {
    fs::create_directories(target.parent_path(), ec);
    if (ec)
      return io_error(
          path, "cannot create folder " + target.parent_path().string() + ": " + ec.message());
  }
  if (fs::is_directory(target, ec)) return io_error(path, "is a folder, not a file");
  const std::string tmp = temp_name(target);
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) return io_error(path, std::string("cannot write: ") + std::strerror(errno));
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) {
      out.close();
      fs::remove(tmp, ec);
      return io_error(path, "write failed (disk full?)");
    }
  }
  // rename() within one folder replaces the target atomically: readers see the old or the
  // new file, never a partial one.
  if (std::rename(tmp.c_str(), target.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    fs::remove(tmp, ec);
    return io_error(path, "cannot replace: " + why);
  }
  return {};
}

}  // namespace swarf
