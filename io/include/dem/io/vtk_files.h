// ParaView's view of a world: three VTK XML PolyData files (.vtp) made from
// a snapshot (the engine's whole state as plain data, dem/snapshot.h), so a
// running world, a saved snapshot file and the end of a run all give the
// same files. 2D worlds lie in the plane z = 0. Units are SI.
//
// particles.vtp  a vertex per particle at its centre. Point data:
//   id, material (ids in the case's order; field data material_names holds
//   their names), radius (m; a shaped particle's bounding radius),
//   velocity (m/s), angular_velocity (rad/s; 2D: about z), coordination
//   (touching contacts with particles and walls), orientation (unit
//   quaternion w, x, y, z; 2D: the rotation about z), and the true shape:
//   semi_axes (m: a superquadric's a, b, 0; an ellipsoid's a1, a2, a3; a
//   disc's R, R, 0 and a sphere's R, R, R), exponent (a superquadric's n; 2
//   for discs, spheres and ellipsoids) and shape_tensor (9 components, VTK's
//   order: components 3j..3j+2 are the particle's body axis j scaled by its
//   semi-axis, so ParaView's Tensor Glyph with eigenvalue extraction off
//   draws a unit sphere as the particle's ellipse or ellipsoid).
// contacts.vtp  a line per touching contact, from the first particle's
//   centre to the second's (across a periodic boundary: to its nearest
//   image) or, against a wall, to the contact point. Cell data:
//   normal_force and shear_force (N; compressive positive; the shear force
//   signed in 2D, its magnitude in 3D), sliding (0/1), first, second (a
//   particle id, or a wall id when wall_contact is 1), wall_contact,
//   overlap (m), normal (unit, first to second) and point (the contact
//   point, m).
// walls.vtp  2D: a line per wall segment; 3D: a quadrilateral per
//   rectangle, a triangle per face of a wall made of faces. Cell data
//   (per cell, so repeated over a wall's faces): wall (its id), name,
//   normal_force (N), contacts, force (N) and velocity (m/s, the motion
//   over the last cycle).
// Each file's field data holds TimeValue (s, ParaView's time) and cycle.
#pragma once

#include <filesystem>

#include "dem/snapshot.h"

namespace dem::io {

// Each writes its file (creating the directory) and throws
// std::runtime_error naming the file when it cannot.
template <int Dim>
void write_particles_vtp(const std::filesystem::path& file, const WorldSnapshotT<Dim>& snapshot);
template <int Dim>
void write_contacts_vtp(const std::filesystem::path& file, const WorldSnapshotT<Dim>& snapshot);
template <int Dim>
void write_walls_vtp(const std::filesystem::path& file, const WorldSnapshotT<Dim>& snapshot);

extern template void write_particles_vtp(const std::filesystem::path&, const WorldSnapshotT<2>&);
extern template void write_particles_vtp(const std::filesystem::path&, const WorldSnapshotT<3>&);
extern template void write_contacts_vtp(const std::filesystem::path&, const WorldSnapshotT<2>&);
extern template void write_contacts_vtp(const std::filesystem::path&, const WorldSnapshotT<3>&);
extern template void write_walls_vtp(const std::filesystem::path&, const WorldSnapshotT<2>&);
extern template void write_walls_vtp(const std::filesystem::path&, const WorldSnapshotT<3>&);

}  // namespace dem::io
