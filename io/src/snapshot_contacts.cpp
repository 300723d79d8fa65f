#include "snapshot_contacts.h"

#include <google/protobuf/descriptor.h>
#include <google/protobuf/reflection.h>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "snapshot_packing.h"

namespace dem::io {

namespace {

using google::protobuf::FieldDescriptor;
using google::protobuf::Reflection;

// The type of a field of ContactSnapshotT<Dim> as the accessor `Field` names it.
template <int Dim, typename Field>
using FieldType = std::remove_cvref_t<std::invoke_result_t<Field, ContactSnapshotT<Dim>&>>;

template <typename T>
constexpr bool kPacked =
    !std::is_same_v<T, bool> && !std::is_same_v<T, std::int32_t> && !std::is_same_v<T, std::uint64_t>;

// The message's field of each list entry, in list order. A name the
// schema lacks is a programming error (tests/io/test_snapshot_contacts.cpp
// checks the two agree).
template <int Dim>
std::array<const FieldDescriptor*, contact_field_count<Dim>()> find_message_fields() {
  std::array<const FieldDescriptor*, contact_field_count<Dim>()> fields{};
  std::size_t k = 0;
  for_each_contact_field<Dim>([&](const ContactFieldInfo& info, auto, auto) {
    const FieldDescriptor* f = proto::SnapshotContacts::descriptor()->FindFieldByName(info.name);
    if (f == nullptr || !f->is_repeated()) {
      throw std::logic_error(std::string("dem.proto.SnapshotContacts has no repeated field ") + info.name);
    }
    fields[k++] = f;
  });
  return fields;
}

template <int Dim>
const std::array<const FieldDescriptor*, contact_field_count<Dim>()>& message_fields() {
  static const auto fields = find_message_fields<Dim>();
  return fields;
}

// Appends doubles to a repeated field through reflection (Packing's output).
struct ReflectedDoubles {
  const Reflection* reflection;
  proto::SnapshotContacts* message;
  const FieldDescriptor* field;
  void Add(double value) const { reflection->AddDouble(message, field, value); }
};

template <typename T>
void add(const Reflection& r, proto::SnapshotContacts& out, const FieldDescriptor* f, const T& value) {
  if constexpr (std::is_same_v<T, bool>) {
    r.AddBool(&out, f, value);
  } else if constexpr (std::is_same_v<T, std::int32_t>) {
    r.AddInt32(&out, f, value);
  } else if constexpr (std::is_same_v<T, std::uint64_t>) {
    r.AddUInt64(&out, f, value);
  } else {
    ReflectedDoubles doubles{&r, &out, f};
    put(&doubles, value);
  }
}

template <typename T>
T read(const Reflection& r, const proto::SnapshotContacts& in, const FieldDescriptor* f, int i) {
  if constexpr (std::is_same_v<T, bool>) {
    return r.GetRepeatedBool(in, f, i);
  } else if constexpr (std::is_same_v<T, std::int32_t>) {
    return r.GetRepeatedInt32(in, f, i);
  } else if constexpr (std::is_same_v<T, std::uint64_t>) {
    return r.GetRepeatedUInt64(in, f, i);
  } else {
    return get<T>(r.GetRepeatedFieldRef<double>(in, f), i);
  }
}

}  // namespace

template <int Dim>
void put_contacts(const std::vector<ContactSnapshotT<Dim>>& contacts, proto::SnapshotContacts& out) {
  const auto& fields = message_fields<Dim>();
  const Reflection& r = *out.GetReflection();
  std::size_t k = 0;
  for_each_contact_field<Dim>([&](const ContactFieldInfo&, auto field, auto) {
    const FieldDescriptor* f = fields[k++];
    for (const ContactSnapshotT<Dim>& c : contacts) add(r, out, f, field(c));
  });
}

template <int Dim>
bool check_contacts(Problems& problems, const proto::SnapshotContacts& in, const Counts& n) {
  const auto& fields = message_fields<Dim>();
  const Reflection& r = *in.GetReflection();
  bool sizes = true;
  std::size_t k = 0;
  for_each_contact_field<Dim>([&](const ContactFieldInfo& info, auto field, auto) {
    using T = FieldType<Dim, decltype(field)>;
    const FieldDescriptor* f = fields[k++];
    const std::string path = std::string("contacts.") + info.name;
    if (info.may_be_empty && r.FieldSize(in, f) == 0) return;
    if constexpr (kPacked<T>) {
      sizes = check_array(problems, path, r.GetRepeatedFieldRef<double>(in, f), n.contacts, width<T>) && sizes;
    } else {
      sizes = check_length(problems, path, r.GetRepeatedFieldRef<T>(in, f), n.contacts) && sizes;
    }
  });
  if (!sizes) return false;
  for (int i = 0; i < in.first_size(); ++i) {
    const std::string path = "contacts[" + std::to_string(i) + "]";
    if (!in_range(in.first(i), n.particle_ids)) {
      problems.add(path + ".first", "particle " + std::to_string(in.first(i)) + " out of range");
    }
    if (!in_range(in.second(i), in.with_wall(i) ? n.walls : n.particle_ids)) {
      problems.add(path + ".second", std::string(in.with_wall(i) ? "wall " : "particle ") +
                                         std::to_string(in.second(i)) + " out of range");
    }
  }
  return true;
}

template <int Dim>
std::vector<ContactSnapshotT<Dim>> get_contacts(const proto::SnapshotContacts& in) {
  const auto& fields = message_fields<Dim>();
  const Reflection& r = *in.GetReflection();
  std::vector<ContactSnapshotT<Dim>> contacts(static_cast<std::size_t>(in.first_size()));
  std::size_t k = 0;
  for_each_contact_field<Dim>([&](const ContactFieldInfo& info, auto field, auto) {
    using T = FieldType<Dim, decltype(field)>;
    const FieldDescriptor* f = fields[k++];
    if (info.may_be_empty && r.FieldSize(in, f) == 0) return;  // the default
    for (std::size_t i = 0; i < contacts.size(); ++i) field(contacts[i]) = read<T>(r, in, f, static_cast<int>(i));
  });
  return contacts;
}

template void put_contacts<2>(const std::vector<ContactSnapshotT<2>>&, proto::SnapshotContacts&);
template void put_contacts<3>(const std::vector<ContactSnapshotT<3>>&, proto::SnapshotContacts&);
template bool check_contacts<2>(Problems&, const proto::SnapshotContacts&, const Counts&);
template bool check_contacts<3>(Problems&, const proto::SnapshotContacts&, const Counts&);
template std::vector<ContactSnapshotT<2>> get_contacts<2>(const proto::SnapshotContacts&);
template std::vector<ContactSnapshotT<3>> get_contacts<3>(const proto::SnapshotContacts&);

}  // namespace dem::io
