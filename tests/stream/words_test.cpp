// split_words, the splitter of the devices' --mode specs: the words in order, empty words
// kept (a spec's empty word is refused by name, not skipped).
#include "stream/words.h"

#include <gtest/gtest.h>

#include <string_view>
#include <vector>

namespace rs4sim::stream {
namespace {

using Words = std::vector<std::string_view>;

TEST(SplitWords, CommaSeparatedWordsInOrder) {
  EXPECT_EQ(split_words("blanking,cycle=30"), (Words{"blanking", "cycle=30"}));
  EXPECT_EQ(split_words("FL1"), (Words{"FL1"}));
}

TEST(SplitWords, EmptyWordsAreKept) {
  EXPECT_EQ(split_words(""), (Words{""}));
  EXPECT_EQ(split_words("slave,,input=NPN"), (Words{"slave", "", "input=NPN"}));
  EXPECT_EQ(split_words("FL1,"), (Words{"FL1", ""}));
}

TEST(SplitWords, AnotherSeparator) {
  EXPECT_EQ(split_words("first+last+count", '+'), (Words{"first", "last", "count"}));
}

}  // namespace
}  // namespace rs4sim::stream
