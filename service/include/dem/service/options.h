// What a dem_server is told at start (its command-line options, docs/SERVICE.md).
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "dem/io/checkpoint_store.h"
#include "dem/service/command_limits.h"

namespace dem::service {

struct ServerOptions {
  std::string name = "dem";  // a ROS 2 name token: the topics are rt/dem/<name>/...
  std::uint32_t domain = 0;  // DDS domain id
  std::string dds_config;    // Cyclone configuration; empty: $CYCLONEDDS_URI, else the repository's loopback file
  // Telemetry is published every `telemetry_cycles` cycles and every
  // `telemetry_seconds` of simulated time, whichever comes first; 0 turns
  // either off (both 0: telemetry only when a command ends).
  std::uint64_t telemetry_cycles = 100;
  double telemetry_seconds = 0.0;
  std::filesystem::path output_directory = "out/dem_server";  // CSV tables and snapshots
  std::optional<std::filesystem::path> initial_case;          // loaded at start
  // Where load_case may read a case by its path, and cases their particle
  // files (io/file_access.h: after "..", links and all); empty: nowhere
  // (load_case by path is refused, saying how to allow it). The initial
  // case's own load reads its directory too.
  std::vector<std::filesystem::path> read_directories;
  std::optional<int> threads;  // engine threads; overrides the case's
  // Cycles between the ParaView files of the programmes it runs; when set,
  // replaces the cases' output.vtk_interval (0: none).
  std::optional<std::uint64_t> vtk_interval;
  bool record_csv =
      true;  // walls.csv and assembly.csv at the telemetry interval, contacts.csv and particles.csv at the end
  // One-shot mode (dem_server --case FILE --run-and-exit): run the initial
  // case's loading programme, write the results and a final snapshot, stop.
  bool run_programme = false;
  // The engine thread looks at its command queue between chunks of cycles
  // sized to take about this long, so commands are answered within it.
  std::chrono::milliseconds chunk_duration{20};
  std::chrono::milliseconds progress_interval{250};  // status updates while a command runs
  std::uint32_t contact_chunk = 4096;                // contacts per reply chunk, by default
  std::uint32_t snapshot_chunk = 1u << 20;           // bytes per reply chunk of a transferred snapshot
  // What one world may take (io/resource_limits.h): 0 sizes each to the
  // machine (half its memory, at 2.5 kB a particle); the threads any case,
  // snapshot or option asks for are capped at the cores.
  std::uint64_t max_particles = 0;
  std::uint64_t memory_budget_bytes = 0;
  CommandLimits limits;  // what one command may ask
  // A load_case or load_snapshot still preparing after this long (a
  // packing that nearly cannot fit) is abandoned with an error.
  std::chrono::milliseconds load_time_limit{120'000};
  // Periodic checkpoints in <output>/<case>/checkpoints: of cycle and
  // run_until when asked (none by default); of programmes (the one-shot
  // mode, run_programme) the same when asked, else a first one 5 s into the
  // run and then every 5 minutes (io::default_programme_checkpoints). And
  // --resume: continue the initial case from the newest of them.
  io::CheckpointSettings checkpoints;
  io::CheckpointSettings programme_checkpoints = io::default_programme_checkpoints();
  bool resume = false;
  // A case whose directory (<output>/<case>/) holds an earlier run's output
  // is refused, unless resumed (--resume) or this is set (--overwrite):
  // then that output is removed first (OutputRecorder::claim).
  bool overwrite = false;
  // Before starting, how long to look for another server of this name,
  // and to wait for one found to leave (name_claim.h).
  std::chrono::milliseconds name_discovery{500};
  std::chrono::milliseconds name_wait{12'000};
  // Commands waiting for the engine thread; beyond them a command is answered "busy".
  std::size_t queue_capacity = 1024;
};

}  // namespace dem::service
