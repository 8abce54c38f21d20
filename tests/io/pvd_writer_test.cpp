// The .pvd collection lists every frame added so far, with its time, after every add.
#include "io/pvd_writer.hpp"

#include <gtest/gtest.h>

#include <map>
#include <regex>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "io/test_files.hpp"

namespace partimix::io {
namespace {

using test::read_file;
using test::TempDir;

using Attributes = std::map<std::string, std::string>;

std::vector<Attributes> data_sets(const std::string& xml) {
  static const std::regex data_set(R"re(<DataSet([^>]*)/>)re");
  static const std::regex attribute(R"re(([A-Za-z_]+)="([^"]*)")re");
  std::vector<Attributes> entries;
  for (std::sregex_iterator it(xml.begin(), xml.end(), data_set), end; it != end; ++it) {
    const std::string text = (*it)[1];
    Attributes attributes;
    for (std::sregex_iterator a(text.begin(), text.end(), attribute); a != end; ++a) {
      attributes[(*a)[1]] = (*a)[2];
    }
    entries.push_back(attributes);
  }
  return entries;
}

TEST(PvdWriter, ListsEveryFrameAfterEachAdd) {
  TempDir dir;
  PvdWriter writer(dir / "frames.pvd");
  const std::vector<double> times = {0.0, 0.1, 2.5e-3};
  for (std::size_t k = 0; k < times.size(); ++k) {
    writer.add(times[k], "frames/frame_" + std::to_string(k) + ".vtp");
    EXPECT_EQ(data_sets(read_file(dir / "frames.pvd")).size(), k + 1);
  }
  const std::string xml = read_file(dir / "frames.pvd");
  EXPECT_EQ(xml.rfind("<?xml version=\"1.0\"?>\n", 0), 0U);
  EXPECT_NE(xml.find("<VTKFile type=\"Collection\" version=\"1.0\""), std::string::npos);
  EXPECT_NE(xml.find("<Collection>"), std::string::npos);
  EXPECT_NE(xml.find("</Collection>\n</VTKFile>\n"), std::string::npos);
  const auto entries = data_sets(xml);
  ASSERT_EQ(entries.size(), 3U);
  for (std::size_t k = 0; k < entries.size(); ++k) {
    EXPECT_EQ(std::stod(entries[k].at("timestep")), times[k]);
    EXPECT_EQ(entries[k].at("group"), "");
    EXPECT_EQ(entries[k].at("part"), "0");
    EXPECT_EQ(entries[k].at("file"), "frames/frame_" + std::to_string(k) + ".vtp");
  }
  EXPECT_EQ(test::count_tmp_files(dir.path()), 0);
}

TEST(PvdWriter, EscapesFileNames) {
  TempDir dir;
  PvdWriter writer(dir / "frames.pvd");
  writer.add(1.0, "a&b\".vtp");
  EXPECT_EQ(data_sets(read_file(dir / "frames.pvd")).at(0).at("file"), "a&amp;b&quot;.vtp");
}

TEST(PvdWriter, UnwritableFolderThrowsRunErrorNamingFile) {
  TempDir dir;
  const auto file = dir / "missing" / "frames.pvd";
  PvdWriter writer(file);
  try {
    writer.add(0.0, "frame.vtp");
    FAIL() << "expected RunError";
  } catch (const RunError& error) {
    EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace partimix::io
