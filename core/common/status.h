// Errors as values: a status code plus a human message that names the file, line or field.
#pragma once

#include <cassert>
#include <optional>
#include <string>
#include <utility>

namespace sightline {

// What kind of failure a Status carries. Callers branch on the code, people read the message.
enum class StatusCode {
  kOk = 0,
  kInvalidArgument,     // A parameter or option is out of range or malformed.
  kNotFound,            // A file, device or key does not exist.
  kParseError,          // A file exists but its content is malformed.
  kUnavailable,         // A device or driver is absent or disconnected.
  kOutOfRange,          // End of stream, seek beyond the end.
  kFailedPrecondition,  // The call is valid but the object is not in a state for it.
  kCancelled,           // Stopped on request.
  kInternal,            // A broken invariant.
};

// Returns a short name for a code, e.g. "parse error".
const char* StatusCodeName(StatusCode code);

// The result of a fallible operation. Cheap to copy when ok.
//
//   Status s = source.Open();
//   if (!s.ok()) std::cerr << s.ToString() << "\n";
class [[nodiscard]] Status {
 public:
  Status() = default;
  Status(StatusCode code, std::string message) : code_(code), message_(std::move(message)) {}

  static Status Ok() { return Status(); }

  bool ok() const { return code_ == StatusCode::kOk; }
  StatusCode code() const { return code_; }
  const std::string& message() const { return message_; }

  // "parse error: calib.txt line 2: expected 12 numbers, found 7".
  std::string ToString() const;

  // Returns a copy whose message is prefixed with context, e.g. the file being read.
  Status WithContext(const std::string& context) const;

 private:
  StatusCode code_ = StatusCode::kOk;
  std::string message_;
};

inline Status InvalidArgument(std::string m) {
  return {StatusCode::kInvalidArgument, std::move(m)};
}
inline Status NotFound(std::string m) { return {StatusCode::kNotFound, std::move(m)}; }
inline Status ParseError(std::string m) { return {StatusCode::kParseError, std::move(m)}; }
inline Status Unavailable(std::string m) { return {StatusCode::kUnavailable, std::move(m)}; }
inline Status OutOfRange(std::string m) { return {StatusCode::kOutOfRange, std::move(m)}; }
inline Status FailedPrecondition(std::string m) {
  return {StatusCode::kFailedPrecondition, std::move(m)};
}
inline Status Cancelled(std::string m) { return {StatusCode::kCancelled, std::move(m)}; }
inline Status Internal(std::string m) { return {StatusCode::kInternal, std::move(m)}; }

// A value or the Status that explains why there is none.
//
//   StatusOr<Trajectory> t = ReadTumTrajectory(path);
//   if (!t.ok()) return t.status();
//   Use(*t);
template <typename T>
class [[nodiscard]] StatusOr {
 public:
  StatusOr(T value) : value_(std::move(value)) {}         // NOLINT: implicit by design.
  StatusOr(Status status) : status_(std::move(status)) {  // NOLINT: implicit by design.
    assert(!status_.ok() && "StatusOr built from an ok Status without a value");
    if (status_.ok()) status_ = Internal("StatusOr constructed from ok status without value");
  }

  bool ok() const { return value_.has_value(); }
  const Status& status() const { return status_; }

  T& value() & { return *value_; }
  const T& value() const& { return *value_; }
  T&& value() && { return std::move(*value_); }
  T& operator*() & { return *value_; }
  const T& operator*() const& { return *value_; }
  T&& operator*() && { return std::move(*value_); }
  T* operator->() { return &*value_; }
  const T* operator->() const { return &*value_; }

 private:
  Status status_;
  std::optional<T> value_;
};

}  // namespace sightline

// Returns from the enclosing function when expr yields a non-ok Status.
#define SIGHTLINE_RETURN_IF_ERROR(expr)      \
  do {                                       \
    ::sightline::Status _sl_status = (expr); \
    if (!_sl_status.ok()) return _sl_status; \
  } while (false)
