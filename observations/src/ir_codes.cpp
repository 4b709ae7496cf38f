/* rfir: IR emitter ID scheme. */
#include <rfir/obs/ir_codes.h>

#include <stdexcept>

namespace rfir::ir {
double codeFrequencyHz(int code) {
    static const double kHz[kNumCodes] = {100, 150, 250, 350, 550, 650, 850, 950, 1150};
    if (code < 1 || code > kNumCodes)
        throw std::out_of_range("IR frequency code must be 1..9, got " +
                                std::to_string(code));
    return kHz[code - 1];
}

static bool validAscending(const std::vector<uint8_t>& c) {
    if (c.empty()) return false;
    for (size_t i = 0; i < c.size(); i++) {
        if (c[i] < 1 || c[i] > kNumCodes) return false;
        if (i && c[i] <= c[i - 1]) return false;
    }
    return true;
}

std::string emitterIdFromCodes(const std::vector<uint8_t>& codes) {
    if (!validAscending(codes))
        throw std::invalid_argument("IR codes must be a non-empty ascending set of 1..9");
    std::string s;
    for (auto c : codes) s += char('0' + c);
    return s;
}

std::optional<std::vector<uint8_t>> codesFromEmitterId(const std::string& id) {
    std::vector<uint8_t> c;
    for (char ch : id) {
        if (ch < '1' || ch > '9') return std::nullopt;
        c.push_back(uint8_t(ch - '0'));
    }
    if (!validAscending(c)) return std::nullopt;
    return c;
}

std::optional<std::vector<uint8_t>> parseCodeList(const std::string& s) {
    std::vector<uint8_t> c;
    size_t i = 0;
    while (i <= s.size()) {
        const size_t j = s.find(',', i);
        const std::string tok =
            s.substr(i, j == std::string::npos ? std::string::npos : j - i);
        if (tok.size() != 1 || tok[0] < '1' || tok[0] > '9') return std::nullopt;
        c.push_back(uint8_t(tok[0] - '0'));
        if (j == std::string::npos) break;
        i = j + 1;
    }
    if (!validAscending(c)) return std::nullopt;
    return c;
}

std::string formatCodeList(const std::vector<uint8_t>& codes) {
    std::string s;
    for (size_t i = 0; i < codes.size(); i++) {
        if (i) s += ',';
        s += std::to_string(int(codes[i]));
    }
    return s;
}

uint64_t countIds(int n, int k) {
    if (n < 0 || k < 0) throw std::invalid_argument("countIds: negative argument");
    uint64_t total = 0, c = 1;  // c = C(n, i)
    for (int i = 1; i <= k && i <= n; i++) {
        c = c * uint64_t(n - i + 1) / uint64_t(i);
        total += c;
    }
    return total;
}

}  // namespace rfir::ir
