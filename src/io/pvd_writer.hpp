#pragma once
// The .pvd collection that ParaView opens to play a run's frames in time. Every add() rewrites
// the whole file atomically, so the collection stays valid and lists every frame written so
// far even if the run dies.
#include <filesystem>
#include <string>
#include <vector>

namespace partimix::io {

class PvdWriter {
 public:
  explicit PvdWriter(std::filesystem::path file);

  // Lists the frame at relative_frame_path (relative to the .pvd's folder) at the given time
  // and rewrites the collection. Throws RunError naming the file on an I/O failure.
  void add(double time, const std::string& relative_frame_path);

 private:
  struct Entry {
    double time = 0.0;
    std::string path;
  };

  std::filesystem::path file_;
  std::vector<Entry> entries_;
};

}  // namespace partimix::io
