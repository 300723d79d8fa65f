#include "contact_mechanics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <stdexcept>

#include "box_settle.h"
#include "mindlin_loading.h"

namespace dem::validation {

namespace {

std::ofstream open_csv(const std::filesystem::path& path) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path.string());
  out.precision(10);
  return out;
}

double sphere_mass(const Sphere& s) { return s.density * 4.0 / 3.0 * std::numbers::pi * std::pow(s.radius, 3); }

// E* of two bodies of the sphere's material (Randall 3.6).
double contact_modulus(const Sphere& s) { return s.youngs_modulus / (2.0 * (1.0 - s.poisson_ratio * s.poisson_ratio)); }

}  // namespace

Sphere maw_sphere() { return Sphere{}; }

ContactModelDef hertz_mindlin_model() {
  ContactModelDef m;
  m.law = ContactLaw::kHertzMindlin;
  return m;
}

ContactModelDef restitution_model(double restitution) {
  ContactModelDef m;
  m.law = ContactLaw::kLinearRestitution;
  m.linear = {1.0e5, 0.8e5};
  m.restitution = restitution;
  return m;
}

Verdict report_hertz_impact(const std::filesystem::path& out) {
  Verdict verdict;
  const Sphere s = maw_sphere();
  auto csv = open_csv(out / "hertz_impact.csv");
  csv << "case,speed,contact_duration,theory_duration,duration_error,peak_force,theory_peak_force,"
         "peak_force_error,restitution\n";
  std::printf("Hertz normal impact (Randall 5.3.1): steel sphere R = %.1f mm, E = %.0f GPa, nu = %.2f\n",
              1e3 * s.radius, 1e-9 * s.youngs_modulus, s.poisson_ratio);
  for (const char* which : {"sphere-wall", "sphere-sphere"}) {
    for (double v : {0.1, 0.4, 1.0}) {
      const bool wall = std::string(which) == "sphere-wall";
      const ImpactResult r = wall ? sphere_wall_impact(s, hertz_mindlin_model(), v, 0.0, kImpactTimeStepFraction)
                                  : sphere_sphere_impact(s, hertz_mindlin_model(), v, kImpactTimeStepFraction);
      const double m = wall ? sphere_mass(s) : 0.5 * sphere_mass(s);
      const double radius = wall ? s.radius : 0.5 * s.radius;
      // A wall of the same material: E* as for two spheres (Randall 3.6).
      const HertzTheory t = hertz_theory(m, radius, contact_modulus(s), v);
      const double de = r.contact_duration / t.contact_duration - 1.0;
      const double fe = r.peak_normal_force / t.peak_normal_force - 1.0;
      csv << which << ',' << v << ',' << r.contact_duration << ',' << t.contact_duration << ',' << de << ','
          << r.peak_normal_force << ',' << t.peak_normal_force << ',' << fe << ',' << r.restitution << '\n';
      std::printf(
          "  %-13s V = %.1f m/s: T_c %.4e s (theory %.4e, %+.3f%%), N_max %.4e N (theory %.4e, %+.3f%%), "
          "e = %.6f\n",
          which, v, r.contact_duration, t.contact_duration, 100.0 * de, r.peak_normal_force, t.peak_normal_force,
          100.0 * fe, r.restitution);
      // Randall 5.12: Hertz's duration and peak force within 1%; elastic and
      // undamped, the sphere leaves as fast as it came.
      char label[64];
      std::snprintf(label, sizeof label, "%s V = %.1f m/s", which, v);
      verdict.near(std::string(label) + ": contact duration / Hertz's", 1.0 + de, 1.0, 0.01);
      verdict.near(std::string(label) + ": peak force / Hertz's", 1.0 + fe, 1.0, 0.01);
      verdict.near(std::string(label) + ": restitution", r.restitution, 1.0, 1e-4);
    }
  }
  return verdict;
}

