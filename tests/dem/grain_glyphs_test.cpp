// The DEM solver's frame arrays and shape fields (docs/dem.md, "Drawing superquadric grains in
// ParaView"):
// - with a superquadric species beside a sphere species, the store carries half_axes and volume
//   (a sphere's: its radius thrice and its ball's volume), and frame_arrays() gives orientation,
//   blockiness, shape_tensor and superquadric_axes for every grain, from its own orientation;
// - with spheres only, no frame arrays and no new fields: the frames stay as they were.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <numbers>
#include <string>
#include <vector>

#include "dem/dem_setups.hpp"
#include "dem/dem_solver.hpp"
#include "dem/glyph_tensors.hpp"

namespace partimix::dem {
namespace {

using test::box;

const Superquadric kBlocky(Vec3(1.0e-3, 1.5e-3, 3.0e-3), 4.0, 6.0);
constexpr double kSphereRadius = 2.0e-3;

Config two_species(bool with_shape) {
  Config config;
  config.species = {Species{"blocky", 2500.0, {1.0e7, 0.3}, {}},
                    Species{"sphere", 2500.0, {1.0e7, 0.3}, {}}};
  if (with_shape)
    config.species[0].shape = kBlocky;
  config.particle_interactions.assign(4, Interaction{});
  config.wall_interactions.assign(2, Interaction{});
  return config;
}

Grains apart() {
  Grains grains;
  grains.position = {Vec3(-0.01, 0.0, 0.0), Vec3(0.01, 0.0, 0.0)};
  grains.radius = {kSphereRadius, kSphereRadius};
  grains.species = {0, 1};
  grains.orientation = {Quaternion(Eigen::AngleAxisd(0.9, Vec3(1.0, -1.0, 2.0).normalized())),
                        Quaternion::Identity()};
  return grains;
}

// The index of the grain with id `id` (the solver sorts the grains by cell).
std::size_t index_of(const ParticleStore& store, std::int64_t id) {
  const auto at = std::find(store.id().begin(), store.id().end(), id);
  return static_cast<std::size_t>(at - store.id().begin());
}

const FrameArray& array_named(const std::vector<FrameArray>& arrays, const std::string& name) {
  const auto at = std::find_if(arrays.begin(), arrays.end(),
                               [&](const FrameArray& a) { return a.name == name; });
  EXPECT_NE(at, arrays.end()) << name;
  return *at;
}

void expect_tensor(const FrameArray& array, std::size_t i, const Mat3& expected) {
  for (int k = 0; k < 9; ++k)
    EXPECT_EQ(array.values[9 * i + static_cast<std::size_t>(k)], expected.data()[k]) << k;
}

TEST(GrainGlyphs, ShapedGrainsCarryTheirShapeAndGlyphArrays) {
  ParticleStore store;
  const Grains grains = apart();
  DemSolver solver(store, box(0.05), two_species(true), Vec3::Zero(), grains);
  const std::size_t blocky = index_of(store, 0);
  const std::size_t sphere = index_of(store, 1);
  const auto& half_axes = store.find_vector("half_axes")->values;
  const auto& volume = store.find_scalar("volume")->values;
  EXPECT_EQ(half_axes[blocky], kBlocky.half_axes());
  EXPECT_EQ(half_axes[sphere], Vec3::Constant(kSphereRadius));
  EXPECT_EQ(volume[blocky], kBlocky.volume());
  EXPECT_DOUBLE_EQ(volume[sphere], 4.0 / 3.0 * std::numbers::pi * std::pow(kSphereRadius, 3));

  const std::vector<FrameArray> arrays = solver.frame_arrays();
  ASSERT_EQ(arrays.size(), 4u);
  const std::vector<std::pair<std::string, int>> expected = {
      {"orientation", 4}, {"blockiness", 2}, {"shape_tensor", 9}, {"superquadric_axes", 9}};
  for (std::size_t k = 0; k < expected.size(); ++k) {
    EXPECT_EQ(arrays[k].name, expected[k].first);
    EXPECT_EQ(arrays[k].components, expected[k].second);
    EXPECT_EQ(arrays[k].values.size(),
              store.size() * static_cast<std::size_t>(arrays[k].components));
  }
  const Quaternion q = grains.orientation[0].normalized();
  const FrameArray& orientation = array_named(arrays, "orientation");
  EXPECT_EQ(std::vector<double>(orientation.values.begin() + 4 * blocky,
                                orientation.values.begin() + 4 * blocky + 4),
            (std::vector<double>{q.w(), q.x(), q.y(), q.z()}));
  const FrameArray& blockiness = array_named(arrays, "blockiness");
  EXPECT_EQ(blockiness.values[2 * blocky], 4.0);
  EXPECT_EQ(blockiness.values[2 * blocky + 1], 6.0);
  EXPECT_EQ(blockiness.values[2 * sphere], 2.0);
  EXPECT_EQ(blockiness.values[2 * sphere + 1], 2.0);
  expect_tensor(array_named(arrays, "shape_tensor"), blocky, shape_tensor(q, kBlocky.half_axes()));
  expect_tensor(array_named(arrays, "shape_tensor"), sphere, kSphereRadius * Mat3::Identity());
  expect_tensor(array_named(arrays, "superquadric_axes"), blocky,
                superquadric_glyph_axes(q, kBlocky.half_axes()));
}

TEST(GrainGlyphs, SpheresOnlyKeepTheirFieldsAndHaveNoFrameArrays) {
  ParticleStore store;
  DemSolver solver(store, box(0.05), two_species(false), Vec3::Zero(), apart());
  EXPECT_TRUE(solver.frame_arrays().empty());
  std::vector<std::string> names;
  for (const auto& field : store.scalar_fields())
    names.push_back(field.name);
  for (const auto& field : store.vector_fields())
    names.push_back(field.name);
  for (const auto& field : store.integer_fields())
    names.push_back(field.name);
  EXPECT_EQ(names,
            (std::vector<std::string>{"mass", "radius", "orientation_w", "position", "velocity",
                                      "angular_velocity", "contact_force", "contact_torque",
                                      "orientation_v", "kind", "tag", "species"}));
}

}  // namespace
}  // namespace partimix::dem
