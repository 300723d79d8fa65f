// The generic half of the snapshot conversion: a struct with a field list
// (SnapshotFields, dem/snapshot_fields.h) to and from a Protocol Buffers
// message, each list entry finding its field by name through reflection.
// Adding a member to a listed struct is its list line and a field of that
// name in idl/dem/snapshot.proto; nothing here.
//
// How a member meets its field (the name is the member's, or, for a member
// that is itself a listed struct with no field of its name, its members'
// names behind "<member>_": ContactModelDef::hertz.restitution is
// hertz_restitution, as the schema flattened them from the start):
//   double, bool, int, uint64, string   the scalar field of that type
//   an enum                             an enum, int32 or bool field, by number
//   MaterialId, WallId, ParticleId      int32, the id's value
//   std::optional<double or struct>     a field with presence (proto3 `optional`, a message)
//   a listed struct                     a message field
//   a vector, quaternion, or a double   a repeated double of Packing's width
//     whose field is repeated             (snapshot_packing.h), 2D spins and arms
//   std::vector / std::array of values  a repeated field, packed item after item
//   std::vector / std::array of structs a repeated message, one per item
//   std::vector of structs, singular    structure of arrays: each member of the
//     message field                       struct a repeated field of the message,
//                                         packed across the items (the particles)
// Columns are copied in bulk through the repeated field itself, not value by
// value through reflection, so a 100,000-particle world costs what the
// hand-written copies did (bench/bench_snapshot.cpp); the contact table's
// columns go the same way (put_column and get_column, snapshot_contacts.cpp).
//
// A list entry with no field, or one whose field cannot carry its type,
// throws std::logic_error naming both at the first conversion;
// schema_problems lists them all without converting anything, and the io
// tests run it over every list (test_snapshot_conversion.cpp).
#pragma once

#include <google/protobuf/descriptor.h>
#include <google/protobuf/message.h>
#include <google/protobuf/repeated_field.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

#include "dem/io/snapshot_conversion.h"
#include "dem/snapshot_fields.h"
#include "snapshot_packing.h"

