// The progress line on a fake clock: plain lines at the interval, a live line redrawn with
// '\r' at most five times a second, and percent, ETA and throughput computed right.
#include "core/progress.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

namespace partimix {
namespace {

// A temporary stream whose content the test reads back.
class CapturedStream {
 public:
  CapturedStream() : file_(std::tmpfile(), &std::fclose) {}
  std::FILE* get() const { return file_.get(); }
  std::string text() const {
    std::fflush(file_.get());
    std::rewind(file_.get());
    std::string text;
    for (int c = std::fgetc(file_.get()); c != EOF; c = std::fgetc(file_.get())) {
      text += static_cast<char>(c);
    }
    return text;
  }

 private:
  std::unique_ptr<std::FILE, decltype(&std::fclose)> file_;
};

std::size_t count(const std::string& text, char c) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), c));
}

TEST(Progress, PlainModeWithZeroIntervalPrintsEveryUpdate) {
  CapturedStream stream;
  double now = 0.0;
  Progress progress(1.0, stream.get(), false, 0.0, [&now] { return now; });
  for (int k = 1; k <= 4; ++k) {
    now = k;
    progress.update(0.25 * k, 10 * static_cast<std::size_t>(k), 100);
  }
  const std::string text = stream.text();
  EXPECT_EQ(count(text, '\n'), 4U);
  EXPECT_EQ(count(text, '\r'), 0U);
  EXPECT_NE(text.find("25.0%"), std::string::npos) << text;
  EXPECT_NE(text.find("100.0%"), std::string::npos) << text;
  progress.finish();
  EXPECT_EQ(stream.text(), text) << "finish repeats nothing already printed";
}

TEST(Progress, PlainModeWaitsForTheInterval) {
  CapturedStream stream;
  double now = 0.0;
  Progress progress(2.0, stream.get(), false, 5.0, [&now] { return now; });
  now = 1.0;
  progress.update(0.1, 1, 10);
  EXPECT_EQ(stream.text(), "");
  now = 6.0;
  progress.update(0.5, 2, 10);
  now = 7.0;
  progress.update(0.6, 3, 10);
  EXPECT_EQ(count(stream.text(), '\n'), 1U);
  progress.finish();
  progress.finish();
  EXPECT_EQ(count(stream.text(), '\n'), 2U) << "finish prints the last state once";
}

TEST(Progress, LineShowsTimePercentEtaAndThroughput) {
  CapturedStream stream;
  double now = 0.0;
  Progress progress(1.0, stream.get(), false, 0.0, [&now] { return now; });
  now = 10.0;
  progress.update(0.25, 100, 1000);
  EXPECT_EQ(stream.text(), "t = 0.25 s  25.0%  ETA 00:00:30  1.00e+04 particle-steps/s\n");
}

TEST(Progress, LiveModeRedrawsOneLineAtMostFiveTimesASecond) {
  CapturedStream stream;
  double now = 0.0;
  Progress progress(1.0, stream.get(), true, 5.0, [&now] { return now; });
  now = 0.25;
  progress.update(0.1, 1, 10);
  now = 0.3;
  progress.update(0.2, 2, 10);
  now = 0.5;
  progress.update(0.3, 3, 10);
  const std::string text = stream.text();
  EXPECT_EQ(count(text, '\r'), 2U) << text;
  EXPECT_EQ(count(text, '\n'), 0U) << text;
  progress.finish();
  const std::string finished = stream.text();
  EXPECT_EQ(finished.back(), '\n');
  EXPECT_EQ(count(finished, '\n'), 1U);
}

TEST(Progress, UnknownEtaBeforeAnyProgress) {
  CapturedStream stream;
  double now = 0.0;
  Progress progress(1.0, stream.get(), false, 0.0, [&now] { return now; });
  now = 1.0;
  progress.update(0.0, 0, 10);
  EXPECT_NE(stream.text().find("ETA --:--:--"), std::string::npos) << stream.text();
}

}  // namespace
}  // namespace partimix
