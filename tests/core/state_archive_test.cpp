// The in-memory archive of a run's state: each kind put and got back with its shape, paths
// checked when put, and a getter that does not fit the entry naming the path, what it expected
// and what it found.
#include "core/state_archive.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace partimix {
namespace {

// The StateError message of calling `get`, or "" when it does not throw.
template <typename Get>
std::string state_error(Get get) {
  try {
    get();
  } catch (const StateError& error) {
    return error.what();
  }
  return "";
}

TEST(StateArchive, PutsAndGetsEveryKind) {
  StateArchive archive;
  const std::vector<double> stress = {1, 2, 3, 4, 5, 6};
  const std::vector<std::int64_t> ids = {7, -8, 9};
  const std::vector<Vec3> positions = {Vec3(1, 2, 3), Vec3(-4, 5.5, 0)};
  archive.put_doubles("sph/stress", stress, 2);
  archive.put_integers("sph/id", ids);
  archive.put_text("case", "fluid: water\n");
  archive.put_scalar("time", 0.25);
  archive.put_vectors("sph/position", positions);

  const auto got_stress = archive.doubles("sph/stress", 2);
  EXPECT_EQ(std::vector<double>(got_stress.begin(), got_stress.end()), stress);
  const auto got_ids = archive.integers("sph/id");
  EXPECT_EQ(std::vector<std::int64_t>(got_ids.begin(), got_ids.end()), ids);
  EXPECT_EQ(archive.text("case"), "fluid: water\n");
  EXPECT_EQ(archive.scalar("time"), 0.25);
  EXPECT_EQ(archive.doubles("time").size(), 1u);
  EXPECT_EQ(archive.vectors("sph/position"), positions);
  EXPECT_EQ(archive.doubles("sph/position", 3).size(), 6u);
}

TEST(StateArchive, EntriesGiveKindAndShapeSortedByPath) {
  StateArchive archive;
  archive.put_text("b/text", "x");
  archive.put_integers("a/ints", std::vector<std::int64_t>(12, 1), 4);
  archive.put_doubles("c", std::vector<double>{}, 3);

  EXPECT_EQ(archive.paths(), (std::vector<std::string>{"a/ints", "b/text", "c"}));
  const auto& entries = archive.entries();
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_EQ(entries.at("a/ints").kind, StateArchive::Kind::integers);
  EXPECT_EQ(entries.at("a/ints").rows(), 3u);
  EXPECT_EQ(entries.at("a/ints").columns, 4u);
  EXPECT_EQ(entries.at("b/text").kind, StateArchive::Kind::text);
  EXPECT_EQ(entries.at("c").kind, StateArchive::Kind::doubles);
  EXPECT_EQ(entries.at("c").rows(), 0u);
  EXPECT_EQ(entries.at("c").columns, 3u);
  EXPECT_TRUE(archive.contains("c"));
  EXPECT_FALSE(archive.contains("a"));
  EXPECT_TRUE(archive.doubles("c", 3).empty());
}

TEST(StateArchive, PuttingAPathAgainReplacesIt) {
  StateArchive archive;
  archive.put_scalar("x", 1.0);
  archive.put_scalar("x", 2.0);
  EXPECT_EQ(archive.scalar("x"), 2.0);
  archive.put_text("x", "now a text");
  EXPECT_EQ(archive.text("x"), "now a text");
  EXPECT_EQ(archive.paths().size(), 1u);
}

TEST(StateArchive, AcceptsPathsOfTheAllowedCharacters) {
  for (const std::string path :
       {"methods/sph/fields/position", "a", "A.b+c-d_e/F9", "x/.hidden", "v1.2/3..4"}) {
    EXPECT_TRUE(StateArchive::is_valid_path(path)) << path;
  }
}

TEST(StateArchive, RefusesBadPaths) {
  StateArchive archive;
  for (const std::string path :
       {"", "/a", "a/", "a//b", "a b", "a/./b", ".", "..", "a/..", "ä", "a\\b", "a:b", "tab\t"}) {
    EXPECT_FALSE(StateArchive::is_valid_path(path)) << path;
    EXPECT_THROW(archive.put_scalar(path, 1.0), std::invalid_argument) << path;
    EXPECT_THROW(archive.put_text(path, ""), std::invalid_argument) << path;
  }
  EXPECT_TRUE(archive.paths().empty());
}

TEST(StateArchive, RefusesSizesThatDoNotFillTheColumns) {
  StateArchive archive;
  EXPECT_THROW(archive.put_doubles("d", std::vector<double>(5, 0.0), 3), std::invalid_argument);
  EXPECT_THROW(archive.put_integers("i", std::vector<std::int64_t>(4, 0), 3),
               std::invalid_argument);
  EXPECT_THROW(archive.put_doubles("d", std::vector<double>{}, 0), std::invalid_argument);
  EXPECT_THROW(archive.put_integers("i", std::vector<std::int64_t>{}, 0), std::invalid_argument);
  EXPECT_FALSE(archive.contains("d"));
  EXPECT_FALSE(archive.contains("i"));
}

// In the file an entry is a dataset and a path prefix a group: one name cannot be both.
TEST(StateArchive, RefusesAnEntryUnderAnotherEntry) {
  StateArchive archive;
  archive.put_scalar("a/b", 1.0);
  EXPECT_THROW(archive.put_scalar("a/b/c", 1.0), std::invalid_argument);
  EXPECT_THROW(archive.put_scalar("a", 1.0), std::invalid_argument);
  archive.put_scalar("a/bc", 1.0);
  archive.put_scalar("a/b.c", 1.0);
  archive.put_scalar("a/b", 2.0);
  EXPECT_EQ(archive.paths(), (std::vector<std::string>{"a/b", "a/b.c", "a/bc"}));
}

TEST(StateArchive, MissingPathThrowsStateErrorNamingIt) {
  const StateArchive archive;
  const std::string message = state_error([&] { archive.doubles("methods/sph/velocity", 3); });
  EXPECT_NE(message.find("'methods/sph/velocity'"), std::string::npos) << message;
  EXPECT_NE(message.find("expected 3-column doubles"), std::string::npos) << message;
  EXPECT_NE(message.find("no such entry"), std::string::npos) << message;
  EXPECT_THROW(archive.text("t"), StateError);
  EXPECT_THROW(archive.scalar("s"), StateError);
  EXPECT_THROW(archive.vectors("v"), StateError);
  EXPECT_THROW(archive.integers("i"), StateError);
}

TEST(StateArchive, OtherKindThrowsStateErrorSayingWhatWasFound) {
  StateArchive archive;
  archive.put_integers("ids", std::vector<std::int64_t>{1, 2});
  archive.put_text("note", "abc");
  archive.put_scalar("time", 1.0);

  const std::string message = state_error([&] { archive.doubles("ids"); });
  EXPECT_NE(message.find("'ids'"), std::string::npos) << message;
  EXPECT_NE(message.find("expected 1-column doubles"), std::string::npos) << message;
  EXPECT_NE(message.find("found 2 x 1 integers"), std::string::npos) << message;
  EXPECT_NE(state_error([&] { archive.text("time"); }).find("found 1 x 1 doubles"),
            std::string::npos);
  EXPECT_NE(state_error([&] { archive.integers("note"); }).find("found a text of 3 bytes"),
            std::string::npos);
}

TEST(StateArchive, OtherShapeThrowsStateError) {
  StateArchive archive;
  archive.put_doubles("pairs", std::vector<double>(6, 0.0), 2);
  archive.put_doubles("list", std::vector<double>(4, 0.0));
  archive.put_integers("table", std::vector<std::int64_t>(6, 0), 3);

  const std::string message = state_error([&] { archive.doubles("pairs"); });
  EXPECT_NE(message.find("found 3 x 2 doubles"), std::string::npos) << message;
  EXPECT_THROW(archive.vectors("pairs"), StateError);
  EXPECT_THROW(archive.integers("table", 2), StateError);
  const std::string scalar = state_error([&] { archive.scalar("list"); });
  EXPECT_NE(scalar.find("expected a scalar"), std::string::npos) << scalar;
  EXPECT_NE(scalar.find("found 4 x 1 doubles"), std::string::npos) << scalar;
}

}  // namespace
}  // namespace partimix
