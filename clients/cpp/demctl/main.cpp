// demctl: drives and watches dem_server over DDS (docs/SERVICE.md).
//   demctl [--server NAME] [--domain ID] SUBCOMMAND ...
// Exit codes (exit_codes.h): 0 done; 1 other failure; 2 bad arguments;
// 3 no such server within --timeout; 4 the server replied with an error;
// 5 no reply in time; 6 run-until --wait ended at its cycle cap without
// meeting its condition; 7 the server's interface and demctl's cannot meet;
// 130 interrupted.
#include <CLI/CLI.hpp>
#include <cstdlib>
#include <iostream>

#include "dem/cli/interrupt.h"
#include "dem/client/errors.h"
#include "dem/dds/error.h"
#include "dem/version.h"
#include "exit_codes.h"
#include "subcommands.h"

namespace {

// Defaults from the environment, so a shell can aim every call at one server.
void environment_defaults(demctl::Global& global) {
  if (const char* server = std::getenv("DEM_SERVER")) global.server = server;
  if (const char* domain = std::getenv("DEM_DOMAIN")) global.domain = static_cast<std::uint32_t>(std::atoi(domain));
}

}  // namespace

int main(int argc, char** argv) {
  demctl::Global global;
  environment_defaults(global);
  CLI::App app{"Drives and watches dem_server simulations over DDS (loopback only by default)."};
  app.set_version_flag("--version", "demctl " DEM_VERSION);
  app.require_subcommand(1);
  app.footer(
      "Exit codes: 0 done, 1 other failure, 2 bad arguments, 3 no such server within --timeout,\n"
      "4 the server replied with an error, 5 no reply in time, 6 run-until --wait reached its cycle cap\n"
      "before its condition, 7 the server's interface and demctl's cannot meet, 130 interrupted.");
  app.fallthrough();  // --server and --domain may also follow the subcommand
  app.add_option("-s,--server", global.server, "server name (default $DEM_SERVER, else dem)")->capture_default_str();
  app.add_option("-d,--domain", global.domain, "DDS domain id (default $DEM_DOMAIN, else 0)")
      ->capture_default_str()
      ->check(CLI::Range(0, 232));
  app.add_option("--dds-config", global.dds_config,
                 "Cyclone DDS configuration; default $CYCLONEDDS_URI, else the repository's loopback-only file");
  app.add_option("--timeout", global.timeout, "seconds to find the server")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  app.add_flag("-q,--quiet", global.quiet, "no progress bar");

  demctl::Action action;
  demctl::add_subcommands(app, global, action);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error) == 0 ? demctl::kOk : demctl::kBadArguments;
  }

  dem::cli::watch_interrupts();
  try {
    return action();
  } catch (const demctl::BadArguments& error) {
    std::cerr << "demctl: " << error.what() << '\n';
    return demctl::kBadArguments;
  } catch (const std::invalid_argument& error) {
    std::cerr << "demctl: " << error.what() << '\n';
    return demctl::kBadArguments;
  } catch (const dem::client::LocalFileError& error) {
    std::cerr << "demctl: " << error.what() << '\n';
    return demctl::kBadArguments;
  } catch (const dem::client::InterfaceMismatch& error) {
    std::cerr << "demctl: " << error.what() << '\n';
    return demctl::kInterfaceMismatch;
  } catch (const dem::client::NoSuchServer& error) {
    std::cerr << "demctl: " << error.what() << '\n';
    return demctl::kNoSuchServer;
  } catch (const dem::client::ServerError& error) {
    std::cerr << "demctl: server " << global.server << ": " << dem::protocol::to_string(error.status()) << ": "
              << error.what() << '\n';
    return demctl::kServerError;
  } catch (const dem::client::ReplyTimeout& error) {
    std::cerr << "demctl: " << error.what() << '\n';
    return demctl::kNoReply;
  } catch (const std::exception& error) {
    std::cerr << "demctl: " << error.what() << '\n';
    return demctl::kFailure;
  }
}
