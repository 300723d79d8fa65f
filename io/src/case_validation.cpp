#include "dem/io/case_validation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <string_view>
#include <utility>

#include "case_fields.h"
#include "case_names.h"
#include "compression_output_checks.h"
#include "contact_model_checks.h"
#include "dem/math.h"
#include "field_path.h"
#include "format_number.h"
#include "problem_list.h"
#include "shape_checks.h"

namespace dem::io {
namespace {

std::string point(const proto::Vector& v, int dimension) {
  std::string text = '(' + format_number(v.x()) + ", " + format_number(v.y());
  if (dimension == 3) text += ", " + format_number(v.z());
  return text + ')';
}

// What a case must say to be the other dimension, for messages about fields
// that only mean something in one.
constexpr std::string_view kSet3d = "set dimension: 3 for a 3D case";

// One pass over a case. Cross-references (materials, walls, particle ids) are
// resolved against the definitions as they are read.
class CaseChecker {
 public:
  CaseChecker(const proto::Case& c, const ResourceLimits& limits) : case_(c), limits_(limits) { note_material_uses(); }

  std::vector<CaseProblem> run() {
    check_dimension();
    check_materials();
    check_contact_models(case_, {materials_, particle_materials_, wall_materials_}, problems_);
    check_particle_sources();
    check_walls();
    check_fields<DampingDef>(case_.damping(), "damping", problems_);
    check_periodic();
    check_time_step();
    vector("gravity", case_.gravity());
    if (case_.has_centripetal_gravity()) check_centripetal("centripetal_gravity", case_.centripetal_gravity());
    if (case_.has_box_control()) check_box_control("box_control", case_.box_control());
    check_stages();
    check_output();
    check_numerics();
    return problems_.take();
  }

 private:
  // 2 or 3; 0 when the case declares neither, and then the checks that
  // depend on the dimension are left out rather than guessed.
  void check_dimension() {
    const std::uint32_t declared = case_.dimension();
    if (declared == 0 || declared == 2) {
      dimension_ = 2;
    } else if (declared == 3) {
      dimension_ = 3;
    } else {
      problems_.add("dimension", "must be 2 or 3 (got " + std::to_string(declared) + "); leave it out for 2");
    }
    if (!proto::Case::PlanarParticle_IsValid(case_.planar_particle())) {
      problems_.add("planar_particle", "must be DISC or SPHERE (got " + std::to_string(case_.planar_particle()) + ")");
    } else {
      only_in_2d("planar_particle", case_.planar_particle() != proto::Case::DISC, "3D particles are spheres");
    }
  }

  // A finite vector, with z left at 0 in a 2D case.
  bool vector(const std::string& path, const proto::Vector& v) {
    if (!problems_.finite(path, v)) return false;
    if (dimension_ == 2 && v.z() != 0) {
      problems_.add(path + ".z", "must be 0 in a 2D case (got " + format_number(v.z()) + "); " + std::string(kSet3d));
      return false;
    }
    return true;
  }

  // A field that only means something in 3D, set in a 2D case (or the reverse).
  void only_in_3d(const std::string& path, bool set) {
    if (dimension_ == 2 && set) problems_.add(path, "is for 3D cases only (this case is 2D); " + std::string(kSet3d));
  }

  void only_in_2d(const std::string& path, bool set, std::string_view instead) {
    if (dimension_ == 3 && set) problems_.add(path, "is for 2D cases only (this case is 3D); " + std::string(instead));
  }

  // Which materials particles and walls are made of, needed before the
  // materials themselves are checked (density) and for the contact pairs.
  void note_material_uses() {
    for (const proto::ParticleSource& source : case_.particles()) {
      switch (source.source_case()) {
        case proto::ParticleSource::kParticle:
          particle_materials_.insert(source.particle().material());
          break;
        case proto::ParticleSource::kLattice:
          particle_materials_.insert(source.lattice().material());
          break;
        case proto::ParticleSource::kRandomPacking:
          particle_materials_.insert(source.random_packing().material());
          break;
        case proto::ParticleSource::kCsvFile:
          particle_materials_.insert(source.csv_file().material());
          break;
        case proto::ParticleSource::SOURCE_NOT_SET:
          break;
      }
    }
    for (const proto::Wall& wall : case_.wall()) wall_materials_.insert(wall.material());
  }

  void check_materials() {
    for (int i = 0; i < case_.material_size(); ++i) {
      const proto::Material& material = case_.material(i);
      const std::string path = indexed("material", i);
      if (material.name().empty()) {
        problems_.add(path + ".name",
                      "must not be empty (particles, walls and contact models refer to materials by name)");
      } else if (const auto [first, inserted] = materials_.emplace(material.name(), i); !inserted) {
        problems_.add(path + ".name", "duplicate material name " + in_quotes(material.name()) + " (" +
                                          indexed("material", first->second) + " has it too)");
      }
      check_fields<MaterialDef>(material, path, problems_);
      // 0 passed its rule (a wall material may leave it out); a particle's cannot.
      if (material.density() == 0 && particle_materials_.contains(material.name())) {
        problems_.add(path + ".density", "must be > 0 for a material particles are made of (got 0)");
      }
    }
  }

  int material_reference(const std::string& path, const std::string& name) {
    return find_material(problems_, materials_, path, name);
  }