Verdict report_oblique_impact(const std::filesystem::path& out) {
  Verdict verdict;
  const Sphere s = maw_sphere();
  const double chi = maw_chi(s.poisson_ratio);
  const double boundary = 4.0 * chi - 1.0;
  int below_one = 0, middle = 0, sliding = 0;
  double min_restitution = 2.0, psi1_at_min = 0.0;
  double restitution_sum = 0.0, largest_e_error = 0.0, largest_psi2_error = 0.0;
  int angles = 0;
  auto csv = open_csv(out / "oblique_impact.csv");
  csv << "angle_deg,psi1,psi2,restitution,sliding_throughout,rigid_psi2,rigid_restitution\n";
  auto forces = open_csv(out / "oblique_impact_forces.csv");
  forces << "angle_deg,t_over_tc,tangential_over_mu_nmax,normal_over_nmax,sliding\n";
  std::printf("Oblique impact (Randall 5.4, Maw et al. 1976): V = 0.4 m/s, mu = %.2f, chi = %.4f, 4 chi - 1 = %.3f\n",
              s.friction, chi, 4.0 * chi - 1.0);
  std::printf("  angle  psi1     psi2     restitution  sliding throughout\n");
  for (double angle = 0.0; angle <= 90.0; angle += 2.5) {
    const double tangent = std::tan(angle * std::numbers::pi / 180.0);
    if (angle >= 90.0) {  // grazing: no normal velocity, no contact, nothing changes
      csv << angle << ",inf,inf,1,0,inf,1\n";
      std::printf("  %5.1f  (grazing: no contact, restitution 1)\n", angle);
      continue;
    }
    const ImpactResult r = sphere_wall_impact(s, hertz_mindlin_model(), 0.4, angle, kImpactTimeStepFraction);
    const double psi1 = maw_psi(s.poisson_ratio, s.friction, tangent);
    const double psi2 = maw_psi(s.poisson_ratio, s.friction, r.tangential_velocity_after / r.normal_velocity_after);
    // Rigid-body impulse theory, exact while the contact slides throughout:
    // the normal impulse 2 m V_n (elastic, e_n = 1), the tangential one mu
    // times it, so V_t' = V_t - 2 mu V_n and the contact point's slip falls
    // by 2 mu V_n (1 + 1/K^2): psi2 = psi1 - 4 chi (Maw et al.; Randall
    // 5.14-5.16), e = sqrt(cos^2 + (sin - 2 mu cos)^2) of the angle.
    const double a = angle * std::numbers::pi / 180.0;
    const double rigid_psi2 = psi1 - 4.0 * chi;
    const double rigid_e = std::hypot(std::cos(a), std::sin(a) - 2.0 * s.friction * std::cos(a));
    csv << angle << ',' << psi1 << ',' << psi2 << ',' << r.restitution << ',' << r.sliding_throughout << ','
        << rigid_psi2 << ',' << rigid_e << '\n';
    std::printf("  %5.1f  %7.3f  %+7.3f  %.5f      %s", angle, psi1, psi2, r.restitution,
                r.sliding_throughout ? "yes" : "no");
    if (r.sliding_throughout) {
      std::printf("   rigid body: psi2 %+7.3f, e %.5f", rigid_psi2, rigid_e);
      largest_e_error = std::max(largest_e_error, std::abs(r.restitution - rigid_e));
      largest_psi2_error = std::max(largest_psi2_error, std::abs(psi2 - rigid_psi2));
    }
    std::printf("\n");
    restitution_sum += r.restitution;
    ++angles;
    // Maw et al.'s three regimes (Randall 5.4): psi2 > 0 below psi1 = 1;
    // psi2 < 0 without sliding throughout up to 4 chi - 1; sliding
    // throughout (|T| = mu N at every step) above.
    char label[48];
    std::snprintf(label, sizeof label, "%.1f deg (psi1 %.2f)", angle, psi1);
    if (angle == 0.0) {
      verdict.near("normal impact: restitution", r.restitution, 1.0, 1e-4);
    } else if (psi1 < 1.0) {
      verdict.above(std::string(label) + ": psi2", psi2, 0.0);
      ++below_one;
    } else if (psi1 < boundary) {
      verdict.below(std::string(label) + ": psi2", psi2, 0.0);
      verdict.expect(std::string(label) + ": not sliding throughout", !r.sliding_throughout);
      ++middle;
    } else {
      verdict.expect(std::string(label) + ": sliding throughout", r.sliding_throughout);
      ++sliding;
    }
    if (angle > 0.0 && r.restitution < min_restitution) {
      min_restitution = r.restitution;
      psi1_at_min = psi1;
    }
    // Randall Fig. 5.9: T / (mu N_max) against t / T_c for a few angles.
    if (angle == 5.0 || angle == 20.0 || angle == 40.0 || angle == 60.0) {
      for (const ImpactSample& sample : r.history) {
        forces << angle << ',' << sample.time / r.contact_duration << ','
               << sample.tangential_force / (s.friction * r.peak_normal_force) << ','
               << sample.normal_force / r.peak_normal_force << ',' << sample.sliding << '\n';
      }
    }
  }
  const double mean_restitution = restitution_sum / angles;
  std::printf(
      "  sliding throughout against rigid-body impulse theory: largest |e - e_rigid| %.2e, "
      "|psi2 - (psi1 - 4 chi)| %.2e\n",
      largest_e_error, largest_psi2_error);
  std::printf(
      "  mean restitution over the %d angles 0-87.5 deg: %.4f (Randall's simulation 0.936, Maw et al.'s "
      "steel pucks 0.93)\n",
      angles, mean_restitution);
  // Where the contact slides throughout, rigid-body impulse theory is
  // exact: e and psi2 to the accuracy of the normal impact (e_n = 1 to 1e-6).
  verdict.below("sliding throughout: largest |e - rigid-body e|", largest_e_error, 1e-5);
  verdict.below("sliding throughout: largest |psi2 - (psi1 - 4 chi)|", largest_psi2_error, 1e-4);
  // Randall 5.4: "an average coefficient of restitution of 0.936 as compared
  // to 0.93 ... reported by Maw et al. (1981)".
  verdict.near("mean restitution over 0-87.5 deg against Randall's 0.936", mean_restitution, 0.936, 0.005);
  verdict.at_least("angles with psi1 < 1", below_one, 2);
  verdict.at_least("angles with 1 <= psi1 < 4 chi - 1", middle, 5);
  verdict.at_least("angles sliding throughout", sliding, 10);
  // The least restitution lies where sliding lasts throughout, as in Randall
  // Fig. 5.17 (50 deg; he relates it to psi1 of about 4 chi - 1).
  verdict.at_least("psi1 at the least restitution", psi1_at_min, boundary);
  verdict.at_least("2 (4 chi - 1) against psi1 at the least restitution", 2.0 * boundary, psi1_at_min);
  verdict.below("the least restitution", min_restitution, 0.95);
  return verdict;
}

