// The service benchmarks' case (bench_service.cpp, bench_responsiveness.cpp):
// a square lattice of discs 0.5% closer than touching, walled in below and
// at the sides, so every neighbour pair is a contact from the first cycle,
// at rest under its own springs.
#pragma once

#include <sstream>
#include <string>

namespace dem::bench {

enum class LatticeTop {
  kOpen,
  kWall,   // a wall "top" that stays put
  kPlate,  // a wall "plate" moving down at 1 cm/s: a loading test
};

inline std::string lattice_case(int columns, int rows, LatticeTop top) {
  constexpr double r = 0.01;
  constexpr double spacing = 2 * r * 0.995;
  std::ostringstream text;
  text.precision(17);
  text << "name: \"lattice_" << columns << "x" << rows << "\"\n"
       << "material { name: \"disc\" density: 2650 friction: 0.5 }\n"
       << "material { name: \"wall\" friction: 0.3 }\n"
       << "contact_model { linear { normal_stiffness: 1e7 shear_stiffness: 0.7e7 } }\n"
       << "damping { contact_beta: 1e-5 global_alpha: 5 }\n"
       << "time_step { fraction: 0.2 }\n";
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      text << "particles { particle { position { x: " << r + i * spacing << " y: " << r + j * spacing
           << " } radius: 0.01 material: \"disc\" } }\n";
    }
  }
  const double width = 2 * r + (columns - 1) * spacing;
  const double height = 2 * r + (rows - 1) * spacing;
  text << "wall { name: \"bottom\" point { x: " << width / 2
       << " y: 0 } angle_deg: 0 h1: -1 h2: 1 material: \"wall\" }\n"
       << "wall { name: \"right\" point { x: " << width << " y: " << height / 2
       << " } angle_deg: 90 h1: -1 h2: 1 material: \"wall\" }\n"
       << "wall { name: \"left\" point { x: 0 y: " << height / 2
       << " } angle_deg: 270 h1: -1 h2: 1 material: \"wall\" }\n";
  if (top == LatticeTop::kWall) {
    text << "wall { name: \"top\" point { x: " << width / 2 << " y: " << height
         << " } angle_deg: 180 h1: -1 h2: 1 material: \"wall\" }\n";
  } else if (top == LatticeTop::kPlate) {
    text << "wall { name: \"plate\" point { x: " << width / 2 << " y: " << height
         << " } angle_deg: 180 h1: -1 h2: 1 material: \"wall\" motion { velocity { y: -0.01 } } }\n";
  }
  return text.str();
}

}  // namespace dem::bench
