// Shared by the service tests: a DDS domain per test (so ctest can run them
// side by side), servers in-process or as dem_server processes, clients.
// Every DDS entity uses the repository's loopback configuration (ctest sets
// CYCLONEDDS_URI; the programs default to it too).
#pragma once

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "dem/client/client.h"
#include "dem/service/server.h"

namespace dem::test {

using namespace std::chrono_literals;

// One domain id per test, distinct across the whole suite by construction.
// The shell tests (CMakeLists.txt) use 118 and 119; the container test
// (tests/container) 150 to 153, the one from source 154 to 157; the Python
// tests (tests/python) 160 to 179.
enum Domain : std::uint32_t {
  kDdsTypedRoundTrip = 40,
  kDdsWaitSet,
  kDdsDomainConfiguration,
  kDdsDiscovery,
  kDdsEntityLifetime,
  kDdsLargeSamples,
  kCommandsLoadCase = 50,
  kCommandsWallMotion,
  kCommandsCycle,
  kCommandsRunUntil,
  kCommandsGetState,
  kCommandsQueryContacts,
  kCommandsSetParameter,
  kCommandsSnapshotPathAndTransfer,
  kCommandsShutdown,
  kCommandsTelemetryBySimulatedTime,
  kCommandsThreeDimensional,
  kErrorsUnknownWall = 65,
  kErrorsNegativeCycles,
  kErrorsMalformedCase,
  kErrorsInvalidCase,
  kErrorsGarbageSnapshot,
  kErrorsOtherServer,
  kErrorsLifecycle,
  kErrorsParameters,
  kErrorsSnapshotPaths,
  kErrorsUnknownKind,
  kTopologyTwoServers = 80,
  kTopologyLateJoiner,
  kTopologyStopCancels,
  kTopologyStalledSubscriber,
  kTopologyListServers,
  kTopologyNoServer,
  kSnapshotContinuation = 90,
  kSnapshotTransfer,
  kExperimentNineDisc = 100,
  kExperimentSignals,
  kOneShotComplete = 105,
  kOneShotStop,
  kOneShotSigterm,
  kOneShotFailure,
  kOneShotBadStarts,
  kOneShotEnvironment,
  kProgrammeCommand,
  kProgrammeCommandStop,
  kProgrammeCommandErrors,
  kProgrammeStableIds,
  kLastDomain
};
static_assert(kLastDomain <= 118, "the shell tests use domains 118 and 119");

// The reliability tests (docs/RELIABILITY.md) take 127 to 141 (the DDS
// Security test, CMakeLists.txt, 142; the responsiveness benchmark 126).
enum ReliabilityDomain : std::uint32_t {
  kHealthCycleBlowUp = 127,
  kLimitsPerCommand,
  kLimitsBusy,
  kLimitsGetStateWhileCycling,
  kFilesCaseFiles,
  kFilesSnapshotLinks,
  kLoadingStop,
  kLoadingTimeLimit,
  kCheckpointsOneShot,
  kCheckpointsInteractive,
  kOwnershipNames,
  kOwnershipRuns,
  kOwnershipVanished,
  kLimitsStalledClient,
  kFilesOwnDirectory,
  kLastReliabilityDomain
};
static_assert(kLastReliabilityDomain <= 142, "the reliability tests' domains are 127-141");
// Two servers of one name started at the same instant: 210 and 211 (142 to
// 209 belong to other tests, CMakeLists.txt; the discovery probe 208).
enum NameContestDomain : std::uint32_t { kOwnershipSimultaneousServers = 210, kOwnershipSimultaneousPrograms };
// What a new user met (issue 34): 213 to 219 (the shell test demctl_usability
// takes 214, and 219 as a domain with no server; tests/ros2's
// older-interfaces test 218).
enum UsabilityDomain : std::uint32_t {
  kProgrammeEnds = 213,
  kTelemetryHistory = 215,
  kInterfaceMismatchServer,
  kInterfaceMismatchClient,
  kLastUsabilityDomain = 219
};
// The reliability tests of issue 37: 191 to 198 (212 to 219 are issue 34's).
enum ReliabilityRoundTwoDomain : std::uint32_t {
  kFilesNoReadDirectory = 191,
  kFilesHiddenContent,
  kGuardsTypeInformation,
  kLimitsDeepPipeline,
  kLastRoundTwoDomain
};
static_assert(kLastRoundTwoDomain <= 199, "issue 37's tests take 191-198 (200 on belong to others)");
// Issue 37's later tests: 175 to 179 (the Python tests take 160 to 174).
enum ReliabilityRoundTwoLaterDomain : std::uint32_t {
  kCheckpointsRandomKills = 175,
  kCheckpointsOutputInUse,
  kLastRoundTwoLaterDomain
};
static_assert(kLastRoundTwoLaterDomain <= 180, "issue 37's later tests take 175-179 (180 on belong to others)");
// Issue 35's: 228 to 232.
enum SessionsDomain : std::uint32_t { kProgrammeSteps = 228, kLastSessionsDomain };
static_assert(kLastSessionsDomain <= 233, "issue 35's tests take 228-232 (Cyclone's domains end at 232)");

// Issue 37's reply tests: 143 to 149 (a domain above 232 has no ports:
// Cyclone's port of domain d is 7400 + 250 d).
enum ReplyDomain : std::uint32_t {
  kLimitsFloodingClients = 143,
  kDdsInstanceFilter,
  kDdsKeylessReplies,
  kLimitsRepliesToTheirClientAlone,
  kLastReplyDomain
};
static_assert(kLastReplyDomain <= 150, "issue 37's reply tests take 143-149");

std::filesystem::path case_file(const std::string& name);  // cases/ball/<name>.case.txtpb
std::string read_text(const std::filesystem::path& path);

// A clean output directory for one test.
std::filesystem::path output_directory(const std::string& test);

// The cycle of the newest checkpoint (checkpoint-<cycle>.resume) in a
// case's output directory, or 0.
std::uint64_t newest_checkpoint(const std::filesystem::path& case_directory);

// Options for a test server: one engine thread, telemetry every 10 cycles,
// its own output directory.
service::ServerOptions server_options(const std::string& name, std::uint32_t domain);

// A dem_server inside the test process, started at once and shut down
// (gracefully) with the test.
class InProcessServer {
 public:
  explicit InProcessServer(service::ServerOptions options);
  ~InProcessServer();
  service::Server& server() { return server_; }

 private:
  service::Server server_;
};

client::ConnectOptions connect_options(const std::string& server, std::uint32_t domain);

// A dem_server process (the real program, talking over loopback). Killed
// with SIGKILL if the test leaves it running.
class ServerProcess {
 public:
  explicit ServerProcess(const std::vector<std::string>& arguments);
  ~ServerProcess();
  pid_t pid() const { return pid_; }
  void signal(int signal) const;
  // Waits for the process to end; its exit code, or -1 when it did not end in time.
  int wait(std::chrono::milliseconds timeout);

 private:
  pid_t pid_ = -1;
};

// Spawns a program with arguments, its output to /dev/null when quiet; returns its pid.
pid_t spawn(const std::string& program, const std::vector<std::string>& arguments, bool quiet = false);

// Polls `condition` every 10 ms until it holds or the timeout passes.
bool eventually(const std::function<bool()>& condition, std::chrono::milliseconds timeout);

}  // namespace dem::test
