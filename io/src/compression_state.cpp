// The plate loading analyses' state as text, for checkpoints: the samples
// and the contact snapshots taken so far (the next target follows from
// how many there are: one snapshot per target reached). Doubles are
// written in the shortest form that reads back to the same bits.
#include <charconv>
#include <sstream>
#include <stdexcept>

#include "dem/analysis/compression_analysis.h"
#include "format_number.h"

namespace dem::io {
namespace {

class Reader {
 public:
  explicit Reader(std::string_view text) : in_(std::string(text)) {}
  template <typename T>
  T next() {
    std::string token;
    if (!(in_ >> token)) throw std::runtime_error("the plate loading analyses' state ends early");
    T value{};
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc{} || end != token.data() + token.size()) {
      throw std::runtime_error("the plate loading analyses' state holds \"" + token + "\" where a number belongs");
    }
    return value;
  }
  void expect(std::string_view word) {
    std::string token;
    if (!(in_ >> token) || token != word)
      throw std::runtime_error("the plate loading analyses' state lacks " + std::string(word));
  }

 private:
  std::istringstream in_;
};

void put(std::string& out, double value) { out += format_number(value) + ' '; }
void put(std::string& out, std::uint64_t value) { out += std::to_string(value) + ' '; }
void put(std::string& out, int value) { out += std::to_string(value) + ' '; }

void put_sample(std::string& out, const analysis::CompressionSample& s) {
  put(out, s.stage);
  put(out, s.cycle);
  put(out, s.time);
  put(out, s.settlement);
  put(out, s.stress);
  put(out, s.loading_contacts);
  put(out, s.bottom_stress);
  put(out, s.bottom_contacts);
  out += '\n';
}

analysis::CompressionSample get_sample(Reader& in) {
  analysis::CompressionSample s;
  s.stage = in.next<int>();
  s.cycle = in.next<std::uint64_t>();
  s.time = in.next<double>();
  s.settlement = in.next<double>();
  s.stress = in.next<double>();
  s.loading_contacts = in.next<int>();
  s.bottom_stress = in.next<double>();
  s.bottom_contacts = in.next<int>();
  return s;
}

template <int Dim>
void put_contacts(std::string& out, const std::vector<analysis::PlateContactT<Dim>>& contacts) {
  put(out, static_cast<std::uint64_t>(contacts.size()));
  out += '\n';
  for (const analysis::PlateContactT<Dim>& c : contacts) {
    put(out, c.particle.value());
    for (int d = 0; d < Dim; ++d) put(out, c.point[d]);
    put(out, c.normal_force);
    put(out, c.shear_force);
    put(out, c.formed_cycle);
    out += '\n';
  }
}

template <int Dim>
std::vector<analysis::PlateContactT<Dim>> get_contacts(Reader& in) {
  std::vector<analysis::PlateContactT<Dim>> contacts(in.next<std::uint64_t>());
  for (analysis::PlateContactT<Dim>& c : contacts) {
    c.particle = ParticleId{in.next<int>()};
    for (int d = 0; d < Dim; ++d) c.point[d] = in.next<double>();
    c.normal_force = in.next<double>();
    c.shear_force = in.next<double>();
    c.formed_cycle = in.next<std::uint64_t>();
  }
  return contacts;
}

}  // namespace
}  // namespace dem::io

// The accumulator is analysis's (dem/analysis/compression_analysis.h); its
// state as text is written and read here, beside the other checkpoint I/O.
namespace dem::analysis {

using io::get_contacts;
using io::get_sample;
using io::put;
using io::put_contacts;
using io::put_sample;
using io::Reader;

template <int Dim>
std::string CompressionAnalysisT<Dim>::state() const {
  std::string out = "samples ";
  put(out, static_cast<std::uint64_t>(samples_.size()));
  out += '\n';
  for (const CompressionSample& s : samples_) put_sample(out, s);
  out += "snapshots ";
  put(out, static_cast<std::uint64_t>(snapshots_.size()));
  out += '\n';
  for (const PlateSnapshotT<Dim>& s : snapshots_) {
    put(out, s.index);
    put(out, s.target_stress);
    put(out, static_cast<int>(s.for_distribution));
    put_sample(out, s.sample);
    put_contacts<Dim>(out, s.loading);
    put_contacts<Dim>(out, s.bottom);
  }
  return out;
}

template <int Dim>
void CompressionAnalysisT<Dim>::restore(std::string_view state) {
  Reader in(state);
  in.expect("samples");
  std::vector<CompressionSample> samples(in.next<std::uint64_t>());
  for (CompressionSample& s : samples) s = get_sample(in);
  in.expect("snapshots");
  std::vector<PlateSnapshotT<Dim>> snapshots(in.next<std::uint64_t>());
  if (snapshots.size() > targets_.size())
    throw std::runtime_error("the plate loading analyses' state has more snapshots than targets");
  for (PlateSnapshotT<Dim>& s : snapshots) {
    s.index = in.next<int>();
    s.target_stress = in.next<double>();
    s.for_distribution = in.next<int>() != 0;
    s.sample = get_sample(in);
    s.loading = get_contacts<Dim>(in);
    s.bottom = get_contacts<Dim>(in);
  }
  samples_ = std::move(samples);
  snapshots_ = std::move(snapshots);
  next_target_ = snapshots_.size();  // a snapshot per target reached
}

template std::string CompressionAnalysisT<2>::state() const;
template std::string CompressionAnalysisT<3>::state() const;
template void CompressionAnalysisT<2>::restore(std::string_view);
template void CompressionAnalysisT<3>::restore(std::string_view);

}  // namespace dem::analysis
