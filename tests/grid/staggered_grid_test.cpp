// grid/staggered_grid.hpp: the counts, numbering and positions of a staggered grid's cells and
// faces, periodic wrapping, and the faces each cell sees.
#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "core/error.hpp"
#include "grid/staggered_grid.hpp"

namespace partimix::grid {
namespace {

StaggeredGrid box_3d() {
  return StaggeredGrid(3, Vec3(1.0, 2.0, 3.0), {4, 3, 2}, Vec3(0.5, 0.25, 1.0),
                       {false, true, false}, 1e6);
}

TEST(StaggeredGrid, CountsCellsAndFacesAlongEachAxis) {
  const StaggeredGrid grid = box_3d();
  EXPECT_EQ(grid.cell_count(), 24u);
  EXPECT_EQ(grid.face_count(0), 5u * 3 * 2);  // one more along x, not periodic
  EXPECT_EQ(grid.face_count(1), 4u * 3 * 2);  // periodic y: as many as cells
  EXPECT_EQ(grid.face_count(2), 4u * 3 * 3);
  EXPECT_DOUBLE_EQ(grid.cell_volume(), 0.125);
  EXPECT_DOUBLE_EQ(grid.face_area(0), 0.25);
}

TEST(StaggeredGrid, PlacesCellCentresAndFaceCentres) {
  const StaggeredGrid grid = box_3d();
  EXPECT_TRUE(grid.cell_centre(0, 0, 0).isApprox(Vec3(1.25, 2.125, 3.5)));
  EXPECT_TRUE(grid.face_centre(0, 4, 2, 1).isApprox(Vec3(3.0, 2.625, 4.5)));
  EXPECT_TRUE(grid.face_centre(2, 1, 0, 2).isApprox(Vec3(1.75, 2.125, 5.0)));
}

TEST(StaggeredGrid, TwoDimensionsHaveOneCellOfUnitDepthAndNoZFaces) {
  const StaggeredGrid grid(2, Vec3::Zero(), {3, 2, 7}, Vec3(0.1, 0.2, 5.0), {true, false, true},
                           1e6);
  EXPECT_EQ(grid.cells(2), 1);
  EXPECT_EQ(grid.face_count(2), 0u);
  EXPECT_DOUBLE_EQ(grid.cell_volume(), 0.02);
  EXPECT_DOUBLE_EQ(grid.cell_centre(0, 0, 0).z(), 0.0);
}

TEST(StaggeredGrid, EachInteriorFaceIsSeenFromBothSidesAndSideFacesOnce) {
  const StaggeredGrid grid = box_3d();
  std::multiset<std::tuple<int, std::size_t, int>> seen;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i)
        grid.for_each_face_of_cell(
            i, j, k, [&](int axis, std::size_t face, int side, std::int64_t neighbour) {
              seen.insert({axis, face, side});
              if (neighbour >= 0) {
                // The neighbour sees the same face from the other side.
                const std::array<int, 3> n =
                    grid.cell_coordinates(static_cast<std::size_t>(neighbour));
                bool back = false;
                grid.for_each_face_of_cell(n[0], n[1], n[2],
                                           [&](int a, std::size_t f, int s, std::int64_t) {
                                             back = back || (a == axis && f == face && s == -side);
                                           });
                EXPECT_TRUE(back);
              }
            });
  for (int axis = 0; axis < 3; ++axis)
    for (std::size_t face = 0; face < grid.face_count(axis); ++face)
      EXPECT_EQ(seen.count({axis, face, -1}) + seen.count({axis, face, 1}),
                grid.periodic(axis) || (axis == 0 ? face % 5 != 0 && face % 5 != 4
                                                  : face / 12 != 0 && face / 12 != 2)
                    ? 2u
                    : 1u);
}

TEST(StaggeredGrid, RefusesEmptyAxesAndTooManyCells) {
  EXPECT_THROW(StaggeredGrid(3, Vec3::Zero(), {0, 1, 1}, Vec3::Ones(), {}, 1e6), InputError);
  EXPECT_THROW(StaggeredGrid(3, Vec3::Zero(), {1, 1, 1}, Vec3(1, -1, 1), {}, 1e6), InputError);
  EXPECT_THROW(StaggeredGrid(3, Vec3::Zero(), {1, 4, 4}, Vec3::Ones(), {true, false, false}, 1e6),
               InputError);
  EXPECT_THROW(StaggeredGrid(3, Vec3::Zero(), {100, 100, 101}, Vec3::Ones(), {}, 1e6), InputError);
}

}  // namespace
}  // namespace partimix::grid
