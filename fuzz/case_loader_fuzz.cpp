// libFuzzer target: the case loader, io::load_case (src/io/case.hpp).
//
// Input: the YAML text of a case file, optionally followed by a line "---set" and then one
// `--set` override "key.path=value" per line (at most kMaxOverrides; longer inputs' extra lines
// are ignored). The YAML goes to a fixed file in a per-process folder under /tmp, beside two
// small STL meshes (cube.stl, closed; open.stl, a box without its lid) that `shape: mesh` items
// may name, and load_case reads it with the overrides.
//
// Expected: the case loads, or load_case throws partimix::InputError (bad input, exit 2 in the
// app). A finding: any other exception (reported and aborted on), a crash, a sanitizer report
// (ASan, UBSan, LeakSanitizer), a timeout or running out of memory.
//
// A loaded case is also built (app::build_simulation, with for_restore so that grains are
// inserted but not settled) when it is small: at most kMaxBuildCells cells of the SPH spacing in
// the domain and at most kMaxBuildGrains grains; a larger case is only loaded, since building
// it costs time in proportion to its size and says nothing new.
#include <omp.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <typeinfo>
#include <vector>

#include "app/simulation.hpp"
#include "core/error.hpp"
#include "io/case.hpp"

namespace {

constexpr std::string_view kSetSeparator = "\n---set\n";
constexpr std::size_t kMaxOverrides = 16;
constexpr double kMaxBuildCells = 4000.0;
constexpr double kMaxBuildGrains = 200.0;

// A closed unit cube, and the same cube without its top (z = 1) face: one face a line,
// corners counter-clockwise seen from outside.
constexpr double kCube[12][9] = {
    {0, 0, 0, 0, 1, 0, 1, 1, 0}, {0, 0, 0, 1, 1, 0, 1, 0, 0},  // z = 0
    {0, 0, 1, 1, 0, 1, 1, 1, 1}, {0, 0, 1, 1, 1, 1, 0, 1, 1},  // z = 1 (the lid)
    {0, 0, 0, 1, 0, 0, 1, 0, 1}, {0, 0, 0, 1, 0, 1, 0, 0, 1},  // y = 0
    {0, 1, 0, 0, 1, 1, 1, 1, 1}, {0, 1, 0, 1, 1, 1, 1, 1, 0},  // y = 1
    {0, 0, 0, 0, 0, 1, 0, 1, 1}, {0, 0, 0, 0, 1, 1, 0, 1, 0},  // x = 0
    {1, 0, 0, 1, 1, 0, 1, 1, 1}, {1, 0, 0, 1, 1, 1, 1, 0, 1},  // x = 1
};

std::string ascii_stl(bool with_lid) {
  std::string text = "solid cube\n";
  for (int t = 0; t < 12; ++t) {
    if (!with_lid && (t == 2 || t == 3)) {
      continue;
    }
    text += "facet normal 0 0 0\nouter loop\n";
    for (int k = 0; k < 3; ++k) {
      text += "vertex " + std::to_string(kCube[t][3 * k]) + " " +
              std::to_string(kCube[t][3 * k + 1]) + " " + std::to_string(kCube[t][3 * k + 2]) +
              "\n";
    }
    text += "endloop\nendfacet\n";
  }
  return text + "endsolid cube\n";
}

void write_file(const std::filesystem::path& file, std::string_view bytes) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) {
    std::fprintf(stderr, "case_loader_fuzz: cannot write %s\n", file.c_str());
    std::abort();
  }
}

const std::filesystem::path& scratch_dir() {
  static const std::filesystem::path dir =
      std::filesystem::temp_directory_path() /
      ("partimix-fuzz-case-" + std::to_string(static_cast<long>(::getpid())));
  return dir;
}

void remove_scratch_dir() {
  std::error_code ignored;
  std::filesystem::remove_all(scratch_dir(), ignored);
}

// The YAML text and the overrides of one input.
struct Input {
  std::string_view yaml;
  std::vector<std::string> overrides;
};

Input split(std::string_view data) {
  Input input;
  const std::size_t separator = data.find(kSetSeparator);
  input.yaml = data.substr(0, separator);
  if (separator == std::string_view::npos) {
    return input;
  }
  std::string_view rest = data.substr(separator + kSetSeparator.size());
  while (!rest.empty() && input.overrides.size() < kMaxOverrides) {
    const std::size_t end = rest.find('\n');
    input.overrides.emplace_back(rest.substr(0, end));
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
  }
  return input;
}

double number_at(const nlohmann::json& document, const nlohmann::json::json_pointer& at) {
  return document.contains(at) && document.at(at).is_number() ? document.at(at).get<double>() : 0.0;
}

// Whether building the case stays cheap: few SPH lattice cells in the domain, few grains.
bool small_enough_to_build(const partimix::io::Case& the_case) {
  using Pointer = nlohmann::json::json_pointer;
  if (the_case.method("sph") != nullptr) {
    const double spacing = number_at(the_case.resolved, Pointer("/sph/spacing"));
    if (!(spacing > 0.0)) {
      return false;
    }
    double cells = 1.0;
    for (int axis = 0; axis < the_case.domain.dimensions; ++axis) {
      cells *= the_case.domain.length()[axis] / spacing + 1.0;
    }
    if (!(cells <= kMaxBuildCells)) {
      return false;
    }
  }
  if (the_case.method("dem") != nullptr) {
    const double grains = number_at(the_case.resolved, Pointer("/dem/fill/count"));
    if (!(grains <= kMaxBuildGrains)) {
      return false;
    }
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  omp_set_num_threads(1);
  remove_scratch_dir();
  std::filesystem::create_directories(scratch_dir());
  write_file(scratch_dir() / "cube.stl", ascii_stl(true));
  write_file(scratch_dir() / "open.stl", ascii_stl(false));
  std::atexit(remove_scratch_dir);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Input input = split(std::string_view(reinterpret_cast<const char*>(data), size));
  const std::filesystem::path file = scratch_dir() / "case.yaml";
  write_file(file, input.yaml);
  try {
    const partimix::io::Case the_case = partimix::io::load_case(file.string(), input.overrides);
    if (small_enough_to_build(the_case)) {
      const partimix::app::Simulation simulation =
          partimix::app::build_simulation(the_case, {.for_restore = true});
    }
  } catch (const partimix::InputError&) {
    // The expected refusal of a bad case.
  } catch (const std::exception& error) {
    std::fprintf(stderr, "case_loader_fuzz: unexpected %s: %s\n", typeid(error).name(),
                 error.what());
    std::abort();
  }
  return 0;
}
