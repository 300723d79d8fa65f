// A file on the client's machine that a command sends (a case, a
// snapshot), read whole; a path that is missing, a directory or unreadable
// throws LocalFileError naming it and why.
#pragma once

#include <filesystem>
#include <string>

namespace dem::client {

std::string read_local_file(const std::filesystem::path& path);

}  // namespace dem::client
