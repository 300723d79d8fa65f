// Guards against two defects of the Cyclone DDS this project builds on
// (Debian 12's 0.10.2) that any peer on the domain can trigger with the
// type information it announces for a reader or writer (XTypes 1.3
// 7.6.3.2.2), found with tests/service/discovery_probe
// (docs/RELIABILITY.md, "Discovery"). Cyclone checks the announced type
// information with ddsi_typeinfo_valid as it parses the announcement, on its
// discovery thread (dq.builtins):
//
// 1. An abort. In 0.10.2 the check asks for the kind of the announced type
//    identifiers, and for a discriminator that is neither a hash, a fully
//    descriptive kind nor a plain collection (0xb0, a strongly connected
//    component, or any other byte) ddsi_typeid_kind_impl calls abort(): one
//    malformed announcement ends the process (the probe: round 30 of seed 1,
//    every time). Fixed upstream after 0.10.5:
//    eclipse-cyclonedds/cyclonedds#2105 (commit 9e9a22e4, "Stricter
//    validation of type information": only hash identifiers) and #2106
//    (f7ca14d6, "Return INVALID instead of aborting in type kinds").
// 2. A type poisoned for good. Cyclone adds every dependency an
//    announcement lists to the type its identifier names, also to a type
//    of the process's own that it has resolved (ddsi_typelib.c,
//    type_add_deps). An announcement with the server's own identifier for
//    Command_ and one made-up dependency leaves Command_ waiting for a type
//    object nobody has: from then on no new client's writer is matched with
//    the server's reader (is_endpoint_type_resolved: unresolved with its
//    dependencies), and the server answers nobody new - until it restarts
//    (the probe: round 16 of seed 1). Master still merges the dependencies
//    the same way; no upstream report or fix is known to us.
//
// libddsc calls ddsi_typeinfo_valid through its procedure linkage table
// (objdump: call ddsi_typeinfo_valid@plt, from the parameter-list parser
// and dds_find_topic), so a definition in the program takes its place, as a
// program's malloc takes libc's. This one allows what upstream allows now -
// a minimal hash, a complete hash and hash dependencies - without asking for
// any other kind, and for the type identifiers of this program's own topic
// types (protect_type_information) only the dependencies the program itself
// compiled in: a peer announcing them with others is refused as invalid,
// like any malformed announcement, and the type stays as it was. It is
// compiled only against 0.10, whose structures it reads.
#include <dds/dds.h>  // before the internal header, which needs its types
#include <dds/ddsi/ddsi_xt_typeinfo.h>
#include <dds/version.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <mutex>
#include <vector>

#include "dem/dds/type_information_guard.h"

#if DDS_VERSION_MAJOR == 0 && DDS_VERSION_MINOR == 10

// Exported by libddsc 0.10 (dds/ddsi/ddsi_typelib.h, which does not build
// on its own in C++): the type information of a descriptor, allocated.
extern "C" {
struct ddsi_sertype_cdr_data;
struct ddsi_typeinfo* ddsi_typeinfo_deser(const struct ddsi_sertype_cdr_data* ser);
void ddsi_typeinfo_fini(struct ddsi_typeinfo* typeinfo);
}