namespace dem::io::fields {

using google::protobuf::Descriptor;
using google::protobuf::FieldDescriptor;
using google::protobuf::Message;
using google::protobuf::Reflection;

template <class T>
struct IsOptional : std::false_type {};
template <class T>
struct IsOptional<std::optional<T>> : std::true_type {};
template <class T>
struct IsId : std::false_type {};
template <class Tag>
struct IsId<Id<Tag>> : std::true_type {};
// std::vector and std::array: their item type.
template <class T>
struct Sequence : std::false_type {};
template <class T>
struct Sequence<std::vector<T>> : std::true_type {
  using Item = T;
};
template <class T, std::size_t N>
struct Sequence<std::array<T, N>> : std::true_type {
  using Item = T;
};
template <class T>
struct IsStdVector : std::false_type {};
template <class T>
struct IsStdVector<std::vector<T>> : std::true_type {};

template <class F>
struct FieldMember;
template <class S, class M>
struct FieldMember<Field<S, M>> {
  using type = M;
};
template <class F>
using MemberOf = typename FieldMember<std::remove_cvref_t<F>>::type;

// The contact table: converted by its own list (for_each_contact_field,
// snapshot_contacts.cpp), so the walker passes it by.
template <class T>
constexpr bool kOwnList = false;
template <int Dim>
constexpr bool kOwnList<std::vector<ContactSnapshotT<Dim>>> = true;

// What one field of a list meets in the schema, as a cpp type and label;
// null when it can carry the member, else why not.
template <class T>
const char* scalar_problem(const FieldDescriptor& f) {
  using C = FieldDescriptor::CppType;
  const C t = f.cpp_type();
  if constexpr (std::is_same_v<T, double>) {
    return t == C::CPPTYPE_DOUBLE ? nullptr : "a double wants a double field";
  } else if constexpr (std::is_same_v<T, bool>) {
    return t == C::CPPTYPE_BOOL ? nullptr : "a bool wants a bool field";
  } else if constexpr (std::is_same_v<T, std::string>) {
    return t == C::CPPTYPE_STRING ? nullptr : "a string wants a string field";
  } else if constexpr (std::is_same_v<T, std::uint64_t>) {
    return t == C::CPPTYPE_UINT64 ? nullptr : "a uint64 wants a uint64 field";
  } else if constexpr (std::is_same_v<T, std::int32_t> || IsId<T>::value) {
    return t == C::CPPTYPE_INT32 ? nullptr : "an int or id wants an int32 field";
  } else if constexpr (std::is_enum_v<T>) {
    return t == C::CPPTYPE_ENUM || t == C::CPPTYPE_INT32 || t == C::CPPTYPE_BOOL
               ? nullptr
               : "an enum wants an enum, int32 or bool field";
  } else {
    static_assert(sizeof(T) == 0, "a member type the snapshot conversion does not know");
    return nullptr;
  }
}

template <class T>
constexpr bool kScalar =
    std::is_arithmetic_v<T> || std::is_enum_v<T> || IsId<T>::value || std::is_same_v<T, std::string>;

// What a column holds per item: Packing's doubles, or one scalar.
template <class T>
constexpr bool kColumnItem = Packable<T> || IsId<T>::value || std::is_enum_v<T> || std::is_same_v<T, bool> ||
                             std::is_same_v<T, std::int32_t> || std::is_same_v<T, std::uint64_t>;
template <class T>
constexpr std::size_t item_width() {
  if constexpr (Packable<T>) {
    return width<T>;
  } else {
    return 1;
  }
}
// A struct that can be stored as columns (structure of arrays): every
// member a column item.
template <class S>
constexpr bool columns_only() {
  return std::apply([](const auto&... entry) { return (kColumnItem<MemberOf<decltype(entry)>> && ...); },
                    SnapshotFields<S>::list);
}

// An item of a column: packed doubles or one scalar per item.
template <class T>
const char* column_problem(const FieldDescriptor& f) {
  if (!f.is_repeated()) return "a sequence wants a repeated field";
  if constexpr (Packable<T>) {
    return f.cpp_type() == FieldDescriptor::CPPTYPE_DOUBLE ? nullptr : "packed values want a repeated double";
  } else if constexpr (std::is_enum_v<T>) {
    // Copied as the column's int32 values (an enum field's are not).
    return f.cpp_type() == FieldDescriptor::CPPTYPE_INT32 ? nullptr : "a column of enums wants a repeated int32";
  } else {
    return scalar_problem<T>(f);
  }
}

template <class T>
const char* type_problem(const FieldDescriptor& f) {
  if constexpr (IsOptional<T>::value) {
    if (!f.has_presence()) return "an optional wants a field with presence (`optional`, a message)";
    return type_problem<typename T::value_type>(f);
  } else if constexpr (Sequence<T>::value) {
    using Item = typename Sequence<T>::Item;
    if constexpr (HasSnapshotFields<Item>) {
      if (f.cpp_type() != FieldDescriptor::CPPTYPE_MESSAGE) {
        // Structs of packable members may be packed doubles (a particle's shape).
        if constexpr (Packable<Item>) return column_problem<Item>(f);
        return "a sequence of structs wants a message field";
      }
      if (f.is_repeated()) return nullptr;
      if (!IsStdVector<T>::value) return "an array of structs wants a repeated message";
      if (!columns_only<Item>()) return "a singular message holds a vector of structs as columns: not of this struct";
      return nullptr;
    } else {
      return column_problem<Item>(f);
    }
  } else if constexpr (HasSnapshotFields<T>) {
    return f.cpp_type() == FieldDescriptor::CPPTYPE_MESSAGE && !f.is_repeated() ? nullptr : "a struct wants a message";
  } else if constexpr (Packable<T> && !kScalar<T>) {
    return column_problem<T>(f);
  } else {
    if (f.is_repeated()) return Packable<T> ? column_problem<T>(f) : "a single value wants a singular field";
    return scalar_problem<T>(f);
  }
}

// The messages a struct's fields are looked for in, and the prefix of a
// flattened struct's names. A name must be in exactly one of them.
template <class M>  // Message or const Message
struct Scope {
  std::array<M*, 2> messages{};
  std::string prefix;

