// The simulation a server owns: the world (2D or 3D, a WorldSession)
// and what the service knows about it beyond the engine (the case's name
// and description, its contact models, its loading programme and its
// output settings). Every operation a command asks for
// checks its arguments first and throws CommandError (a reply status and a
// message) without changing anything; a new world replaces the old one only
// once it is complete. Used by the engine thread only.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dem/io/case_definition.h"
#include "dem/io/file_access.h"
#include "dem/io/resource_limits.h"
#include "dem/io/snapshot_conversion.h"
#include "dem/protocol/messages.h"
#include "dem/service/case_programme.h"
#include "dem/service/command_limits.h"
#include "dem/service/world_session.h"

namespace dem::service {

class Simulation {
 public:
  // `files`: where a case named by its path, and the particle files cases
  // name, may be read from (null: nowhere).
  explicit Simulation(std::optional<int> threads = std::nullopt, io::ResourceLimits limits = io::machine_limits(),
                      std::uint64_t max_query_contacts = CommandLimits{}.max_query_contacts,
                      std::shared_ptr<const io::FileAccess> files = nullptr);

  bool loaded() const { return world_ != nullptr; }
  const WorldSession& world() const { return *world_; }
  WorldSession& world() { return *world_; }
  const std::string& case_name() const { return case_name_; }
  std::uint8_t dimension() const { return loaded() ? world_->dimension() : 0; }
  const std::string& case_digest() const { return digest_; }
  // The case's stages (none for a snapshot).
  const CaseProgramme& programme() const { return programme_; }
  // The case's output settings (a snapshot's are the defaults).
  const io::OutputSettings& output() const { return output_; }
  // Cycles between rows of the case's time series (its output.interval).
  std::uint64_t output_interval() const { return output_.interval; }

  // A world built and ready to replace the current one.
  struct Prepared {
    std::unique_ptr<WorldSession> world;
    std::string case_name;
    std::string description;
    std::vector<ContactModelDef> contact_models;
    CaseProgramme programme;    // the case's stages; a snapshot keeps none
    io::OutputSettings output;  // the case's; a snapshot keeps the defaults
    std::string digest;         // SHA-256 of the case's bytes (hex); empty for a snapshot: what a checkpoint resumes
    std::string message;        // what was loaded, for the reply
  };
  // Prepares worlds for it: a value, so a preparation may run on another
  // thread and even outlive the simulation (an abandoned load).
  class Preparer {
   public:
    Preparer(io::ResourceLimits limits, std::shared_ptr<const io::FileAccess> files)
        : limits_(limits), files_(std::move(files)) {}
    // A case (2D or 3D) from a file the server reads, text or serialized
    // bytes, within the resource limits. INVALID_CASE names the file, line
    // and field of each problem (a file's syntax errors its line and column
    // only, not its text); NOT_FOUND when the file is missing or outside the
    // directories the server reads (the same answer: whether a file exists
    // outside them is not said); REFUSED when it reads no files at all.
    Prepared prepare_case(const protocol::LoadCaseArgs& args) const;
    // A framed, serialized dem.proto.Snapshot of either dimension, within
    // the resource limits; INVALID_SNAPSHOT when it is not one or is
    // inconsistent. `source` names it in messages.
    Prepared prepare_snapshot(std::string_view bytes, const std::string& source) const;
    // The same preparer, its random packings ended when `stopped` says so
    // (io::ResourceLimits::stop_packing).
    Preparer stopped_by(std::function<bool()> stopped) const {
      Preparer copy = *this;
      copy.limits_.stop_packing = std::move(stopped);
      return copy;
    }
    // The same preparer, reading files through `files` instead.
    Preparer reading(std::shared_ptr<const io::FileAccess> files) const {
      Preparer copy = *this;
      copy.files_ = std::move(files);
      return copy;
    }

   private:
    io::ResourceLimits limits_;
    std::shared_ptr<const io::FileAccess> files_;
  };
  Preparer preparer() const { return Preparer(limits_, files_); }
  Prepared prepare_case(const protocol::LoadCaseArgs& args) const { return preparer().prepare_case(args); }
  Prepared prepare_snapshot(std::string_view bytes, const std::string& source) const {
    return preparer().prepare_snapshot(bytes, source);
  }
  // Makes a prepared world the simulation; returns its message.
  std::string install(Prepared prepared);
  // Lets the world go (a restore that failed for want of memory left the
  // session without one): nothing is loaded afterwards.
  void drop();
  std::string snapshot_bytes() const;
  io::SnapshotInfo snapshot_info() const { return {case_name_, description_}; }  // what a snapshot says of the case

  std::string set_wall_velocity(const protocol::WallVelocityArgs& args);
  std::string set_wall_servo(const protocol::WallServoArgs& args);
  std::string set_parameter(const protocol::ParameterArgs& args);
  // BAD_REQUEST when more contacts match than one query may return.
  std::vector<protocol::ContactEntry> query_contacts(const protocol::ContactQueryArgs& args) const;

  // A wall by name, or by id when the name is empty; NOT_FOUND otherwise.
  WallId find_wall(const std::string& name, std::int32_t id) const;

 private:
  std::optional<int> threads_;
  io::ResourceLimits limits_;
  std::shared_ptr<const io::FileAccess> files_;
  std::uint64_t max_query_contacts_;
  std::unique_ptr<WorldSession> world_;
  std::string case_name_;
  std::string description_;
  std::vector<ContactModelDef> contact_models_;
  CaseProgramme programme_;
  io::OutputSettings output_;
  std::string digest_;
};

}  // namespace dem::service
