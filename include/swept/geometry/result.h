#pragma once
/// Error values for bad input (files, configurations, NaN coordinates, empty meshes).
/// Bad input is never an exception inside the library: functions that can meet it return
/// `Result<T>`. Exceptions are only thrown at the CLI boundary.
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

namespace swept {

/// A human-readable description of what was wrong with the input, naming the file and the
/// line, triangle or entity where that is known.
struct Error {
  std::string message;
};

/// Either a value or an Error.
template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : data_(std::move(value)) {}            // NOLINT: implicit by design
  Result(Error error) : data_(std::move(error)) {}        // NOLINT: implicit by design

  bool ok() const { return data_.index() == 0; }
  explicit operator bool() const { return ok(); }

  const T& value() const& { check(); return std::get<0>(data_); }
  T& value() & { check(); return std::get<0>(data_); }
  T&& value() && { check(); return std::get<0>(std::move(data_)); }
  const T& operator*() const& { return value(); }
  T& operator*() & { return value(); }
  const T* operator->() const { return &value(); }
  T* operator->() { return &value(); }

  const Error& error() const { return std::get<1>(data_); }

 private:
  void check() const {
    if (!ok()) throw std::runtime_error("swept: value() on an error result: " + std::get<1>(data_).message);
  }
  std::variant<T, Error> data_;
};

}  // namespace swept
