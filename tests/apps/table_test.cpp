// The CLI's aligned text table: a column with a width limit wraps a long list after its
// separators, and every other column stays aligned across the continuation lines.
#include "swept/bench/output.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace swept::bench {
namespace {

std::vector<std::string> lines_of(const Table& t) {
  std::ostringstream os;
  t.print(os);
  std::vector<std::string> out;
  std::istringstream in(os.str());
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

TEST(Table, AlignsTextLeftAndNumbersRight) {  // the header row is text throughout
  Table t({"name", "n"});
  t.add({"a", "7"});
  t.add({"longer", "123"});
  EXPECT_EQ(lines_of(t), (std::vector<std::string>{"name    n", "a         7", "longer  123"}));
}

// A group of 19 parts is one cell of 19 names joined by " + ": limited to 30 characters, it
// takes as many lines as it needs, none wider than 30, broken only after a " + ", and the
// column after it starts at the same place on every line.
TEST(Table, WrapsALimitedColumnAfterItsSeparators) {
  std::string group;
  for (int i = 0; i < 19; ++i) group += (i ? " + " : "") + std::string("part_") + std::to_string(100 + i);
  Table t({"#", "part", "status"});
  t.limit_width(1, 30);
  t.add({"1", group, "removed"});
  t.add({"2", "bolt", "removed"});
  const auto lines = lines_of(t);
  ASSERT_GT(lines.size(), 3u);
  const std::size_t status_at = lines[0].find("status");
  ASSERT_NE(status_at, std::string::npos);
  EXPECT_EQ(status_at, 1u + 2u + 30u + 2u);  // "#", the limited column, two gaps
  std::string joined;
  for (std::size_t i = 1; i + 1 < lines.size(); ++i) {
    const std::string part = lines[i].substr(3, std::min<std::size_t>(30, lines[i].size() - 3));
    EXPECT_LE(lines[i].find_last_not_of(' ') + 1, i == 1 ? status_at + 7 : 3u + 30u) << lines[i];
    std::string trimmed = part.substr(0, part.find_last_not_of(' ') + 1);
    if (i > 1) EXPECT_EQ(lines[i].substr(0, 3), "   ");  // continuation: the other cells blank
    if (i + 2 < lines.size()) EXPECT_EQ(trimmed.substr(trimmed.size() - 2), " +") << trimmed;
    joined += (joined.empty() ? "" : " ") + trimmed;
  }
  EXPECT_EQ(joined, group);
  EXPECT_EQ(lines[1].substr(status_at), "removed");
  EXPECT_EQ(lines.back(), "2  bolt" + std::string(status_at - 7, ' ') + "removed");
}

// A name with no separator in it is never cut, however long; a ", " list breaks after a comma.
TEST(Table, NeverCutsInsideAName) {
  Table t({"blockers"});
  t.limit_width(0, 10);
  t.add({"a_very_long_part_name, b"});
  EXPECT_EQ(lines_of(t), (std::vector<std::string>{"blockers", "a_very_long_part_name,", "b"}));
}

}  // namespace
}  // namespace swept::bench
