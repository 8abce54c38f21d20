#pragma once
// An output folder and what partimix wrote into it (docs/case-reference.md, "Outputs"): every
// file and folder a run, a sweep or `plot` creates there is listed, one path per line relative
// to the folder, in its manifest `.partimix-files`. A new run into the folder removes exactly
// those (and its own subfolders' listed files), never a file of the user's: a folder that holds
// files but no manifest is refused unless the user says --overwrite, and then nothing in it is
// removed.
#include <filesystem>
#include <string>

namespace partimix::app {

inline constexpr const char* kManifestName = ".partimix-files";

// Throws InputError (at "--out") when `dir` holds files but no manifest and not `overwrite`:
// what prepare_output_folder would refuse, checked before a run spends time on its set-up.
void check_output_folder(const std::filesystem::path& dir, bool overwrite);

// Makes `dir` ready for a new run or sweep: created if missing, else cleared of what the
// manifest lists, and given an empty manifest. Throws InputError (at "--out") for a folder with
// files of others and no `overwrite`, RunError when the file system refuses.
void prepare_output_folder(const std::filesystem::path& dir, bool overwrite);

// Adds `relative` (a file or folder partimix is writing in `dir`) to the manifest.
void record_output(const std::filesystem::path& dir, const std::string& relative);

}  // namespace partimix::app
