#pragma once
// Whether a checkpoint belongs to a case (docs/architecture-notes.md, "Checkpoints"): a run
// resumes only from a checkpoint of the same case, every resolved key equal but time.end (a run
// may be extended), time.checkpoint_interval and description.
#include <filesystem>

#include "core/state_archive.hpp"
#include "io/case.hpp"

namespace partimix::app {

// Throws InputError naming the checkpoint file and the first key that differs.
void check_checkpoint_matches(const io::Case& the_case, const StateArchive& checkpoint,
                              const std::filesystem::path& file);

}  // namespace partimix::app