Verdict report_restitution(const std::filesystem::path& out) {
  Verdict verdict;
  const Sphere s = maw_sphere();
  auto csv = open_csv(out / "restitution.csv");
  csv << "case,requested,measured,error\n";
  std::printf("Linear spring-dashpot restitution (Miyata et al. 2002, eq. 17), time step %.3f of critical:\n",
              kRestitutionTimeStepFraction);
  for (double e : {0.1, 0.5, 0.9}) {
    const ImpactResult wall = sphere_wall_impact(s, restitution_model(e), 0.4, 0.0, kRestitutionTimeStepFraction);
    const ImpactResult pair = sphere_sphere_impact(s, restitution_model(e), 0.4, kRestitutionTimeStepFraction);
    for (const auto& [name, r] : {std::pair{"sphere-wall", wall}, std::pair{"sphere-sphere", pair}}) {
      csv << name << ',' << e << ',' << r.restitution << ',' << r.restitution / e - 1.0 << '\n';
      std::printf("  %-13s e = %.1f: measured %.5f (%+.3f%%)\n", name, e, r.restitution,
                  100.0 * (r.restitution / e - 1.0));
      char label[64];
      std::snprintf(label, sizeof label, "%s e = %.1f: measured / requested", name, e);
      verdict.near(label, r.restitution / e, 1.0, 0.01);  // Miyata eq. 17 within 1%
    }
  }
  return verdict;
}

