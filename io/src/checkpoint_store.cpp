#include "dem/io/checkpoint_store.h"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "dem/io/snapshot_file.h"
#include "dem/io/snapshot_frame.h"

namespace dem::io {
namespace {

constexpr std::string_view kResumeHeader = "dem.resume 1";

// checkpoint-00000000000000123456: names that sort by cycle.
std::string stem(std::uint64_t cycle) {
  char name[40];
  std::snprintf(name, sizeof(name), "checkpoint-%020llu", static_cast<unsigned long long>(cycle));
  return name;
}

std::string hex(std::string_view bytes) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string out;
  for (unsigned char c : bytes) {
    out += kDigits[c >> 4];
    out += kDigits[c & 15];
  }
  return out;
}

std::uint64_t number(std::string_view text, std::string_view what) {
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc{} || end != text.data() + text.size()) {
    throw std::runtime_error("resume file: " + std::string(what) + " is not a number: \"" + std::string(text) + '"');
  }
  return value;
}

}  // namespace

void PeriodicCheckpoints::begin(const std::filesystem::path& directory, std::string case_digest, std::uint64_t cycle) {
  store_.reset();
  if (settings_.enabled() && !directory.empty()) store_.emplace(directory, settings_.keep);
  case_digest_ = std::move(case_digest);
  last_cycle_ = cycle;
  last_time_ = std::chrono::steady_clock::now();
  written_ = false;
}

bool PeriodicCheckpoints::due(std::uint64_t cycle) const {
  if (!store_) return false;
  const bool by_cycles = settings_.cycles > 0 && cycle - last_cycle_ >= settings_.cycles;
  const double seconds = !written_ && settings_.first_seconds > 0.0 ? settings_.first_seconds : settings_.seconds;
  const bool by_time =
      seconds > 0.0 && std::chrono::duration<double>(std::chrono::steady_clock::now() - last_time_).count() >= seconds;
  return by_cycles || by_time;
}

void PeriodicCheckpoints::write(std::string_view snapshot_bytes, ResumePoint point) {
  point.case_digest = case_digest_;
  store_->write(snapshot_bytes, point);
  last_cycle_ = point.cycle;
  last_time_ = std::chrono::steady_clock::now();
  written_ = true;
}

std::string resume_text(const ResumePoint& point) {
  std::string text(kResumeHeader);
  text += "\ncycle " + std::to_string(point.cycle) + "\nstage " + std::to_string(point.stage) + "\nstage_cycles " +
          std::to_string(point.stage_cycles) + "\ncase " + point.case_digest + '\n';
  for (const auto& [name, bytes] : point.tables) text += "table " + name + ' ' + std::to_string(bytes) + '\n';
  for (const VtkSeries::Step& step : point.vtk_steps) {
    // The shortest text that reads back as the same double: the .pvd lists the time.
    char time[32];
    const auto written = std::to_chars(time, time + sizeof(time), step.time);
    text += "vtk " + std::to_string(step.cycle) + ' ' + std::string(time, written.ptr) + '\n';
  }
  text += "analysis " + std::to_string(point.analysis.size()) + '\n' + point.analysis;
  return text;
}

ResumePoint parse_resume(std::string_view text) {
  ResumePoint point;
  std::istringstream in{std::string(text)};
  std::string line;
  if (!std::getline(in, line) || line != kResumeHeader) throw std::runtime_error("not a resume file");
  bool ended = false;
  while (!ended && std::getline(in, line)) {
    const auto space = line.find(' ');
    const std::string key = line.substr(0, space);
    const std::string value = space == std::string::npos ? std::string() : line.substr(space + 1);
    if (key == "cycle") {
      point.cycle = number(value, key);
    } else if (key == "stage") {
      point.stage = number(value, key);
    } else if (key == "stage_cycles") {
      point.stage_cycles = number(value, key);
    } else if (key == "case") {
      point.case_digest = value;
    } else if (key == "table") {
      const auto split = value.rfind(' ');
      if (split == std::string::npos) throw std::runtime_error("resume file: a table without its size");
      point.tables[value.substr(0, split)] = number(value.substr(split + 1), "a table's size");
    } else if (key == "vtk") {
      const auto split = value.find(' ');
      if (split == std::string::npos) throw std::runtime_error("resume file: a ParaView step without its time");
      const std::string time = value.substr(split + 1);
      VtkSeries::Step step{number(value.substr(0, split), "a ParaView step's cycle"), 0.0};
      const auto [end, error] = std::from_chars(time.data(), time.data() + time.size(), step.time);
      if (error != std::errc{} || end != time.data() + time.size()) {
        throw std::runtime_error("resume file: a ParaView step's time is not a number: \"" + time + '"');
      }
      point.vtk_steps.push_back(step);
    } else if (key == "analysis") {
      const std::uint64_t size = number(value, key);
      point.analysis.resize(size);
      if (!in.read(point.analysis.data(), static_cast<std::streamsize>(size))) {
        throw std::runtime_error("resume file: the analyses' state is cut short");
      }
      ended = true;
    } else {
      throw std::runtime_error("resume file: unknown line \"" + line + '"');
    }
  }
  if (!ended) throw std::runtime_error("resume file: cut short");
  return point;
}

std::string file_digest(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return bytes_digest(bytes);
}

std::string bytes_digest(std::string_view bytes) { return hex(sha256(bytes)); }

CheckpointStore::CheckpointStore(std::filesystem::path directory, int keep)
    : directory_(std::move(directory)), keep_(std::max(keep, 1)) {
  std::error_code error;
  std::filesystem::create_directories(directory_, error);
}

void CheckpointStore::write(std::string_view snapshot_bytes, const ResumePoint& point) {
  const std::string name = stem(point.cycle);
  write_snapshot_bytes(directory_ / (name + ".snapshot"), snapshot_bytes);
  // Last: a resume file says its snapshot is whole. Written the same safe way.
  write_snapshot_bytes(directory_ / (name + ".resume"), resume_text(point));
  std::vector<std::filesystem::path> resumes;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory_, error)) {
    if (entry.path().extension() == ".resume") resumes.push_back(entry.path());
  }
  std::sort(resumes.begin(), resumes.end());
  for (std::size_t i = 0; i + static_cast<std::size_t>(keep_) < resumes.size(); ++i) {
    std::filesystem::remove(resumes[i], error);  // the resume file first: never a whole-looking half
    std::filesystem::path snapshot = resumes[i];
    std::filesystem::remove(snapshot.replace_extension(".snapshot"), error);
  }
}

std::optional<CheckpointStore::Latest> CheckpointStore::latest() const {
  std::vector<std::filesystem::path> resumes;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory_, error)) {
    if (entry.path().extension() == ".resume") resumes.push_back(entry.path());
  }
  std::sort(resumes.rbegin(), resumes.rend());
  for (const auto& resume : resumes) {
    try {
      Latest latest;
      latest.point = parse_resume(read_snapshot_bytes(resume));
      latest.path = std::filesystem::path(resume).replace_extension(".snapshot");
      latest.snapshot_bytes = read_snapshot_bytes(latest.path);
      (void)unframe_snapshot(latest.snapshot_bytes, latest.path.string());  // its checksum
      return latest;
    } catch (const std::exception&) {
      // A damaged checkpoint: the one before it will do.
    }
  }
  return std::nullopt;
}

}  // namespace dem::io
