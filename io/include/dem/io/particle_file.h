// Particles listed in a CSV file, the csv_file particle source of a case
// (dem.proto.ParticleFile): one particle a line, "x,y,r" in 2D and
// "x,y,z,r" in 3D, in metres. Lines starting with # are comments; an
// optional header line before the first particle names the columns (x,y,r
// or x,y,z,r). It is the format of the shared benchmark packings
// (../shared/bench/README.md).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "dem/definitions.h"
#include "dem/io/case_error.h"
#include "dem/io/case_loader.h"

namespace dem::io {

// Positions and radii; material, velocities and the rest keep their
// defaults for the caller to set. Throws CaseError naming the file when it
// cannot be read, and "FILE:LINE: message" for each malformed line (the
// first few of them, then how many more there are); with Excerpts::kHidden
// (a server reading for a client) the messages quote nothing of the file.
template <int Dim>
std::vector<ParticleDefT<Dim>> read_particle_file(const std::filesystem::path& path,
                                                  Excerpts excerpts = Excerpts::kShown);

// As read_particle_file, for text already in memory; source_name stands in
// for the file name in messages.
template <int Dim>
std::vector<ParticleDefT<Dim>> parse_particle_text(std::string_view text, const std::string& source_name,
                                                   Excerpts excerpts = Excerpts::kShown);

extern template std::vector<ParticleDefT<2>> read_particle_file<2>(const std::filesystem::path&, Excerpts);
extern template std::vector<ParticleDefT<3>> read_particle_file<3>(const std::filesystem::path&, Excerpts);
extern template std::vector<ParticleDefT<2>> parse_particle_text<2>(std::string_view, const std::string&, Excerpts);
extern template std::vector<ParticleDefT<3>> parse_particle_text<3>(std::string_view, const std::string&, Excerpts);

}  // namespace dem::io
