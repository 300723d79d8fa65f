// The service's messages as plain C++ values: what dem_server and its
// clients read and write. They mirror the IDL in idl/dem/*.idl field for
// field; protocol/src/type_support.cpp converts them to and from the C
// structs idlc generates (the only code that sees those). Units are SI; in
// 2D, forces are per unit depth and vectors have z = 0 (spins are about z).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dem::protocol {

struct Vector3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
  friend bool operator==(const Vector3&, const Vector3&) = default;
};

// builtin_interfaces/Time: wall-clock time since the Unix epoch.
struct Stamp {
  std::int32_t sec = 0;
  std::uint32_t nanosec = 0;
  friend bool operator==(const Stamp&, const Stamp&) = default;
};
Stamp now_stamp();

// Status_Constants in idl/dem/telemetry.idl.
enum class ServerState : std::uint8_t { kIdle = 0, kLoaded = 1, kRunning = 2, kError = 3, kShutdown = 4 };

// Command_Constants in idl/dem/command.idl.
enum class CommandKind : std::uint8_t {
  kLoadCase = 1,
  kSetWallVelocity = 2,
  kSetWallServo = 3,
  kCycle = 4,
  kRunUntil = 5,
  kStop = 6,
  kGetState = 7,
  kShutdown = 8,
  kQueryContacts = 9,
  kSaveSnapshot = 10,
  kLoadSnapshot = 11,
  kSetParameter = 12,
  kRunProgramme = 13,
};

// Reply_Constants in idl/dem/command.idl.
enum class ReplyStatus : std::int32_t {
  kOk = 0,
  kCancelled = 1,
  kBadRequest = 2,
  kNotFound = 3,
  kInvalidCase = 4,
  kInvalidSnapshot = 5,
  kRefused = 6,
  kFailed = 7,
  kShuttingDown = 8,
  kBusy = 9,
};

std::string_view to_string(ServerState state);
std::string_view to_string(CommandKind kind);  // "load_case", "cycle", ...; "unknown" otherwise
std::string_view to_string(ReplyStatus status);  // "ok", "cancelled", ...
std::optional<CommandKind> command_kind(std::uint8_t value);

struct Status {
  std::string server;
  ServerState state = ServerState::kIdle;
  std::string case_name;
  std::uint8_t dimension = 0;
  std::int32_t particles = 0;
  std::int32_t walls = 0;
  std::uint64_t cycle = 0;
  double time = 0.0;
  double time_step = 0.0;
  std::string command;  // the running command's kind, or empty
  std::string command_client;
  std::uint64_t command_request_id = 0;
  std::uint64_t command_cycles_done = 0;
  std::uint64_t command_cycles_total = 0;
  double progress = 0.0;
  std::string message;
  std::uint64_t commands_served = 0;
  std::uint64_t telemetry_dropped = 0;
  Stamp stamp;
  friend bool operator==(const Status&, const Status&) = default;
};

struct WallForce {
  std::string name;
  std::int32_t id = -1;
  Vector3 force;
  Vector3 moment;
  double normal_force = 0.0;
  double area = 0.0;
  double normal_stress = 0.0;
  Vector3 position;
  Vector3 displacement;
  double settlement = 0.0;
  std::int32_t contacts = 0;
  friend bool operator==(const WallForce&, const WallForce&) = default;
};

struct PlateForces {
  std::string server;
  std::uint64_t cycle = 0;
  double time = 0.0;
  Stamp stamp;
  std::vector<WallForce> walls;
  friend bool operator==(const PlateForces&, const PlateForces&) = default;
};

struct ContactStats {
  std::string server;
  std::uint64_t cycle = 0;
  double time = 0.0;
  Stamp stamp;
  std::int32_t particles = 0;
  std::int32_t contacts = 0;
  std::int32_t wall_contacts = 0;
  std::int32_t sliding_contacts = 0;
  double sliding_fraction = 0.0;
  double coordination_number = 0.0;
  double mean_normal_force = 0.0;
  double max_normal_force = 0.0;
  double histogram_bin_width = 0.0;
  std::vector<std::uint32_t> histogram;
  double kinetic_energy = 0.0;
  double out_of_balance = 0.0;
  friend bool operator==(const ContactStats&, const ContactStats&) = default;
};

// The measures of one region (idl/dem/telemetry.idl, RegionMeasures_);
// tensors row by row, dimension x dimension values.
struct RegionMeasure {
  std::string name;
  std::int32_t particles = 0;
  std::int32_t rattlers = 0;
  std::int32_t contacts = 0;
  std::int32_t particle_contacts = 0;
  std::int32_t sliding_contacts = 0;
  double sliding_fraction = 0.0;
  double coordination = 0.0;
  double mechanical_coordination = 0.0;
  double porosity = 0.0;
  double void_ratio = 0.0;
  std::vector<double> stress;
  std::vector<double> principal_stress;
  double stress_angle = 0.0;
  double mean_stress = 0.0;
  double deviator_stress = 0.0;
  double sin_phi = 0.0;
  double tangential_share = 0.0;
  std::vector<double> fabric;
  std::vector<double> principal_fabric;
  double fabric_angle = 0.0;
  double anisotropy = 0.0;
  std::vector<double> weighted_fabric;
  std::vector<double> principal_weighted_fabric;
  double weighted_fabric_angle = 0.0;
  double weighted_anisotropy = 0.0;
  double fabric_trace = 0.0;
  double mean_normal_force = 0.0;
  double max_normal_force = 0.0;
  double mean_rotation = 0.0;
  double mean_abs_rotation = 0.0;
  friend bool operator==(const RegionMeasure&, const RegionMeasure&) = default;
};

