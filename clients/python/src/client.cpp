// dem::client::Client for Python. Every command is sent, then its reply
// awaited in short slices with the GIL released: between slices the caller's
// thread takes the GIL back only to notice Ctrl-C (a signal raised in
// Python) and to call an optional on_wait callback - a live plot's update,
// say. A run (cycle, run_until) interrupted that way is stopped on the
// server, as demctl stops it on Ctrl-C.
#include "dem/client/client.h"

#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <memory>
#include <optional>
#include <sstream>

#include "bindings.h"
#include "client_handle.h"

namespace dem::python {

namespace py = pybind11;
using namespace std::chrono_literals;
using protocol::CommandKind;
using protocol::Reply;

namespace {

using Seconds = std::optional<double>;
using Vector = std::array<double, 3>;

constexpr auto kForever = std::chrono::hours(24 * 365);

std::chrono::milliseconds milliseconds(double seconds) {
  return std::chrono::milliseconds(static_cast<std::int64_t>(std::max(0.0, seconds) * 1000.0));
}

protocol::Vector3 vector3(const Vector& v) { return {v[0], v[1], v[2]}; }

protocol::Command command(CommandKind kind) {
  protocol::Command c;
  c.kind = static_cast<std::uint8_t>(kind);
  return c;
}

std::string seconds_text(std::chrono::milliseconds duration) {
  std::ostringstream out;
  out << std::chrono::duration<double>(duration).count() << " s";
  return out.str();
}

// How one call waits for its reply.
struct Wait {
  std::chrono::milliseconds timeout;
  py::object on_wait;  // called every `interval` while waiting, or None
  std::chrono::milliseconds interval;
  bool is_run;  // a cycle or run_until: stopped when the wait is interrupted
};

// Asks the server to stop the run this client is waiting for, and collects
// both replies so they do not linger; failures are beside the point here.
void stop_run(client::Client& client, std::uint64_t run_id) {
  py::gil_scoped_release release;
  try {
    const std::uint64_t stop_id = client.send(command(CommandKind::kStop));
    client.await(stop_id, 2s);
    client.await(run_id, 2s);
  } catch (const std::exception&) {
  }
}

Reply await_reply(client::Client& client, std::uint64_t id, const std::string& what, const Wait& wait) {
  const auto deadline = std::chrono::steady_clock::now() + wait.timeout;
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    std::optional<Reply> reply;
    {
      py::gil_scoped_release release;
      reply = client.await(id, std::clamp(left, 0ms, wait.interval));
    }
    if (reply) {
      if (!reply->ok()) throw client::ServerError(std::move(*reply));
      return std::move(*reply);
    }
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (!wait.on_wait.is_none()) wait.on_wait();
    } catch (...) {
      if (wait.is_run) stop_run(client, id);
      throw;
    }
    if (std::chrono::steady_clock::now() >= deadline) {
      throw client::ReplyTimeout("no reply from server \"" + client.server() + "\" to " + what + " within " +
                                 seconds_text(wait.timeout) + (client.server_alive() ? "" : " (the server is gone)"));
    }
  }
}

std::uint64_t send(client::Client& client, protocol::Command c) {
  py::gil_scoped_release release;
  return client.send(std::move(c));
}

// The wait of an ordinary command: the client's reply timeout unless given.
Wait command_wait(const ClientHandle& handle, const Seconds& timeout, py::object on_wait, double interval) {
  return {timeout ? milliseconds(*timeout) : handle.get().options().reply_timeout, std::move(on_wait),
          milliseconds(interval), false};
}

// The wait of a run: as long as it takes unless given.
Wait run_wait(const Seconds& timeout, py::object on_wait, double interval) {
  return {timeout ? milliseconds(*timeout) : std::chrono::duration_cast<std::chrono::milliseconds>(kForever),
          std::move(on_wait), milliseconds(interval), true};
}

Reply call(ClientHandle& handle, protocol::Command c, const Wait& wait) {
  client::Client& client = handle.get();
  const auto kind = protocol::command_kind(c.kind);
  const std::string what = kind ? std::string(protocol::to_string(*kind)) : "command";
  const std::uint64_t id = send(client, std::move(c));
  return await_reply(client, id, what, wait);
}

protocol::RunUntilArgs run_until_args(const std::string& wall, std::optional<double> stress,
                                      std::optional<double> settlement, std::optional<double> kinetic_energy,
                                      std::int64_t max_cycles, std::int64_t check_interval) {
  protocol::RunUntilArgs args;
  args.wall = wall;
  args.stress = stress;
  args.settlement = settlement;
  args.kinetic_energy = kinetic_energy;
  args.max_cycles = max_cycles;
  args.check_interval = check_interval;
  return args;
}

