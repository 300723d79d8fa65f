#include "probe_participant.h"

// ddsi_typelib.h needs ddsi_xqos.h's QoS types, so the order is not alphabetical
// clang-format off
#include <dds/dds.h>
#include <dds/ddsi/ddsi_xqos.h>
#include <dds/ddsi/ddsi_typelib.h>
// clang-format on
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "dem/command.h"
#include "dem/telemetry.h"
#include "probe_variants.h"

namespace dem::probe {
namespace {

// The server's topics and, for each, the descriptions of its type name a
// round may use: the server's own, three others of the same name
// (probe_variants.h), and the server's without its type information.
struct ProbeTopic {
  const char* suffix;
  std::array<const dds_topic_descriptor_t*, 4> described;  // the server's own first
};

const std::array<ProbeTopic, 5>& probe_topics() {
  static const std::array<ProbeTopic, 5> topics{{
      {"command",
       {&dem_interfaces_msg_dds__Command__desc, &probe_final_Command_desc, &probe_appendable_Command_desc,
        &probe_mutable_Command_desc}},
      {"reply",
       {&dem_interfaces_msg_dds__Reply__desc, &probe_final_Reply_desc, &probe_appendable_Reply_desc,
        &probe_mutable_Reply_desc}},
      {"status",
       {&dem_interfaces_msg_dds__Status__desc, &probe_final_Status_desc, &probe_appendable_Status_desc,
        &probe_mutable_Status_desc}},
      {"plate_forces",
       {&dem_interfaces_msg_dds__PlateForces__desc, &probe_final_PlateForces_desc, &probe_appendable_PlateForces_desc,
        &probe_mutable_PlateForces_desc}},
      {"contact_stats",
       {&dem_interfaces_msg_dds__ContactStats__desc, &probe_final_ContactStats_desc,
        &probe_appendable_ContactStats_desc, &probe_mutable_ContactStats_desc}},
  }};
  return topics;
}

// A description with its type information taken away: what a peer that
// does not do XTypes (ROS 2's rmw_cyclonedds, older Cyclone) announces.
dds_topic_descriptor_t without_type_information(const dds_topic_descriptor_t& described) {
  return dds_topic_descriptor_t{described.m_size,
                                described.m_align,
                                described.m_flagset & ~static_cast<std::uint32_t>(DDS_TOPIC_XTYPES_METADATA),
                                described.m_nkeys,
                                described.m_typename,
                                described.m_keys,
                                described.m_nops,
                                described.m_ops,
                                described.m_meta,
                                {nullptr, 0},
                                {nullptr, 0},
                                described.restrict_data_representation};
}

dds_qos_t* random_qos(std::mt19937_64& random) {
  dds_qos_t* qos = dds_create_qos();
  if (random() % 2 == 0) {
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
  } else {
    dds_qset_reliability(qos, DDS_RELIABILITY_BEST_EFFORT, 0);
  }
  if (random() % 2 == 0) dds_qset_durability(qos, DDS_DURABILITY_TRANSIENT_LOCAL);
  if (random() % 2 == 0) {
    dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
  } else {
    dds_qset_history(qos, DDS_HISTORY_KEEP_LAST, static_cast<int32_t>(1 + random() % 64));
  }
  return qos;
}

// Asks for the type objects of the server's endpoints found through the
// built-in topics: with an empty type library each is a type-lookup
// request to the server.
void look_up_server_types(dds_entity_t participant, const std::string& prefix, int timeout_ms) {
  for (const dds_entity_t builtin : {DDS_BUILTIN_TOPIC_DCPSPUBLICATION, DDS_BUILTIN_TOPIC_DCPSSUBSCRIPTION}) {
    const dds_entity_t reader = dds_create_reader(participant, builtin, nullptr, nullptr);
    if (reader < 0) continue;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    void* samples[64] = {};
    dds_sample_info_t infos[64];
    const int32_t n = dds_take(reader, samples, infos, 64, 64);
    for (int32_t i = 0; i < n; ++i) {
      if (!infos[i].valid_data) continue;
      auto* endpoint = static_cast<dds_builtintopic_endpoint_t*>(samples[i]);
      if (endpoint->topic_name == nullptr || std::string(endpoint->topic_name).rfind(prefix, 0) != 0) continue;
      const dds_typeinfo_t* type_info = nullptr;
      if (dds_builtintopic_get_endpoint_type_info(endpoint, &type_info) != DDS_RETCODE_OK || type_info == nullptr) {
        continue;
      }
      for (const ddsi_typeid_t* id :
           {ddsi_typeinfo_minimal_typeid(type_info), ddsi_typeinfo_complete_typeid(type_info)}) {
        dds_typeobj_t* object = nullptr;
        if (id != nullptr && dds_get_typeobj(participant, id, DDS_MSECS(timeout_ms), &object) == DDS_RETCODE_OK) {
          dds_free_typeobj(object);
        }
      }
      dds_topic_descriptor_t* resolved = nullptr;
      if (dds_create_topic_descriptor(DDS_FIND_SCOPE_GLOBAL, participant, type_info, DDS_MSECS(timeout_ms),
                                      &resolved) == DDS_RETCODE_OK) {
        dds_delete_topic_descriptor(resolved);
      }
    }
    if (n > 0) dds_return_loan(reader, samples, n);
    dds_delete(reader);
  }
}

}  // namespace

int run_participant_round(const ParticipantRound& round) {
  std::mt19937_64 random(round.seed);
  const dds_entity_t participant = dds_create_participant(round.domain, nullptr, nullptr);
  if (participant < 0) {
    std::fprintf(stderr, "probe: cannot create a participant on domain %u: %s\n", round.domain,
                 dds_strretcode(participant));
    return 1;
  }
  const std::string prefix = "rt/dem/" + round.server + "/";
  // Each topic once per participant (Cyclone refuses a second description
  // of a topic in one participant); readers and writers on it at random.
  std::vector<dds_topic_descriptor_t> bare;
  bare.reserve(probe_topics().size());
  for (const ProbeTopic& topic : probe_topics()) {
    const std::size_t pick = random() % (topic.described.size() + 1);
    const dds_topic_descriptor_t* described = nullptr;
    if (pick < topic.described.size()) {
      described = topic.described[pick];
    } else {
      bare.push_back(without_type_information(*topic.described[random() % topic.described.size()]));
      described = &bare.back();
    }
    const std::string name = prefix + topic.suffix;
    const dds_entity_t handle = dds_create_topic(participant, described, name.c_str(), nullptr, nullptr);
    if (handle < 0) continue;
    const int endpoints = static_cast<int>(random() % 4);
    for (int e = 0; e < endpoints; ++e) {
      dds_qos_t* qos = random_qos(random);
      if (random() % 2 == 0) {
        dds_create_reader(participant, handle, qos, nullptr);
      } else {
        dds_create_writer(participant, handle, qos, nullptr);
      }
      dds_delete_qos(qos);
    }
  }
  look_up_server_types(participant, prefix, round.lookup_timeout_ms);
  std::this_thread::sleep_for(std::chrono::milliseconds(random() % 200));
  switch (random() % 3) {
    case 0:  // dies: its proxies stay on the server until the lease ends
      std::fflush(nullptr);
      _exit(0);
    case 1:  // leaves cleanly
      dds_delete(participant);
      break;
    default:  // leaves with the whole domain at once
      dds_delete(DDS_CYCLONEDDS_HANDLE);
      break;
  }
  return 0;
}

}  // namespace dem::probe
