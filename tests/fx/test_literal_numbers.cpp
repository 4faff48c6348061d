// The one reading of literal values outside the effect's syntax (fx/LiteralNumbers.h): what --set gives a
// parameter and what a script's ClearSet*/LoopByCount literal holds read alike.
#include <fx/LiteralNumbers.h>

#include <gtest/gtest.h>

namespace fx::test_literal_numbers {
namespace {

TEST(LiteralNumbers, ListsInEitherSpelling) {
    EXPECT_EQ(parseLiteralNumbers("1,0,0,1"), (std::vector<float>{1, 0, 0, 1}));
    EXPECT_EQ(parseLiteralNumbers("{1, 0.5, -2e-1}"), (std::vector<float>{1, 0.5f, -0.2f}));
    EXPECT_EQ(parseLiteralNumbers("4"), (std::vector<float>{4}));
    EXPECT_EQ(parseLiteralNumbers("TRUE false"), (std::vector<float>{1, 0}));
    EXPECT_EQ(parseLiteralNumbers("  "), std::vector<float>{});  // no words: the caller judges
}

TEST(LiteralNumbers, EveryWordWholeAndFinite) {
    EXPECT_FALSE(parseLiteralNumbers("0.5f"));
    EXPECT_FALSE(parseLiteralNumbers("1,two,3"));
    EXPECT_FALSE(parseLiteralNumbers("1e40"));  // beyond float
    EXPECT_FALSE(parseLiteralNumbers("nan"));
    EXPECT_FALSE(parseLiteralNumbers("ClearColor"));  // a name, which the callers look up first
}

}  // namespace
}  // namespace fx::test_literal_numbers
