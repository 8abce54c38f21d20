#include "particles/store_state.hpp"

#include <algorithm>
#include <set>

#include <fmt/format.h>

namespace partimix {
namespace {

std::string field_path(const std::string& prefix, const std::string& name) {
  return prefix + "fields/" + name;
}

template <class T>
void save_integers(const std::deque<Field<T>>& fields, StateArchive& archive,
                   const std::string& prefix) {
  std::vector<std::int64_t> values;
  for (const auto& field : fields) {
    values.assign(field.values.begin(), field.values.end());
    archive.put_integers(field_path(prefix, field.name), values);
  }
}

// A saved field's values, which must be one per particle of the store.
template <class Values>
Values sized(Values values, std::size_t count, const std::string& path) {
  if (values.size() != count) {
    throw StateError(
        fmt::format("{} holds {} values for {} particles", path, values.size(), count));
  }
  return values;
}

// Fields that hold what a particle is, fixed when the case is built: a run only reorders them.
bool fixed_at_build(const std::string& name) {
  return name == "id" || name == "kind" || name == "body";
}

// Whether `a` and `b` hold the same values, in any order.
template <class T>
bool same_values(std::vector<T> a, std::vector<T> b) {
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  return a == b;
}

template <class T>
void restore_integers(std::deque<Field<T>>& fields, const StateArchive& archive,
                      const std::string& prefix, std::size_t count, bool check_fixed) {
  for (auto& field : fields) {
    const std::string path = field_path(prefix, field.name);
    const auto values = sized(archive.integers(path), count, path);
    std::vector<T> restored(count);
    std::transform(values.begin(), values.end(), restored.begin(),
                   [](std::int64_t v) { return static_cast<T>(v); });
    if (check_fixed && fixed_at_build(field.name) && !same_values(restored, field.values)) {
      throw StateError(
          fmt::format("{} holds other values than the case builds (the particles' "
                      "{} can only be reordered by a run)",
                      path, field.name));
    }
    field.values = std::move(restored);
  }
}

std::set<std::string> field_names(const ParticleStore& store) {
  std::set<std::string> names;
  for (const auto& f : store.scalar_fields())
    names.insert(f.name);
  for (const auto& f : store.vector_fields())
    names.insert(f.name);
  for (const auto& f : store.integer_fields())
    names.insert(f.name);
  for (const auto& f : store.id_fields())
    names.insert(f.name);
  return names;
}

// The fields of the checkpoint must be those of the store: a field of one and not the other
// means another method set-up (another rheology, a different wall treatment).
void check_fields(const ParticleStore& store, const StateArchive& archive,
                  const std::string& prefix) {
  const std::string folder = prefix + "fields/";
  std::set<std::string> saved;
  for (const std::string& path : archive.paths()) {
    if (path.rfind(folder, 0) == 0)
      saved.insert(path.substr(folder.size()));
  }
  const std::set<std::string> built = field_names(store);
  for (const std::string& name : saved) {
    if (built.count(name) == 0)
      throw StateError(
          fmt::format("the checkpoint has the particle field '{}' under {}, which "
                      "the case does not make",
                      name, prefix));
  }
  for (const std::string& name : built) {
    if (saved.count(name) == 0)
      throw StateError(
          fmt::format("the case makes the particle field '{}', which the "
                      "checkpoint does not have under {}",
                      name, prefix));
  }
}

}  // namespace

void save_store(const ParticleStore& store, StateArchive& archive, const std::string& prefix) {
  archive.put_integers(prefix + "particles",
                       std::vector<std::int64_t>{static_cast<std::int64_t>(store.size())});
  for (const auto& field : store.scalar_fields())
    archive.put_doubles(field_path(prefix, field.name), field.values);
  for (const auto& field : store.vector_fields())
    archive.put_vectors(field_path(prefix, field.name), field.values);
  save_integers(store.integer_fields(), archive, prefix);
  save_integers(store.id_fields(), archive, prefix);
}

void restore_store(ParticleStore& store, const StateArchive& archive, const std::string& prefix,
                   bool count_may_change) {
  const auto saved = archive.integers(prefix + "particles");
  // The count is taken only when a saved field has that many values (the file's size bounds
  // them), so a crafted count cannot make the store allocate.
  if (count_may_change && saved.size() == 1 &&
      saved[0] == static_cast<std::int64_t>(archive.doubles(field_path(prefix, "mass")).size())) {
    store.resize(static_cast<std::size_t>(saved[0]));
  }
  if (saved.size() != 1 || saved[0] != static_cast<std::int64_t>(store.size())) {
    throw StateError(fmt::format("the checkpoint holds {} particles under {}, the case builds {}",
                                 saved.empty() ? 0 : saved[0], prefix, store.size()));
  }
  check_fields(store, archive, prefix);
  const std::size_t count = store.size();
  for (auto& field : store.scalar_fields()) {
    const std::string path = field_path(prefix, field.name);
    const auto values = sized(archive.doubles(path), count, path);
    std::copy(values.begin(), values.end(), field.values.begin());
  }
  for (auto& field : store.vector_fields()) {
    const std::string path = field_path(prefix, field.name);
    field.values = sized(archive.vectors(path), count, path);
  }
  restore_integers(store.integer_fields(), archive, prefix, count, !count_may_change);
  restore_integers(store.id_fields(), archive, prefix, count, !count_may_change);
}

}  // namespace partimix
