// Shared by the fuzz targets (docs/FUZZING.md): the limits they run under,
// small enough that every input finishes in milliseconds (the server's own
// defaults are sized to the machine), and what counts as a finding. An
// input may be refused - CaseError, SnapshotError, DefinitionError,
// CommandError, each with its message - but any other exception, a crash,
// a sanitizer report or an input that takes seconds is a bug.
#pragma once

#include <google/protobuf/stubs/logging.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>

#include "dem/io/file_access.h"
#include "dem/io/resource_limits.h"

// libFuzzer calls this once before the first input. Protocol Buffers logs
// every string of invalid UTF-8 it parses - most mutations of a serialized
// input - to stderr: no finding, and the writing slows the runs. Not
// inline: libFuzzer finds it by name, and each target is one source file.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  google::protobuf::SetLogHandler(nullptr);
  return 0;
}

namespace dem::fuzz {

// 4,000 packing attempts a particle, asked for or not (the limit caps the
// engine's default of 100,000 too): every seed's packing still fits (the
// densest, ellipsoids_reduced, does not at 1,000), and a packing that jams -
// the inputs that cost most while fuzzing - gives up 25 times sooner, with
// the refusal ("no free place") a server's own limit ends in.
// DEM_FUZZ_SHOW_REFUSALS=1 over the seeds shows that none is refused for it.
inline io::ResourceLimits limits() {
  io::ResourceLimits limits = io::limits_with_budget(300, 0);
  limits.max_threads = 1;
  limits.max_packing_attempts = 4'000;
  return limits;
}

// The only files a fuzzed case may name: the seed corpus's particle files
// (tests/fuzz/corpus/files), through the server's own confinement.
inline std::shared_ptr<const io::FileAccess> files() {
  static const auto access =
      std::make_shared<const io::FileAccess>(std::vector<std::filesystem::path>{DEM_FUZZ_FILES_DIR});
  return access;
}

// A refusal is no finding. DEM_FUZZ_SHOW_REFUSALS=1 prints each one: run
// over the seeds, it shows which get through to a world and which the
// limits above refuse (docs/FUZZING.md).
inline void refused(const std::exception& error) {
  static const bool show = std::getenv("DEM_FUZZ_SHOW_REFUSALS") != nullptr;
  if (show) std::fprintf(stderr, "refused: %s\n", error.what());
}

// An exception no refusal explains: report it and abort, so libFuzzer keeps the input.
[[noreturn]] inline void unexpected(const char* target, const std::exception& error) {
  std::fprintf(stderr, "%s: unexpected exception: %s\n", target, error.what());
  std::abort();
}

}  // namespace dem::fuzz
