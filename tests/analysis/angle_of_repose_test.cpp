// Dynamic angle of repose (docs/mixing.md, "Dynamic angle of repose"): a synthetic bed of grains
// on a square lattice below a plane tilted at a known angle through the drum axis is measured
// within 0.5 degree (the lattice's steps make the surface points scatter by up to one spacing
// below the plane), whatever the drum axis and gravity directions; trim leaves out a raised lip at
// the bed's end that would otherwise tilt the fit; too few surface points give NaN.
#include "analysis/angle_of_repose.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "load_fixtures.hpp"

namespace partimix::analysis {
namespace {

using analysis_test::add_particle;
using analysis_test::sample_once;

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr double kSpacing = 0.002;  // lattice spacing [m]: 100 grains across the bed
constexpr double kHalfWidth = 0.1;  // the bed spans x in [-0.1, 0.1]
constexpr double kDepth = 0.1;      // down to y = -0.1 - the surface's drop
// The surface points lie up to one spacing below the plane (the lattice's steps); with 5 columns
// per bin the fitted angles come within 0.19 degrees of the truth. Asked: within 0.5 degrees.
constexpr double kWithin = 0.5;  // degrees

// Bed coordinates (x across, y up, z along the axis) -> space, for a drum of axis `axis` through
// `centre` with gravity along `down`: the analysis' own frame, horizontal = up x axis.
struct Frame {
  Vec3 axis = Vec3::UnitZ();
  Vec3 centre = Vec3::Zero();
  Vec3 down = -Vec3::UnitY();
  Vec3 to_space(double x, double y, double z) const {
    const Vec3 a = axis.normalized();
    const Vec3 up = -(down - down.dot(a) * a).normalized();
    return centre + x * up.cross(a) + y * up + z * a;
  }
};

// Grains at lattice points (x, y) with y <= x tan(angle) + lip(x), in 3 layers along the axis, a
// wall particle above the surface (must not count).
void bed(ParticleStore& store, const Frame& frame, double angle_deg, double lip_height = 0.0,
         double lip_from = 1.0) {
  const double slope = std::tan(angle_deg * kDegree);
  const int columns = static_cast<int>(std::lround(2.0 * kHalfWidth / kSpacing));
  for (int layer = 0; layer < 3; ++layer) {
    for (int i = 0; i <= columns; ++i) {
      const double x = -kHalfWidth + i * kSpacing;
      const double top = x * slope + (x >= lip_from ? lip_height : 0.0);
      for (double y = -kDepth - kHalfWidth * std::abs(slope); y <= top; y += kSpacing)
        add_particle(store, ParticleKind::grain, frame.to_space(x, y, 0.01 * layer));
    }
  }
  add_particle(store, ParticleKind::wall, frame.to_space(0.0, 0.5, 0.0));
}

ReposeSection section_of(const Frame& frame, int bins = 20, double trim = 0.2) {
  ReposeSection s;
  s.axis = frame.axis;
  s.centre = frame.centre;
  s.down = frame.down;
  s.bins = bins;
  s.trim = trim;
  return s;
}

double measure(const ParticleStore& store, const ReposeSection& section) {
  AngleOfRepose angle(section);
  return sample_once(angle, store, 0.0)[0];
}

TEST(AngleOfRepose, Column) {
  const AngleOfRepose angle(ReposeSection{});
  ASSERT_EQ(angle.columns().size(), 1u);
  EXPECT_EQ(angle.columns()[0].name, "angle_of_repose");
  EXPECT_EQ(angle.columns()[0].unit, "deg");
  // Default frame: axis z, down -y: horizontal x, up y.
  EXPECT_TRUE(angle.horizontal().isApprox(Vec3::UnitX()));
  EXPECT_TRUE(angle.up().isApprox(Vec3::UnitY()));
}

TEST(AngleOfRepose, TiltedBedsWithinHalfADegree) {
  const Frame frame;
  for (const double angle : {30.0, -30.0, 20.0, 40.0}) {
    ParticleStore store;
    bed(store, frame, angle);
    EXPECT_NEAR(measure(store, section_of(frame)), std::abs(angle), kWithin) << angle;
  }
}

TEST(AngleOfRepose, AnyAxisAndGravity) {
  // Axis along x through (1, 2, 3), gravity along -z (with a part along the axis, ignored).
  Frame frame;
  frame.axis = Vec3(2, 0, 0);
  frame.centre = Vec3(1, 2, 3);
  frame.down = Vec3(0.3, 0, -9.81);
  ParticleStore store;
  bed(store, frame, 30.0);
  EXPECT_NEAR(measure(store, section_of(frame)), 30.0, kWithin);
  // A drum axis tilted out of the coordinate axes.
  Frame oblique;
  oblique.axis = Vec3(1, 1, 1);
  oblique.down = Vec3(0, -1, 0);
  ParticleStore tilted;
  bed(tilted, oblique, 30.0);
  EXPECT_NEAR(measure(tilted, section_of(oblique)), 30.0, kWithin);
}

TEST(AngleOfRepose, TrimLeavesOutARaisedLip) {
  // Grains climbing 0.05 m up the wall over the last 10% of the width: trim 0.2 drops them
  // (the angle stays within 0.5 degree); trim 0 fits them and the angle rises to 35.5 degrees.
  const Frame frame;
  ParticleStore store;
  bed(store, frame, 30.0, 0.05, 0.08);
  EXPECT_NEAR(measure(store, section_of(frame)), 30.0, kWithin);
  EXPECT_GT(measure(store, section_of(frame, 20, 0.0)), 33.0);
}

TEST(AngleOfRepose, TooFewSurfacePointsGiveNan) {
  ParticleStore store;
  const Frame frame;
  EXPECT_TRUE(std::isnan(measure(store, section_of(frame))));  // no particles
  add_particle(store, ParticleKind::grain, Vec3(0, 0, 0));
  EXPECT_TRUE(std::isnan(measure(store, section_of(frame))));  // no width
  add_particle(store, ParticleKind::grain, Vec3(1, 0, 0));
  // Two points, at the ends: trim 0.2 leaves none.
  EXPECT_TRUE(std::isnan(measure(store, section_of(frame))));
  EXPECT_NEAR(measure(store, section_of(frame, 20, 0.0)), 0.0, 1e-12);
}

TEST(AngleOfRepose, BadSectionsAreRefused) {
  ReposeSection s;
  s.down = Vec3(0, 0, -1);  // along the axis
  EXPECT_THROW(AngleOfRepose{s}, std::invalid_argument);
  s = ReposeSection{};
  s.axis = Vec3::Zero();
  EXPECT_THROW(AngleOfRepose{s}, std::invalid_argument);
  s = ReposeSection{};
  s.bins = 1;
  EXPECT_THROW(AngleOfRepose{s}, std::invalid_argument);
  s = ReposeSection{};
  s.trim = 0.5;
  EXPECT_THROW(AngleOfRepose{s}, std::invalid_argument);
}

TEST(AngleOfRepose, RegisteredByNameWithAFinalFigure) {
  AnalysisOptions options;
  const auto analysis = analysis_registry().create("angle_of_repose", options);
  ASSERT_NE(analysis, nullptr);
  ParticleStore empty;
  EXPECT_TRUE(std::isnan(sample_once(*analysis, empty, 0.0)[0]));
  Figures none;
  analysis->add_figures(none);
  EXPECT_FALSE(none.contains("angle_of_repose_final"));  // a NaN angle gives no figure
  ParticleStore store;
  bed(store, Frame{}, 30.0);
  const double angle = sample_once(*analysis, store, 0.0)[0];
  Figures figures;
  analysis->add_figures(figures);
  EXPECT_DOUBLE_EQ(figures.at("angle_of_repose_final"), angle);
}

}  // namespace
}  // namespace partimix::analysis