Verdict report_mindlin_loading(const std::filesystem::path& out) {
  Verdict verdict;
  const MindlinLoadingResult r = mindlin_constant_normal_force(2000);
  auto csv = open_csv(out / "mindlin_loading.csv");
  csv << "branch,displacement,simulated,theory\n";
  for (const MindlinPoint& p : r.points) {
    csv << p.branch << ',' << p.displacement << ',' << p.simulated << ',' << p.theory << '\n';
  }
  const VaryingNormalResult v = mindlin_varying_normal_force();
  std::printf("Mindlin-Deresiewicz loading (Randall 5.2): N = %.3f N, mu N = %.3f N, slip displacement %.4e m\n",
              r.normal_force, r.friction_force, r.slip_displacement);
  std::printf("  constant N, loading / unloading / reloading: largest error %.4f%% of mu N over %zu points\n",
              100.0 * r.largest_error, r.points.size());
  std::printf(
      "  varying N: largest |T|/(mu N) = %.6f, %d sliding steps, %d lagging steps with theta = 1 "
      "(largest error %.2e)\n",
      v.largest_ratio, v.sliding_steps, v.lagging_checks, v.largest_lag_error);
  verdict.near("normal force reached, N", r.normal_force, 88.0, 1e-6);
  verdict.near("points on the loading, unloading and reloading branches", static_cast<double>(r.points.size()), 60.0,
               0.0);
  // Each point within 2% of the closed form (or of 0.1 mu N near T = 0,
  // where a relative error means nothing).
  int off = 0;
  for (const MindlinPoint& p : r.points) {
    off += std::abs(p.simulated - p.theory) > 0.02 * std::max(std::abs(p.theory), 0.1 * r.friction_force) ? 1 : 0;
  }
  verdict.expect("points within 2% of the closed form", off == 0,
                 std::to_string(off) + " of " + std::to_string(r.points.size()) + " off");
  // The loop closes inside the first: unloading passed through zero and reloading went back up.
  if (r.points.size() == 60) {
    verdict.below("unloading's last force, N", r.points[39].simulated, 0.0);
    verdict.above("reloading's last force over 0.99 of loading's, N", r.points.back().simulated,
                  0.99 * r.points[19].simulated);
  }
  verdict.at_least("1 + 1e-12 against the largest |T| / (mu N) under varying N", 1.0 + 1e-12, v.largest_ratio);
  verdict.above("sliding steps under varying N", v.sliding_steps, 0);
  verdict.above("steps with dT < mu dN", v.lagging_checks, 100);
  verdict.below("largest error of those steps (Randall 3.98, theta = 1)", v.largest_lag_error, 1e-9);
  // A contact formed with its whole overlap in one step, then loaded under
  // a slowly rising N: on the constant-N curve of the current N (Randall
  // 3.4.1), pair and wall alike.
  for (const bool wall : {false, true}) {
    const FreshContactResult f = mindlin_fresh_contact_rising_normal_force(wall);
    for (const MindlinPoint& p : f.points) {
      csv << p.branch << ',' << p.displacement << ',' << p.simulated << ',' << p.theory << '\n';
    }
    const std::string which = wall ? "fresh wall contact" : "fresh pair contact";
    std::printf("  %s, N rising %.2f -> %.2f N to delta/delta* = %.3f: largest error %.4f%% of mu N%s\n", which.c_str(),
                f.initial_normal_force, f.final_normal_force, f.final_ratio, 100.0 * f.largest_error,
                f.sliding ? " (SLID)" : "");
    verdict.below(which + ": largest |T - mu N (1 - (1 - delta/delta*)^1.5)| / (mu N)", f.largest_error, 0.01);
    verdict.expect(which + ": no sliding below delta*", !f.sliding);
  }
  return verdict;
}

Verdict report_box_settle(const std::filesystem::path& case_file, const std::filesystem::path& out) {
  Verdict verdict;
  const BoxSettleResult r = box_settle(case_file);
  const EnergyBudget& e = r.energy;
  auto csv = open_csv(out / "box_settle.csv");
  csv << "particles,cycles,at_rest,weight,floor_force,side_walls_vertical,gravity_work,kinetic,strain,contact_damping,"
         "friction,global_damping,local_damping,residual\n";
  csv << r.particles << ',' << r.cycles << ',' << r.at_rest << ',' << r.weight << ',' << r.floor_force << ','
      << r.side_walls_vertical << ',' << e.gravity_work << ',' << e.kinetic << ',' << e.strain << ','
      << e.contact_damping << ',' << e.friction << ',' << e.global_damping << ',' << e.local_damping << ','
      << e.residual() << '\n';
  std::printf("Box settle: %d spheres, %llu cycles, %s\n", r.particles, static_cast<unsigned long long>(r.cycles),
              r.at_rest ? "at rest" : "NOT at rest within the stage's cycles");
  std::printf("  weight %.6e N, floor carries %.6e N (%+.4f%%), side walls %.2e N\n", r.weight, r.floor_force,
              100.0 * (r.floor_force / r.weight - 1.0), r.side_walls_vertical);
  std::printf(
      "  energy: gravity work %.6e J = kinetic %.3e + strain %.3e + dashpots %.6e + friction %.6e + "
      "local damping %.6e + global damping %.3e; residual %+.3e J (%+.4f%% of the potential energy drop)\n",
      e.gravity_work, e.kinetic, e.strain, e.contact_damping, e.friction, e.local_damping, e.global_damping,
      e.residual(), 100.0 * e.residual() / e.gravity_work);
  verdict.near("spheres", r.particles, 2000, 0);
  verdict.expect("at rest within the stage's cycles", r.at_rest);
  verdict.near("floor force / weight", r.floor_force / r.weight, 1.0, 0.005);
  verdict.below("|energy residual| / potential energy drop", std::abs(e.residual()) / e.gravity_work, 0.01);
  verdict.below("kinetic energy / potential energy drop", e.kinetic / e.gravity_work, 1e-6);
  return verdict;
}

}  // namespace dem::validation
