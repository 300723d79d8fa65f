#include "service_test_support.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <spdlog/spdlog.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <regex>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace dem::test {

namespace {
// The servers log every command at info level; tests show warnings only.
const bool quiet_logs = [] {
  spdlog::set_level(spdlog::level::warn);
  return true;
}();
}  // namespace

std::filesystem::path case_file(const std::string& name) {
  return std::filesystem::path(DEM_CASES_DIR) / "ball" / (name + ".case.txtpb");
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::filesystem::path output_directory(const std::string& test) {
  const auto directory = std::filesystem::path(DEM_SERVICE_TEST_OUTPUT) / test;
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  return directory;
}

std::uint64_t newest_checkpoint(const std::filesystem::path& case_directory) {
  std::uint64_t newest = 0;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(case_directory / "checkpoints", error)) {
    std::smatch match;
    const std::string name = entry.path().filename().string();
    if (std::regex_match(name, match, std::regex("checkpoint-0*([0-9]+)\\.resume"))) {
      newest = std::max<std::uint64_t>(newest, std::stoull(match[1]));
    }
  }
  return newest;
}

service::ServerOptions server_options(const std::string& name, std::uint32_t domain) {
  service::ServerOptions options;
  options.name = name;
  options.domain = domain;
  options.telemetry_cycles = 10;
  options.threads = 1;
  options.output_directory = output_directory(name + "_" + std::to_string(domain));
  // Servers of a test have names of their own: a short look for another is enough.
  options.name_discovery = 100ms;
  options.name_wait = 1s;
  // The cases a test names by their path on the server.
  options.read_directories = {DEM_CASES_DIR, DEM_SERVICE_TEST_DATA};
  return options;
}

InProcessServer::InProcessServer(service::ServerOptions options) : server_(std::move(options)) { server_.start(); }

InProcessServer::~InProcessServer() {
  server_.request_shutdown();
  server_.wait();
}

client::ConnectOptions connect_options(const std::string& server, std::uint32_t domain) {
  client::ConnectOptions options;
  options.server = server;
  options.domain = domain;
  options.timeout = 10s;  // generous: ctest runs tests side by side on two cores
  options.reply_timeout = 30s;
  return options;
}

pid_t spawn(const std::string& program, const std::vector<std::string>& arguments, bool quiet) {
  std::vector<std::string> all{program};
  all.insert(all.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& argument : all) argv.push_back(argument.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (quiet) {
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  }
  pid_t pid = -1;
  const int error = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) throw std::runtime_error("cannot start " + program);
  return pid;
}

ServerProcess::ServerProcess(const std::vector<std::string>& arguments) : pid_(spawn(DEM_SERVER_PROGRAM, arguments)) {}

ServerProcess::~ServerProcess() {
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
}

void ServerProcess::signal(int signal) const { ::kill(pid_, signal); }

int ServerProcess::wait(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    std::this_thread::sleep_for(10ms);
  }
  return -1;
}

bool eventually(const std::function<bool()>& condition, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!condition()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(10ms);
  }
  return true;
}

}  // namespace dem::test
