#pragma once
// Where partimix finds its helper scripts (tools/): the PARTIMIX_TOOLS_DIR environment variable
// if set, else the tools folder of the source tree it was built from.
#include <filesystem>

namespace partimix::app {

std::filesystem::path tools_dir();

}  // namespace partimix::app
