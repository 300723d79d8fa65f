#include "dem/io/case_loader.h"

#include <google/protobuf/io/tokenizer.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <utility>
#include <vector>

namespace dem::io {
namespace {

// Protobuf's tokenizer advances tab stops of this width when it counts columns.
constexpr int kTabWidth = 8;

std::string nth_line(std::string_view text, int line) {
  for (int i = 0; i < line; ++i) {
    const auto next = text.find('\n');
    if (next == std::string_view::npos) return {};
    text.remove_prefix(next + 1);
  }
  return std::string(text.substr(0, text.find('\n')));
}

std::string expand_tabs(std::string_view line) {
  std::string expanded;
  for (char c : line) {
    if (c == '\t') {
      expanded.append(kTabWidth - expanded.size() % kTabWidth, ' ');
    } else if (c != '\r') {
      expanded += c;
    }
  }
  return expanded;
}

// The parser's message without the file's text it quotes: protobuf's
// messages quote it in double quotes ("no field named \"root\""), after a
// colon ("got: root", "Couldn't parse integer: 12x") or in parentheses
// ("Integer out of range (99999999999)"), so those give way.
std::string without_quotes(std::string_view message) {
  std::string out;
  bool quoted = false;
  for (const char c : message) {
    if (c == '"') {
      if (!quoted) out += "\"...\"";
      quoted = !quoted;
    } else if (quoted) {
      continue;
    } else if (c == ':' || c == '(') {
      break;
    } else {
      out += c;
    }
  }
  while (!out.empty() && (out.back() == ' ' || out.back() == '.')) out.pop_back();
  if (out.ends_with(", got")) out.resize(out.size() - 5);
  return out;
}

// Turns the parser's zero-based positions into "NAME:LINE:COLUMN: message"
// and shows the line with a caret under the column, as compilers do (with
// Excerpts::kHidden, neither the line nor the text the message quotes).
class ErrorCollector : public google::protobuf::io::ErrorCollector {
 public:
  ErrorCollector(std::string_view text, std::string source_name, Excerpts excerpts)
      : text_(text), source_name_(std::move(source_name)), excerpts_(excerpts) {}

  void AddError(int line, google::protobuf::io::ColumnNumber column, const std::string& message) override {
    std::string problem = source_name_;
    if (line >= 0) {
      problem += ':' + std::to_string(line + 1) + ':' + std::to_string(column + 1);
    }
    if (excerpts_ == Excerpts::kHidden) {
      problems_.push_back(problem + ": " + without_quotes(message) +
                          " (the server does not show the content of its files)");
      return;
    }
    problem += ": " + message;
    // The tokenizer's text for the end of the input is empty: "got: ".
    if (message.ends_with("got: ")) problem += "end of file";
    const std::string source_line = line >= 0 ? expand_tabs(nth_line(text_, line)) : "";
    if (!source_line.empty()) {
      const std::string number = std::to_string(line + 1);
      problem += "\n  " + number + " | " + source_line;
      problem += "\n  " + std::string(number.size(), ' ') + " | " + std::string(column, ' ') + '^';
    }
    problems_.push_back(std::move(problem));
  }

  std::vector<std::string> take_problems() { return std::move(problems_); }

 private:
  std::string_view text_;
  std::string source_name_;
  Excerpts excerpts_;
  std::vector<std::string> problems_;
};

}  // namespace

LoadedCase parse_case_text(std::string_view text, std::string source_name, Excerpts excerpts) {
  auto locations = std::make_shared<google::protobuf::TextFormat::ParseInfoTree>();
  ErrorCollector errors(text, source_name, excerpts);
  google::protobuf::TextFormat::Parser parser;
  parser.RecordErrorsTo(&errors);
  parser.WriteLocationsTo(locations.get());

  LoadedCase loaded;
  if (!parser.ParseFromString(std::string(text), &loaded.message)) {
    std::vector<std::string> problems = errors.take_problems();
    if (problems.empty()) problems.push_back(source_name + ": not a valid case in protobuf text format");
    throw CaseError(std::move(problems));
  }
  loaded.source.name = std::move(source_name);
  loaded.source.locations = std::move(locations);
  return loaded;
}

LoadedCase load_case_file(const std::filesystem::path& path, Excerpts excerpts) {
  const std::string name = path.string();
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw CaseError(name + ": cannot read the case file: it is a directory");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CaseError(name + ": cannot read the case file: " + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw CaseError(name + ": cannot read the case file: " + std::strerror(errno));
  LoadedCase loaded = parse_case_text(text.str(), name, excerpts);
  loaded.source.directory = path.parent_path();
  return loaded;
}

LoadedCase parse_case_binary(std::string_view bytes, std::string source_name) {
  LoadedCase loaded;
  if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()) ||
      !loaded.message.ParseFromArray(bytes.data(), static_cast<int>(bytes.size()))) {
    throw CaseError(source_name + ": not a serialized dem.proto.Case message");
  }
  loaded.source.name = std::move(source_name);
  return loaded;
}

}  // namespace dem::io
