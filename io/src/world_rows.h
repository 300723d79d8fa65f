// The rows of contacts.csv and particles.csv (csv_writers.h describes their
// columns), written once here for every table that holds them: the two
// files a run writes at its end, and the plate loading analyses'
// contacts_at_stress.csv and particles_at_stress.csv, which put the
// snapshot's columns before them (compression_csv.h).
#pragma once

#include <string>
#include <string_view>

#include "dem/io/csv_file.h"
#include "dem/world.h"

namespace dem::io {

// The header's columns, without a line end.
template <int Dim>
std::string contact_columns();
template <int Dim>
std::string particle_columns();

// One row per touching contact, or per particle, in the engine's order,
// each beginning with `leading` (cells already joined with commas; empty
// for none).
template <int Dim>
void write_contact_rows(CsvFile& file, const BasicWorld<Dim>& world, std::string_view leading);
template <int Dim>
void write_particle_rows(CsvFile& file, const BasicWorld<Dim>& world, std::string_view leading);

}  // namespace dem::io
