#include "swarf/core/status.h"

namespace swarf {

std::string_view error_name(Error e) {
  switch (e) {
    case Error::kOk:
      return "ok";
    case Error::kBadInput:
      return "bad input";
    case Error::kBadParameter:
      return "bad parameter";
    case Error::kToolTooLarge:
      return "tool too large";
    case Error::kNoEntryFound:
      return "no entry found";
    case Error::kOpenMesh:
      return "open mesh";
    case Error::kEmptyResult:
      return "empty result";
    case Error::kIo:
      return "i/o error";
    case Error::kCancelled:
      return "cancelled";
    case Error::kInternal:
      return "internal error";
  }
  return "unknown error";
}

std::string Status::to_string() const {
  if (ok()) return "ok";
  std::string s(error_name(code_));
  s += ": ";
  s += message_;
  return s;
}

Status Status::with_context(std::string_view context) const {
  if (ok()) return *this;
  std::string m(context);
  m += ": ";
  m += message_;
  return {code_, std::move(m)};
}

}  // namespace swarf
