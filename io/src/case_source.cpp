#include "dem/io/case_source.h"

#include <charconv>
#include <optional>

#include "dem/case.pb.h"

namespace dem::io {
namespace {

using google::protobuf::Descriptor;
using google::protobuf::FieldDescriptor;
using ParseInfoTree = google::protobuf::TextFormat::ParseInfoTree;
using ParseLocation = google::protobuf::TextFormat::ParseLocation;

struct PathStep {
  std::string_view field;
  int index = -1;  // -1 for a singular field, or a repeated field named as a whole
};

std::optional<PathStep> parse_step(std::string_view text) {
  PathStep step{text, -1};
  const auto open = text.find('[');
  if (open == std::string_view::npos) return step;
  if (text.back() != ']') return std::nullopt;
  step.field = text.substr(0, open);
  const std::string_view digits = text.substr(open + 1, text.size() - open - 2);
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), step.index);
  if (error != std::errc{} || end != digits.data() + digits.size()) return std::nullopt;
  return step;
}

// Walks the path through the message types and the parse tree side by side,
// keeping the last place the text spelled out.
std::optional<ParseLocation> locate(const ParseInfoTree& root, std::string_view path) {
  const Descriptor* type = proto::Case::descriptor();
  const ParseInfoTree* tree = &root;
  std::optional<ParseLocation> found;
  while (!path.empty() && type != nullptr && tree != nullptr) {
    const auto dot = path.find('.');
    const auto step = parse_step(path.substr(0, dot));
    path = dot == std::string_view::npos ? std::string_view{} : path.substr(dot + 1);
    if (!step) break;
    const FieldDescriptor* field = type->FindFieldByName(std::string(step->field));
    // The parse tree logs an error for an index that does not match the
    // field's cardinality, so stop before asking.
    if (field == nullptr || field->is_repeated() != (step->index >= 0)) break;
    const ParseLocation here = tree->GetLocation(field, step->index);
    if (here.line < 0) break;
    found = here;
    if (field->type() != FieldDescriptor::TYPE_MESSAGE) break;
    tree = tree->GetTreeForNested(field, step->index);
    type = field->message_type();
  }
  return found;
}

}  // namespace

std::string describe_problem(const CaseSource& source, std::string_view path, std::string_view message) {
  std::string text;
  if (!source.name.empty()) {
    text += source.name;
    if (source.locations) {
      if (const auto where = locate(*source.locations, path)) {
        // The parser counts from zero; editors count from one.
        text += ':' + std::to_string(where->line + 1) + ':' + std::to_string(where->column + 1);
      }
    }
    text += ": ";
  }
  if (!path.empty()) {
    text += path;
    text += ": ";
  }
  text += message;
  return text;
}

}  // namespace dem::io
