// A domain participant on a domain configured explicitly.
//
// Which Cyclone DDS configuration a process uses: the one it is given (a
// --dds-config option), else $CYCLONEDDS_URI, else the repository's
// loopback-only file (config/cyclonedds-loopback.xml) - never Cyclone's
// built-in default, which discovers over multicast on the external interface.
#pragma once

#include <dds/dds.h>

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "dem/dds/entity.h"

namespace dem::dds {

// The compiled-in default: "file://<source>/config/cyclonedds-loopback.xml",
// or that file's text when it is gone (an installed program).
std::string default_config();

// Turns an option value into a Cyclone configuration string: empty -> the
// environment or the default above; XML (starting with '<') and URIs
// ("file://...") as they are; anything else is a file path, made absolute.
std::string resolve_config(std::string_view requested);

class Domain;

class Participant {
 public:
  // `config` as for resolve_config. All participants of one domain in a
  // process share its configuration; asking for another throws DdsError.
  Participant(std::uint32_t domain_id, std::string_view config = {});
  ~Participant();
  Participant(Participant&&) noexcept;
  Participant& operator=(Participant&&) noexcept;

  dds_entity_t handle() const { return entity_.handle(); }
  std::uint32_t domain_id() const { return domain_id_; }
  const std::string& config() const;

 private:
  std::uint32_t domain_id_;
  std::shared_ptr<Domain> domain_;  // declared first: outlives the participant entity
  Entity entity_;
};

}  // namespace dem::dds
