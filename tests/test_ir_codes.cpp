#include <rfir/obs/ir_codes.h>

#include <gtest/gtest.h>

using namespace rfir::ir;

TEST(IRCodes, IdsAndCounts) {
    EXPECT_EQ(emitterIdFromCodes({3, 9}), "39");
    EXPECT_EQ(*codesFromEmitterId("39"), (std::vector<uint8_t>{3, 9}));
    EXPECT_FALSE(codesFromEmitterId("93"));
    EXPECT_FALSE(codesFromEmitterId("0"));
    EXPECT_FALSE(codesFromEmitterId(""));
    EXPECT_EQ(countIds(9, 9), 511u);
    EXPECT_EQ(countIds(30, 6), 768211u);
    EXPECT_EQ(*parseCodeList("1,5,9"), (std::vector<uint8_t>{1, 5, 9}));
    EXPECT_FALSE(parseCodeList("5,1"));
    EXPECT_FALSE(parseCodeList("1,,2"));
    EXPECT_FALSE(parseCodeList("10"));
    EXPECT_DOUBLE_EQ(codeFrequencyHz(9), 1150.0);
}
