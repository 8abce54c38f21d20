// libFuzzer target: the checkpoint reader, io::read_checkpoint (src/io/checkpoint_file.hpp),
// and the resume steps that decode the archive it returns.
//
// Input: one mode byte, then the bytes of a checkpoint file. Mode bit 0 clear: the bytes are
// the file as they are, so the fuzzer meets the header check (src/io/checkpoint_header.cpp),
// which refuses nearly every mutation at its length or checksum. Mode bit 0 set: the first 512
// bytes (the header; zeros are added to a shorter input) are replaced by a header that is valid
// for the bytes after it, written as checkpoint_header::stamp writes it, so that the HDF5 part
// and the archive decoding (src/io/checkpoint_reader.cpp) see the mutated file. The file is
// written to a fixed path in /tmp (removed first, so each input is a new inode and HDF5 cannot
// mistake it for a file it still holds open).
//
// A checkpoint that reads is then resumed as `partimix run --resume` would, into the case
// fuzz/seeds/checkpoint_case.yaml (SPH and DEM): app::check_checkpoint_matches, and when it
// matches app::restore_run_state and each method's Solver::restore on a freshly built
// simulation.
//
// Expected: success; partimix::InputError from read_checkpoint and check_checkpoint_matches
// (exit 2 in the app); partimix::StateError from the restores (which the app turns into
// InputError). A finding: any other exception (reported and aborted on), a crash, a sanitizer
// report (ASan, UBSan, LeakSanitizer), a timeout, running out of memory, or HDF5 identifiers
// still open after read_checkpoint returned or threw.
#include <fmt/format.h>
#include <hdf5.h>
#include <omp.h>
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <typeinfo>

#include "app/checkpoint_match.hpp"
#include "app/run_state.hpp"
#include "app/simulation.hpp"
#include "core/error.hpp"
#include "core/state_archive.hpp"
#include "io/case.hpp"
#include "io/checkpoint_file.hpp"
#include "io/checkpoint_header.hpp"

#ifndef PARTIMIX_FUZZ_SEEDS_DIR
#error "PARTIMIX_FUZZ_SEEDS_DIR must name fuzz/seeds (fuzz/CMakeLists.txt)"
#endif

namespace {

namespace io = partimix::io;
constexpr std::size_t kHeaderBytes = io::checkpoint_header::kBytes;

[[noreturn]] void fail(const std::string& what) {
  std::fprintf(stderr, "checkpoint_reader_fuzz: %s\n", what.c_str());
  std::abort();
}

const std::filesystem::path& checkpoint_file() {
  static const std::filesystem::path file =
      std::filesystem::temp_directory_path() /
      ("partimix-fuzz-checkpoint-" + std::to_string(static_cast<long>(::getpid())) + ".h5");
  return file;
}

void remove_checkpoint_file() {
  std::error_code ignored;
  std::filesystem::remove(checkpoint_file(), ignored);
}

// 64-bit FNV-1a over `bytes`, the checksum of the header's `fnv1a64` line.
std::uint64_t fnv1a64(std::string_view bytes) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const char c : bytes) {
    hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
  }
  return hash;
}

// `file` with its first kHeaderBytes replaced by a header that is valid for the rest.
std::string with_repaired_header(std::string file) {
  file.resize(std::max(file.size(), kHeaderBytes), '\0');
  const std::string_view body = std::string_view(file).substr(kHeaderBytes);
  std::string header =
      fmt::format("{}\nformat_version {}\npartimix_version {}\nfile_bytes {}\nfnv1a64 {:016x}\n",
                  io::checkpoint_header::kFormatName, io::kCheckpointFormatVersion,
                  PARTIMIX_VERSION, file.size(), fnv1a64(body));
  header.resize(kHeaderBytes, '\0');
  file.replace(0, kHeaderBytes, header);
  return file;
}

void write_checkpoint_file(std::string_view bytes) {
  remove_checkpoint_file();
  std::ofstream out(checkpoint_file(), std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out) {
    fail("cannot write " + checkpoint_file().string());
  }
}

const io::Case& resume_case() {
  static const io::Case the_case =
      io::load_case(std::string(PARTIMIX_FUZZ_SEEDS_DIR) + "/checkpoint_case.yaml");
  return the_case;
}

void check_no_open_hdf5_objects(const char* after) {
  const ssize_t open = H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL);
  if (open != 0) {
    fail(fmt::format("{} HDF5 identifiers still open after {}", open, after));
  }
}

// The resume steps after the read: the case check, then the run state and the methods' states.
void resume(const partimix::StateArchive& archive) {
  try {
    partimix::app::check_checkpoint_matches(resume_case(), archive, checkpoint_file());
  } catch (const partimix::InputError&) {
    return;  // not a checkpoint of this case: the app refuses it with exit 2
  }
  try {
    partimix::app::restore_run_state(archive);
    partimix::app::Simulation simulation =
        partimix::app::build_simulation(resume_case(), {.for_restore = true});
    for (std::size_t m = 0; m < simulation.methods.size(); ++m) {
      simulation.methods[m].solver->restore(archive,
                                            "methods/" + resume_case().methods[m].name + "/");
    }
  } catch (const partimix::StateError&) {
    // The checkpoint does not fit the simulation: the app refuses it with exit 2.
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  omp_set_num_threads(1);
  resume_case();  // a broken case file stops here, before any input
  std::atexit(remove_checkpoint_file);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) {
    return 0;
  }
  const bool repair = (data[0] & 1) != 0;
  std::string file(reinterpret_cast<const char*>(data) + 1, size - 1);
  if (repair) {
    file = with_repaired_header(std::move(file));
  }
  write_checkpoint_file(file);
  try {
    std::optional<partimix::StateArchive> archive;
    try {
      archive = io::read_checkpoint(checkpoint_file());
    } catch (const partimix::InputError&) {
      // The expected refusal of a bad checkpoint.
    }
    check_no_open_hdf5_objects("read_checkpoint");
    if (archive) {
      resume(*archive);
    }
  } catch (const std::exception& error) {
    fail(fmt::format("unexpected {}: {}", typeid(error).name(), error.what()));
  }
  return 0;
}