  void check_particle_sources() {
    if (case_.particles_size() == 0) {
      problems_.add("particles",
                    "the case defines no particles; add a particle, lattice, random_packing or csv_file source");
      return;
    }
    for (int i = 0; i < case_.particles_size(); ++i) {
      const proto::ParticleSource& source = case_.particles(i);
      const std::string path = indexed("particles", i);
      switch (source.source_case()) {
        case proto::ParticleSource::kParticle:
          check_particle(path + ".particle", source.particle());
          break;
        case proto::ParticleSource::kLattice:
          check_lattice(path + ".lattice", source.lattice());
          break;
        case proto::ParticleSource::kRandomPacking:
          check_random_packing(path + ".random_packing", source.random_packing());
          break;
        case proto::ParticleSource::kCsvFile:
          check_particle_file(path + ".csv_file", source.csv_file());
          break;
        case proto::ParticleSource::SOURCE_NOT_SET:
          problems_.add(path, "is empty; set particle, lattice, random_packing or csv_file");
          break;
      }
    }
    if (const auto problem = particle_count_problem(particle_count_, limits_)) problems_.add("particles", *problem);
  }

  void check_particle(const std::string& path, const proto::Particle& particle) {
    vector(path + ".position", particle.position());
    if (particle.has_superquadric() && particle.has_ellipsoid()) {
      problems_.add(path, "sets both superquadric (2D) and ellipsoid (3D); keep the one of the case's dimension");
    }
    if (particle.has_superquadric()) {
      const proto::Superquadric& shape = particle.superquadric();
      if (check_shape(path + ".superquadric", shape, false)) note_radius(std::max(shape.a(), shape.b()));
    } else if (particle.has_ellipsoid()) {
      if (check_ellipsoid_shape(path + ".ellipsoid", particle.ellipsoid(), false)) {
        note_radius(largest_semi_axis(particle.ellipsoid()));
      }
    } else if (problems_.positive(path + ".radius", particle.radius())) {
      note_radius(particle.radius());
    }
    const bool shaped = particle.has_superquadric() || particle.has_ellipsoid();
    if (shaped && particle.radius() != 0) {
      problems_.add(path + ".radius", "is set by the shape (its bounding radius); leave it out");
    }
    shapes_.note(problems_, path, shaped, dimension_);
    material_reference(path + ".material", particle.material());
    vector(path + ".velocity", particle.velocity());
    check_spin(path + ".angular_velocity", particle.angular_velocity(), particle.has_angular_velocity_3d(),
               particle.angular_velocity_3d());
    particle_count_ = saturating_add(particle_count_, 1);
  }

  // A particle's bounding radius (its shape's largest semi-axis), for the contact tolerance.
  void note_radius(double radius) { largest_radius_ = std::max(largest_radius_, radius); }
  static double largest_semi_axis(const proto::Ellipsoid& shape) {
    const proto::Vector& axes = shape.semi_axes();
    return std::max({axes.x(), axes.y(), axes.z()});
  }

  // An angular velocity: a scalar about z in 2D, a vector in 3D.
  void check_spin(const std::string& path, double about_z, bool has_vector, const proto::Vector& spin) {
    if (problems_.finite(path, about_z)) {
      only_in_2d(path, about_z != 0, "set " + path.substr(path.rfind('.') + 1) + "_3d { x: ... y: ... z: ... }");
    }
    if (has_vector) {
      problems_.finite(path + "_3d", spin);
      only_in_3d(path + "_3d", true);
    }
  }

  // A superquadric: 2D only, of unit thickness, with sound numbers.
  bool check_shape(const std::string& path, const proto::Superquadric& shape, bool random_angle) {
    only_in_2d(path, true, "3D particles are spheres or ellipsoids (set ellipsoid)");
    if (case_.planar_particle() == proto::Case::SPHERE) {
      problems_.add(path, "superquadrics have unit thickness; leave planar_particle out (DISC)");
    }
    return check_superquadric(problems_, path, shape, random_angle);
  }

  // An ellipsoid: 3D only, with sound numbers.
  bool check_ellipsoid_shape(const std::string& path, const proto::Ellipsoid& shape, bool random_orientation) {
    if (dimension_ == 2) {
      problems_.add(path, "is for 3D cases only (this case is 2D); set dimension: 3, or superquadric for a 2D shape");
      return false;
    }
    return check_ellipsoid(problems_, path, shape, random_orientation);
  }

  void check_lattice(const std::string& path, const proto::Lattice& lattice) {
    shapes_.note(problems_, path, false, dimension_);
    material_reference(path + ".material", lattice.material());
    check_fields<LatticeDefT<3>>(lattice, path, problems_);  // a 2D lattice's rules are the same
    const bool radius_ok = !problems_.reported(path + ".radius");
    if (radius_ok) note_radius(lattice.radius());
    vector(path + ".origin", lattice.origin());
    if (lattice.columns() == 0) problems_.add(path + ".columns", "must be > 0");
    if (lattice.rows() == 0) problems_.add(path + ".rows", "must be > 0");
    // 0 means the default, one layer.
    only_in_3d(path + ".layers", lattice.layers() > 1);
    // 0 means the default, touching neighbours at 2 * radius.
    if (problems_.non_negative(path + ".spacing", lattice.spacing()) && radius_ok && lattice.spacing() > 0 &&
        lattice.spacing() < 2 * lattice.radius()) {
      problems_.add(path + ".spacing", "must be at least 2 * radius (" + format_number(2 * lattice.radius()) +
                                           ") so neighbours do not overlap (got " + format_number(lattice.spacing()) +
                                           "); leave it out for touching neighbours");
    }
    // Three uint32 factors overflow 64 bits together: the count saturates.
    particle_count_ = saturating_add(
        particle_count_,
        saturating_multiply(saturating_multiply(lattice.columns(), lattice.rows()), std::max(lattice.layers(), 1u)));
  }

