// Spheres against walls of several faces in the DEM solver (docs/dem.md, "Walls of several
// faces"):
// - a sphere settling under gravity into the concave 90-degree corner of a mesh (triangles half
//   its radius) and of a box container touches both faces and comes to rest: the wall forces
//   balance its weight to 1e-6 (relative; measured 1.3e-16 and 0). With one contact per wall
//   (the nearer face only) it keeps one contact and does not come to rest.
// - a sphere rolling down an incline made of a mesh of small triangles moves as on a plane: its
//   springs pass from triangle to triangle, so the distance after 0.2 s equals the plane's to
//   1e-9 (relative; measured 0); restarting the springs at each triangle leaves it 8.1e-5 off.
// - spheres rolling over a mesh and into the corner of a box container give the same result
//   resumed from a checkpoint, bit for bit; 343 of them (above the grains that run in parallel)
//   give the same result on one and two threads, bit for bit.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <numbers>

#include "core/state_archive.hpp"
#include "dem/dem_setups.hpp"
#include "dem/dem_solver.hpp"
#include "geometry/box_container_surface.hpp"
#include "geometry/grid_meshes.hpp"
#include "geometry/mesh_shell_surface.hpp"

namespace partimix::dem {
namespace {

using test::add_plane;
using test::box;

constexpr double kRadius = 0.002;
constexpr double kDensity = 2500.0;

Config one_species(double restitution, double friction) {
  Config config;
  config.species = {Species{"grain", kDensity, {1.0e7, 0.3}, std::nullopt}};
  config.particle_interactions = {Interaction{restitution, friction, 0.0}};
  config.wall_interactions = {Interaction{restitution, friction, 0.0}};
  return config;
}

void add_wall(Config& config, std::shared_ptr<const geometry::Surface> surface) {
  config.walls.push_back({std::move(surface), {}, {2.0e11, 0.3}, {}});
}

std::shared_ptr<const geometry::Surface> mesh_corner() {
  return std::make_shared<geometry::MeshShellSurface>(geometry::testing::corner_mesh(0.001, 12));
}

std::shared_ptr<const geometry::Surface> box_corner() {
  return std::make_shared<geometry::BoxContainerSurface>(
      Vec3::Zero(), Vec3::Constant(0.012), std::vector<geometry::Face>{geometry::Face{2, 1}});
}

// A sphere dropped near the corner x = 0, z = 0 with gravity pointing into it, settled for 0.2
// s: |F_walls + m g| / (m g) and the number of its wall contacts.
std::pair<double, double> settle_in_corner(std::shared_ptr<const geometry::Surface> wall) {
  Config config = one_species(0.3, 0.3);
  add_wall(config, std::move(wall));
  const Vec3 gravity = 9.81 * Vec3(-1.0, 0.0, -1.0).normalized();
  ParticleStore store;
  const Vec3 start(kRadius + 2e-4, 0.0031, kRadius + 5e-4);
  DemSolver solver(store, box(0.02), config, gravity, Grains{{start}, {kRadius}, {0}, {}, {}, {}});
  for (double t = 0.0; t < 0.2; t += solver.stable_dt())
    solver.step(solver.stable_dt());
  const Vec3 weight = store.mass()[0] * gravity;
  const Vec3& walls = store.find_vector("contact_force")->values[0];
  return {(walls + weight).norm() / weight.norm(), solver.mean_contacts()};
}

TEST(MultiFaceWalls, ASphereComesToRestInTheConcaveCornerOfAMeshAndOfABox) {
  for (const bool mesh : {true, false}) {
    const auto [imbalance, contacts] = settle_in_corner(mesh ? mesh_corner() : box_corner());
    RecordProperty(mesh ? "mesh_force_imbalance" : "box_force_imbalance",
                   fmt::format("{:.3e}", imbalance));
    EXPECT_EQ(contacts, 2.0) << (mesh ? "mesh" : "box");
    EXPECT_LT(imbalance, 1e-6) << (mesh ? "mesh" : "box");
  }
}

// Distance along a 30-degree incline after 0.2 s from rest (periodic along it), on the plane
// y = 0 or on a mesh of 1 mm cells in that plane.
double incline_distance(bool mesh) {
  Config config = one_species(0.3, 0.5);
  config.sort_interval = 1;
  if (mesh) {
    geometry::TriangleSoup floor;
    geometry::testing::add_patch(floor, Vec3(-0.05, 0.0, -0.01), 0.001 * Vec3::UnitX(),
                                 0.001 * Vec3::UnitZ(), 100, 20);
    add_wall(config, std::make_shared<geometry::MeshShellSurface>(floor));
  } else {
    add_plane(config, Vec3::Zero(), Vec3::UnitY());
  }
  const double alpha = std::numbers::pi / 6.0;
  const Vec3 gravity = 9.81 * Vec3(std::sin(alpha), -std::cos(alpha), 0.0);
  Domain domain = box(0.05);
  domain.periodic = {true, false, false};
  ParticleStore store;
  DemSolver solver(store, domain, config, gravity,
                   Grains{{Vec3(0.0, kRadius, 0.0003)}, {kRadius}, {0}, {}, {}, {}});
  double travelled = 0.0;
  const double dt = solver.stable_dt();
  for (double t = 0.0; t < 0.2; t += dt) {
    solver.step(dt);
    travelled += store.velocity()[0].x() * dt;
  }
  return travelled;
}

TEST(MultiFaceWalls, ASphereRollsDownAMeshInclineAsDownAPlane) {
  const double on_plane = incline_distance(false);
  const double on_mesh = incline_distance(true);
  RecordProperty("relative_difference", fmt::format("{:.3e}", on_mesh / on_plane - 1.0));
  EXPECT_NEAR(on_mesh, on_plane, 1e-9 * on_plane);
}

// Eight spheres rolling over a mesh floor into the corner of a box container, with friction.
struct Corner {
  Config config = one_species(0.5, 0.5);
  Grains grains;
  Corner() {
    geometry::TriangleSoup floor;
    geometry::testing::add_patch(floor, Vec3(0.0, 0.0, 0.002), 0.0015 * Vec3::UnitX(),
                                 0.0015 * Vec3::UnitY(), 8, 8);
    add_wall(config, std::make_shared<geometry::MeshShellSurface>(floor));
    add_wall(config, box_corner());
    for (int k = 0; k < 8; ++k) {
      grains.position.push_back(
          Vec3(0.003 + 0.0045 * (k % 2), 0.003 + 0.0045 * (k / 2 % 2), 0.005 + 0.0045 * (k / 4)));
      grains.radius.push_back(0.0018 + 0.0001 * k);
      grains.species.push_back(0);
    }
  }
};

const Vec3 kTiltedGravity = 9.81 * Vec3(-0.3, -0.2, -1.0).normalized();

std::vector<Vec3> corner_state(const ParticleStore& store) {
  std::vector<Vec3> state = store.position();
  state.insert(state.end(), store.velocity().begin(), store.velocity().end());
  const auto& omega = store.find_vector("angular_velocity")->values;
  state.insert(state.end(), omega.begin(), omega.end());
  return state;
}

void run_steps(DemSolver& solver, int steps) {
  for (int n = 0; n < steps; ++n)
    solver.step(solver.stable_dt());
}

// 7 x 7 x 7 spheres (radii 1.8-2.4 mm, speeds up to 0.3 m/s) on a lattice of 5.2 mm in a box
// container 4 cm wide, thrown into its corner and onto a mesh over its floor.
struct Bed {
  Config config = one_species(0.5, 0.5);
  Grains grains;
  Bed() {
    geometry::TriangleSoup floor;
    geometry::testing::add_patch(floor, Vec3(-0.02, -0.02, -0.019), 0.002 * Vec3::UnitX(),
                                 0.002 * Vec3::UnitY(), 20, 20);
    add_wall(config, std::make_shared<geometry::MeshShellSurface>(floor));
    add_wall(config,
             std::make_shared<geometry::BoxContainerSurface>(
                 Vec3::Constant(-0.02), Vec3::Constant(0.02), std::vector<geometry::Face>{}));
    for (int k = 0; k < 343; ++k) {
      const Vec3 lattice(k % 7, k / 7 % 7, k / 49);
      grains.position.push_back(0.0052 * (lattice - Vec3::Constant(3.0)));
      grains.radius.push_back(0.0018 + 0.0001 * (k % 7));
      grains.species.push_back(0);
      grains.velocity.push_back(0.3 * Vec3(std::sin(k), std::cos(3.0 * k), std::sin(7.0 * k)));
    }
  }
};

std::vector<Vec3> bed_after(int threads, int steps) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  const Bed bed;
  ParticleStore store;
  DemSolver solver(store, box(0.02), bed.config, kTiltedGravity, bed.grains);
  run_steps(solver, steps);
  omp_set_num_threads(saved);
  EXPECT_GT(solver.mean_contacts(), 0.5);  // measured 0.60 (grains and walls)
  return corner_state(store);
}

TEST(MultiFaceWalls, OneAndTwoThreadsAgreeBitForBit) {
  const std::vector<Vec3> one = bed_after(1, 1500);
  const std::vector<Vec3> two = bed_after(2, 1500);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t k = 0; k < one.size(); ++k)
    ASSERT_EQ(one[k], two[k]) << "entry " << k;
}

TEST(MultiFaceWalls, ARestoredCheckpointContinuesBitForBit) {
  const Corner corner;
  ParticleStore store;
  DemSolver solver(store, box(0.02), corner.config, kTiltedGravity, corner.grains);
  run_steps(solver, 1500);
  EXPECT_GT(solver.mean_contacts(), 1.0);
  StateArchive archive;
  solver.save(archive, "methods/dem/");
  run_steps(solver, 1500);

  ParticleStore copy;
  DemSolver resumed(copy, box(0.02), corner.config, kTiltedGravity, corner.grains);
  resumed.restore(archive, "methods/dem/");
  run_steps(resumed, 1500);
  const std::vector<Vec3> through = corner_state(store);
  const std::vector<Vec3> again = corner_state(copy);
  for (std::size_t k = 0; k < through.size(); ++k)
    ASSERT_EQ(through[k], again[k]) << "entry " << k;
}

}  // namespace
}  // namespace partimix::dem
