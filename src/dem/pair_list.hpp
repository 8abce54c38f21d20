#pragma once
// The grain pairs that may touch (docs/dem.md, "The solver"): a half neighbour list with a skin
// (each pair once, i < j), rebuilt only when a grain has moved half the skin since the last
// build, with each pair's contact history (tangential and rolling springs, as grain i sees
// them) and the loads the pair's contact puts on its two grains. Each grain then gathers its
// loads from its pairs in the order of its partners' indices, whatever the thread count or the
// step the list was built at, so the sums are the same to the last bit (DESIGN.md, "Data and
// speed": a deterministic scatter).
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/state_archive.hpp"
#include "core/vec.hpp"
#include "particles/cell_grid.hpp"
#include "particles/domain.hpp"

namespace partimix::dem {

struct PairHistory {
  Vec3 spring = Vec3::Zero();          // xi of grain i [m]
  Vec3 rolling_spring = Vec3::Zero();  // M_r^k on grain i [N m]
  // Superquadrics: the last midway point less grain i's centre, and its multiplier mu, kept
  // while the pair's bounding spheres overlap; mu = 0: none (the next detection starts cold).
  Vec3 midway = Vec3::Zero();
  double mu = 0.0;
};

// What a pair's contact does to its grains: the force on i (j gets its opposite) and the torque
// on each.
struct PairLoad {
  Vec3 force = Vec3::Zero();
  Vec3 torque_i = Vec3::Zero();
  Vec3 torque_j = Vec3::Zero();
};

class PairList {
 public:
  // Pairs closer than R_i + R_j + skin; the grid's radius must be at least 2 R_max + skin.
  explicit PairList(double skin) : skin_(skin) {}

  double skin() const { return skin_; }

  // True when a grain has moved more than half the skin since the last build (or there was
  // none, or the grain count changed).
  bool stale(std::span<const Vec3> positions, const Domain& domain) const;

  // Finds the pairs again with `grid` built on `positions`. `new_to_old` (empty when the grains
  // kept their places) says where each grain was at the last build: the springs of the pairs
  // that were touching then follow their grains.
  void build(const CellGrid& grid, std::span<const Vec3> positions, std::span<const double> radius,
             std::span<const std::uint32_t> new_to_old = {});

  std::size_t size() const { return first_.size(); }
  std::uint32_t first(std::size_t k) const { return first_[k]; }
  std::uint32_t second(std::size_t k) const { return second_[k]; }
  PairHistory& history(std::size_t k) { return history_[k]; }
  PairLoad& load(std::size_t k) { return loads_[k]; }
  // Marks pair k touching (its load counts) or apart (its springs are cleared; a superquadric
  // pair's warm start stays while the grains are near).
  void set_touching(std::size_t k, bool touching);
  bool touching(std::size_t k) const { return touching_[k] != 0; }

  // Adds to force[i] and torque[i] the loads of i's touching pairs, partners in index order.
  void gather(std::size_t i, Vec3& force, Vec3& torque) const;
  // Touching pairs of grain i.
  int contacts(std::size_t i) const;

  // The pairs with a history (touching, or near superquadrics with a warm start): the ids of
  // both grains and their histories, for a checkpoint. restore()
  // builds the list and gives the saved springs back to the pairs of the same ids; it throws
  // StateError when a saved pair is not one of this list's (the grains are not where the
  // checkpoint had them) or the entries are malformed.
  void save(StateArchive& archive, const std::string& prefix,
            std::span<const std::int64_t> ids) const;
  void restore(const StateArchive& archive, const std::string& prefix, const CellGrid& grid,
               std::span<const Vec3> positions, std::span<const double> radius,
               std::span<const std::int64_t> ids);

  std::size_t bytes() const;

 private:
  void find_pairs(const CellGrid& grid, std::span<const Vec3> positions,
                  std::span<const double> radius);
  void index_incoming(std::size_t grains);
  // The pair (a, b) of the list, a != b, or -1; `flipped` when it is stored as (b, a).
  std::int64_t find(std::uint32_t a, std::uint32_t b, bool& flipped) const;
  void carry_history(std::span<const std::uint32_t> new_to_old);

  double skin_;
  // Pairs (first_[k], second_[k]), first < second, sorted by first then second; the pairs of
  // grain i as first are [start_[i], start_[i + 1]).
  std::vector<std::uint32_t> first_;
  std::vector<std::uint32_t> second_;
  std::vector<std::uint32_t> start_;
  // The pairs of grain i as second, by first: incoming_[incoming_start_[i] ...].
  std::vector<std::uint32_t> incoming_;
  std::vector<std::uint32_t> incoming_start_;
  std::vector<PairHistory> history_;
  std::vector<PairLoad> loads_;
  std::vector<std::uint8_t> touching_;
  std::vector<Vec3> built_at_;  // positions at the last build
  // The list before the last build (its springs move to the new one), kept to reuse memory.
  std::vector<std::uint32_t> old_first_;
  std::vector<std::uint32_t> old_second_;
  std::vector<std::uint32_t> old_start_;
  std::vector<PairHistory> old_history_;
  std::vector<std::uint8_t> old_touching_;
  std::vector<std::uint32_t> old_to_new_;
  std::vector<std::uint32_t> counts_;  // scratch: pairs per grain
};

}  // namespace partimix::dem