  void check_random_packing(const std::string& path, const proto::RandomPacking& packing) {
    material_reference(path + ".material", packing.material());
    const bool min_ok = vector(path + ".min", packing.min());
    const bool max_ok = vector(path + ".max", packing.max());
    const bool three = dimension_ == 3;
    const double width = packing.max().x() - packing.min().x();
    const double height = packing.max().y() - packing.min().y();
    const double depth = packing.max().z() - packing.min().z();
    const bool box_ok = min_ok && max_ok && width > 0 && height > 0 && (!three || depth > 0);
    if (min_ok && max_ok && !box_ok) {
      problems_.add(path + ".max",
                    std::string(three ? "must exceed min along x, y and z" : "must lie above and to the right of min") +
                        " (min " + point(packing.min(), dimension_) + ", max " + point(packing.max(), dimension_) +
                        ")");
    }
    const double smallest_side = three ? std::min({width, height, depth}) : std::min(width, height);
    const std::string box =
        format_number(width) + " x " + format_number(height) + (three ? " x " + format_number(depth) : std::string());
    if (packing.size_size() == 0) {
      problems_.add(path + ".size", "lists no size classes; add at least one size { radius: ... count: ... }");
    }
    for (int j = 0; j < packing.size_size(); ++j) {
      const proto::SizeClass& size = packing.size(j);
      const std::string size_path = indexed(path + ".size", j);
      const bool shaped = size.has_superquadric() || size.has_ellipsoid();
      shapes_.note(problems_, size_path, shaped, dimension_);
      if (size.has_superquadric() && size.has_ellipsoid()) {
        problems_.add(size_path,
                      "sets both superquadric (2D) and ellipsoid (3D); keep the one of the case's dimension");
      }
      if (shaped && size.radius() != 0) {
        problems_.add(size_path + ".radius", "is set by the shape (its bounding radius); leave it out");
      }
      if (size.has_ellipsoid()) {
        // Placed by its bounding sphere (dem/packing.h), of the largest semi-axis.
        const double largest = largest_semi_axis(size.ellipsoid());
        const bool shape_ok = check_ellipsoid_shape(size_path + ".ellipsoid", size.ellipsoid(), true);
        if (shape_ok) note_radius(largest);
        if (shape_ok && box_ok && 2 * largest > smallest_side) {
          problems_.add(size_path + ".ellipsoid", "ellipsoids with a semi-axis of " + format_number(largest) +
                                                      " do not fit in the box (" + box + ")");
        }
      } else if (size.has_superquadric()) {
        // Placed by its bounding circle (dem/packing.h), at least as large
        // as the larger semi-axis.
        const proto::Superquadric& shape = size.superquadric();
        const bool shape_ok = check_shape(size_path + ".superquadric", shape, true);
        if (shape_ok) note_radius(std::max(shape.a(), shape.b()));
        if (shape_ok && box_ok && 2 * std::max(shape.a(), shape.b()) > smallest_side) {
          problems_.add(size_path + ".superquadric", "superquadrics with a semi-axis of " +
                                                         format_number(std::max(shape.a(), shape.b())) +
                                                         " do not fit in the box (" + box + ")");
        }
      } else if (problems_.positive(size_path + ".radius", size.radius())) {
        note_radius(size.radius());
        if (box_ok && 2 * size.radius() > smallest_side) {
          problems_.add(size_path + ".radius", std::string(three ? "spheres" : "discs") + " of radius " +
                                                   format_number(size.radius()) + " do not fit in the box (" + box +
                                                   ")");
        }
      }
      if (size.count() == 0) problems_.add(size_path + ".count", "must be > 0");
      particle_count_ = saturating_add(particle_count_, size.count());
    }
    if (box_ok) check_packing_room(path, packing);
    if (packing.max_attempts() > limits_.max_packing_attempts) {
      problems_.add(path + ".max_attempts", "must be at most " + std::to_string(limits_.max_packing_attempts) +
                                                " (got " + std::to_string(packing.max_attempts()) +
                                                "): a packing that cannot fit would try that many times a particle");
    }
  }

  // What a random packing will need before it is tried: the engine's
  // placement grid has a cell per largest diameter of the box, and the
  // particles' own area (2D) or volume (3D) must fit in it.
  void check_packing_room(const std::string& path, const proto::RandomPacking& packing) {
    const bool three = dimension_ == 3;
    double largest = 0.0;
    double solid = 0.0;  // m^2 or m^3
    for (const proto::SizeClass& size : packing.size()) {
      double radius = size.radius();
      if (size.has_ellipsoid()) {
        radius = largest_semi_axis(size.ellipsoid());
      } else if (size.has_superquadric()) {
        // Its bounding circle is at least this large (it reaches the
        // corners when n > 2), so the cells and the room are not underestimated.
        radius = std::max(size.superquadric().a(), size.superquadric().b());
      }
      if (!(radius > 0) || !std::isfinite(radius)) return;  // reported with the size class
      largest = std::max(largest, radius);
      solid += static_cast<double>(size.count()) *
               (three ? 4.0 / 3.0 * std::numbers::pi * radius * radius * radius : std::numbers::pi * radius * radius);
    }
    if (largest == 0.0) return;
    // Cells of the engine's size would be fewer; these are an upper bound.
    const double extent[3] = {packing.max().x() - packing.min().x(), packing.max().y() - packing.min().y(),
                              packing.max().z() - packing.min().z()};
    double cells = 1.0;
    double box = 1.0;
    for (int d = 0; d < dimension_; ++d) {
      cells *= std::floor(extent[d] / (2.0 * largest)) + 1.0;
      box *= extent[d];
    }
    if (!(cells <= static_cast<double>(limits_.max_packing_cells))) {
      problems_.add(path + ".max", "the box is " + format_number(cells) + " times the largest particle's diameter" +
                                       (three ? " cubed" : " squared") + ", more than the packing grid's limit of " +
                                       std::to_string(limits_.max_packing_cells) +
                                       " cells: shrink the box or place the particles in several packings");
    }
    // Bounding circles and spheres: shaped particles take at least this room.
    if (solid > box) {
      problems_.add(path + ".size", "the particles' " + std::string(three ? "volume" : "area") + " (" +
                                        format_number(solid) + ") exceeds the box's (" + format_number(box) +
                                        "): they cannot fit; enlarge the box or reduce the counts");
    }
  }

