#include "dem/dds/participant.h"

#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>

#include "dem/dds/error.h"
#include "loopback_config.h"

namespace dem::dds {

std::string default_config() {
  // An installed program has no repository to read the file from: it
  // carries the file's text, which Cyclone takes in place of a URI.
  if (std::filesystem::exists(DEM_DEFAULT_DDS_CONFIG)) return "file://" DEM_DEFAULT_DDS_CONFIG;
  return std::string(kLoopbackConfig);
}

std::string resolve_config(std::string_view requested) {
  if (requested.empty()) {
    const char* environment = std::getenv("CYCLONEDDS_URI");
    if (environment != nullptr && *environment != '\0') return environment;
    return default_config();
  }
  if (requested.front() == '<' || requested.find("://") != std::string_view::npos) return std::string(requested);
  return "file://" + std::filesystem::absolute(std::filesystem::path(requested)).string();
}

// One Cyclone domain per domain id and process, created with an explicit
// configuration and deleted with its last participant. The registry lock
// is held while a domain is created or deleted, so a new participant never
// races the deletion of the previous domain of its id.
class Domain {
 public:
  Domain(std::uint32_t id, std::string config) : id_(id), config_(std::move(config)) {
    const dds_entity_t handle = dds_create_domain(id, config_.c_str());
    if (handle == DDS_RETCODE_PRECONDITION_NOT_MET) {
      throw DdsError(handle,
                     "domain " + std::to_string(id) + " was created outside dem::dds (its configuration is unknown)");
    }
    entity_ = Entity(check(handle, "creating DDS domain " + std::to_string(id) + " with " + config_));
  }
  const std::string& config() const { return config_; }
  std::uint32_t id() const { return id_; }

 private:
  std::uint32_t id_;
  std::string config_;
  Entity entity_;
};

namespace {

std::mutex registry_mutex;
std::map<std::uint32_t, std::weak_ptr<Domain>>& registry() {
  static std::map<std::uint32_t, std::weak_ptr<Domain>> domains;
  return domains;
}

std::shared_ptr<Domain> acquire_domain(std::uint32_t id, const std::string& config) {
  std::lock_guard lock(registry_mutex);
  if (auto existing = registry()[id].lock()) {
    if (existing->config() != config) {
      throw DdsError(DDS_RETCODE_PRECONDITION_NOT_MET, "DDS domain " + std::to_string(id) + " already runs with " +
                                                           existing->config() + ", not " + config);
    }
    return existing;
  }
  std::shared_ptr<Domain> domain(new Domain(id, config), [](Domain* d) {
    std::lock_guard deleting(registry_mutex);
    delete d;
  });
  registry()[id] = domain;
  return domain;
}

}  // namespace

Participant::Participant(std::uint32_t domain_id, std::string_view config)
    : domain_id_(domain_id), domain_(acquire_domain(domain_id, resolve_config(config))) {
  entity_ = Entity(check(dds_create_participant(domain_id, nullptr, nullptr),
                         "creating a participant on DDS domain " + std::to_string(domain_id)));
}

Participant::~Participant() = default;
Participant::Participant(Participant&&) noexcept = default;
Participant& Participant::operator=(Participant&&) noexcept = default;

const std::string& Participant::config() const { return domain_->config(); }

}  // namespace dem::dds
