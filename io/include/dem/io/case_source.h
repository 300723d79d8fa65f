// Where a case came from, so a problem found after parsing can point back to
// the line that caused it: "cases/biaxial.case.txtpb:14:3: wall[2].h2: ...".
#pragma once

#include <google/protobuf/text_format.h>

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

namespace dem::io {

struct CaseSource {
  std::string name;  // the file path, or a label such as "<text>"; empty when unknown
  // Where each field was written in the text; null for binary cases.
  std::shared_ptr<const google::protobuf::TextFormat::ParseInfoTree> locations;
  // Where the files a case names (csv_file.path) are found when their paths
  // are relative: the case file's directory; empty for the current directory.
  std::filesystem::path directory;
  // When set, the files a case names must be readable through it
  // (file_access.h): a server confines them to its directories.
  std::shared_ptr<const class FileAccess> files;
};

// "NAME:LINE:COLUMN: PATH: MESSAGE", leaving out what is unknown. PATH is a
// field path into dem.proto.Case such as "wall[2].h2"; the line and column are
// those of the deepest field on the path that the text spells out (a field
// left at its default has no place of its own, so its message points there).
std::string describe_problem(const CaseSource& source, std::string_view path, std::string_view message);

}  // namespace dem::io