  // How many particles the file holds is known only when it is read (at
  // conversion), so checks that count particles stop here.
  void check_particle_file(const std::string& path, const proto::ParticleFile& file) {
    shapes_.note(problems_, path, false, dimension_);
    if (file.path().empty()) {
      problems_.add(path + ".path", std::string("must name a CSV file of particles (lines of ") +
                                        (dimension_ == 3 ? "x,y,z,r" : "x,y,r") +
                                        "), relative to the case file's directory");
    }
    material_reference(path + ".material", file.material());
    vector(path + ".offset", file.offset());
    count_known_ = false;
  }

  void check_walls() {
    for (int i = 0; i < case_.wall_size(); ++i) {
      const proto::Wall& wall = case_.wall(i);
      const std::string path = indexed("wall", i);
      if (wall.name().empty()) {
        problems_.add(path + ".name", "must not be empty (stages and outputs refer to walls by name)");
      } else if (const auto [first, inserted] = walls_.emplace(wall.name(), i); !inserted) {
        problems_.add(path + ".name", "duplicate wall name " + in_quotes(wall.name()) + " (" +
                                          indexed("wall", first->second) + " has it too)");
      }
      vector(path + ".point", wall.point());
      const bool direction_ok =
          wall.orientation_case() == proto::Wall::kDirection && non_zero_vector(path + ".direction", wall.direction());
      switch (wall.orientation_case()) {
        case proto::Wall::kDirection:
          break;
        case proto::Wall::kAngleDeg:
          problems_.finite(path + ".angle_deg", wall.angle_deg());
          only_in_2d(path + ".angle_deg", true, "set direction { x: ... y: ... z: ... } and direction2");
          break;
        case proto::Wall::ORIENTATION_NOT_SET:
          problems_.add(path, dimension_ == 3 ? "has no orientation; set direction { x: ... y: ... z: ... } and "
                                                "direction2 (the normal direction x direction2 faces the particles)"
                                              : "has no orientation; set direction { x: ... y: ... } or angle_deg");
          break;
      }
      if (wall.face_size() == 0) check_extent(path, "h1", wall.h1(), "h2", wall.h2());
      if (dimension_ == 3) {
        check_rectangle(path, wall, direction_ok);
        check_faces(path, wall);
      } else {
        only_in_3d(path + ".face", wall.face_size() > 0);
        only_in_3d(path + ".direction2", wall.has_direction2());
        only_in_3d(path + ".k1", wall.k1() != 0);
        only_in_3d(path + ".k2", wall.k2() != 0);
      }
      material_reference(path + ".material", wall.material());
      check_motion(path + ".motion", wall.motion());
    }
  }

  bool non_zero_vector(const std::string& path, const proto::Vector& v) {
    if (!vector(path, v)) return false;
    if (v.x() == 0 && v.y() == 0 && v.z() == 0) {
      problems_.add(path, "must not be zero-length");
      return false;
    }
    return true;
  }

  void check_extent(const std::string& path, std::string_view low_name, double low, std::string_view high_name,
                    double high) {
    const bool low_ok = problems_.finite(path + '.' + std::string(low_name), low);
    if (problems_.finite(path + '.' + std::string(high_name), high) && low_ok && high <= low) {
      problems_.add(path + '.' + std::string(high_name), "must be greater than " + std::string(low_name) + " (" +
                                                             format_number(high) + " <= " + format_number(low) + ")");
    }
  }

  // The second side of a 3D wall: v perpendicular to u, and its extent.
  void check_rectangle(const std::string& path, const proto::Wall& wall, bool direction_ok) {
    if (!wall.has_direction2()) {
      problems_.add(path + ".direction2",
                    "must be set for a 3D wall: the second side's direction, perpendicular to direction (the "
                    "normal direction x direction2 faces the particles)");
    } else if (non_zero_vector(path + ".direction2", wall.direction2()) && direction_ok) {
      const proto::Vector& u = wall.direction();
      const proto::Vector& v = wall.direction2();
      // Perpendicular to within what a case written with a few digits can
      // say; conversion removes the rest.
      const double cosine =
          (u.x() * v.x() + u.y() * v.y() + u.z() * v.z()) /
          std::sqrt((u.x() * u.x() + u.y() * u.y() + u.z() * u.z()) * (v.x() * v.x() + v.y() * v.y() + v.z() * v.z()));
      if (std::abs(cosine) > 1e-6) {
        // In hundredths of a degree: enough to see how far off they are.
        const double degrees = std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / std::numbers::pi;
        problems_.add(path + ".direction2", "must be perpendicular to direction (they are " +
                                                format_number(std::round(degrees * 100.0) / 100.0) + " degrees apart)");
      }
    }
    if (wall.face_size() == 0) check_extent(path, "k1", wall.k1(), "k2", wall.k2());
  }