namespace dem::dds {
namespace {

// A struct ddsi_typeinfo is its one member, a DDS_XTypes_TypeInformation
// (dds/ddsi/ddsi_xt_impl.h).
const DDS_XTypes_TypeInformation& information_of(const struct ddsi_typeinfo* typeinfo) {
  return *reinterpret_cast<const DDS_XTypes_TypeInformation*>(typeinfo);
}

bool is_hash(const DDS_XTypes_TypeIdentifier& id, std::uint8_t kind) { return id._d == kind; }

// Two hash identifiers (checked to be hashes first).
bool same_hash(const DDS_XTypes_TypeIdentifier& a, const DDS_XTypes_TypeIdentifier& b) {
  return a._d == b._d && std::memcmp(a._u.equivalence_hash, b._u.equivalence_hash, sizeof a._u.equivalence_hash) == 0;
}

// The dependencies of one part (minimal or complete): all hashes of that
// part, as many as the count says at least, sized (upstream's rule).
bool dependencies_valid(const DDS_XTypes_TypeIdentifierWithDependencies& part, std::uint8_t kind) {
  const auto& dependencies = part.dependent_typeids;
  if (part.dependent_typeid_count == -1) return dependencies._length == 0;
  if (dependencies._length > INT32_MAX || part.dependent_typeid_count < static_cast<std::int32_t>(dependencies._length))
    return false;
  if (dependencies._length > 0 && dependencies._buffer == nullptr) return false;
  for (std::uint32_t n = 0; n < dependencies._length; ++n) {
    if (!is_hash(dependencies._buffer[n].type_id, kind) || dependencies._buffer[n].typeobject_serialized_size == 0) {
      return false;
    }
  }
  return true;
}

bool same_dependencies(const DDS_XTypes_TypeIdentifierWithDependencies& a,
                       const DDS_XTypes_TypeIdentifierWithDependencies& b) {
  if (a.dependent_typeid_count != b.dependent_typeid_count ||
      a.dependent_typeids._length != b.dependent_typeids._length) {
    return false;
  }
  for (std::uint32_t n = 0; n < a.dependent_typeids._length; ++n) {
    if (!same_hash(a.dependent_typeids._buffer[n].type_id, b.dependent_typeids._buffer[n].type_id)) return false;
  }
  return true;
}

// The program's own type information, as its topics' descriptors give it;
// kept for the life of the process (a handful of types).
std::mutex own_mutex;
std::vector<struct ddsi_typeinfo*>& own_types() {
  static std::vector<struct ddsi_typeinfo*> types;
  return types;
}

// Whether `info` names one of the program's own types but not as the
// program does (other identifiers beside it, other dependencies).
bool rewrites_own_type(const DDS_XTypes_TypeInformation& info) {
  std::lock_guard lock(own_mutex);
  for (const struct ddsi_typeinfo* own : own_types()) {
    const DDS_XTypes_TypeInformation& mine = information_of(own);
    const bool minimal = same_hash(info.minimal.typeid_with_size.type_id, mine.minimal.typeid_with_size.type_id);
    const bool complete = same_hash(info.complete.typeid_with_size.type_id, mine.complete.typeid_with_size.type_id);
    if (!minimal && !complete) continue;
    return !(minimal && complete && same_dependencies(info.minimal, mine.minimal) &&
             same_dependencies(info.complete, mine.complete));
  }
  return false;
}

}  // namespace

void protect_type_information(const dds_topic_descriptor_t& descriptor) {
  if ((descriptor.m_flagset & DDS_TOPIC_XTYPES_METADATA) == 0 || descriptor.type_information.sz == 0) return;
  // ddsi_sertype_cdr_data is {uint32_t sz; uint8_t* data;} (dds/ddsi/ddsi_sertype.h).
  struct {
    std::uint32_t sz;
    std::uint8_t* data;
  } serialized{descriptor.type_information.sz, descriptor.type_information.data};
  struct ddsi_typeinfo* typeinfo =
      ddsi_typeinfo_deser(reinterpret_cast<const struct ddsi_sertype_cdr_data*>(&serialized));
  if (typeinfo == nullptr) return;
  std::lock_guard lock(own_mutex);
  const DDS_XTypes_TypeInformation& info = information_of(typeinfo);
  const bool known = std::any_of(own_types().begin(), own_types().end(), [&](const struct ddsi_typeinfo* own) {
    return same_hash(information_of(own).minimal.typeid_with_size.type_id, info.minimal.typeid_with_size.type_id);
  });
  if (known) {
    ddsi_typeinfo_fini(typeinfo);
    dds_free(typeinfo);
    return;
  }
  own_types().push_back(typeinfo);
}

}  // namespace dem::dds

// Interposes libddsc's function of the same name and signature
// (dds/ddsi/ddsi_typelib.h); visible to the dynamic linker also from a
// shared library (the Python extension).
extern "C" __attribute__((visibility("default"))) bool ddsi_typeinfo_valid(const struct ddsi_typeinfo* typeinfo) {
  if (typeinfo == nullptr) return false;
  const DDS_XTypes_TypeInformation& info = dem::dds::information_of(typeinfo);
  return dem::dds::is_hash(info.minimal.typeid_with_size.type_id, DDS_XTypes_EK_MINIMAL) &&
         dem::dds::is_hash(info.complete.typeid_with_size.type_id, DDS_XTypes_EK_COMPLETE) &&
         dem::dds::dependencies_valid(info.minimal, DDS_XTypes_EK_MINIMAL) &&
         dem::dds::dependencies_valid(info.complete, DDS_XTypes_EK_COMPLETE) && !dem::dds::rewrites_own_type(info);
}

#else

namespace dem::dds {
void protect_type_information(const dds_topic_descriptor_t&) {}
}  // namespace dem::dds

#endif
