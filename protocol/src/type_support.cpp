// The bridge between the service's C++ messages and the C structs idlc
// generates from idl/dem/*.idl. Writing borrows the C++ values' memory
// (strings, byte and integer arrays) for the duration of dds_write, which
// serializes before it returns; only sequences of nested structs need a
// converted array. Reading copies out of Cyclone's loaned samples.
#include "dem/protocol/type_support.h"

#include <dds/dds.h>

#include <cstring>
#include <vector>

#include "command_sample.h"
#include "dem/command.h"
#include "dem/telemetry.h"

namespace dem::dds {

namespace {

using CVector3 = geometry_msgs_msg_dds__Vector3_;
using CTime = builtin_interfaces_msg_dds__Time_;
using CStatus = dem_interfaces_msg_dds__Status_;
using CWallForce = dem_interfaces_msg_dds__WallForce_;
using CPlateForces = dem_interfaces_msg_dds__PlateForces_;
using CContactStats = dem_interfaces_msg_dds__ContactStats_;
using CRegionMeasures = dem_interfaces_msg_dds__RegionMeasures_;
using CRegionTelemetry = dem_interfaces_msg_dds__RegionTelemetry_;
using CCommand = dem_interfaces_msg_dds__Command_;
using CContactEntry = dem_interfaces_msg_dds__ContactEntry_;
using CReply = dem_interfaces_msg_dds__Reply_;

// The wire's constants and the C++ enums must agree.
static_assert(dem_interfaces_msg_Status_Constants_RUNNING == static_cast<int>(protocol::ServerState::kRunning));
static_assert(dem_interfaces_msg_Status_Constants_SHUTDOWN == static_cast<int>(protocol::ServerState::kShutdown));
static_assert(dem_interfaces_msg_Command_Constants_LOAD_CASE == static_cast<int>(protocol::CommandKind::kLoadCase));
static_assert(dem_interfaces_msg_Command_Constants_RUN_PROGRAMME ==
              static_cast<int>(protocol::CommandKind::kRunProgramme));
static_assert(dem_interfaces_msg_Reply_Constants_SHUTTING_DOWN ==
              static_cast<int>(protocol::ReplyStatus::kShuttingDown));
static_assert(dem_interfaces_msg_Reply_Constants_BUSY == static_cast<int>(protocol::ReplyStatus::kBusy));

// --- C++ -> C, borrowing -------------------------------------------------

char* borrow(const std::string& text) { return const_cast<char*>(text.c_str()); }

dds_sequence_octet borrow_bytes(const std::string& bytes) {
  auto* data = reinterpret_cast<std::uint8_t*>(const_cast<char*>(bytes.data()));
  const auto size = static_cast<std::uint32_t>(bytes.size());
  return {size, size, data, false};
}

template <typename Sequence, typename Element>
Sequence borrow_sequence(const std::vector<Element>& elements) {
  const auto size = static_cast<std::uint32_t>(elements.size());
  return Sequence{size, size, const_cast<Element*>(elements.data()), false};
}

CVector3 to_c(const protocol::Vector3& v) { return {v.x, v.y, v.z}; }
CTime to_c(const protocol::Stamp& s) { return {s.sec, s.nanosec}; }

CStatus to_c(const protocol::Status& s) {
  CStatus c{};
  c.server = borrow(s.server);
  c.state = static_cast<std::uint8_t>(s.state);
  c.state_name = const_cast<char*>(to_string(s.state).data());  // string literals: NUL-terminated
  c.case_name = borrow(s.case_name);
  c.dimension = s.dimension;
  c.particles = s.particles;
  c.walls = s.walls;
  c.cycle = s.cycle;
  c.time = s.time;
  c.time_step = s.time_step;
  c.command = borrow(s.command);
  c.command_client = borrow(s.command_client);
  c.command_request_id = s.command_request_id;
  c.command_cycles_done = s.command_cycles_done;
  c.command_cycles_total = s.command_cycles_total;
  c.progress = s.progress;
  c.message = borrow(s.message);
  c.commands_served = s.commands_served;
  c.telemetry_dropped = s.telemetry_dropped;
  c.stamp = to_c(s.stamp);
  return c;
}

CWallForce to_c(const protocol::WallForce& w) {
  CWallForce c{};
  c.name = borrow(w.name);
  c.id = w.id;
  c.force = to_c(w.force);
  c.moment = to_c(w.moment);
  c.normal_force = w.normal_force;
  c.area = w.area;
  c.normal_stress = w.normal_stress;
  c.position = to_c(w.position);
  c.displacement = to_c(w.displacement);
  c.settlement = w.settlement;
  c.contacts = w.contacts;
  return c;
}

// A PlateForces_ with the array its wall sequence points into.
struct CPlateForcesStorage {
  std::vector<CWallForce> walls;
  CPlateForces message{};
};

void to_c(const protocol::PlateForces& p, CPlateForcesStorage& out) {
  out.walls.clear();
  for (const auto& wall : p.walls) out.walls.push_back(to_c(wall));
  out.message.server = borrow(p.server);
  out.message.cycle = p.cycle;
  out.message.time = p.time;
  out.message.stamp = to_c(p.stamp);
  out.message.walls = borrow_sequence<dds_sequence_dem_interfaces_msg_dds__WallForce_>(out.walls);
}

CContactStats to_c(const protocol::ContactStats& s) {
  CContactStats c{};
  c.server = borrow(s.server);
  c.cycle = s.cycle;
  c.time = s.time;
  c.stamp = to_c(s.stamp);
  c.particles = s.particles;
  c.contacts = s.contacts;
  c.wall_contacts = s.wall_contacts;
  c.sliding_contacts = s.sliding_contacts;
  c.sliding_fraction = s.sliding_fraction;
  c.coordination_number = s.coordination_number;
  c.mean_normal_force = s.mean_normal_force;
  c.max_normal_force = s.max_normal_force;
  c.histogram_bin_width = s.histogram_bin_width;
  c.histogram = borrow_sequence<dds_sequence_uint32>(s.histogram);
  c.kinetic_energy = s.kinetic_energy;
  c.out_of_balance = s.out_of_balance;
  return c;
}

CRegionMeasures to_c(const protocol::RegionMeasure& m) {
  CRegionMeasures c{};
  c.name = borrow(m.name);
  c.particles = m.particles;
  c.rattlers = m.rattlers;
  c.contacts = m.contacts;
  c.particle_contacts = m.particle_contacts;
  c.sliding_contacts = m.sliding_contacts;
  c.sliding_fraction = m.sliding_fraction;
  c.coordination = m.coordination;
  c.mechanical_coordination = m.mechanical_coordination;
  c.porosity = m.porosity;
  c.void_ratio = m.void_ratio;
  c.stress = borrow_sequence<dds_sequence_double>(m.stress);
  c.principal_stress = borrow_sequence<dds_sequence_double>(m.principal_stress);
  c.stress_angle = m.stress_angle;
  c.mean_stress = m.mean_stress;
  c.deviator_stress = m.deviator_stress;
  c.sin_phi = m.sin_phi;
  c.tangential_share = m.tangential_share;
  c.fabric = borrow_sequence<dds_sequence_double>(m.fabric);
  c.principal_fabric = borrow_sequence<dds_sequence_double>(m.principal_fabric);
  c.fabric_angle = m.fabric_angle;
  c.anisotropy = m.anisotropy;
  c.weighted_fabric = borrow_sequence<dds_sequence_double>(m.weighted_fabric);
  c.principal_weighted_fabric = borrow_sequence<dds_sequence_double>(m.principal_weighted_fabric);
  c.weighted_fabric_angle = m.weighted_fabric_angle;
  c.weighted_anisotropy = m.weighted_anisotropy;
  c.fabric_trace = m.fabric_trace;
  c.mean_normal_force = m.mean_normal_force;
  c.max_normal_force = m.max_normal_force;
  c.mean_rotation = m.mean_rotation;
  c.mean_abs_rotation = m.mean_abs_rotation;
  return c;
}

struct CRegionTelemetryStorage {
  std::vector<CRegionMeasures> regions;
  CRegionTelemetry message{};
};

void to_c(const protocol::RegionTelemetry& t, CRegionTelemetryStorage& out) {
  out.regions.clear();
  for (const auto& region : t.regions) out.regions.push_back(to_c(region));
  out.message.server = borrow(t.server);
  out.message.cycle = t.cycle;
  out.message.time = t.time;
  out.message.stamp = to_c(t.stamp);
  out.message.dimension = t.dimension;
  out.message.regions = borrow_sequence<dds_sequence_dem_interfaces_msg_dds__RegionMeasures_>(out.regions);
}

CContactEntry to_c(const protocol::ContactEntry& e) {
  CContactEntry c{};
  c.first = e.first;
  c.second_particle = e.second_particle;
  c.second_wall = e.second_wall;
  c.point = to_c(e.point);
  c.normal = to_c(e.normal);
  c.overlap = e.overlap;
  c.normal_force = e.normal_force;
  c.shear_force = e.shear_force;
  c.normal_damping = e.normal_damping;
  c.shear_damping = e.shear_damping;
  c.sliding = e.sliding;
  return c;
}

CCommand to_c(const protocol::Command& m) {
  CCommand c{};
  c.server = borrow(m.server);
  c.client_id = borrow(m.client_id);
  c.request_id = m.request_id;
  c.kind = m.kind;
  c.load_case.path = borrow(m.load_case.path);
  c.load_case.text = borrow(m.load_case.text);
  c.load_case.binary = borrow_bytes(m.load_case.binary);
  c.load_case.source_name = borrow(m.load_case.source_name);
  c.wall_velocity.wall = borrow(m.wall_velocity.wall);
  c.wall_velocity.wall_id = m.wall_velocity.wall_id;
  c.wall_velocity.twist.linear = to_c(m.wall_velocity.velocity);
  c.wall_velocity.twist.angular = to_c(m.wall_velocity.angular_velocity);
  c.wall_servo.wall = borrow(m.wall_servo.wall);
  c.wall_servo.wall_id = m.wall_servo.wall_id;
  c.wall_servo.target_stress = m.wall_servo.target_stress;
  c.wall_servo.gain = m.wall_servo.gain;
  c.wall_servo.max_speed = m.wall_servo.max_speed;
  c.cycle.cycles = m.cycle.cycles;
  const auto& r = m.run_until;
  c.run_until.wall = borrow(r.wall);
  c.run_until.wall_id = r.wall_id;
  c.run_until.stress_set = r.stress.has_value();
  c.run_until.stress = r.stress.value_or(0.0);
  c.run_until.settlement_set = r.settlement.has_value();
  c.run_until.settlement = r.settlement.value_or(0.0);
  c.run_until.kinetic_energy_set = r.kinetic_energy.has_value();
  c.run_until.kinetic_energy = r.kinetic_energy.value_or(0.0);
  c.run_until.max_cycles = r.max_cycles;
  c.run_until.check_interval = r.check_interval;
  const auto& q = m.query;
  c.query.wall_set = q.wall_set;
  c.query.wall = borrow(q.wall);
  c.query.wall_id = q.wall_id;
  c.query.box_set = q.box_set;
  c.query.box_min = to_c(q.box_min);
  c.query.box_max = to_c(q.box_max);
  c.query.force_set = q.min_normal_force.has_value();
  c.query.min_normal_force = q.min_normal_force.value_or(0.0);
  c.query.chunk_size = q.chunk_size;
  c.snapshot.path = borrow(m.snapshot.path);
  c.snapshot.transfer = m.snapshot.transfer;
  c.snapshot.data = borrow_bytes(m.snapshot.data);
  c.parameter.name = borrow(m.parameter.name);
  c.parameter.material = borrow(m.parameter.material);
  c.parameter.value = m.parameter.value;
  c.parameter.vector = to_c(m.parameter.vector);
  c.programme.first_stage = m.programme.first_stage;
  c.programme.stage_count = m.programme.stage_count;
  c.stamp = to_c(m.stamp);
  c.force = m.force;
  return c;
}

// --- C -> C++, copying ----------------------------------------------------

std::string copy(const char* text) { return text != nullptr ? std::string(text) : std::string(); }
std::string copy(const dds_sequence_octet& bytes) {
  return bytes._length > 0 ? std::string(reinterpret_cast<const char*>(bytes._buffer), bytes._length) : std::string();
}
protocol::Vector3 from_c(const CVector3& v) { return {v.x, v.y, v.z}; }
protocol::Stamp from_c(const CTime& t) { return {t.sec, t.nanosec}; }

protocol::ServerState state_from_c(std::uint8_t value) {
  return value <= static_cast<std::uint8_t>(protocol::ServerState::kShutdown) ? static_cast<protocol::ServerState>(value)
                                                                              : protocol::ServerState::kError;
}

protocol::Status from_c(const CStatus& c) {
  protocol::Status s;
  s.server = copy(c.server);
  s.state = state_from_c(c.state);
  s.case_name = copy(c.case_name);
  s.dimension = c.dimension;
  s.particles = c.particles;
  s.walls = c.walls;
  s.cycle = c.cycle;
  s.time = c.time;
  s.time_step = c.time_step;
  s.command = copy(c.command);
  s.command_client = copy(c.command_client);
  s.command_request_id = c.command_request_id;
  s.command_cycles_done = c.command_cycles_done;
  s.command_cycles_total = c.command_cycles_total;
  s.progress = c.progress;
  s.message = copy(c.message);
  s.commands_served = c.commands_served;
  s.telemetry_dropped = c.telemetry_dropped;
  s.stamp = from_c(c.stamp);
  return s;
}

protocol::WallForce from_c(const CWallForce& c) {
  protocol::WallForce w;
  w.name = copy(c.name);
  w.id = c.id;
  w.force = from_c(c.force);
  w.moment = from_c(c.moment);
  w.normal_force = c.normal_force;
  w.area = c.area;
  w.normal_stress = c.normal_stress;
  w.position = from_c(c.position);
  w.displacement = from_c(c.displacement);
  w.settlement = c.settlement;
  w.contacts = c.contacts;
  return w;
}

protocol::PlateForces from_c(const CPlateForces& c) {
  protocol::PlateForces p;
  p.server = copy(c.server);
  p.cycle = c.cycle;
  p.time = c.time;
  p.stamp = from_c(c.stamp);
  p.walls.reserve(c.walls._length);
  for (std::uint32_t i = 0; i < c.walls._length; ++i) p.walls.push_back(from_c(c.walls._buffer[i]));
  return p;
}

protocol::ContactStats from_c(const CContactStats& c) {
  protocol::ContactStats s;
  s.server = copy(c.server);
  s.cycle = c.cycle;
  s.time = c.time;
  s.stamp = from_c(c.stamp);
  s.particles = c.particles;
  s.contacts = c.contacts;
  s.wall_contacts = c.wall_contacts;
  s.sliding_contacts = c.sliding_contacts;
  s.sliding_fraction = c.sliding_fraction;
  s.coordination_number = c.coordination_number;
  s.mean_normal_force = c.mean_normal_force;
  s.max_normal_force = c.max_normal_force;
  s.histogram_bin_width = c.histogram_bin_width;
  s.histogram.assign(c.histogram._buffer, c.histogram._buffer + c.histogram._length);
  s.kinetic_energy = c.kinetic_energy;
  s.out_of_balance = c.out_of_balance;
  return s;
}

std::vector<double> copy_doubles(const dds_sequence_double& s) { return {s._buffer, s._buffer + s._length}; }

protocol::RegionMeasure from_c(const CRegionMeasures& c) {
  protocol::RegionMeasure m;
  m.name = copy(c.name);
  m.particles = c.particles;
  m.rattlers = c.rattlers;
  m.contacts = c.contacts;
  m.particle_contacts = c.particle_contacts;
  m.sliding_contacts = c.sliding_contacts;
  m.sliding_fraction = c.sliding_fraction;
  m.coordination = c.coordination;
  m.mechanical_coordination = c.mechanical_coordination;
  m.porosity = c.porosity;
  m.void_ratio = c.void_ratio;
  m.stress = copy_doubles(c.stress);
  m.principal_stress = copy_doubles(c.principal_stress);
  m.stress_angle = c.stress_angle;
  m.mean_stress = c.mean_stress;
  m.deviator_stress = c.deviator_stress;
  m.sin_phi = c.sin_phi;
  m.tangential_share = c.tangential_share;
  m.fabric = copy_doubles(c.fabric);
  m.principal_fabric = copy_doubles(c.principal_fabric);
  m.fabric_angle = c.fabric_angle;
  m.anisotropy = c.anisotropy;
  m.weighted_fabric = copy_doubles(c.weighted_fabric);
  m.principal_weighted_fabric = copy_doubles(c.principal_weighted_fabric);
  m.weighted_fabric_angle = c.weighted_fabric_angle;
  m.weighted_anisotropy = c.weighted_anisotropy;
  m.fabric_trace = c.fabric_trace;
  m.mean_normal_force = c.mean_normal_force;
  m.max_normal_force = c.max_normal_force;
  m.mean_rotation = c.mean_rotation;
  m.mean_abs_rotation = c.mean_abs_rotation;
  return m;
}

protocol::RegionTelemetry from_c(const CRegionTelemetry& c) {
  protocol::RegionTelemetry t;
  t.server = copy(c.server);
  t.cycle = c.cycle;
  t.time = c.time;
  t.stamp = from_c(c.stamp);
  t.dimension = c.dimension;
  t.regions.reserve(c.regions._length);
  for (std::uint32_t i = 0; i < c.regions._length; ++i) t.regions.push_back(from_c(c.regions._buffer[i]));
  return t;
}

protocol::ContactEntry from_c(const CContactEntry& c) {
  protocol::ContactEntry e;
  e.first = c.first;
  e.second_particle = c.second_particle;
  e.second_wall = c.second_wall;
  e.point = from_c(c.point);
  e.normal = from_c(c.normal);
  e.overlap = c.overlap;
  e.normal_force = c.normal_force;
  e.shear_force = c.shear_force;
  e.normal_damping = c.normal_damping;
  e.shear_damping = c.shear_damping;
  e.sliding = c.sliding;
  return e;
}

protocol::Command from_c(const CCommand& c) {
  protocol::Command m;
  m.server = copy(c.server);
  m.client_id = copy(c.client_id);
  m.request_id = c.request_id;
  m.kind = c.kind;
  m.load_case = {copy(c.load_case.path), copy(c.load_case.text), copy(c.load_case.binary),
                 copy(c.load_case.source_name)};
  m.wall_velocity = {copy(c.wall_velocity.wall), c.wall_velocity.wall_id, from_c(c.wall_velocity.twist.linear),
                     from_c(c.wall_velocity.twist.angular)};
  m.wall_servo = {copy(c.wall_servo.wall), c.wall_servo.wall_id, c.wall_servo.target_stress, c.wall_servo.gain,
                  c.wall_servo.max_speed};
  m.cycle.cycles = c.cycle.cycles;
  const auto& r = c.run_until;
  m.run_until.wall = copy(r.wall);
  m.run_until.wall_id = r.wall_id;
  if (r.stress_set) m.run_until.stress = r.stress;
  if (r.settlement_set) m.run_until.settlement = r.settlement;
  if (r.kinetic_energy_set) m.run_until.kinetic_energy = r.kinetic_energy;
  m.run_until.max_cycles = r.max_cycles;
  m.run_until.check_interval = r.check_interval;
  const auto& q = c.query;
  m.query.wall_set = q.wall_set;
  m.query.wall = copy(q.wall);
  m.query.wall_id = q.wall_id;
  m.query.box_set = q.box_set;
  m.query.box_min = from_c(q.box_min);
  m.query.box_max = from_c(q.box_max);
  if (q.force_set) m.query.min_normal_force = q.min_normal_force;
  m.query.chunk_size = q.chunk_size;
  m.snapshot = {copy(c.snapshot.path), c.snapshot.transfer, copy(c.snapshot.data)};
  m.parameter = {copy(c.parameter.name), copy(c.parameter.material), c.parameter.value, from_c(c.parameter.vector)};
  m.programme = {c.programme.first_stage, c.programme.stage_count};
  m.stamp = from_c(c.stamp);
  m.force = c.force;
  return m;
}

protocol::Reply from_c(const CReply& c) {
  protocol::Reply r;
  r.server = copy(c.server);
  r.client_id = copy(c.client_id);
  r.request_id = c.request_id;
  r.kind = c.kind;
  r.status = static_cast<protocol::ReplyStatus>(c.status);
  r.message = copy(c.message);
  r.duration = c.duration;
  r.chunk = c.chunk;
  r.last = c.last;
  r.state = from_c(c.state);
  r.cycles_run = c.cycles_run;
  r.condition_met = c.condition_met;
  r.plates = from_c(c.plates);
  r.stats = from_c(c.stats);
  r.state_hash = c.state_hash;
  r.total_contacts = c.total_contacts;
  r.contacts.reserve(c.contacts._length);
  for (std::uint32_t i = 0; i < c.contacts._length; ++i) r.contacts.push_back(from_c(c.contacts._buffer[i]));
  r.total_bytes = c.total_bytes;
  r.data = copy(c.data);
  r.path = copy(c.path);
  r.stamp = from_c(c.stamp);
  return r;
}

}  // namespace

const dds_topic_descriptor_t* TypeSupport<protocol::Status>::descriptor() {
  return &dem_interfaces_msg_dds__Status__desc;
}
dds_return_t TypeSupport<protocol::Status>::write(dds_entity_t writer, const protocol::Status& value) {
  const CStatus sample = to_c(value);
  return dds_write(writer, &sample);
}
protocol::Status TypeSupport<protocol::Status>::from_sample(const void* sample) {
  return from_c(*static_cast<const CStatus*>(sample));
}

const dds_topic_descriptor_t* TypeSupport<protocol::PlateForces>::descriptor() {
  return &dem_interfaces_msg_dds__PlateForces__desc;
}
dds_return_t TypeSupport<protocol::PlateForces>::write(dds_entity_t writer, const protocol::PlateForces& value) {
  CPlateForcesStorage storage;
  to_c(value, storage);
  return dds_write(writer, &storage.message);
}
protocol::PlateForces TypeSupport<protocol::PlateForces>::from_sample(const void* sample) {
  return from_c(*static_cast<const CPlateForces*>(sample));
}

const dds_topic_descriptor_t* TypeSupport<protocol::ContactStats>::descriptor() {
  return &dem_interfaces_msg_dds__ContactStats__desc;
}
dds_return_t TypeSupport<protocol::ContactStats>::write(dds_entity_t writer, const protocol::ContactStats& value) {
  const CContactStats sample = to_c(value);
  return dds_write(writer, &sample);
}
protocol::ContactStats TypeSupport<protocol::ContactStats>::from_sample(const void* sample) {
  return from_c(*static_cast<const CContactStats*>(sample));
}

const dds_topic_descriptor_t* TypeSupport<protocol::RegionTelemetry>::descriptor() {
  return &dem_interfaces_msg_dds__RegionTelemetry__desc;
}
dds_return_t TypeSupport<protocol::RegionTelemetry>::write(dds_entity_t writer, const protocol::RegionTelemetry& value) {
  CRegionTelemetryStorage storage;
  to_c(value, storage);
  return dds_write(writer, &storage.message);
}
protocol::RegionTelemetry TypeSupport<protocol::RegionTelemetry>::from_sample(const void* sample) {
  return from_c(*static_cast<const CRegionTelemetry*>(sample));
}

const dds_topic_descriptor_t* TypeSupport<protocol::Command>::descriptor() {
  return &dem_interfaces_msg_dds__Command__desc;
}
dds_return_t TypeSupport<protocol::Command>::write(dds_entity_t writer, const protocol::Command& value) {
  const CCommand sample = to_c(value);
  return dds_write(writer, &sample);
}
protocol::Command TypeSupport<protocol::Command>::from_sample(const void* sample) {
  return from_c(*static_cast<const CCommand*>(sample));
}

const dds_topic_descriptor_t* TypeSupport<protocol::Reply>::descriptor() { return &dem_interfaces_msg_dds__Reply__desc; }
dds_return_t TypeSupport<protocol::Reply>::write(dds_entity_t writer, const protocol::Reply& value) {
  CReply c{};
  c.server = borrow(value.server);
  c.client_id = borrow(value.client_id);
  c.request_id = value.request_id;
  c.kind = value.kind;
  c.status = static_cast<std::int32_t>(value.status);
  c.message = borrow(value.message);
  c.duration = value.duration;
  c.chunk = value.chunk;
  c.last = value.last;
  c.state = to_c(value.state);
  c.cycles_run = value.cycles_run;
  c.condition_met = value.condition_met;
  CPlateForcesStorage plates;
  to_c(value.plates, plates);
  c.plates = plates.message;
  c.stats = to_c(value.stats);
  c.state_hash = value.state_hash;
  c.total_contacts = value.total_contacts;
  std::vector<CContactEntry> contacts;
  contacts.reserve(value.contacts.size());
  for (const auto& entry : value.contacts) contacts.push_back(to_c(entry));
  c.contacts = borrow_sequence<dds_sequence_dem_interfaces_msg_dds__ContactEntry_>(contacts);
  c.total_bytes = value.total_bytes;
  c.data = borrow_bytes(value.data);
  c.path = borrow(value.path);
  c.stamp = to_c(value.stamp);
  return dds_write(writer, &c);
}
protocol::Reply TypeSupport<protocol::Reply>::from_sample(const void* sample) {
  return from_c(*static_cast<const CReply*>(sample));
}

}  // namespace dem::dds

namespace dem::protocol {

void with_command_sample(const Command& command, const std::function<void(const void*)>& use) {
  const dds::CCommand sample = dds::to_c(command);
  use(&sample);
}

}  // namespace dem::protocol