  // A wall of triangle faces (Miyata et al. 2002, 2.4(2)): each face has
  // finite corners not on one line; the faces replace the rectangle's extent.
  void check_faces(const std::string& path, const proto::Wall& wall) {
    if (wall.face_size() == 0) return;
    for (const auto& [name, value] :
         {std::pair{".h1", wall.h1()}, {".h2", wall.h2()}, {".k1", wall.k1()}, {".k2", wall.k2()}}) {
      if (value != 0) {
        problems_.add(path + name,
                      "must be left out for a wall of faces (their extent along direction and "
                      "direction2 replaces the rectangle's)");
      }
    }
    for (int k = 0; k < wall.face_size(); ++k) {
      const proto::Triangle& face = wall.face(k);
      const std::string face_path = indexed(path + ".face", k);
      const bool i_ok = problems_.finite(face_path + ".i", face.i());
      const bool j_ok = problems_.finite(face_path + ".j", face.j());
      const bool k_ok = problems_.finite(face_path + ".k", face.k());
      if (!(i_ok && j_ok && k_ok)) continue;
      const Vec3 a(face.i().x(), face.i().y(), face.i().z());
      const Vec3 b(face.j().x(), face.j().y(), face.j().z());
      const Vec3 c(face.k().x(), face.k().y(), face.k().z());
      // Relative to the face's size, as the engine checks it.
      const double scale = std::max((b - a).squaredNorm(), (c - a).squaredNorm());
      if (!((b - a).cross(c - a).norm() > 1e-9 * scale)) {
        problems_.add(face_path, "is degenerate: its corners i, j, k lie on one line (or coincide)");
      }
    }
    // The faces' extent along direction and direction2 gives the wall's
    // (its centre and half-sizes for eccentricities): it must not be flat.
    const Vec3 u(wall.direction().x(), wall.direction().y(), wall.direction().z());
    const Vec3 v(wall.direction2().x(), wall.direction2().y(), wall.direction2().z());
    if (!(u.allFinite() && v.allFinite() && u.norm() > 0 && v.norm() > 0)) return;
    const auto extent = [&](const Vec3& axis) {
      double low = std::numeric_limits<double>::infinity(), high = -low;
      for (const proto::Triangle& face : wall.face()) {
        for (const proto::Vector* corner : {&face.i(), &face.j(), &face.k()}) {
          const double along = Vec3(corner->x(), corner->y(), corner->z()).dot(axis.normalized());
          low = std::min(low, along);
          high = std::max(high, along);
        }
      }
      return high - low;
    };
    if (!(extent(u) > 0) || !(extent(v) > 0)) {
      problems_.add(path + ".face",
                    "span nothing along direction or direction2; those should lie along the faces "
                    "(the normal, direction x direction2, faces the particles)");
    }
  }

  void check_motion(const std::string& path, const proto::WallMotion& motion) {
    vector(path + ".velocity", motion.velocity());
    check_spin(path + ".angular_velocity", motion.angular_velocity(), motion.has_angular_velocity_3d(),
               motion.angular_velocity_3d());
    check_fields<WallMotionT<3>>(motion, path,
                                 problems_);  // the servo's numbers when set; a 2D motion's rules are the same
    if (!motion.has_servo()) return;
    const proto::Vector& v = motion.velocity();
    const proto::Vector& spin = motion.angular_velocity_3d();
    if (v.x() != 0 || v.y() != 0 || v.z() != 0 || motion.angular_velocity() != 0 || spin.x() != 0 || spin.y() != 0 ||
        spin.z() != 0) {
      problems_.add(path, "sets both servo and velocity/angular_velocity; the servo replaces them, so drop one");
    }
  }

  void check_time_step() { check_time_step("time_step", case_.time_step(), false); }

  // A stage's time step replaces the case's: it must say what it is.
  void check_time_step(const std::string& path, const proto::TimeStep& step, bool in_stage) {
    const double fraction = step.fraction();
    // 0 means the default, 0.1.
    if (problems_.finite(path + ".fraction", fraction) && fraction != 0 && !(fraction > 0 && fraction <= 1)) {
      problems_.add(path + ".fraction",
                    "must be in (0, 1] (got " + format_number(fraction) + "); leave it out for the default 0.1");
    }
    problems_.non_negative(path + ".fixed", step.fixed());
    if (in_stage && fraction == 0 && step.fixed() == 0) {
      problems_.add(path, "set fraction (of the critical step) or fixed (s)");
    }
  }

