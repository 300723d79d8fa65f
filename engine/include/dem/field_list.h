// Field lists: a struct's members by name, walked by the code that copies
// them elsewhere (a file, a message), and the compile-time checks that keep
// a list whole. member_count is the guard behind every list (dem/snapshot.h,
// dem/measures.h): a new member - a bool that fits in padding too - fails
// the build until its list names it, which a sizeof mirror cannot see.
#pragma once

#include <cstddef>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>

namespace dem {

// One member of a struct: its name and where it is.
template <class Struct, class Member>
struct Field {
  std::string_view name;
  Member Struct::*member;
};
template <class Struct, class Member>
Field(std::string_view, Member Struct::*) -> Field<Struct, Member>;

// A list's entry, the member's name spelled once: DEM_FIELD(MaterialDef, friction).
#define DEM_FIELD(Struct, member) \
  ::dem::Field { #member, &Struct::member }

namespace detail {

// Converts to any member type: counts an aggregate's members by the
// longest brace list that initializes it.
struct AnyMember {
  template <typename T>
  operator T() const;  // NOLINT(google-explicit-constructor): only named in unevaluated contexts
};

template <typename T, typename... Members>
constexpr std::size_t member_count() {
  if constexpr (requires { T{Members{}..., AnyMember{}}; }) {
    return member_count<T, Members..., AnyMember>();
  } else {
    return sizeof...(Members);
  }
}

template <class A, class B>
constexpr bool same_member(A a, B b) {
  if constexpr (std::is_same_v<A, B>) {
    return a == b;
  } else {
    return false;
  }
}

template <class A, class B>
constexpr bool same_field(const A& a, const B& b) {
  return a.name == b.name || same_member(a.member, b.member);
}

template <class Tuple, std::size_t... I>
constexpr bool fields_distinct(const Tuple& list, std::index_sequence<I...>) {
  bool distinct = true;
  const auto against_all = [&]<std::size_t A>(std::integral_constant<std::size_t, A>) {
    ((distinct = distinct && (A == I || !same_field(std::get<A>(list), std::get<I>(list)))), ...);
  };
  (against_all(std::integral_constant<std::size_t, I>{}), ...);
  return distinct;
}

}  // namespace detail

// A list of Fields (a tuple) names every member of Struct once: as many
// entries as members, no name or member twice.
template <class Struct, class Tuple>
constexpr bool lists_every_member(const Tuple& list) {
  constexpr std::size_t n = std::tuple_size_v<Tuple>;
  return n == detail::member_count<Struct>() && detail::fields_distinct(list, std::make_index_sequence<n>{});
}

// The position of the field called `name` in a list, or the list's size.
template <class Tuple>
constexpr std::size_t field_index(const Tuple& list, std::string_view name) {
  std::size_t index = std::tuple_size_v<Tuple>;
  std::size_t i = 0;
  std::apply(
      [&](const auto&... field) {
        ((index = (index == std::tuple_size_v<Tuple> && field.name == name) ? i : index, ++i), ...);
      },
      list);
  return index;
}

}  // namespace dem