ClientHandle connect(const std::string& server, std::uint32_t domain, const std::string& dds_config, double timeout,
                     double reply_timeout, const std::string& client_id) {
  client::ConnectOptions options;
  options.server = server;
  options.domain = domain;
  options.dds_config = dds_config;
  options.timeout = milliseconds(timeout);
  options.reply_timeout = milliseconds(reply_timeout);
  options.client_id = client_id;
  py::gil_scoped_release release;  // discovery takes a while; other threads go on
  return ClientHandle{std::make_shared<client::Client>(std::move(options))};
}

// Shared by every command: timeout (s, None: the default), on_wait, wait_interval (s).
struct WaitArgs {
  py::arg_v timeout, on_wait, interval;
};
WaitArgs wait_args() {
  return {py::arg("timeout") = py::none(), py::arg("on_wait") = py::none(), py::arg("wait_interval") = 0.1};
}

// Connecting, and what the connection knows.
void bind_connection(py::class_<ClientHandle>& handle_class) {
  handle_class
      .def(py::init(&connect), py::arg("server"), py::arg("domain"), py::arg("dds_config"), py::arg("timeout"),
           py::arg("reply_timeout"), py::arg("client_id"))
      .def_property_readonly("server", [](const ClientHandle& h) { return h.get().server(); })
      .def_property_readonly("client_id", [](const ClientHandle& h) { return h.get().client_id(); })
      .def_property_readonly("domain", [](const ClientHandle& h) { return h.get().options().domain; })
      .def_property_readonly("closed", [](const ClientHandle& h) { return !h.client; })
      .def("close",
           [](ClientHandle& h) {
             std::shared_ptr<client::Client> last = std::move(h.client);
             py::gil_scoped_release release;  // joining its receiver thread
             last.reset();
           })
      .def("status", [](const ClientHandle& h) { return h.get().status(); })
      .def("server_alive", [](const ClientHandle& h) { return h.get().server_alive(); });
}

// Cases and snapshots, sent or read on the server.
void bind_loads(py::class_<ClientHandle>& handle_class) {
  const WaitArgs a = wait_args();
  handle_class
      .def(
          "load_case_text",
          [](ClientHandle& h, std::string text, std::string source_name, Seconds t, py::object w, double i) {
            protocol::Command c = command(CommandKind::kLoadCase);
            c.load_case.text = std::move(text);
            c.load_case.source_name = std::move(source_name);
            return call(h, std::move(c), command_wait(h, t, std::move(w), i));
          },
          py::arg("text"), py::arg("source_name"), a.timeout, a.on_wait, a.interval)
      .def(
          "load_case_binary",
          [](ClientHandle& h, py::bytes bytes, std::string source_name, Seconds t, py::object w, double i) {
            protocol::Command c = command(CommandKind::kLoadCase);
            c.load_case.binary = std::string(bytes);
            c.load_case.source_name = std::move(source_name);
            return call(h, std::move(c), command_wait(h, t, std::move(w), i));
          },
          py::arg("data"), py::arg("source_name"), a.timeout, a.on_wait, a.interval)
      .def(
          "load_case_path",
          [](ClientHandle& h, std::string path, Seconds t, py::object w, double i) {
            protocol::Command c = command(CommandKind::kLoadCase);
            c.load_case.path = std::move(path);
            return call(h, std::move(c), command_wait(h, t, std::move(w), i));
          },
          py::arg("path"), a.timeout, a.on_wait, a.interval)
      .def(
          "save_snapshot",
          [](ClientHandle& h, std::string path, bool transfer, Seconds t) {
            protocol::Command c = command(CommandKind::kSaveSnapshot);
            c.snapshot.path = std::move(path);
            c.snapshot.transfer = transfer;
            return call(h, std::move(c), command_wait(h, t, py::none(), 0.1));
          },
          py::arg("path"), py::arg("transfer"), a.timeout)
      .def(
          "load_snapshot_path",
          [](ClientHandle& h, std::string path, Seconds t) {
            protocol::Command c = command(CommandKind::kLoadSnapshot);
            c.snapshot.path = std::move(path);
            return call(h, std::move(c), command_wait(h, t, py::none(), 0.1));
          },
          py::arg("path"), a.timeout)
      .def(
          "load_snapshot_bytes",
          [](ClientHandle& h, py::bytes data, Seconds t) {
            protocol::Command c = command(CommandKind::kLoadSnapshot);
            c.snapshot.transfer = true;
            c.snapshot.data = std::string(data);
            return call(h, std::move(c), command_wait(h, t, py::none(), 0.1));
          },
          py::arg("data"), a.timeout);
}

