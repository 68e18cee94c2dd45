// The one type for an expected failure: an outcome the caller is meant to look at (a mesh that is
// no prism, a stiffness table with a bad row, a tooth layout the mesh contradicts), as opposed to
// bad input that stops everything (throw InputError, errors.hpp) or a bug (GEARSIM_CHECK).
// Result<T> holds a T or a Refusal: the reason in one sentence and, when one item is at fault,
// its 0-based index (a row, a tooth, a loop). Check = Result<void>: passed, or why not.
//   Result<Prism> p = recover_prism(mesh, tol);
//   if (!p) throw InputError(file + ": " + p.reason());
// Lists of findings for a report (a gear pair's interference notes) are not failures and stay
// plain vectors of strings.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <variant>

#include "core/errors.hpp"

namespace gearsim {

struct Refusal {
  std::string reason;  // one sentence: what is wrong, with the figures
  int index = -1;  // the item at fault (row, tooth, loop), −1 when not one item's
};

template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) : v_(std::move(value)) {}  // NOLINT: implicit, as `return value;`
  Result(Refusal refusal) : v_(std::move(refusal)) {}  // NOLINT: implicit, as `return Refusal{…};`
  bool ok() const { return v_.index() == 0; }
  explicit operator bool() const { return ok(); }
  const T& value() const {
    GEARSIM_CHECK(ok(), "Result::value() of a refusal: " + reason());
    return std::get<0>(v_);
  }
  T& value() {
    GEARSIM_CHECK(ok(), "Result::value() of a refusal: " + reason());
    return std::get<0>(v_);
  }
  const T& operator*() const { return value(); }
  T& operator*() { return value(); }
  const T* operator->() const { return &value(); }
  T* operator->() { return &value(); }
  // The refusal (GEARSIM_CHECK that there is one), or its reason ("" when ok).
  const Refusal& refusal() const {
    GEARSIM_CHECK(!ok(), "Result::refusal() of a success");
    return std::get<1>(v_);
  }
  std::string reason() const { return ok() ? std::string() : std::get<1>(v_).reason; }
  // The value as an optional (the refusal dropped): for callers that only need to know whether.
  std::optional<T> optional() const { return ok() ? std::optional<T>(std::get<0>(v_)) : std::nullopt; }

 private:
  std::variant<T, Refusal> v_;
};

template <>
class [[nodiscard]] Result<void> {
 public:
  Result() = default;  // passed
  Result(Refusal refusal) : refusal_(std::move(refusal)) {}  // NOLINT: implicit
  bool ok() const { return !refusal_; }
  explicit operator bool() const { return ok(); }
  const Refusal& refusal() const {
    GEARSIM_CHECK(!ok(), "Result::refusal() of a success");
    return *refusal_;
  }
  std::string reason() const { return refusal_ ? refusal_->reason : std::string(); }

 private:
  std::optional<Refusal> refusal_;
};

using Check = Result<void>;

}  // namespace gearsim
