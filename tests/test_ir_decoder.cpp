#include <rfir/obs/ir_codes.h>
#include <rfir/obs/ir_decoder.h>

#include <gtest/gtest.h>

using namespace rfir::ir;

// Every one of the 511 IDs decodes from a clean window.
TEST(IRDecoder, AllIdsClean)
{
    const double rate = 8000;
    int ok = 0;
    for (int mask = 1; mask < 512; mask++)
    {
        std::vector<uint8_t> codes;
        std::vector<double> ph;
        for (int c = 1; c <= 9; c++)
            if (mask & (1 << (c - 1)))
            {
                codes.push_back(uint8_t(c));
                ph.push_back(0.137 * c);
            }
        auto x = synthesizeIRWindow(codes, 1.5, 0.3, rate, 800, ph);
        auto d = decodeIRWindow(x, rate);
        if (d.codes == codes && std::abs(d.volts - 1.5) < 0.1) ok++;
    }
    EXPECT_EQ(ok, 511);
}
