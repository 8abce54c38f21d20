#include "dem/pair_list.hpp"

#include <algorithm>
#include <numeric>
#include <unordered_map>

#include <fmt/format.h>
#include <omp.h>

#include "core/error.hpp"

namespace partimix::dem {
namespace {

constexpr std::size_t kColumns = 10;  // a checkpoint's history of one pair: PairHistory

// The history as grain j sees it: the springs with the sign changed; the midway point, kept
// from grain i's centre, is dropped (the next detection starts cold).
PairHistory seen_from_j(const PairHistory& h) {
  return {-h.spring, -h.rolling_spring, Vec3f::Zero(), 0.0F};
}

}  // namespace

bool PairList::stale(std::span<const Vec3> positions, const Domain& domain) const {
  if (built_at_.size() != positions.size())
    return true;
  const double limit = 0.25 * skin_ * skin_;
  double largest = 0.0;
#pragma omp parallel for schedule(static) reduction(max : largest) if (parallel(positions.size()))
  for (std::size_t i = 0; i < positions.size(); ++i)
    largest = std::max(largest, domain.displacement(positions[i], built_at_[i]).squaredNorm());
  return largest > limit;
}

void PairList::build(const CellGrid& grid, std::span<const Vec3> positions,
                     std::span<const double> radius, std::span<const std::uint32_t> new_to_old) {
  first_.swap(old_first_);
  second_.swap(old_second_);
  start_.swap(old_start_);
  history_.swap(old_history_);
  touching_.swap(old_touching_);
  find_pairs(grid, positions, radius);
  index_incoming(positions.size());
  carry_history(new_to_old);
  built_at_.assign(positions.begin(), positions.end());
  travel_.assign(positions.size(), 0.0);
  block_start_.clear();
}

// One pass over the grid: each thread lists the partners of a run of grains in its own buffer
// (each grain's sorted by index), then copies them into place and clears their histories.
void PairList::find_pairs(const CellGrid& grid, std::span<const Vec3> positions,
                          std::span<const double> radius) {
  const std::size_t n = positions.size();
  counts_.resize(n);
  start_.resize(n + 1);
  found_.resize(static_cast<std::size_t>(omp_get_max_threads()));
#pragma omp parallel if (parallel(n))
  {
    const auto thread = static_cast<std::size_t>(omp_get_thread_num());
    const auto threads = static_cast<std::size_t>(omp_get_num_threads());
    const std::size_t begin = n * thread / threads;
    const std::size_t end = n * (thread + 1) / threads;
    std::vector<std::uint32_t>& found = found_[thread];
    found.clear();
    for (std::size_t i = begin; i < end; ++i) {
      const std::size_t before = found.size();
      const auto partner = [&](std::size_t j, const Vec3&, double r2) {
        const double reach = radius[i] + radius[j] + skin_;
        if (r2 < reach * reach)
          found.push_back(static_cast<std::uint32_t>(j));
      };
      grid.for_each_neighbour(i, positions, partner, n, i + 1);
      std::sort(found.begin() + static_cast<std::ptrdiff_t>(before), found.end());
      counts_[i] = static_cast<std::uint32_t>(found.size() - before);
    }
#pragma omp barrier
#pragma omp single
    {
      start_[0] = 0;
      for (std::size_t i = 0; i < n; ++i)
        start_[i + 1] = start_[i] + counts_[i];
      first_.resize(start_[n]);
      second_.resize(start_[n]);
      history_.resize(start_[n]);
      loads_.resize(start_[n]);
      touching_.resize(start_[n]);
      clearance_.resize(start_[n]);
    }
    std::copy(found.begin(), found.end(), second_.begin() + start_[begin]);
    for (std::size_t i = begin; i < end; ++i)
      std::fill(first_.begin() + start_[i], first_.begin() + start_[i + 1],
                static_cast<std::uint32_t>(i));
    std::fill(history_.begin() + start_[begin], history_.begin() + start_[end], PairHistory{});
    std::fill(touching_.begin() + start_[begin], touching_.begin() + start_[end], 0);
    std::fill(clearance_.begin() + start_[begin], clearance_.begin() + start_[end], 0.0);
  }
}

// The pairs are in order of their first grain, so each grain's incoming pairs come out in order
// of their partner.
void PairList::index_incoming(std::size_t grains) {
  incoming_start_.assign(grains + 1, 0);
  for (const std::uint32_t j : second_)
    ++incoming_start_[j + 1];
  for (std::size_t i = 0; i < grains; ++i)
    incoming_start_[i + 1] += incoming_start_[i];
  incoming_.resize(second_.size());
  counts_.assign(grains, 0);
  for (std::size_t k = 0; k < second_.size(); ++k) {
    const std::uint32_t j = second_[k];
    incoming_[incoming_start_[j] + counts_[j]++] = static_cast<std::uint32_t>(k);
  }
}

std::int64_t PairList::find(std::uint32_t a, std::uint32_t b, bool& flipped) const {
  flipped = a > b;
  const std::uint32_t low = std::min(a, b);
  const std::uint32_t high = std::max(a, b);
  const auto begin = second_.begin() + start_[low];
  const auto end = second_.begin() + start_[low + 1];
  const auto at = std::lower_bound(begin, end, high);
  return at != end && *at == high ? at - second_.begin() : -1;
}

// A pair that touched at the last build keeps its history, turned to the new order of its
// grains.
void PairList::carry_history(std::span<const std::uint32_t> new_to_old) {
  if (old_start_.empty())
    return;
  const std::size_t n = start_.size() - 1;
  old_to_new_.resize(n);
  for (std::size_t k = 0; k < n; ++k)
    old_to_new_[new_to_old.empty() ? k : new_to_old[k]] = static_cast<std::uint32_t>(k);
#pragma omp parallel for schedule(static) if (parallel(n))
  for (std::size_t old_pair = 0; old_pair < old_first_.size(); ++old_pair) {
    if (!old_touching_[old_pair])
      continue;
    bool flipped = false;
    const std::int64_t k =
        find(old_to_new_[old_first_[old_pair]], old_to_new_[old_second_[old_pair]], flipped);
    if (k < 0)
      continue;
    const PairHistory& old = old_history_[old_pair];
    history_[k] = flipped ? seen_from_j(old) : old;
    touching_[k] = old_touching_[old_pair];
  }
}

void PairList::set_apart(std::size_t k) {
  if (touching_[k])
    history_[k] = PairHistory{};
  touching_[k] = 0;
}

void PairList::partition(int blocks) {
  const std::size_t grains = start_.size() - 1;
  const std::size_t count = std::clamp<std::size_t>(static_cast<std::size_t>(blocks), 1,
                                                    std::max<std::size_t>(grains, 1));
  if (block_start_.size() == count + 1)
    return;
  block_start_.assign(count + 1, static_cast<std::uint32_t>(grains));
  block_start_[0] = 0;
  for (std::size_t b = 1; b < count; ++b) {
    const std::size_t share = first_.size() * b / count;
    const auto at = std::lower_bound(start_.begin(), start_.end() - 1, share);
    block_start_[b] =
        std::max(block_start_[b - 1], static_cast<std::uint32_t>(at - start_.begin()));
  }
  gathered_.assign(grains, 0);
  for (std::size_t b = 0; b < count; ++b) {
    const std::uint32_t end = block_start_[b + 1];
    for (std::uint32_t k = start_[block_start_[b]]; k < start_[end]; ++k) {
      if (second_[k] >= end)
        gathered_[second_[k]] = 1;
    }
  }
}

void PairList::gather(std::size_t i, Vec3& force, Vec3& torque) const {
  for (std::uint32_t e = incoming_start_[i]; e < incoming_start_[i + 1]; ++e) {
    const std::uint32_t k = incoming_[e];
    if (touching_[k]) {
      force -= loads_[k].force;
      torque += loads_[k].torque_j;
    }
  }
  for (std::uint32_t k = start_[i]; k < start_[i + 1]; ++k) {
    if (touching_[k]) {
      force += loads_[k].force;
      torque += loads_[k].torque_i;
    }
  }
}

int PairList::contacts(std::size_t i) const {
  int count = 0;
  for (std::uint32_t e = incoming_start_[i]; e < incoming_start_[i + 1]; ++e)
    count += touching_[incoming_[e]];
  for (std::uint32_t k = start_[i]; k < start_[i + 1]; ++k)
    count += touching_[k];
  return count;
}

void PairList::save(StateArchive& archive, const std::string& prefix,
                    std::span<const std::int64_t> ids) const {
  std::vector<std::int64_t> pairs;
  std::vector<double> springs;
  for (std::size_t k = 0; k < first_.size(); ++k) {
    if (!touching_[k])
      continue;
    pairs.insert(pairs.end(), {ids[first_[k]], ids[second_[k]]});
    const PairHistory& h = history_[k];
    springs.insert(springs.end(), {h.spring.x(), h.spring.y(), h.spring.z(), h.rolling_spring.x(),
                                   h.rolling_spring.y(), h.rolling_spring.z(), h.midway.x(),
                                   h.midway.y(), h.midway.z(), h.mu});
  }
  archive.put_integers(prefix + "pairs", pairs, 2);
  archive.put_doubles(prefix + "springs", springs, kColumns);
}

void PairList::restore(const StateArchive& archive, const std::string& prefix, const CellGrid& grid,
                       std::span<const Vec3> positions, std::span<const double> radius,
                       std::span<const std::int64_t> ids) {
  const auto pairs = archive.integers(prefix + "pairs", 2);
  const auto springs = archive.doubles(prefix + "springs", kColumns);
  if (pairs.size() / 2 != springs.size() / kColumns)
    throw StateError(prefix + ": the pairs and their springs differ in number");
  start_.clear();  // nothing to carry over
  build(grid, positions, radius);
  std::unordered_map<std::int64_t, std::uint32_t> index;
  for (std::size_t i = 0; i < ids.size(); ++i)
    index.emplace(ids[i], static_cast<std::uint32_t>(i));
  for (std::size_t p = 0; p < pairs.size() / 2; ++p) {
    const auto a = index.find(pairs[2 * p]);
    const auto b = index.find(pairs[2 * p + 1]);
    bool flipped = false;
    const std::int64_t k = a == index.end() || b == index.end() || a->second == b->second
                               ? -1
                               : find(a->second, b->second, flipped);
    if (k < 0) {
      throw StateError(
          fmt::format("{}pairs: grains {} and {} touch in the checkpoint but are "
                      "not neighbours here",
                      prefix, pairs[2 * p], pairs[2 * p + 1]));
    }
    const double* s = &springs[kColumns * p];
    const PairHistory saved{Vec3(s[0], s[1], s[2]), Vec3(s[3], s[4], s[5]),
                            Vec3(s[6], s[7], s[8]).cast<float>(), static_cast<float>(s[9])};
    history_[k] = flipped ? seen_from_j(saved) : saved;
    touching_[k] = 1;
  }
}

std::size_t PairList::bytes() const {
  const std::size_t indices =
      first_.capacity() + second_.capacity() + start_.capacity() + incoming_.capacity() +
      incoming_start_.capacity() + old_first_.capacity() + old_second_.capacity() +
      old_start_.capacity() + old_to_new_.capacity() + counts_.capacity() +
      std::accumulate(found_.begin(), found_.end(), std::size_t{0},
                      [](std::size_t sum, const auto& buffer) { return sum + buffer.capacity(); });
  return indices * sizeof(std::uint32_t) +
         (history_.capacity() + old_history_.capacity()) * sizeof(PairHistory) +
         loads_.capacity() * sizeof(PairLoad) + touching_.capacity() + old_touching_.capacity() +
         block_start_.capacity() * sizeof(std::uint32_t) + gathered_.capacity() +
         built_at_.capacity() * sizeof(Vec3) +
         (clearance_.capacity() + travel_.capacity()) * sizeof(double);
}

}  // namespace partimix::dem