struct RegionTelemetry {
  std::string server;
  std::uint64_t cycle = 0;
  double time = 0.0;
  Stamp stamp;
  std::uint8_t dimension = 0;
  std::vector<RegionMeasure> regions;
  friend bool operator==(const RegionTelemetry&, const RegionTelemetry&) = default;
};

// Command arguments, one group per kind (see idl/dem/command.idl).
struct LoadCaseArgs {
  std::string path;
  std::string text;
  std::string binary;  // bytes of a serialized dem.proto.Case
  std::string source_name;
  friend bool operator==(const LoadCaseArgs&, const LoadCaseArgs&) = default;
};

struct WallVelocityArgs {
  std::string wall;
  std::int32_t wall_id = -1;
  Vector3 velocity;
  Vector3 angular_velocity;
  friend bool operator==(const WallVelocityArgs&, const WallVelocityArgs&) = default;
};

struct WallServoArgs {
  std::string wall;
  std::int32_t wall_id = -1;
  double target_stress = 0.0;
  double gain = 0.0;
  double max_speed = 0.0;
  friend bool operator==(const WallServoArgs&, const WallServoArgs&) = default;
};

struct CycleArgs {
  std::int64_t cycles = 0;
  friend bool operator==(const CycleArgs&, const CycleArgs&) = default;
};

struct RunUntilArgs {
  std::string wall;
  std::int32_t wall_id = -1;
  std::optional<double> stress;
  std::optional<double> settlement;
  std::optional<double> kinetic_energy;
  std::int64_t max_cycles = 0;
  std::int64_t check_interval = 0;
  friend bool operator==(const RunUntilArgs&, const RunUntilArgs&) = default;
};

struct ContactQueryArgs {
  bool wall_set = false;
  std::string wall;
  std::int32_t wall_id = -1;
  bool box_set = false;
  Vector3 box_min;
  Vector3 box_max;
  std::optional<double> min_normal_force;
  std::uint32_t chunk_size = 0;
  friend bool operator==(const ContactQueryArgs&, const ContactQueryArgs&) = default;
};

struct SnapshotArgs {
  std::string path;
  bool transfer = false;
  std::string data;  // load_snapshot with transfer: the snapshot's bytes
  friend bool operator==(const SnapshotArgs&, const SnapshotArgs&) = default;
};

struct ParameterArgs {
  std::string name;
  std::string material;
  double value = 0.0;
  Vector3 vector;
  friend bool operator==(const ParameterArgs&, const ParameterArgs&) = default;
};

// run_programme: stages numbered from 1; first_stage 0 = 1, stage_count 0 = to the last.
struct ProgrammeArgs {
  std::uint32_t first_stage = 0;
  std::uint32_t stage_count = 0;
  friend bool operator==(const ProgrammeArgs&, const ProgrammeArgs&) = default;
};

struct Command {
  std::string server;
  std::string client_id;
  std::uint64_t request_id = 0;
  std::uint8_t kind = 0;  // a CommandKind, kept raw so an unknown one can be answered
  LoadCaseArgs load_case;
  WallVelocityArgs wall_velocity;
  WallServoArgs wall_servo;
  CycleArgs cycle;
  RunUntilArgs run_until;
  ContactQueryArgs query;
  SnapshotArgs snapshot;
  ParameterArgs parameter;
  ProgrammeArgs programme;
  Stamp stamp;
  bool force = false;  // stop and shutdown: also another client's run
  friend bool operator==(const Command&, const Command&) = default;
};

struct ContactEntry {
  std::int32_t first = -1;
  std::int32_t second_particle = -1;
  std::int32_t second_wall = -1;
  Vector3 point;
  Vector3 normal;
  double overlap = 0.0;
  double normal_force = 0.0;
  double shear_force = 0.0;
  double normal_damping = 0.0;
  double shear_damping = 0.0;
  bool sliding = false;
  friend bool operator==(const ContactEntry&, const ContactEntry&) = default;
};

struct Reply {
  std::string server;
  std::string client_id;
  std::uint64_t request_id = 0;
  std::uint8_t kind = 0;
  ReplyStatus status = ReplyStatus::kOk;
  std::string message;
  double duration = 0.0;  // s
  std::uint32_t chunk = 0;
  bool last = true;
  Status state;
  std::uint64_t cycles_run = 0;
  bool condition_met = false;
  PlateForces plates;
  ContactStats stats;
  std::uint64_t state_hash = 0;
  std::uint64_t total_contacts = 0;
  std::vector<ContactEntry> contacts;
  std::uint64_t total_bytes = 0;
  std::string data;
  std::string path;
  Stamp stamp;

  bool ok() const { return status == ReplyStatus::kOk; }
  friend bool operator==(const Reply&, const Reply&) = default;
};

}  // namespace dem::protocol
