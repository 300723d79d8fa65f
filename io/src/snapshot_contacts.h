// The contact table in a snapshot message (dem.proto.SnapshotContacts):
// one repeated field per contact field, each named and typed as the engine's
// one field list says (for_each_contact_field in dem/snapshot.h), so writing,
// checking and reading follow from that list.
#pragma once

#include <vector>

#include "dem/snapshot.h"
#include "dem/snapshot.pb.h"
#include "snapshot_problems.h"

namespace dem::io {

template <int Dim>
void put_contacts(const std::vector<ContactSnapshotT<Dim>>& contacts, proto::SnapshotContacts& out);

// Every field holds one item for each of the contacts `first` names (a
// field added after version 1 may be empty), doubles finite, ids in range.
// Returns false when the lengths do not allow reading.
template <int Dim>
bool check_contacts(Problems& problems, const proto::SnapshotContacts& in, const Counts& n);

// Reads a message that passed check_contacts.
template <int Dim>
std::vector<ContactSnapshotT<Dim>> get_contacts(const proto::SnapshotContacts& in);

}  // namespace dem::io
