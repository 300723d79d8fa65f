// Values inside messages between C++ and the C structs idlc generates: the
// overloads the generated c_conversions.h calls for each member. C++ -> C
// borrows the C++ value's memory (strings, byte and number arrays) for as
// long as the C sample is used, as dds_write serializes before it returns;
// only sequences of structs need converted arrays, which Borrowed keeps.
// C -> C++ copies (out of Cyclone's loaned samples). In dem::protocol, so
// argument-dependent lookup finds the generated overloads of each message.
#pragma once

#include <dds/dds.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace dem::protocol {

// The arrays a C sample's sequences of structs point into.
class Borrowed {
 public:
  template <class T>
  T* array(std::size_t size) {
    auto storage = std::make_shared<std::vector<T>>(size);  // zero-initialized C structs
    arrays_.push_back(storage);
    return storage->data();
  }

 private:
  std::vector<std::shared_ptr<void>> arrays_;
};

template <class T>
concept Number = std::is_arithmetic_v<T>;  // bool too

// --- C++ -> C, borrowing ----------------------------------------------------

template <Number T>
void to_c(T value, T& c, Borrowed&) {
  c = value;
}

inline void to_c(const std::string& text, char*& c, Borrowed&) { c = const_cast<char*>(text.c_str()); }

inline void to_c(const std::string& bytes, dds_sequence_octet& c, Borrowed&) {
  c._maximum = c._length = static_cast<std::uint32_t>(bytes.size());
  c._buffer = reinterpret_cast<std::uint8_t*>(const_cast<char*>(bytes.data()));
  c._release = false;
}

// An optional as its flag and its value (0 when unset).
template <Number T>
void to_c(const std::optional<T>& value, bool& set, T& c, Borrowed&) {
  set = value.has_value();
  c = value.value_or(T{});
}

// A sequence: numbers borrowed in place, structs converted into a borrowed array.
template <class T, class Sequence>
void to_c(const std::vector<T>& values, Sequence& c, Borrowed& borrowed) {
  using CElement = std::remove_pointer_t<decltype(c._buffer)>;
  c._maximum = c._length = static_cast<std::uint32_t>(values.size());
  c._release = false;
  if constexpr (std::is_same_v<CElement, T>) {
    c._buffer = const_cast<T*>(values.data());
  } else {
    c._buffer = borrowed.array<CElement>(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) to_c(values[i], c._buffer[i], borrowed);
  }
}

// --- C -> C++, copying ------------------------------------------------------

template <Number T>
void from_c(T c, T& value) {
  value = c;
}

inline void from_c(const char* c, std::string& text) { text = c != nullptr ? c : ""; }

inline void from_c(const dds_sequence_octet& c, std::string& bytes) {
  if (c._length == 0) {
    bytes.clear();
  } else {
    bytes.assign(reinterpret_cast<const char*>(c._buffer), c._length);
  }
}

template <Number T>
void from_c(bool set, T c, std::optional<T>& value) {
  value = set ? std::optional<T>(c) : std::nullopt;
}

template <class Sequence, class T>
void from_c(const Sequence& c, std::vector<T>& values) {
  values.clear();
  values.reserve(c._length);
  for (std::uint32_t i = 0; i < c._length; ++i) {
    if constexpr (std::is_same_v<std::remove_cvref_t<decltype(c._buffer[i])>, T>) {
      values.push_back(c._buffer[i]);
    } else {
      from_c(c._buffer[i], values.emplace_back());
    }
  }
}

}  // namespace dem::protocol