  void check_stages() {
    // Which walls are servo-controlled as the programme goes, for servo_tolerance.
    std::vector<bool> servo(case_.wall_size());
    for (int i = 0; i < case_.wall_size(); ++i) servo[i] = case_.wall(i).motion().has_servo();

    box_controlled_ = case_.has_box_control();
    for (int i = 0; i < case_.stage_size(); ++i) {
      const proto::Stage& stage = case_.stage(i);
      const std::string path = indexed("stage", i);
      if (stage.has_box_control()) box_controlled_ = true;
      if (stage.release_box_control()) box_controlled_ = false;
      std::map<std::string, int, std::less<>> commanded;
      for (int j = 0; j < stage.wall_size(); ++j) {
        const proto::WallCommand& command = stage.wall(j);
        const std::string command_path = indexed(path + ".wall", j);
        const auto wall = walls_.find(command.wall());
        if (command.wall().empty()) {
          problems_.add(command_path + ".wall", "must name a wall " + defined_names(walls_));
        } else if (wall == walls_.end()) {
          problems_.add(command_path + ".wall",
                        "unknown wall " + in_quotes(command.wall()) + ' ' + defined_names(walls_));
        } else if (const auto [first, inserted] = commanded.emplace(command.wall(), j); !inserted) {
          problems_.add(command_path + ".wall", "wall " + in_quotes(command.wall()) + " is already commanded by " +
                                                    indexed(path + ".wall", first->second));
        } else {
          servo[wall->second] = command.motion().has_servo();
        }
        check_motion(command_path + ".motion", command.motion());
      }
      if (stage.cycles() == 0) {
        problems_.add(path + ".cycles", "must be > 0 (the stage's length, or its cap when until is set)");
      }
      if (stage.has_trim()) check_trim(path + ".trim", stage.trim());
      if (stage.has_place_wall()) {
        find_wall(problems_, walls_, path + ".place_wall.wall", stage.place_wall().wall());
        problems_.non_negative(path + ".place_wall.clearance", stage.place_wall().clearance());
      }
      for (int j = 0; j < stage.remove_wall_size(); ++j) {
        find_wall(problems_, walls_, indexed(path + ".remove_wall", j), stage.remove_wall(j));
      }
      if (stage.has_box_control()) check_box_control(path + ".box_control", stage.box_control());
      if (stage.has_box_control() && stage.release_box_control()) {
        problems_.add(path + ".release_box_control", "a stage sets box_control or releases it, not both");
      }
      if (stage.has_damping()) check_fields<DampingDef>(stage.damping(), path + ".damping", problems_);
      if (stage.has_body_force()) {
        vector(path + ".body_force.gravity", stage.body_force().gravity());
        if (stage.body_force().has_centripetal()) {
          check_centripetal(path + ".body_force.centripetal", stage.body_force().centripetal());
        }
      }
      if (stage.has_time_step()) check_time_step(path + ".time_step", stage.time_step(), true);
      for (int j = 0; j < stage.friction_size(); ++j) {
        const std::string friction = indexed(path + ".friction", j);
        find_material(problems_, materials_, friction + ".material", stage.friction(j).material());
        problems_.non_negative(friction + ".friction", stage.friction(j).friction());
      }
      if (stage.has_until()) {
        check_until(path, stage, std::ranges::count(servo, true) > 0);
      }
    }
  }

  // Element-test control of a box of walls: one axis per dimension, each
  // naming its two walls and what drives them; the engine checks that the
  // walls face along their axes when it builds the world.
  void check_box_control(const std::string& path, const proto::BoxControl& box) {
    if (box.axis_size() != dimension_ && dimension_ != 0) {
      problems_.add(path + ".axis", "must list " + std::to_string(dimension_) + " axes (x then y" +
                                        (dimension_ == 3 ? " then z" : "") + ") in a " + std::to_string(dimension_) +
                                        "D case (got " + std::to_string(box.axis_size()) + ")");
    }
    int path_axes = 0;
    bool servo = false;
    for (int i = 0; i < box.axis_size(); ++i) {
      const proto::BoxAxis& axis = box.axis(i);
      const std::string axis_path = indexed(path + ".axis", i);
      find_wall(problems_, walls_, axis_path + ".lower_wall", axis.lower_wall());
      find_wall(problems_, walls_, axis_path + ".upper_wall", axis.upper_wall());
      if (!axis.lower_wall().empty() && axis.lower_wall() == axis.upper_wall()) {
        problems_.add(axis_path + ".upper_wall",
                      "must differ from lower_wall (both are " + in_quotes(axis.lower_wall()) + ")");
      }
      check_fields<BoxAxisDef>(axis, axis_path, problems_);  // the strain rate or stress, whichever is set
      switch (axis.control_case()) {
        case proto::BoxAxis::kStrainRate:
          break;
        case proto::BoxAxis::kStress:
          servo = true;
          break;
        case proto::BoxAxis::kStressPath:
          if (!axis.stress_path()) problems_.add(axis_path + ".stress_path", "must be true when set");
          ++path_axes;
          servo = true;
          break;
        case proto::BoxAxis::CONTROL_NOT_SET:
          problems_.add(axis_path,
                        "says nothing of what drives it; set strain_rate (1/s), stress (Pa) or "
                        "stress_path: true");
          break;
      }
    }
    if (servo) {
      problems_.positive(path + ".gain", box.gain());
      problems_.positive(path + ".max_speed", box.max_speed());
    }
    switch (box.path_case()) {
      case proto::BoxControl::kConstantMeanStress:
        problems_.positive(path + ".constant_mean_stress", box.constant_mean_stress());
        break;
      case proto::BoxControl::kStressRatio:
        if (problems_.finite(path + ".stress_ratio", box.stress_ratio()) && !(box.stress_ratio() >= 1.0)) {
          problems_.add(path + ".stress_ratio",
                        "must be >= 1 (sigma_1 / sigma_3; got " + format_number(box.stress_ratio()) + ")");
        }
        break;
      case proto::BoxControl::PATH_NOT_SET:
        if (path_axes > 0) {
          problems_.add(path,
                        "an axis follows the stress path, but no path is set; set constant_mean_stress or "
                        "stress_ratio");
        }
        break;
    }
    if (box.continuum() && case_.has_periodic()) {
      problems_.add(path + ".continuum",
                    "a continuum field carries the particles across a deforming box; a periodic cell does not "
                    "deform (leave periodic out or continuum false)");
    }
    if (box.path_case() != proto::BoxControl::PATH_NOT_SET) {
      if (path_axes == 0) {
        problems_.add(path, "sets a stress path, but no axis follows it; set stress_path: true on an axis");
      } else if (path_axes == box.axis_size()) {
        problems_.add(path, "every axis follows the stress path; the path needs an axis driven otherwise");
      }
    }
  }

