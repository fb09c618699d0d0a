// Escaped / Quoted: a name from outside stays on its line.
#include <gtest/gtest.h>

#include "runtime/escaped.h"

namespace {

TEST(Escaped, ControlCharactersAndBackslashesAreWrittenOut) {
  EXPECT_EQ(ws::Escaped("calib.yaml"), "calib.yaml");
  EXPECT_EQ(ws::Escaped("a\nINFO forged line"), "a\\nINFO forged line");
  EXPECT_EQ(ws::Escaped(std::string("\r\t\x1b[2J\\", 7)), "\\r\\t\\x1b[2J\\\\");
  EXPECT_EQ(ws::Escaped(std::string("\0\x7f", 2)), "\\x00\\x7f");
  EXPECT_EQ(ws::Quoted("x\ny"), "'x\\ny'");
}

}  // namespace