// Runs: waited for (cycle, run_until, run_programme) or started and awaited later.
void bind_runs(py::class_<ClientHandle>& handle_class) {
  const WaitArgs a = wait_args();
  handle_class
      .def(
          "cycle",
          [](ClientHandle& h, std::int64_t cycles, Seconds t, py::object w, double i) {
            protocol::Command c = command(CommandKind::kCycle);
            c.cycle.cycles = cycles;
            return call(h, std::move(c), run_wait(t, std::move(w), i));
          },
          py::arg("cycles"), a.timeout, a.on_wait, a.interval)
      .def(
          "start_cycle",
          [](ClientHandle& h, std::int64_t cycles) {
            protocol::Command c = command(CommandKind::kCycle);
            c.cycle.cycles = cycles;
            return send(h.get(), std::move(c));
          },
          py::arg("cycles"))
      .def(
          "run_until",
          [](ClientHandle& h, const std::string& wall, std::optional<double> stress, std::optional<double> settlement,
             std::optional<double> kinetic_energy, std::int64_t max_cycles, std::int64_t check_interval, Seconds t,
             py::object w, double i) {
            protocol::Command c = command(CommandKind::kRunUntil);
            c.run_until = run_until_args(wall, stress, settlement, kinetic_energy, max_cycles, check_interval);
            return call(h, std::move(c), run_wait(t, std::move(w), i));
          },
          py::arg("wall"), py::arg("stress"), py::arg("settlement"), py::arg("kinetic_energy"), py::arg("max_cycles"),
          py::arg("check_interval"), a.timeout, a.on_wait, a.interval)
      .def(
          "start_run_until",
          [](ClientHandle& h, const std::string& wall, std::optional<double> stress, std::optional<double> settlement,
             std::optional<double> kinetic_energy, std::int64_t max_cycles, std::int64_t check_interval) {
            protocol::Command c = command(CommandKind::kRunUntil);
            c.run_until = run_until_args(wall, stress, settlement, kinetic_energy, max_cycles, check_interval);
            return send(h.get(), std::move(c));
          },
          py::arg("wall"), py::arg("stress"), py::arg("settlement"), py::arg("kinetic_energy"), py::arg("max_cycles"),
          py::arg("check_interval"))
      .def(
          "run_programme",
          [](ClientHandle& h, std::uint32_t first_stage, std::uint32_t stage_count, std::uint64_t sample_every,
             bool stage_ends, bool resume, std::uint64_t stage_cycles_done, Seconds t, py::object w, double i) {
            protocol::Command c = command(CommandKind::kRunProgramme);
            c.programme = {first_stage, stage_count};
            c.programme_steps = {sample_every, stage_ends, resume, stage_cycles_done};
            return call(h, std::move(c), run_wait(t, std::move(w), i));
          },
          py::arg("first_stage"), py::arg("stage_count"), py::arg("sample_every"), py::arg("stage_ends"),
          py::arg("resume"), py::arg("stage_cycles_done"), a.timeout, a.on_wait, a.interval)
      .def(
          "start_run_programme",
          [](ClientHandle& h, std::uint32_t first_stage, std::uint32_t stage_count, std::uint64_t sample_every,
             bool stage_ends, bool resume, std::uint64_t stage_cycles_done) {
            protocol::Command c = command(CommandKind::kRunProgramme);
            c.programme = {first_stage, stage_count};
            c.programme_steps = {sample_every, stage_ends, resume, stage_cycles_done};
            return send(h.get(), std::move(c));
          },
          py::arg("first_stage"), py::arg("stage_count"), py::arg("sample_every"), py::arg("stage_ends"),
          py::arg("resume"), py::arg("stage_cycles_done"))
      .def(
          "await_reply",
          [](ClientHandle& h, std::uint64_t id, Seconds t, py::object w, double i, bool is_run) {
            const Wait wait = is_run ? run_wait(t, std::move(w), i) : command_wait(h, t, std::move(w), i);
            return await_reply(h.get(), id, "request " + std::to_string(id), wait);
          },
          py::arg("request_id"), a.timeout, a.on_wait, a.interval, py::arg("is_run") = true)
      .def(
          "stop",
          [](ClientHandle& h, Seconds t) {
            return call(h, command(CommandKind::kStop), command_wait(h, t, py::none(), 0.1));
          },
          a.timeout);
}