  // Miyata et al. (2002) eq. 60: a sine of this amplitude and wavelength
  // about the height (case_rules.h); a smooth cut needs no wavelength.
  void check_trim(const std::string& path, const proto::Trim& trim) {
    check_fields<TrimDef>(trim, path, problems_);
    if (!problems_.reported(path + ".amplitude") && trim.amplitude() > 0) {
      if (problems_.finite(path + ".wavelength", trim.wavelength()) && !(trim.wavelength() > 0)) {
        problems_.add(path + ".wavelength", "must be > 0 for a rough surface (amplitude " +
                                                format_number(trim.amplitude()) + "; got " +
                                                format_number(trim.wavelength()) + ")");
      }
    } else {
      problems_.non_negative(path + ".wavelength", trim.wavelength());
    }
  }

  // Randall's centripetal gravity field (6.4.2).
  void check_centripetal(const std::string& path, const proto::CentripetalGravity& field) {
    vector(path + ".centre", field.centre());
    check_fields<CentripetalGravityT<3>>(field, path, problems_);  // a 2D field's rules are the same
  }

  void check_threshold(const std::string& path, const proto::WallThreshold& threshold) {
    find_wall(problems_, walls_, path + ".wall", threshold.wall());
    problems_.finite(path + ".value", threshold.value());
  }

  void check_until(const std::string& stage_path, const proto::Stage& stage, bool any_servo) {
    const proto::Until& until = stage.until();
    const std::string path = stage_path + ".until";
    if (!until.has_kinetic_energy_below() && !until.has_out_of_balance_below() &&
        !until.has_kinetic_to_elastic_below() && !until.has_unbalanced_force_below() && !until.has_servo_tolerance() &&
        !until.has_wall_stress_above() && !until.has_wall_settlement_above() && !until.has_deviator_strain_above() &&
        !until.has_region_out_of_balance_below()) {
      problems_.add(path,
                    "sets no stop condition; set kinetic_energy_below, out_of_balance_below, "
                    "kinetic_to_elastic_below, unbalanced_force_below, servo_tolerance, wall_stress_above, "
                    "wall_settlement_above, deviator_strain_above or region_out_of_balance_below, or leave until "
                    "out");
    }
    if (until.has_region_out_of_balance_below()) {
      const proto::RegionThreshold& threshold = until.region_out_of_balance_below();
      const std::string region_path = path + ".region_out_of_balance_below";
      const auto& regions = case_.output().region();
      if (std::ranges::none_of(regions, [&](const auto& r) { return r.name() == threshold.region(); })) {
        std::string names;
        for (const proto::MeasurementRegion& r : regions) names += (names.empty() ? "" : ", ") + in_quotes(r.name());
        problems_.add(region_path + ".region", "names no output.region (" +
                                                   (names.empty() ? std::string("the case defines none") : names) +
                                                   "; got " + in_quotes(threshold.region()) + ")");
      }
      problems_.positive(region_path + ".value", threshold.value());
    }
    check_fields<StopConditions>(until, path, problems_);
    if (until.has_deviator_strain_above() && !box_controlled_) {
      problems_.add(path + ".deviator_strain_above", "no box control is set during this stage (box_control)");
    }
    if (until.has_wall_stress_above()) check_threshold(path + ".wall_stress_above", until.wall_stress_above());
    if (until.has_wall_settlement_above()) {
      check_threshold(path + ".wall_settlement_above", until.wall_settlement_above());
    }
    if (until.has_servo_tolerance() && !problems_.reported(path + ".servo_tolerance") && !any_servo &&
        !box_controlled_) {
      problems_.add(path + ".servo_tolerance", "no wall is servo-controlled during this stage");
    }
    if (stage.cycles() > 0 && until.min_cycles() > stage.cycles()) {
      problems_.add(path + ".min_cycles", "must not exceed the stage's cycles (" + std::to_string(until.min_cycles()) +
                                              " > " + std::to_string(stage.cycles()) + ")");
    }
  }

  void check_output() {
    if (case_.output().has_compression()) {
      check_compression_output(case_.output().compression(), walls_, problems_);
    }
    check_regions();
    const bool count_known =
        count_known_ && particle_count_ <= static_cast<std::uint64_t>(std::numeric_limits<std::int32_t>::max());
    std::map<std::string, int, std::less<>> names;
    for (int i = 0; i < case_.output().probe_size(); ++i) {
      const proto::ContactProbe& probe = case_.output().probe(i);
      const std::string path = indexed("output.probe", i);
      if (probe.name().empty()) {
        problems_.add(path + ".name", "must not be empty (it labels the probe's rows in probes.csv)");
      } else if (const auto [first, inserted] = names.emplace(probe.name(), i); !inserted) {
        problems_.add(path + ".name", "duplicate probe name " + in_quotes(probe.name()) + " (" +
                                          indexed("output.probe", first->second) + " has it too)");
      }
      const auto check_id = [&](const std::string& id_path, std::uint32_t id) {
        if (!count_known || id < particle_count_) return;
        problems_.add(id_path, no_particle_with_id(id, particle_count_));
      };
      check_id(path + ".first", probe.first());
      check_id(path + ".second", probe.second());
      if (probe.first() == probe.second()) {
        problems_.add(path + ".second", "must differ from first (both are " + std::to_string(probe.first()) + ")");
      }
    }
  }

