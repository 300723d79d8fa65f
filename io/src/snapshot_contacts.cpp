#include "snapshot_contacts.h"

#include <google/protobuf/descriptor.h>
#include <google/protobuf/reflection.h>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "snapshot_conversion_fields.h"
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
  for_each_contact_field<Dim>([&](const ContactFieldInfo& info, auto field, auto) {
    const FieldDescriptor* f = proto::SnapshotContacts::descriptor()->FindFieldByName(info.name);
    if (f == nullptr || !f->is_repeated()) {
      throw std::logic_error(std::string("dem.proto.SnapshotContacts has no repeated field ") + info.name);
    }
    if (const char* problem = fields::column_problem<FieldType<Dim, decltype(field)>>(*f)) {
      throw std::logic_error("field " + f->full_name() + " cannot carry its list entry: " + problem);
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

}  // namespace

template <int Dim>
void put_contacts(const std::vector<ContactSnapshotT<Dim>>& contacts, proto::SnapshotContacts& out) {
  const auto& fields = message_fields<Dim>();
  std::size_t k = 0;
  for_each_contact_field<Dim>([&](const ContactFieldInfo&, auto field, auto) {
    using T = FieldType<Dim, decltype(field)>;
    // Column by column, in bulk (snapshot_conversion_fields.h).
    fields::put_column<T>(out, fields[k++], contacts.size(),
                          [&](std::size_t i) -> const T& { return field(contacts[i]); });
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
      sizes = check_array(problems, path, fields::column<double>(in, f), n.contacts, width<T>) && sizes;
    } else {
      sizes = check_length(problems, path, fields::column<T>(in, f), n.contacts) && sizes;
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
  std::vector<ContactSnapshotT<Dim>> contacts(static_cast<std::size_t>(in.first_size()));
  std::size_t k = 0;
  for_each_contact_field<Dim>([&](const ContactFieldInfo&, auto field, auto) {
    using T = FieldType<Dim, decltype(field)>;
    // An empty field (may_be_empty, checked) leaves the default.
    fields::get_column<T>(in, fields[k++], contacts.size(), [&](std::size_t i) -> T& { return field(contacts[i]); });
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
