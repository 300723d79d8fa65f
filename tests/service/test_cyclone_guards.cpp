// The guards against Cyclone DDS 0.10's defects (dds/src/cyclone_guards.cpp):
// the program's own ddsi_typeinfo_valid is the one libddsc calls, and it
// refuses what made 0.10.2 abort or poisoned the program's own types. The
// discovery probe (ctest dds_discovery_probe) drives the same against a
// whole server over the wire.
#include <dds/dds.h>  // before the internal header, which needs its types
#include <dds/ddsi/ddsi_xt_typeinfo.h>
#include <dds/version.h>
#include <gtest/gtest.h>

#include <cstring>
#include <memory>

#include "dem/dds/topic.h"
#include "dem/dds/type_information_guard.h"
#include "dem/protocol/topics.h"
#include "dem/protocol/type_support.h"
#include "discovery_probe/probe_variants.h"
#include "service_test_support.h"

#if DDS_VERSION_MAJOR == 0 && DDS_VERSION_MINOR == 10

extern "C" {
struct ddsi_sertype_cdr_data;
struct ddsi_typeinfo* ddsi_typeinfo_deser(const struct ddsi_sertype_cdr_data* ser);
void ddsi_typeinfo_fini(struct ddsi_typeinfo* typeinfo);
}

namespace dem::test {
namespace {

// A descriptor's type information, decoded, to edit.
struct TypeInformation {
  explicit TypeInformation(const dds_topic_descriptor_t& descriptor) {
    struct {
      std::uint32_t sz;
      std::uint8_t* data;
    } serialized{descriptor.type_information.sz, descriptor.type_information.data};
    typeinfo = ddsi_typeinfo_deser(reinterpret_cast<const struct ddsi_sertype_cdr_data*>(&serialized));
  }
  ~TypeInformation() {
    ddsi_typeinfo_fini(typeinfo);
    dds_free(typeinfo);
  }
  DDS_XTypes_TypeInformation& info() { return *reinterpret_cast<DDS_XTypes_TypeInformation*>(typeinfo); }
  struct ddsi_typeinfo* typeinfo = nullptr;
};

// dds_find_topic checks the type information it is given with
// ddsi_typeinfo_valid before anything else: BAD_PARAMETER when invalid.
dds_return_t find(const dds::Participant& participant, const TypeInformation& type) {
  return dds_find_topic(DDS_FIND_SCOPE_LOCAL_DOMAIN, participant.handle(), "rt/dem/guarded/plate_forces", type.typeinfo,
                        0);
}

// The server registers its own types without XTypes type information, as
// rmw_cyclonedds registers ROS 2's (idl/CMakeLists.txt): a peer has none of
// their type identifiers to poison, and endpoints match by type name.
TEST(CycloneGuards, TheServersOwnTypesCarryNoTypeInformation) {
  EXPECT_EQ(dds::TypeSupport<protocol::Status>::descriptor()->type_information.sz, 0u);
  EXPECT_EQ(dds::TypeSupport<protocol::Command>::descriptor()->type_information.sz, 0u);
  EXPECT_EQ(dds::TypeSupport<protocol::Reply>::descriptor()->type_information.sz, 0u);
  EXPECT_EQ(dds::TypeSupport<protocol::PlateForces>::descriptor()->type_information.sz, 0u);
  EXPECT_EQ(dds::TypeSupport<protocol::ContactStats>::descriptor()->type_information.sz, 0u);
}

// A peer's type information comes all the same, in discovery and type
// lookups: here the discovery probe's description of PlateForces_ (compiled
// with type information, tests/service/discovery_probe).
TEST(CycloneGuards, TypeInformationWithAnIdentifierOfAnotherKindIsRefusedWithoutAnAbort) {
  dds::Participant participant(kGuardsTypeInformation);
  TypeInformation type(probe_final_PlateForces_desc);
  ASSERT_NE(type.typeinfo, nullptr);
  // A strongly connected component's discriminator where a minimal hash
  // belongs: libddsc 0.10.2's own check aborts the process on it.
  type.info().minimal.typeid_with_size.type_id._d = DDS_XTypes_TI_STRONGLY_CONNECTED_COMPONENT;
  EXPECT_EQ(find(participant, type), DDS_RETCODE_BAD_PARAMETER);
}

// A program whose own types do carry type information (a client built with
// idlc's defaults, say) has them guarded: Topic<T> registers them, as
// protect_type_information does here for the probe's PlateForces_ (whose stamp is a dependency).
TEST(CycloneGuards, AnOwnTypeAnnouncedWithOtherDependenciesIsRefused) {
  dds::Participant participant(kGuardsTypeInformation);
  dds::protect_type_information(probe_final_PlateForces_desc);
  const dds_entity_t topic = dds_create_topic(participant.handle(), &probe_final_PlateForces_desc,
                                              "rt/dem/guarded/plate_forces", nullptr, nullptr);
  ASSERT_GT(topic, 0);
  TypeInformation own(probe_final_PlateForces_desc);
  ASSERT_NE(own.typeinfo, nullptr);
  EXPECT_NE(find(participant, own), DDS_RETCODE_BAD_PARAMETER);  // as the program compiled it: valid

  // The same identifiers with one dependency's hash changed: what a peer
  // would need to leave PlateForces_ waiting for a type nobody has.
  TypeInformation poisoned(probe_final_PlateForces_desc);
  auto& dependencies = poisoned.info().minimal.dependent_typeids;
  ASSERT_GT(dependencies._length, 0u);
  dependencies._buffer[0].type_id._u.equivalence_hash[0] ^= 0x01;
  EXPECT_EQ(find(participant, poisoned), DDS_RETCODE_BAD_PARAMETER);

  // Another program's type of the same name is not this one's to judge.
  TypeInformation other(probe_final_PlateForces_desc);
  other.info().minimal.typeid_with_size.type_id._u.equivalence_hash[0] ^= 0x01;
  other.info().complete.typeid_with_size.type_id._u.equivalence_hash[0] ^= 0x01;
  other.info().minimal.dependent_typeids._buffer[0].type_id._u.equivalence_hash[0] ^= 0x01;
  EXPECT_NE(find(participant, other), DDS_RETCODE_BAD_PARAMETER);
}

}  // namespace
}  // namespace dem::test

#endif
