// Texts nested a chosen number of levels deep, as models/common/nesting_limit.h
// counts them, for the preset and config file tests of the nesting limit.
#pragma once

#include <string>

namespace cdvp::test {

inline std::string repeated(const std::string& text, int times) {
    std::string out;
    for (int k = 0; k < times; ++k) out += text;
    return out;
}

// 'open' 'levels' times, then 'inside', then 'close' as many times:
// nested("[", "]", 3, "1") is [[[1]]].
inline std::string nested(const std::string& open, const std::string& close, int levels,
                          const std::string& inside = "") {
    return repeated(open, levels) + inside + repeated(close, levels);
}

// "a.a.a" of 'parts' parts, joined by 'dot'.
inline std::string dotted(int parts, const std::string& part = "a", const std::string& dot = ".") {
    return part + repeated(dot + part, parts - 1);
}

}  // namespace cdvp::test
