#include "dem/io/particle_file.h"

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <utility>

#include "format_number.h"

namespace dem::io {
namespace {

// Enough to show what is wrong with a file without burying the terminal
// under a file that is wrong throughout (a 3D file in a 2D case).
constexpr std::size_t kReportedLines = 10;

std::string_view trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  while (true) {
    const auto comma = line.find(',');
    fields.push_back(trim(line.substr(0, comma)));
    if (comma == std::string_view::npos) return fields;
    line.remove_prefix(comma + 1);
  }
}

std::string join(const std::vector<std::string_view>& fields) {
  std::string joined;
  for (const std::string_view field : fields) {
    if (!joined.empty()) joined += ',';
    joined += field;
  }
  return joined;
}

constexpr const char* columns_of(int dimension) { return dimension == 2 ? "x,y,r" : "x,y,z,r"; }

std::optional<double> parse_number(std::string_view text) {
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc{} || end != text.data() + text.size()) return std::nullopt;
  return value;
}

template <int Dim>
class ParticleTextParser {
 public:
  ParticleTextParser(std::string source_name, Excerpts excerpts)
      : name_(std::move(source_name)), shown_(excerpts == Excerpts::kShown) {}

  std::vector<ParticleDefT<Dim>> run(std::string_view text) {
    int line_number = 0;
    while (!text.empty()) {
      const auto end = text.find('\n');
      ++line_number;
      read_line(line_number, trim(text.substr(0, end)));
      text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
    }
    if (problems_.empty() && particles_.empty()) {
      problem(name_ + ": holds no particles (expected lines of " + columns_of(Dim) + ")");
    }
    if (problems_.size() > kReportedLines) {
      const std::size_t more = problems_.size() - kReportedLines;
      problems_.resize(kReportedLines);
      problems_.push_back(name_ + ": " + std::to_string(more) + " more malformed line" + (more == 1 ? "" : "s") +
                          " not listed");
    }
    if (!problems_.empty()) throw CaseError(std::move(problems_));
    return std::move(particles_);
  }

 private:
  void read_line(int line_number, std::string_view line) {
    if (line.empty() || line.front() == '#') return;
    const std::vector<std::string_view> fields = split_fields(line);
    const std::string where = name_ + ':' + std::to_string(line_number) + ": ";
    // A header comes before the first particle and starts with a name, not a number.
    if (particles_.empty() && !header_seen_ && !fields.front().empty() &&
        std::isalpha(static_cast<unsigned char>(fields.front().front())) != 0) {
      check_header(where, join(fields));
      return;
    }
    constexpr std::size_t kColumns = Dim + 1;
    if (fields.size() != kColumns) {
      std::string message = "expected " + std::to_string(kColumns) + " values (" + columns_of(Dim) + "), got " +
                            std::to_string(fields.size());
      if (fields.size() == (Dim == 2 ? 4u : 3u)) {
        message += std::string(" (") + columns_of(5 - Dim) + " is a " + std::to_string(5 - Dim) +
                   "D row; the case is " + std::to_string(Dim) + "D)";
      }
      problem(where + message);
      return;
    }
    Eigen::Matrix<double, kColumns, 1> values;
    bool ok = true;
    for (std::size_t i = 0; i < kColumns; ++i) {
      const std::string column = "column " + std::to_string(i + 1) + " (" + column_name(i) + "): ";
      const std::optional<double> value = parse_number(fields[i]);
      if (!value) {
        problem(where + column + (shown_ ? '"' + std::string(fields[i]) + "\" is" : std::string("is")) +
                " not a number");
        ok = false;
      } else if (!std::isfinite(*value)) {
        problem(where + column + "must be a finite number" + got(*value));
        ok = false;
      } else if (i == Dim && *value <= 0) {
        problem(where + column + "the radius must be > 0" + got(*value));
        ok = false;
      } else {
        values[static_cast<Eigen::Index>(i)] = *value;
      }
    }
    if (!ok) return;
    ParticleDefT<Dim> particle;
    particle.position = values.template head<Dim>();
    particle.radius = values[Dim];
    particles_.push_back(particle);
  }

  void check_header(const std::string& where, const std::string& header) {
    header_seen_ = true;
    if (header == columns_of(Dim)) return;
    if (!shown_) {
      problem(where + "the header does not name the columns " + columns_of(Dim) + " (the case is " +
              std::to_string(Dim) + "D)");
    } else if (header == columns_of(5 - Dim)) {
      problem(where + "the header " + header + " is that of a " + std::to_string(5 - Dim) + "D file; the case is " +
              std::to_string(Dim) + "D (columns " + columns_of(Dim) + ")");
    } else {
      problem(where + "the header names the columns " + header + "; expected " + columns_of(Dim) + " (the case is " +
              std::to_string(Dim) + "D)");
    }
  }

  static std::string column_name(std::size_t index) {
    if (index == Dim) return "r";
    return std::string(1, "xyz"[index]);
  }

  void problem(std::string text) { problems_.push_back(std::move(text)); }
  // A value read from the file, where its text may be shown.
  std::string got(double value) const { return shown_ ? " (got " + format_number(value) + ')' : std::string(); }

  std::string name_;
  bool shown_;
  bool header_seen_ = false;
  std::vector<ParticleDefT<Dim>> particles_;
  std::vector<std::string> problems_;
};

}  // namespace

template <int Dim>
std::vector<ParticleDefT<Dim>> parse_particle_text(std::string_view text, const std::string& source_name,
                                                   Excerpts excerpts) {
  return ParticleTextParser<Dim>(source_name, excerpts).run(text);
}

template <int Dim>
std::vector<ParticleDefT<Dim>> read_particle_file(const std::filesystem::path& path, Excerpts excerpts) {
  const std::string name = path.string();
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw CaseError(name + ": cannot read the particle file: it is a directory");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CaseError(name + ": cannot read the particle file: " + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw CaseError(name + ": cannot read the particle file: " + std::strerror(errno));
  return parse_particle_text<Dim>(text.str(), name, excerpts);
}

template std::vector<ParticleDefT<2>> read_particle_file<2>(const std::filesystem::path&, Excerpts);
template std::vector<ParticleDefT<3>> read_particle_file<3>(const std::filesystem::path&, Excerpts);
template std::vector<ParticleDefT<2>> parse_particle_text<2>(std::string_view, const std::string&, Excerpts);
template std::vector<ParticleDefT<3>> parse_particle_text<3>(std::string_view, const std::string&, Excerpts);

}  // namespace dem::io
