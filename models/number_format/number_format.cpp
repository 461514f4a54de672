#include "models/number_format/number_format.h"

#include <algorithm>

#include <cstring>
#include <stdexcept>

#include "models/common/user_text.h"

namespace cdvp {

namespace {
float as_float(uint32_t bits) {
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

const char* expected_text() { return "expected float32 or fixedK with K from 8 to 32"; }
}  // namespace

NumberFormat NumberFormat::fixed(uint32_t bits) {
    if (bits < kMinFixedBits || bits > kMaxFixedBits) {
        throw std::invalid_argument(std::string(expected_text()) + ", got fixed" + std::to_string(bits));
    }
    return NumberFormat(bits);
}

NumberFormat NumberFormat::parse(const std::string& text) {
    if (text == "float32") return float32();
    const std::string prefix = "fixed";
    const std::string digits = text.compare(0, prefix.size(), prefix) == 0 ? text.substr(prefix.size()) : "";
    const bool decimal = !digits.empty() && digits.size() <= 2 && digits[0] != '0' &&
                         digits.find_first_not_of("0123456789") == std::string::npos;
    if (decimal) {
        const auto bits = static_cast<uint32_t>(std::stoul(digits));
        if (bits >= kMinFixedBits && bits <= kMaxFixedBits) return NumberFormat(bits);
    }
    throw std::invalid_argument(std::string(expected_text()) + ", got '" + excerpt(text) + "'");
}

NumberFormat NumberFormat::from_register(uint32_t value) {
    if (value == 0) return float32();
    if (value >= kMinFixedBits && value <= kMaxFixedBits) return NumberFormat(value);
    throw std::invalid_argument("FORMAT register: expected 0 (float32) or 8 to 32 (fixedK), got " +
                                std::to_string(value));
}

std::string NumberFormat::name() const { return is_float() ? "float32" : "fixed" + std::to_string(fixed_bits_); }

BlockRamLayout NumberFormat::block_ram_layout(uint64_t boxes) const {
    // An 18-Kbit primitive's aspects with their parity bits, widest first: a
    // tie keeps the wider, shallower one (fewer cascaded primitives to mux).
    constexpr BlockRamLayout kAspects[] = {{36, 512, 1}, {18, 1024, 1}, {9, 2048, 1}};
    BlockRamLayout best;
    bool found = false;
    for (BlockRamLayout layout : kAspects) {
        if (layout.width < bits()) continue;
        layout.coordinates_per_word = std::min(layout.width / bits(), BlockRamLayout::kCoordinates);
        if (!found || layout.primitives(boxes) < best.primitives(boxes)) best = layout;
        found = true;
    }
    return best;
}

bool NumberFormat::less_equal(uint32_t a, uint32_t b) const {
    if (is_float()) return as_float(a) <= as_float(b);
    return (a & word_mask()) <= (b & word_mask());
}

}  // namespace cdvp
