// dem.grains and dem.grains_file (docs/case-reference.md, "dem"): grains placed one by one, in
// the case or in a CSV file, in place of a random fill; every problem is located.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "case_files.hpp"
#include "dem/dem_section.hpp"

namespace partimix::case_test {
namespace {

using ::testing::HasSubstr;

const std::string kDem = R"(solver: dem
dimensions: 3
domain: {min: [-1, -1, -1], max: [1, 1, 1]}
time: {end: 1.0, output_interval: 0.1}
dem:
  species:
    - {name: a, density: 2500}
    - {name: b, density: 2500}
)";

const dem::Grains& grains_of(const io::Case& the_case) {
  return the_case.section<dem::DemSection>("dem").grains;
}

TEST(CaseGrains, AListGivesPositionsRadiiVelocitiesSpinsAndSpecies) {
  const io::Case loaded = load_text(kDem + R"(  grains:
    - {position: [0, 0, 0], radius: 0.01}
    - {position: [0.1, 0, 0], radius: 0.02, velocity: [1, 2, 3], angular_velocity: [4, 5, 6],
       species: b}
)");
  const dem::Grains& grains = grains_of(loaded);
  ASSERT_EQ(grains.position.size(), 2u);
  EXPECT_EQ(grains.position[1], Vec3(0.1, 0, 0));
  EXPECT_EQ(grains.radius[1], 0.02);
  EXPECT_EQ(grains.velocity[1], Vec3(1, 2, 3));
  EXPECT_EQ(grains.angular_velocity[1], Vec3(4, 5, 6));
  EXPECT_EQ(grains.species, (std::vector<int>{0, 1}));
  EXPECT_EQ(grains.velocity[0], Vec3::Zero());
}

TEST(CaseGrains, ACsvFileTakesItsColumnsInAnyOrder) {
  const CaseFile file(kDem + "  grains_file: grains.csv\n");
  file.add_file("grains.csv",
                "# two grains\nradius, x, y, z, vx, species\n0.01, 0, 0, 0, 1.5, 1\n\n"
                "0.02,0.1,0,0,-1,a\n");
  const io::Case loaded = io::load_case(file.path());
  const dem::Grains& grains = grains_of(loaded);
  ASSERT_EQ(grains.position.size(), 2u);
  EXPECT_EQ(grains.velocity[0], Vec3(1.5, 0, 0));
  EXPECT_EQ(grains.radius[1], 0.02);
  EXPECT_EQ(grains.species, (std::vector<int>{1, 0}));
}

TEST(CaseGrains, ACsvProblemNamesTheFileLineAndColumn) {
  const CaseFile file(kDem + "  grains_file: grains.csv\n");
  const std::string csv = file.add_file("grains.csv", "x,y,z,radius\n0,0,0,0.01\n0,0,zero,0.01\n");
  const InputError error = load_error(file);
  EXPECT_EQ(error.location().file, csv);
  EXPECT_EQ(error.location().line, 3);
  EXPECT_EQ(error.location().column, 3);
  EXPECT_THAT(error.message(), HasSubstr("z: expected a finite number, got 'zero'"));
}

TEST(CaseGrains, ACsvWithoutARequiredColumnOrWithAnUnknownOneIsRefused) {
  const CaseFile file(kDem + "  grains_file: grains.csv\n");
  file.add_file("grains.csv", "x,y,radius\n0,0,0.01\n");
  EXPECT_THAT(load_error(file).message(), HasSubstr("the header lacks the column 'z'"));
  file.add_file("grains.csv", "x,y,z,radius,mass\n0,0,0,0.01,1\n");
  EXPECT_THAT(load_error(file).message(), HasSubstr("unknown column 'mass'"));
  file.add_file("grains.csv", "x,y,z,radius\n0,0,0,-0.01\n");
  EXPECT_THAT(load_error(file).message(), HasSubstr("radius: must be > 0"));
  file.add_file("grains.csv", "x,y,z,radius,species\n0,0,0,0.01,c\n");
  EXPECT_THAT(load_error(file).message(), HasSubstr("species: 'c' is none of: a, b"));
}

// As for meshes (fuzz/regressions): a folder or an endless device is refused, not read.
TEST(CaseGrains, AGrainFileThatIsNoRegularFileIsRefused) {
  for (const std::string file : {"/dev/zero", "."}) {
    const InputError error = load_error(kDem + "  grains_file: " + file + "\n");
    EXPECT_THAT(error.message(), HasSubstr("no such readable regular file")) << file;
  }
}

TEST(CaseGrains, ExactlyOneWayOfPlacingGrains) {
  const InputError none = load_error(kDem);
  EXPECT_EQ(none.location().key_path, "dem.fill");
  EXPECT_THAT(none.message(), HasSubstr("give exactly one of fill"));
  const InputError two = load_error(kDem + R"(  grains: [{position: [0, 0, 0], radius: 0.01}]
  grains_file: grains.csv
)");
  EXPECT_EQ(two.location().key_path, "dem.grains_file");
}

TEST(CaseGrains, MoreGrainsThanTheLimitAreRefused) {
  const InputError error = load_error(kDem + R"(  grains:
    - {position: [0, 0, 0], radius: 0.01}
    - {position: [0.5, 0, 0], radius: 0.01}
)",
                                      {"limits.particles=1"});
  EXPECT_EQ(error.location().key_path, "dem.grains");
  EXPECT_THAT(error.message(), HasSubstr("more than limits.particles = 1"));
}

}  // namespace
}  // namespace partimix::case_test