  Scope(M* first, M* second = nullptr) : messages{first, second} {}
  Scope flattened(std::string_view member) const {
    Scope inner = *this;
    inner.prefix += std::string(member) + "_";
    return inner;
  }
};

struct Found {
  std::size_t message = 0;
  const FieldDescriptor* field = nullptr;
};

// The field called prefix + name in one of the descriptors; none: field null.
inline Found find_field(std::initializer_list<const Descriptor*> descriptors, const std::string& name) {
  Found found;
  std::size_t i = 0;
  for (const Descriptor* d : descriptors) {
    if (d != nullptr) {
      if (const FieldDescriptor* f = d->FindFieldByName(name)) {
        if (found.field != nullptr) {
          throw std::logic_error("the snapshot schema has a field " + name + " in both " +
                                 found.field->containing_type()->full_name() + " and " + d->full_name() +
                                 ": a field list entry must find one");
        }
        found = Found{i, f};
      }
    }
    ++i;
  }
  return found;
}

template <class M>
std::string scope_names(const Scope<M>& scope) {
  std::string names;
  for (M* m : scope.messages) {
    if (m != nullptr) names += (names.empty() ? "" : " or ") + m->GetDescriptor()->full_name();
  }
  return names;
}

// A list entry's field, whose type must carry T: throws naming both otherwise.
template <class T, class M>
Found field_for(const Scope<M>& scope, std::string_view name) {
  const std::string full = scope.prefix + std::string(name);
  const Descriptor* a = scope.messages[0] != nullptr ? scope.messages[0]->GetDescriptor() : nullptr;
  const Descriptor* b = scope.messages[1] != nullptr ? scope.messages[1]->GetDescriptor() : nullptr;
  const Found found = find_field({a, b}, full);
  if (found.field == nullptr) {
    throw std::logic_error(scope_names(scope) + " has no field " + full +
                           ", which a field list names (dem/snapshot_fields.h): add it to idl/dem/snapshot.proto");
  }
  if (const char* problem = type_problem<T>(*found.field)) {
    throw std::logic_error("field " + found.field->full_name() + " cannot carry its list entry: " + problem);
  }
  return found;
}

template <class M>
bool has_field(const Scope<M>& scope, std::string_view name) {
  const Descriptor* a = scope.messages[0]->GetDescriptor();
  const Descriptor* b = scope.messages[1] != nullptr ? scope.messages[1]->GetDescriptor() : nullptr;
  return find_field({a, b}, scope.prefix + std::string(name)).field != nullptr;
}

// --- struct -> message ------------------------------------------------------

// The repeated field itself: columns are appended in bulk, not a value at a
// time through reflection. Reflection's RepeatedFieldRef would do the same
// through a virtual call per value.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
template <class V>
google::protobuf::RepeatedField<V>* mutable_column(Message& m, const FieldDescriptor* f) {
  return m.GetReflection()->MutableRepeatedField<V>(&m, f);
}
template <class V>
const google::protobuf::RepeatedField<V>& column(const Message& m, const FieldDescriptor* f) {
  return m.GetReflection()->GetRepeatedField<V>(m, f);
}
#pragma GCC diagnostic pop

// The value type of a column of T items.
template <class T>
using ColumnValue =
    std::conditional_t<Packable<T>, double, std::conditional_t<IsId<T>::value || std::is_enum_v<T>, std::int32_t, T>>;

// Appends n items, at(i) the i-th.
template <class T, class At>
void put_column(Message& m, const FieldDescriptor* f, std::size_t n, At at) {
  auto* out = mutable_column<ColumnValue<T>>(m, f);
  if constexpr (Packable<T>) {
    out->Reserve(out->size() + static_cast<int>(n * width<T>));
    for (std::size_t i = 0; i < n; ++i) Packing<T>::put(out, at(i));
  } else {
    out->Reserve(out->size() + static_cast<int>(n));
    for (std::size_t i = 0; i < n; ++i) {
      if constexpr (IsId<T>::value) {
        out->Add(at(i).value());
      } else {
        out->Add(static_cast<ColumnValue<T>>(at(i)));
      }
    }
  }
}

template <class T>
void put_struct(const T& value, const Scope<Message>& scope, std::initializer_list<std::string_view> skip = {});

template <class T>
void set_scalar(Message& m, const FieldDescriptor* f, const T& v) {
  const Reflection& r = *m.GetReflection();
  if constexpr (std::is_same_v<T, double>) {
    r.SetDouble(&m, f, v);
  } else if constexpr (std::is_same_v<T, bool>) {
    r.SetBool(&m, f, v);
  } else if constexpr (std::is_same_v<T, std::string>) {
    r.SetString(&m, f, v);
  } else if constexpr (std::is_same_v<T, std::uint64_t>) {
    r.SetUInt64(&m, f, v);
  } else if constexpr (IsId<T>::value) {
    r.SetInt32(&m, f, v.value());
  } else if constexpr (std::is_enum_v<T>) {
    const int number = static_cast<int>(v);
    if (f->cpp_type() == FieldDescriptor::CPPTYPE_ENUM) {
      r.SetEnumValue(&m, f, number);
    } else if (f->cpp_type() == FieldDescriptor::CPPTYPE_BOOL) {
      if (number > 1) throw std::logic_error("field " + f->full_name() + " is a bool: an enum value above 1 is lost");
      r.SetBool(&m, f, number == 1);
    } else {
      r.SetInt32(&m, f, number);
    }
  } else {
    r.SetInt32(&m, f, v);
  }
}

template <class T>
void put_value(const T& v, Message& m, const FieldDescriptor* f) {
  if constexpr (IsOptional<T>::value) {
    if (v) put_value(*v, m, f);
  } else if constexpr (Sequence<T>::value) {
    using Item = typename Sequence<T>::Item;
    if constexpr (Packable<Item>) {
      if (f->cpp_type() != FieldDescriptor::CPPTYPE_MESSAGE) {
        put_column<Item>(m, f, v.size(), [&](std::size_t i) -> const Item& { return v[i]; });
        return;
      }
    }
    if constexpr (HasSnapshotFields<Item>) {
      const Reflection& r = *m.GetReflection();
      if (f->is_repeated()) {
        // One message per item; items already there (a wall's definition,
        // written before its state) are filled in.
        for (std::size_t i = 0; i < v.size(); ++i) {
          const int at = static_cast<int>(i);
          Message* item = at < r.FieldSize(m, f) ? r.MutableRepeatedMessage(&m, f, at) : r.AddMessage(&m, f);
          put_struct(v[i], Scope<Message>(item));
        }
      } else if constexpr (IsStdVector<T>::value && columns_only<Item>()) {
        // Structure of arrays: a column per member.
        Message& columns = *r.MutableMessage(&m, f);
        std::apply(
            [&](const auto&... entry) {
              ((put_column<MemberOf<decltype(entry)>>(
                   columns,
                   field_for<std::vector<MemberOf<decltype(entry)>>>(Scope<Message>(&columns), entry.name).field,
                   v.size(), [&](std::size_t i) -> const auto& { return v[i].*entry.member; })),
               ...);
            },
            SnapshotFields<Item>::list);
      }
    } else {
      put_column<Item>(m, f, v.size(), [&](std::size_t i) -> const Item& { return v[i]; });
    }
  } else if constexpr (HasSnapshotFields<T>) {
    put_struct(v, Scope<Message>(m.GetReflection()->MutableMessage(&m, f)));
  } else if constexpr (Packable<T>) {
    if (f->is_repeated()) {
      put_column<T>(m, f, 1, [&](std::size_t) -> const T& { return v; });
    } else if constexpr (kScalar<T>) {
      set_scalar(m, f, v);
    }
  } else {
    set_scalar(m, f, v);
  }
}

template <class T>
void put_member(const T& v, std::string_view name, const Scope<Message>& scope) {
  if constexpr (!kOwnList<T>) {
    if constexpr (HasSnapshotFields<T>) {
      // A struct with no message of its name: its members beside the others.
      if (!has_field(scope, name)) {
        put_struct(v, scope.flattened(name));
        return;
      }
    }
    const Found found = field_for<T>(scope, name);
    put_value(v, *scope.messages[found.message], found.field);
  }
}

inline bool skipped(std::initializer_list<std::string_view> skip, std::string_view name) {
  for (std::string_view s : skip) {
    if (s == name) return true;
  }
  return false;
}

template <class T>
void put_struct(const T& value, const Scope<Message>& scope, std::initializer_list<std::string_view> skip) {
  std::apply(
      [&](const auto&... entry) {
        ((skipped(skip, entry.name) ? void() : put_member(value.*entry.member, entry.name, scope)), ...);
      },
      SnapshotFields<T>::list);
}

// --- message -> struct ------------------------------------------------------

inline std::string wrong_length(const FieldDescriptor* f, int size, std::size_t expected) {
  return f->full_name() + ": has " + std::to_string(size) + " values, expected " + std::to_string(expected);
}

// Reads n items into at(i). An empty column leaves the items as they are
// (a field added after a file was written); another length is an error.
template <class T, class At>
void get_column(const Message& m, const FieldDescriptor* f, std::size_t n, At at) {
  const auto& in = column<ColumnValue<T>>(m, f);
  if (in.empty()) return;
  constexpr std::size_t w = item_width<T>();
  if (static_cast<std::size_t>(in.size()) != n * w) throw SnapshotError(wrong_length(f, in.size(), n * w));
  for (std::size_t i = 0; i < n; ++i) {
    if constexpr (Packable<T>) {
      at(i) = Packing<T>::get(in, static_cast<int>(i * w));
    } else if constexpr (IsId<T>::value || std::is_enum_v<T>) {
      at(i) = T(in.Get(static_cast<int>(i)));
    } else {
      at(i) = in.Get(static_cast<int>(i));
    }
  }
}

// The items a column holds.
template <class T>
std::size_t column_items(const Message& m, const FieldDescriptor* f) {
  const std::size_t size = static_cast<std::size_t>(m.GetReflection()->FieldSize(m, f));
  constexpr std::size_t w = item_width<T>();
  if (size % w != 0) throw SnapshotError(wrong_length(f, static_cast<int>(size), (size / w + 1) * w));
  return size / w;
}

template <class T>
void get_struct(T& value, const Scope<const Message>& scope, std::initializer_list<std::string_view> skip = {});

template <class T>
T get_scalar(const Message& m, const FieldDescriptor* f) {
  const Reflection& r = *m.GetReflection();
  if constexpr (std::is_same_v<T, double>) {
    return r.GetDouble(m, f);
  } else if constexpr (std::is_same_v<T, bool>) {
    return r.GetBool(m, f);
  } else if constexpr (std::is_same_v<T, std::string>) {
    return r.GetString(m, f);
  } else if constexpr (std::is_same_v<T, std::uint64_t>) {
    return r.GetUInt64(m, f);
  } else if constexpr (IsId<T>::value) {
    return T{r.GetInt32(m, f)};
  } else if constexpr (std::is_enum_v<T>) {
    if (f->cpp_type() == FieldDescriptor::CPPTYPE_ENUM) return static_cast<T>(r.GetEnumValue(m, f));
    if (f->cpp_type() == FieldDescriptor::CPPTYPE_BOOL) return static_cast<T>(r.GetBool(m, f) ? 1 : 0);
    return static_cast<T>(r.GetInt32(m, f));
  } else {
    return static_cast<T>(r.GetInt32(m, f));
  }
}

template <class T>
void get_value(T& v, const Message& m, const FieldDescriptor* f) {
  const Reflection& r = *m.GetReflection();
  if constexpr (IsOptional<T>::value) {
    if (r.HasField(m, f)) {
      get_value(v.emplace(), m, f);
    } else {
      v.reset();
    }
  } else if constexpr (Sequence<T>::value) {
    using Item = typename Sequence<T>::Item;
    if constexpr (Packable<Item>) {
      if (f->cpp_type() != FieldDescriptor::CPPTYPE_MESSAGE) {
        if constexpr (IsStdVector<T>::value) v.resize(column_items<Item>(m, f));
        get_column<Item>(m, f, v.size(), [&](std::size_t i) -> Item& { return v[i]; });
        return;
      }
    }
    if constexpr (HasSnapshotFields<Item>) {
      if (f->is_repeated()) {
        const int size = r.FieldSize(m, f);
        if constexpr (IsStdVector<T>::value) v.resize(static_cast<std::size_t>(size));
        for (std::size_t i = 0; i < v.size() && static_cast<int>(i) < size; ++i) {
          get_struct(v[i], Scope<const Message>(&r.GetRepeatedMessage(m, f, static_cast<int>(i))));
        }
      } else if constexpr (IsStdVector<T>::value && columns_only<Item>()) {
        // Structure of arrays: as many items as the first column holds.
        const Message& columns = r.GetMessage(m, f);
        const Scope<const Message> scope(&columns);
        constexpr auto& list = SnapshotFields<Item>::list;
        using First = MemberOf<decltype(std::get<0>(list))>;
        v.resize(column_items<First>(columns, field_for<std::vector<First>>(scope, std::get<0>(list).name).field));
        std::apply(
            [&](const auto&... entry) {
              ((get_column<MemberOf<decltype(entry)>>(
                   columns, field_for<std::vector<MemberOf<decltype(entry)>>>(scope, entry.name).field,
                   v.size(), [&](std::size_t i) -> auto& { return v[i].*entry.member; })),
               ...);
            },
            list);
      }
    } else {
      if constexpr (IsStdVector<T>::value) v.resize(column_items<Item>(m, f));
      get_column<Item>(m, f, v.size(), [&](std::size_t i) -> Item& { return v[i]; });
    }
  } else if constexpr (HasSnapshotFields<T>) {
    get_struct(v, Scope<const Message>(&r.GetMessage(m, f)));
  } else if constexpr (Packable<T>) {
    if (f->is_repeated()) {
      get_column<T>(m, f, 1, [&](std::size_t) -> T& { return v; });
    } else if constexpr (kScalar<T>) {
      v = get_scalar<T>(m, f);
    }
  } else {
    v = get_scalar<T>(m, f);
  }
}

template <class T>
void get_member(T& v, std::string_view name, const Scope<const Message>& scope) {
  if constexpr (!kOwnList<T>) {
    if constexpr (HasSnapshotFields<T>) {
      if (!has_field(scope, name)) {
        get_struct(v, scope.flattened(name));
        return;
      }
    }
    const Found found = field_for<T>(scope, name);
    get_value(v, *scope.messages[found.message], found.field);
  }
}

template <class T>
void get_struct(T& value, const Scope<const Message>& scope, std::initializer_list<std::string_view> skip) {
  std::apply(
      [&](const auto&... entry) {
        ((skipped(skip, entry.name) ? void() : get_member(value.*entry.member, entry.name, scope)), ...);
      },
      SnapshotFields<T>::list);
}

// --- the lists against the schema, without converting ----------------------

// Walks T's list as the conversion would against the message types of
// `descriptors` (behind `prefix`), adding a line per entry with no field or
// a field that cannot carry it; `checked` counts the entries found.
template <class T>
void schema_problems(std::initializer_list<const Descriptor*> descriptors, const std::string& prefix,
                     std::initializer_list<std::string_view> skip, std::vector<std::string>& problems, int& checked);

template <class T>
void schema_problems_of_member(std::string_view name, std::initializer_list<const Descriptor*> descriptors,
                               const std::string& prefix, std::vector<std::string>& problems, int& checked) {
  if constexpr (!kOwnList<T>) {
    const std::string full = prefix + std::string(name);
    const Found found = find_field(descriptors, full);
    if (found.field == nullptr) {
      if constexpr (HasSnapshotFields<T>) {
        schema_problems<T>(descriptors, full + "_", {}, problems, checked);
      } else {
        std::string names;
        for (const Descriptor* d : descriptors) {
          if (d != nullptr) names += (names.empty() ? "" : " or ") + d->full_name();
        }
        problems.push_back(names + " has no field " + full);
      }
      return;
    }
    ++checked;
    if (const char* problem = type_problem<T>(*found.field)) {
      problems.push_back(found.field->full_name() + ": " + problem);
      return;
    }
    // Into the message of the member's struct, or of its items.
    const auto into = [&]<class S>() {
      if constexpr (HasSnapshotFields<S>) {
        if (found.field->message_type() != nullptr) {
          schema_problems<S>({found.field->message_type()}, "", {}, problems, checked);
        }
      }
    };
    if constexpr (IsOptional<T>::value) {
      into.template operator()<typename T::value_type>();
    } else if constexpr (Sequence<T>::value) {
      using Item = typename Sequence<T>::Item;
      if constexpr (HasSnapshotFields<Item>) {
        if (found.field->message_type() == nullptr) return;  // packed doubles, checked above
        if (found.field->is_repeated()) {
          into.template operator()<Item>();
        } else if constexpr (IsStdVector<T>::value && columns_only<Item>()) {
          std::apply(
              [&](const auto&... entry) {
                (schema_problems_of_member<std::vector<MemberOf<decltype(entry)>>>(
                     entry.name, {found.field->message_type()}, "", problems, checked),
                 ...);
              },
              SnapshotFields<Item>::list);
        }
      }
    } else {
      into.template operator()<T>();
    }
  }
}

template <class T>
void schema_problems(std::initializer_list<const Descriptor*> descriptors, const std::string& prefix,
                     std::initializer_list<std::string_view> skip, std::vector<std::string>& problems, int& checked) {
  std::apply(
      [&](const auto&... entry) {
        ((skipped(skip, entry.name) ? void()
                                    : schema_problems_of_member<MemberOf<decltype(entry)>>(entry.name, descriptors,
                                                                                           prefix, problems, checked)),
         ...);
      },
      SnapshotFields<T>::list);
}

}  // namespace dem::io::fields
