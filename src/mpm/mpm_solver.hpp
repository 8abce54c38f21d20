#pragma once
// The material point method for dense granular flow (docs/mpm.md): material points in the
// particle store over a background grid, explicit MUSL (or USL) steps with APIC or FLIP
// transfers, the elastic + mu(I) stress update, and the walls as grid boundary conditions.
#include <memory>
#include <vector>

#include "grid/cartesian_grid.hpp"
#include "grid/node_buckets.hpp"
#include "grid/point_stencil.hpp"
#include "grid/shape_function.hpp"
#include "io/size_limits.hpp"
#include "mpm/config.hpp"
#include "mpm/grid_boundaries.hpp"
#include "mpm/grid_fields.hpp"
#include "mpm/point_feeds.hpp"
#include "mpm/point_fields.hpp"
#include "mpm/transfers.hpp"
#include "particles/solver.hpp"

namespace partimix::mpm {

class MpmSolver final : public Solver {
 public:
  // Fills the store with the points of config.fills. Throws InputError with a key path of the
  // `mpm` section when the case cannot be built.
  MpmSolver(ParticleStore& store, const Domain& domain, const MpmConfig& config,
            const Vec3& gravity, const io::SizeLimits& limits);

  std::string_view name() const override { return "mpm"; }
  const ParticleStore& particles() const override { return store_; }
  const Domain& domain() const override { return domain_; }
  double stable_dt() const override;
  void step(double dt) override;
  std::map<std::string, double> derived_parameters() const override;
  void save(StateArchive& archive, const std::string& prefix) const override;
  void restore(const StateArchive& archive, const std::string& prefix) override;

  double time() const { return time_; }
  // The mass that has left through the exits [kg; kg/m in 2D].
  double mass_out() const { return mass_out_; }
  // The mass the feeds have added [kg; kg/m in 2D].
  double mass_in() const { return mass_in_; }

 private:
  void prepare_points();
  void update_stresses(double dt);
  void move_points(double dt);
  PointView view() const;

  ParticleStore& store_;
  Domain domain_;
  MpmConfig config_;
  Vec3 gravity_;
  PointFields fields_;
  grid::CartesianGrid grid_;
  std::unique_ptr<grid::ShapeFunction> shape_;
  GridBoundaries boundaries_;
  PointFeeds feeds_;
  TransferOptions transfer_;
  double min_node_mass_ = 0.0;
  double wave_speed_ = 0.0;
  // Per step, kept between steps (no allocation once sized).
  std::vector<grid::PointStencil> stencils_;
  grid::NodeBuckets buckets_;
  GridFields nodes_;
  std::vector<Mat3> affine_;
  std::vector<Mat3> stress_volume_;
  std::vector<Mat3> gradient_;
  std::vector<Vec3> grid_velocity_;
  std::vector<std::uint32_t> exit_order_;
  double time_ = 0.0;
  double max_speed_ = 0.0;
  double mass_out_ = 0.0;
  double mass_in_ = 0.0;
  std::int64_t next_id_ = 0;
  std::int64_t steps_ = 0;
};

}  // namespace partimix::mpm
