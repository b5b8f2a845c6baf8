#pragma once
// The number of fields of an aggregate struct: the most initializers its
// brace initialization takes. A check that a function handles every field
// (a hash, a table of settings) compares against it: unlike sizeof, it sees
// a field that fits into padding. Needs members that an arbitrary value
// converts to (no C arrays, whose brace elision would count elements).
#include <cstddef>

namespace penumbra {
namespace detail {
struct AnyField {
  template <class T>
  operator T() const;
};
}  // namespace detail

template <class T, class... Fields>
constexpr size_t fieldCount() {
  if constexpr (requires { T{Fields{}..., detail::AnyField{}}; })
    return fieldCount<T, Fields..., detail::AnyField>();
  else
    return sizeof...(Fields);
}

}  // namespace penumbra
