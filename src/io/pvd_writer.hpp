#pragma once
// The .pvd collection that ParaView opens to play a run's frames in time. Every add() rewrites
// the whole file atomically, so the collection stays valid and lists every frame written so
// far even if the run dies.
#include <filesystem>
#include <string>
#include <vector>

namespace partimix::io {

struct PvdEntry {
  double time = 0.0;
  std::string path;  // relative to the .pvd's folder
};

class PvdWriter {
 public:
  // A collection that lists `entries` already (a resumed run's frames before its checkpoint).
  explicit PvdWriter(std::filesystem::path file, std::vector<PvdEntry> entries = {});

  // Lists the frame at relative_frame_path (relative to the .pvd's folder) at the given time
  // and rewrites the collection. Throws RunError naming the file on an I/O failure.
  void add(double time, const std::string& relative_frame_path);
  // Rewrites the collection with the entries it has.
  void write() const;

  const std::vector<PvdEntry>& entries() const { return entries_; }

 private:
  std::filesystem::path file_;
  std::vector<PvdEntry> entries_;
};

}  // namespace partimix::io