  // Measurement regions (regions.csv): named, and a box or a ball that
  // encloses something.
  void check_regions() {
    std::map<std::string, int, std::less<>> names;
    for (int i = 0; i < case_.output().region_size(); ++i) {
      const proto::MeasurementRegion& region = case_.output().region(i);
      const std::string path = indexed("output.region", i);
      if (region.name().empty()) {
        problems_.add(path + ".name", "must not be empty (it labels the region's rows in regions.csv)");
      } else if (const auto [first, inserted] = names.emplace(region.name(), i); !inserted) {
        problems_.add(path + ".name", "duplicate region name " + in_quotes(region.name()) + " (" +
                                          indexed("output.region", first->second) + " has it too)");
      }
      switch (region.shape_case()) {
        case proto::MeasurementRegion::kWhole:
          if (!region.whole()) problems_.add(path + ".whole", "must be true when set");
          break;
        case proto::MeasurementRegion::kBox: {
          const proto::Box& box = region.box();
          if (!vector(path + ".box.min", box.min()) || !vector(path + ".box.max", box.max())) break;
          const std::pair<double, double> sides[] = {
              {box.min().x(), box.max().x()}, {box.min().y(), box.max().y()}, {box.min().z(), box.max().z()}};
          for (int d = 0; d < (dimension_ == 3 ? 3 : 2); ++d) {
            const char axis = "xyz"[d];
            if (!(sides[d].second > sides[d].first)) {
              problems_.add(path + ".box.max." + axis, "must be greater than box.min." + std::string(1, axis) + " (" +
                                                           format_number(sides[d].second) +
                                                           " <= " + format_number(sides[d].first) + ")");
            }
          }
          break;
        }
        case proto::MeasurementRegion::kBall:
          vector(path + ".ball.centre", region.ball().centre());
          problems_.positive(path + ".ball.radius", region.ball().radius());
          break;
        case proto::MeasurementRegion::SHAPE_NOT_SET:
          problems_.add(path,
                        "has no shape; set whole: true, box { min ... max ... } or ball { centre ... radius ... }");
          break;
      }
    }
  }

  void check_periodic() {
    if (!case_.has_periodic()) return;
    const proto::Periodic& p = case_.periodic();
    only_in_3d("periodic.z", p.z());
    if (!vector("periodic.min", p.min()) || !vector("periodic.max", p.max())) return;
    if (!p.x() && !p.y() && !p.z()) problems_.add("periodic", "names no periodic axis; set x, y or z to true");
    const std::pair<bool, const char*> axes[] = {{p.x(), "x"}, {p.y(), "y"}, {p.z(), "z"}};
    const double lo[] = {p.min().x(), p.min().y(), p.min().z()}, hi[] = {p.max().x(), p.max().y(), p.max().z()};
    for (int d = 0; d < 3; ++d) {
      if (axes[d].first && !(hi[d] > lo[d])) {
        problems_.add(std::string("periodic.max.") + axes[d].second,
                      "must exceed periodic.min." + std::string(axes[d].second) + " (" + format_number(hi[d]) +
                          " <= " + format_number(lo[d]) + ")");
      }
    }
  }

  // The tolerance against the largest particle the sources give: all of
  // them unless a particle file's radii are unknown until conversion
  // reads it (case_conversion.cpp). Without a sound particle the sources
  // have their own problems.
  void check_numerics() {
    const double tolerance = case_.numerics().contact_tolerance();
    if (problems_.non_negative("numerics.contact_tolerance", tolerance) && count_known_ && largest_radius_ > 0) {
      if (const auto problem = contact_tolerance_problem(tolerance, largest_radius_)) {
        problems_.add("numerics.contact_tolerance", *problem);
      }
    }
    if (const auto problem = thread_count_problem(case_.numerics().threads(), limits_)) {
      problems_.add("numerics.threads", *problem);
    }
  }

  const proto::Case& case_;
  const ResourceLimits& limits_;
  ProblemList problems_;
  NameIndex materials_;
  NameIndex walls_;
  std::set<std::string> particle_materials_;
  std::set<std::string> wall_materials_;
  std::uint64_t particle_count_ = 0;
  bool count_known_ = true;      // false once a csv_file source holds an unknown number (and unknown radii)
  double largest_radius_ = 0.0;  // m, of the particles whose size passed its checks
  ShapeMix shapes_;
  int dimension_ = 0;            // 2 or 3; 0 until known (or when the case declares neither)
  bool box_controlled_ = false;  // a box control is set in the stage being checked
};

}  // namespace

std::vector<CaseProblem> find_case_problems(const proto::Case& message, const ResourceLimits& limits) {
  return CaseChecker(message, limits).run();
}

void validate_case(const proto::Case& message, const CaseSource& source, const ResourceLimits& limits) {
  const std::vector<CaseProblem> problems = find_case_problems(message, limits);
  if (problems.empty()) return;
  std::vector<std::string> lines;
  lines.reserve(problems.size());
  for (const CaseProblem& problem : problems) {
    lines.push_back(describe_problem(source, problem.path, problem.message));
  }
  throw CaseError(std::move(lines));
}

}  // namespace dem::io
