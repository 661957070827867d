// LineReader: LF and CR LF endings, a last line without LF, long lines.
#include <gtest/gtest.h>

#include <string>

#include "firmware/host/dataset/line_reader.hpp"
#include "host_tests/support/temp_dir.hpp"

using sinu::dataset::LineReader;

TEST(LineReader, AcceptsLfAndCrLfAndAMissingFinalNewline) {
  sinu::test::TempDir dir;
  const auto path = dir.write("x.txt", "a,b\r\nc\n\nlast");
  LineReader r;
  ASSERT_TRUE(r.open(path));
  std::string_view line;
  ASSERT_EQ(r.next(line), LineReader::Status::Line);
  EXPECT_EQ(line, "a,b");
  ASSERT_EQ(r.next(line), LineReader::Status::Line);
  EXPECT_EQ(line, "c");
  ASSERT_EQ(r.next(line), LineReader::Status::Line);
  EXPECT_EQ(line, "");
  ASSERT_EQ(r.next(line), LineReader::Status::Line);
  EXPECT_EQ(line, "last");
  EXPECT_EQ(r.line_number(), 4u);
  EXPECT_EQ(r.next(line), LineReader::Status::End);
}

TEST(LineReader, LinesAcrossManyRefillsStayIntact) {
  // 300 k lines of varying length cross the 256 KiB refill boundary many times.
  sinu::test::TempDir dir;
  std::string text;
  for (int i = 0; i < 300000; ++i) text += std::to_string(i) + std::string(static_cast<std::size_t>(i % 7), 'x') + "\n";
  const auto path = dir.write("big.txt", text);
  LineReader r;
  ASSERT_TRUE(r.open(path));
  std::string_view line;
  for (int i = 0; i < 300000; ++i) {
    ASSERT_EQ(r.next(line), LineReader::Status::Line) << i;
    ASSERT_EQ(line, std::to_string(i) + std::string(static_cast<std::size_t>(i % 7), 'x'));
  }
  EXPECT_EQ(r.next(line), LineReader::Status::End);
}

TEST(LineReader, ReportsALineLongerThanItsBound) {
  sinu::test::TempDir dir;
  const auto path = dir.write("long.txt", "ok\n" + std::string(600 * 1024, 'y') + "\nafter\n");
  LineReader r(1024);
  ASSERT_TRUE(r.open(path));
  std::string_view line;
  ASSERT_EQ(r.next(line), LineReader::Status::Line);
  EXPECT_EQ(r.next(line), LineReader::Status::TooLong);
  EXPECT_EQ(r.line_number(), 2u);
  ASSERT_EQ(r.next(line), LineReader::Status::Line) << "reading goes on after the long line";
  EXPECT_EQ(line, "after");
  EXPECT_EQ(r.line_number(), 3u);
}

TEST(LineReader, ALongLineIsTooLongWhereverItFallsAgainstTheRefills) {
  // A 5000-byte line with a 4 KiB bound once came back whole or as an error
  // depending on whether it straddled the 256 KiB refill boundary.
  for (std::size_t before : {std::size_t{0}, std::size_t{100}, std::size_t{255 * 1024}, std::size_t{256 * 1024 - 2500},
                             std::size_t{256 * 1024 - 1}, std::size_t{300 * 1024}}) {
    sinu::test::TempDir dir;
    std::string pad;  // lines of at most 100 bytes, `before` bytes in all
    std::size_t pad_lines = 0;
    for (; pad.size() + 100 <= before; ++pad_lines) pad += std::string(99, 'p') + "\n";
    if (pad.size() < before) {
      pad += std::string(before - pad.size() - 1, 'q') + "\n";
      ++pad_lines;
    }
    const auto path = dir.write("x.txt", pad + std::string(5000, 'g') + "\nafter\n");
    LineReader r(4096);
    ASSERT_TRUE(r.open(path));
    std::string_view line;
    for (std::size_t i = 0; i < pad_lines; ++i) ASSERT_EQ(r.next(line), LineReader::Status::Line) << before;
    EXPECT_EQ(r.next(line), LineReader::Status::TooLong) << "padding " << before;
    ASSERT_EQ(r.next(line), LineReader::Status::Line) << before;
    EXPECT_EQ(line, "after") << before;
    EXPECT_EQ(r.next(line), LineReader::Status::End);
  }
}

TEST(LineReader, OpenFailsOnMissingFile) {
  LineReader r;
  EXPECT_FALSE(r.open("/nonexistent/file.csv"));
}
