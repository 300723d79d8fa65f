#include "dem/io/compression_state.h"

#include <charconv>
#include <sstream>
#include <stdexcept>

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

template <int Dim>
std::string compression_state_text(const analysis::CompressionStateT<Dim>& state) {
  std::string out = "samples ";
  put(out, static_cast<std::uint64_t>(state.samples.size()));
  out += '\n';
  for (const analysis::CompressionSample& s : state.samples) put_sample(out, s);
  out += "snapshots ";
  put(out, static_cast<std::uint64_t>(state.snapshots.size()));
  out += '\n';
  for (const analysis::PlateSnapshotT<Dim>& s : state.snapshots) {
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
analysis::CompressionStateT<Dim> compression_state_from_text(std::string_view text) {
  Reader in(text);
  analysis::CompressionStateT<Dim> state;
  in.expect("samples");
  state.samples.resize(in.next<std::uint64_t>());
  for (analysis::CompressionSample& s : state.samples) s = get_sample(in);
  in.expect("snapshots");
  state.snapshots.resize(in.next<std::uint64_t>());
  for (analysis::PlateSnapshotT<Dim>& s : state.snapshots) {
    s.index = in.next<int>();
    s.target_stress = in.next<double>();
    s.for_distribution = in.next<int>() != 0;
    s.sample = get_sample(in);
    s.loading = get_contacts<Dim>(in);
    s.bottom = get_contacts<Dim>(in);
  }
  return state;
}

template std::string compression_state_text(const analysis::CompressionStateT<2>&);
template std::string compression_state_text(const analysis::CompressionStateT<3>&);
template analysis::CompressionStateT<2> compression_state_from_text<2>(std::string_view);
template analysis::CompressionStateT<3> compression_state_from_text<3>(std::string_view);

}  // namespace dem::io
