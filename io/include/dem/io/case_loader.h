// Reading a case: protobuf text format from a file or a string, or the
// serialized binary form the service receives. Loading only parses; see
// case_validation.h for the checks and case_conversion.h for the engine
// definitions.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "dem/case.pb.h"
#include "dem/io/case_error.h"
#include "dem/io/case_source.h"

namespace dem::io {

// Whether a syntax error shows the line it is on. A server reading a file
// for a client hides it (kHidden): the file may hold what the client may
// not read (a secret beside the cases), so the error gives the file, line
// and column only, and the parser's message without the text it quotes.
enum class Excerpts { kShown, kHidden };

struct LoadedCase {
  proto::Case message;
  CaseSource source;  // for pointing later problems at their lines
};

// Throws CaseError naming the file when it cannot be read, and
// "FILE:LINE:COLUMN: message" followed by the offending line for a syntax
// error or an unknown field (without the line when `excerpts` is kHidden).
// Files the case names by a relative path (csv_file.path) are found beside it.
LoadedCase load_case_file(const std::filesystem::path& path, Excerpts excerpts = Excerpts::kShown);

// As load_case_file, for text already in memory; source_name stands in for
// the file name in messages, and relative paths start from the current
// directory unless the caller sets source.directory.
LoadedCase parse_case_text(std::string_view text, std::string source_name = "<text>",
                           Excerpts excerpts = Excerpts::kShown);

// A serialized dem.proto.Case. Throws CaseError when the bytes are not one.
LoadedCase parse_case_binary(std::string_view bytes, std::string source_name = "<binary>");

}  // namespace dem::io
