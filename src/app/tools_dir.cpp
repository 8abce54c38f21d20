#include "app/tools_dir.hpp"

#include <cstdlib>

namespace partimix::app {

std::filesystem::path tools_dir() {
  const char* tools = std::getenv("PARTIMIX_TOOLS_DIR");
  return tools ? tools : PARTIMIX_TOOLS_DIR;
}

}  // namespace partimix::app