// Walls, parameters, queries and the server itself.
void bind_controls(py::class_<ClientHandle>& handle_class) {
  const WaitArgs a = wait_args();
  handle_class
      .def(
          "set_wall_velocity",
          [](ClientHandle& h, std::string wall, Vector velocity, Vector angular, Seconds t, py::object w, double i) {
            protocol::Command c = command(CommandKind::kSetWallVelocity);
            c.wall_velocity.wall = std::move(wall);
            c.wall_velocity.twist.linear = vector3(velocity);
            c.wall_velocity.twist.angular = vector3(angular);
            return call(h, std::move(c), command_wait(h, t, std::move(w), i));
          },
          py::arg("wall"), py::arg("velocity"), py::arg("angular_velocity"), a.timeout, a.on_wait, a.interval)
      .def(
          "set_wall_servo",
          [](ClientHandle& h, std::string wall, double stress, double gain, double max_speed, Seconds t, py::object w,
             double i) {
            protocol::Command c = command(CommandKind::kSetWallServo);
            c.wall_servo.wall = std::move(wall);
            c.wall_servo.target_stress = stress;
            c.wall_servo.gain = gain;
            c.wall_servo.max_speed = max_speed;
            return call(h, std::move(c), command_wait(h, t, std::move(w), i));
          },
          py::arg("wall"), py::arg("target_stress"), py::arg("gain"), py::arg("max_speed"), a.timeout, a.on_wait,
          a.interval)
      .def(
          "get_state",
          [](ClientHandle& h, Seconds t) {
            return call(h, command(CommandKind::kGetState), command_wait(h, t, py::none(), 0.1));
          },
          a.timeout)
      .def(
          "shutdown",
          [](ClientHandle& h, Seconds t) {
            return call(h, command(CommandKind::kShutdown), command_wait(h, t, py::none(), 0.1));
          },
          a.timeout)
      .def(
          "query_contacts",
          [](ClientHandle& h, std::optional<std::string> wall, std::optional<Vector> box_min,
             std::optional<Vector> box_max, std::optional<double> min_normal_force,
             std::optional<std::int32_t> particle, std::uint32_t chunk_size, Seconds t) {
            if (box_min.has_value() != box_max.has_value()) {
              throw py::value_error("a contact box needs both corners (box_min and box_max)");
            }
            protocol::Command c = command(CommandKind::kQueryContacts);
            if (wall) {
              c.query.wall_set = true;
              c.query.wall = *wall;
            }
            if (box_min) {
              c.query.box_set = true;
              c.query.box_min = vector3(*box_min);
              c.query.box_max = vector3(*box_max);
            }
            c.query.min_normal_force = min_normal_force;
            c.query.particle = particle;
            c.query.chunk_size = chunk_size;
            return call(h, std::move(c), command_wait(h, t, py::none(), 0.1));
          },
          py::arg("wall"), py::arg("box_min"), py::arg("box_max"), py::arg("min_normal_force"), py::arg("particle"),
          py::arg("chunk_size"), a.timeout)
      .def(
          "set_parameter",
          [](ClientHandle& h, std::string name, double value, std::string material, Seconds t) {
            protocol::Command c = command(CommandKind::kSetParameter);
            c.parameter.name = std::move(name);
            c.parameter.value = value;
            c.parameter.material = std::move(material);
            return call(h, std::move(c), command_wait(h, t, py::none(), 0.1));
          },
          py::arg("name"), py::arg("value"), py::arg("material"), a.timeout)
      .def(
          "set_gravity",
          [](ClientHandle& h, Vector gravity, Seconds t) {
            protocol::Command c = command(CommandKind::kSetParameter);
            c.parameter.name = "gravity";
            c.parameter.vector = vector3(gravity);
            return call(h, std::move(c), command_wait(h, t, py::none(), 0.1));
          },
          py::arg("gravity"), a.timeout);
}

}  // namespace

client::Client& ClientHandle::get() const {
  if (!client) throw std::runtime_error("this client is closed");
  return *client;
}

void bind_client(py::module_& m) {
  py::class_<ClientHandle> handle_class(m, "Client", "A connection to one dem_server (dem::client::Client)");
  bind_connection(handle_class);
  bind_loads(handle_class);
  bind_runs(handle_class);
  bind_controls(handle_class);
  m.def(
      "list_servers",
      [](std::uint32_t domain, const std::string& dds_config, double discovery) {
        std::vector<client::ServerInfo> servers;
        {
          py::gil_scoped_release release;
          servers = client::list_servers(domain, dds_config, milliseconds(discovery));
        }
        py::list found;
        for (const client::ServerInfo& info : servers) {
          found.append(py::make_tuple(info.name, info.status ? py::cast(*info.status) : py::none()));
        }
        return found;
      },
      py::arg("domain"), py::arg("dds_config"), py::arg("discovery"),
      "The servers alive on a domain: (name, Status or None) pairs");
}

}  // namespace dem::python
