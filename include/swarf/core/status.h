// Failures as values with names (STYLE.md 4): every fallible library call returns a
// Status or a Result<T>. The CLI turns a failure into one line and exit status 2.
#pragma once

#include <cassert>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace swarf {

enum class Error {
  kOk = 0,
  kBadInput,      ///< a malformed file: STL, pocket, G-code, job, tool library
  kBadParameter,  ///< a parameter out of range: negative stepover, stepdown > flute length
  kToolTooLarge,  ///< the tool does not fit the feature it must machine
  kNoEntryFound,  ///< nowhere to plunge or ramp in
  kOpenMesh,      ///< a mesh that is not closed where a solid is needed
  kEmptyResult,   ///< the operation would produce no toolpath at all
  kIo,            ///< a file could not be read or written
  kCancelled,     ///< the caller cancelled through the Context
  kInternal,      ///< a bug: an invariant did not hold
};

/// Short stable name of an error code ("bad input", "tool too large", ...).
std::string_view error_name(Error e);

/// An error code and a human message that names the input and the fault,
/// e.g. "part.stl: triangle 12: vertex 2 has a NaN coordinate".
class Status {
 public:
  Status() = default;
  Status(Error code, std::string message) : code_(code), message_(std::move(message)) {}
  static Status ok_status() { return {}; }

  bool ok() const { return code_ == Error::kOk; }
  explicit operator bool() const { return ok(); }
  Error code() const { return code_; }
  const std::string& message() const { return message_; }
  /// "error name: message", the line the CLI prints.
  std::string to_string() const;
  /// Same code, message prefixed with context: "ctx: message".
  Status with_context(std::string_view context) const;

 private:
  Error code_ = Error::kOk;
  std::string message_;
};

inline Status bad_input(std::string message) {
  return {Error::kBadInput, std::move(message)};
}
inline Status bad_parameter(std::string message) {
  return {Error::kBadParameter, std::move(message)};
}

/// A value or a failure Status. Like std::expected (C++23), kept small.
template <class T>
class Result {
 public:
  Result(T value) : data_(std::move(value)) {}        // NOLINT(google-explicit-constructor)
  Result(Status status) : data_(std::move(status)) {  // NOLINT(google-explicit-constructor)
    assert(!std::get<Status>(data_).ok() && "a Result made from a Status must hold a failure");
  }

  bool ok() const { return std::holds_alternative<T>(data_); }
  explicit operator bool() const { return ok(); }
  const T& value() const& { return std::get<T>(data_); }
  T& value() & { return std::get<T>(data_); }
  T&& value() && { return std::get<T>(std::move(data_)); }
  const T& operator*() const& { return value(); }
  T& operator*() & { return value(); }
  const T* operator->() const { return &value(); }
  T* operator->() { return &value(); }
  /// The failure; an ok Status when this holds a value.
  Status status() const { return ok() ? Status{} : std::get<Status>(data_); }

 private:
  std::variant<T, Status> data_;
};

}  // namespace swarf

/// Returns early from a function returning Status or Result with the failure of expr.
#define SWARF_RETURN_IF_ERROR(expr)                \
  do {                                             \
    ::swarf::Status swarf_status_ = (expr);        \
    if (!swarf_status_.ok()) return swarf_status_; \
  } while (false)
