#pragma once
// The grain pairs that may touch (docs/dem.md, "The solver"): a half neighbour list with a skin
// (each pair once, i < j), rebuilt only when a grain has moved half the skin since the last
// build, with each pair's contact history (tangential and rolling springs, as grain i sees
// them). The pairs are split into blocks of consecutive first grains, one per thread; a pair's
// load goes straight to its grains when both belong to the pair's block, and is kept for a
// gather otherwise. Either way each grain sums its loads in the order of its partners' indices,
// whatever the thread count or the step the list was built at, so the sums are the same to the
// last bit (DESIGN.md, "Data and speed": a deterministic scatter).
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/state_archive.hpp"
#include "core/vec.hpp"
#include "particles/cell_grid.hpp"
#include "particles/domain.hpp"

namespace partimix::dem {

// Whether the loops over `grains` grains run on several threads: below a few hundred grains a
// parallel region costs more than it saves (measured: 2 threads made a one-grain test 8 times
// slower than one).
constexpr bool parallel(std::size_t grains) {
  return grains >= 256;
}

struct alignas(64) PairHistory {
  Vec3 spring = Vec3::Zero();          // xi of grain i [m]
  Vec3 rolling_spring = Vec3::Zero();  // M_r^k on grain i [N m]
  // Superquadrics: the last midway point less grain i's centre, and its multiplier mu, kept
  // while the grains touch; mu = 0: none (the next detection starts cold). A starting point for
  // Newton needs no more than single precision, and so the history fills one cache line.
  Vec3f midway = Vec3f::Zero();
  float mu = 0.0F;
};
static_assert(sizeof(PairHistory) == 64);

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
  explicit PairList(double skin) : skin_(skin), gap_margin_(1e-9 * skin) {}

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
  // Marks pair k apart: its springs and a superquadric pair's warm start are cleared.
  void set_apart(std::size_t k);
  bool touching(std::size_t k) const { return touching_[k] != 0; }

  // Pairs known apart (docs/dem.md, "Pairs known apart"): travel(i) bounds how far any point of
  // grain i has moved since the last build; a pair whose grains were `gap` apart stays apart
  // until their travels since then add up to the gap, and need not be looked at before.
  void add_travel(std::size_t i, double distance) {
    if (i < travel_.size())
      travel_[i] += distance;
  }
  // Pair k's surfaces are at least `gap` apart now (gap <= 0: nothing known).
  void set_gap(std::size_t k, double gap) {
    clearance_[k] = travel_[first_[k]] + travel_[second_[k]] + gap - gap_margin_;
  }
  bool known_apart(std::size_t k) const {
    return travel_[first_[k]] + travel_[second_[k]] < clearance_[k];
  }

  // Splits the grains into `blocks` runs of consecutive indices with about equal numbers of
  // pairs as first grain (fewer blocks when there are fewer grains), and marks gathered each
  // grain that is the second of a pair of another block. Does nothing when neither the list nor
  // the number has changed since the last call.
  void partition(int blocks);
  int blocks() const { return static_cast<int>(block_start_.size()) - 1; }
  // Block b's grains [block_start(b), block_start(b + 1)) and the pairs they are first of,
  // [pair_start(block_start(b)), pair_start(block_start(b + 1))).
  std::uint32_t block_start(int b) const { return block_start_[b]; }
  std::uint32_t pair_start(std::uint32_t grain) const { return start_[grain]; }
  bool gathered(std::size_t i) const { return gathered_[i] != 0; }

  // Marks pair k touching and adds its load to force and torque of each grain that is not
  // gathered (the pairs of a block are delivered in order, by the block's thread alone); keeps
  // it for the gather when one of them is.
  void deliver(std::size_t k, const PairLoad& load, std::span<Vec3> force, std::span<Vec3> torque) {
    touching_[k] = 1;
    const std::uint32_t i = first_[k];
    const std::uint32_t j = second_[k];
    if (gathered_[i] || gathered_[j])
      loads_[k] = load;
    if (!gathered_[i]) {
      force[i] += load.force;
      torque[i] += load.torque_i;
    }
    if (!gathered_[j]) {
      force[j] -= load.force;
      torque[j] += load.torque_j;
    }
  }
  // Adds to force[i] and torque[i] (i gathered) the loads of i's touching pairs, partners in
  // index order.
  void gather(std::size_t i, Vec3& force, Vec3& torque) const;
  // Touching pairs of grain i.
  int contacts(std::size_t i) const;

  // The touching pairs: the ids of both grains and their histories, for a checkpoint. restore()
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
  // Taken off every gap: far above the round-off of positions and travels over a list's life.
  double gap_margin_;
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
  std::vector<double> clearance_;  // pair k is apart while its grains' travels sum below this
  std::vector<double> travel_;     // per grain, since the last build
  std::vector<std::uint32_t> block_start_;  // grains; empty: to be partitioned
  std::vector<std::uint8_t> gathered_;
  std::vector<Vec3> built_at_;  // positions at the last build
  // The list before the last build (its springs move to the new one), kept to reuse memory.
  std::vector<std::uint32_t> old_first_;
  std::vector<std::uint32_t> old_second_;
  std::vector<std::uint32_t> old_start_;
  std::vector<PairHistory> old_history_;
  std::vector<std::uint8_t> old_touching_;
  std::vector<std::uint32_t> old_to_new_;
  std::vector<std::uint32_t> counts_;              // scratch: pairs per grain
  std::vector<std::vector<std::uint32_t>> found_;  // scratch: partners found by each thread
};

}  // namespace partimix::dem
