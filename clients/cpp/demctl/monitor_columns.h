// demctl monitor's columns after the plates' stress and settlement: the
// one list of them, in the order of the live table and of the CSV file
// (--csv, the demo's monitor.csv). A column added here is a column of both,
// in the same place on every run; the plates' columns before them follow
// the server's order of its walls (the case's), whatever order --wall
// names them in.
#pragma once

#include <array>

#include "dem/protocol/messages.h"

namespace demctl {

struct StatisticsColumn {
  const char* csv;      // its name in the CSV file's header
  const char* heading;  // its heading in the live table, or nullptr: in the CSV file only
  int width;            // of the live table's column
  const char* format;   // printf format of its value in the live table ("%*.3f": width, then value)
  double scale;         // the live table shows value * scale (100 for a percentage)
  double (*value)(const dem::protocol::ContactStats&);
};

using dem::protocol::ContactStats;

inline constexpr std::array kStatisticsColumns{
    StatisticsColumn{"contacts", "contacts", 9, "%*.0f", 1.0,
                     [](const ContactStats& s) { return static_cast<double>(s.contacts); }},
    StatisticsColumn{"coordination_number", "Z", 6, "%*.3f", 1.0,
                     [](const ContactStats& s) { return s.coordination_number; }},
    StatisticsColumn{"sliding_fraction", "sliding", 7, "%*.1f%%", 100.0,
                     [](const ContactStats& s) { return s.sliding_fraction; }},
    StatisticsColumn{"mean_normal_force", nullptr, 0, nullptr, 1.0,
                     [](const ContactStats& s) { return s.mean_normal_force; }},
    StatisticsColumn{"max_normal_force", nullptr, 0, nullptr, 1.0,
                     [](const ContactStats& s) { return s.max_normal_force; }},
    StatisticsColumn{"kinetic_energy", "KE [J]", 12, "%*.5g", 1.0,
                     [](const ContactStats& s) { return s.kinetic_energy; }},
    StatisticsColumn{"out_of_balance", nullptr, 0, nullptr, 1.0,
                     [](const ContactStats& s) { return s.out_of_balance; }},
    // The quasi-static measures (docs/CASES.md): how far the sample is
    // from the equilibrium a slow test assumes.
    StatisticsColumn{"kinetic_to_elastic", "KE/elastic", 10, "%*.2g", 1.0,
                     [](const ContactStats& s) { return s.kinetic_to_elastic; }},
    StatisticsColumn{"unbalanced_force", "unbalanced", 10, "%*.2g", 1.0,
                     [](const ContactStats& s) { return s.unbalanced_force; }},
    StatisticsColumn{"inertial_number", "I", 8, "%*.2g", 1.0, [](const ContactStats& s) { return s.inertial_number; }},
    StatisticsColumn{"elastic_energy", nullptr, 0, nullptr, 1.0,
                     [](const ContactStats& s) { return s.elastic_energy; }},
    StatisticsColumn{"mean_stress", nullptr, 0, nullptr, 1.0, [](const ContactStats& s) { return s.mean_stress; }},
};

}  // namespace demctl
